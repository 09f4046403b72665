// Vec2: every operator and function. Values are chosen so that results are exact in binary
// floating point (small integers, halves and quarters), so most checks compare with ==.
#include "vec2.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

// constexpr use: the operators and functions marked constexpr work at compile time.
constexpr Vec2 kA{1.0, 2.0};
constexpr Vec2 kB{3.0, -4.0};
static_assert(Vec2{}.x == 0.0 && Vec2{}.y == 0.0, "default is the zero vector");
static_assert(kA[0] == 1.0 && kA[1] == 2.0, "const operator[]");
static_assert(kA + kB == Vec2{4.0, -2.0}, "operator+");
static_assert(kA - kB == Vec2{-2.0, 6.0}, "operator-");
static_assert(-kA == Vec2{-1.0, -2.0}, "unary operator-");
static_assert(kA * 2.0 == Vec2{2.0, 4.0}, "vector times scalar");
static_assert(2.0 * kA == Vec2{2.0, 4.0}, "scalar times vector");
static_assert(kB / 2.0 == Vec2{1.5, -2.0}, "operator/");
static_assert(kA != kB && !(kA != kA), "operator!=");
static_assert(dot(kA, kB) == -5.0, "dot");
static_assert(cross(kA, kB) == -10.0, "cross");
static_assert(lengthSquared(kB) == 25.0, "lengthSquared");
static_assert(perpendicular(Vec2{1.0, 0.0}) == Vec2{0.0, 1.0}, "perpendicular");

constexpr Vec2 compoundAtCompileTime() {
    Vec2 v;
    v[0] = 3.0; // non-const operator[] writes
    v[1] = 4.0;
    v += Vec2{1.0, 1.0};
    v -= Vec2{2.0, 3.0};
    v *= 4.0;
    v /= 2.0;
    return v; // ((3,4) + (1,1) - (2,3)) * 4 / 2 = (4, 4)
}
static_assert(compoundAtCompileTime() == Vec2{4.0, 4.0}, "compound operators are constexpr");

TEST(Vec2, ConstructionAndIndexRead) {
    const Vec2 v{1.5, -2.5};
    EXPECT_EQ(v.x, 1.5);
    EXPECT_EQ(v.y, -2.5);
    EXPECT_EQ(v[0], 1.5);
    EXPECT_EQ(v[1], -2.5);
    const Vec2 zero;
    EXPECT_EQ(zero.x, 0.0);
    EXPECT_EQ(zero.y, 0.0);
}

TEST(Vec2, IndexWriteChangesTheRightComponent) {
    Vec2 v{1.0, 2.0};
    v[0] = 7.0;
    EXPECT_EQ(v, (Vec2{7.0, 2.0}));
    v[1] = -3.0;
    EXPECT_EQ(v, (Vec2{7.0, -3.0}));
    v[1] += 1.0;
    EXPECT_EQ(v.y, -2.0);
}

TEST(Vec2, ArithmeticOperators) {
    const Vec2 a{1.0, 2.0}, b{3.0, -4.0};
    EXPECT_EQ(a + b, (Vec2{4.0, -2.0}));
    EXPECT_EQ(a - b, (Vec2{-2.0, 6.0}));
    EXPECT_EQ(b - a, (Vec2{2.0, -6.0}));
    EXPECT_EQ(-a, (Vec2{-1.0, -2.0}));
    EXPECT_EQ(a * 0.5, (Vec2{0.5, 1.0}));
    EXPECT_EQ(0.5 * a, (Vec2{0.5, 1.0}));
    EXPECT_EQ(b / 4.0, (Vec2{0.75, -1.0}));
}

TEST(Vec2, CompoundOperatorsModifyAndReturnSelf) {
    Vec2 v{1.0, 2.0};
    Vec2& r1 = (v += Vec2{1.0, 1.0});
    EXPECT_EQ(&r1, &v);
    EXPECT_EQ(v, (Vec2{2.0, 3.0}));
    Vec2& r2 = (v -= Vec2{0.5, 4.0});
    EXPECT_EQ(&r2, &v);
    EXPECT_EQ(v, (Vec2{1.5, -1.0}));
    Vec2& r3 = (v *= -2.0);
    EXPECT_EQ(&r3, &v);
    EXPECT_EQ(v, (Vec2{-3.0, 2.0}));
    Vec2& r4 = (v /= 4.0);
    EXPECT_EQ(&r4, &v);
    EXPECT_EQ(v, (Vec2{-0.75, 0.5}));
}

TEST(Vec2, EqualityComparesBothComponents) {
    EXPECT_TRUE((Vec2{1.0, 2.0} == Vec2{1.0, 2.0}));
    EXPECT_FALSE((Vec2{1.0, 2.0} == Vec2{1.0, 3.0}));
    EXPECT_FALSE((Vec2{1.0, 2.0} == Vec2{0.0, 2.0}));
    EXPECT_TRUE((Vec2{1.0, 2.0} != Vec2{2.0, 1.0}));
    EXPECT_FALSE((Vec2{1.0, 2.0} != Vec2{1.0, 2.0}));
}

TEST(Vec2, DotAndCross) {
    EXPECT_EQ(dot(Vec2{1.0, 2.0}, Vec2{3.0, -4.0}), -5.0);
    EXPECT_EQ(dot(Vec2{1.0, 0.0}, Vec2{0.0, 1.0}), 0.0);
    // cross is the z of the 3D cross product: x̂ × ŷ = +1, ŷ × x̂ = -1, antisymmetric.
    EXPECT_EQ(cross(Vec2{1.0, 0.0}, Vec2{0.0, 1.0}), 1.0);
    EXPECT_EQ(cross(Vec2{0.0, 1.0}, Vec2{1.0, 0.0}), -1.0);
    EXPECT_EQ(cross(Vec2{2.0, 3.0}, Vec2{4.0, 6.0}), 0.0); // parallel
    EXPECT_EQ(cross(Vec2{1.0, 2.0}, Vec2{3.0, -4.0}), -10.0);
}

TEST(Vec2, LengthAndLengthSquared) {
    EXPECT_EQ(lengthSquared(Vec2{3.0, 4.0}), 25.0);
    EXPECT_EQ(length(Vec2{3.0, 4.0}), 5.0);
    EXPECT_EQ(length(Vec2{-3.0, -4.0}), 5.0);
    EXPECT_EQ(length(Vec2{}), 0.0);
    // sqrt is correctly rounded, so length(1,1) is exactly the double nearest √2.
    EXPECT_EQ(length(Vec2{1.0, 1.0}), std::sqrt(2.0));
}

TEST(Vec2, NormalizedIsUnitAndKeepsDirection) {
    const Vec2 n = normalized(Vec2{3.0, 4.0});
    // 3/5 and 4/5 are each one correctly rounded division: exact to the nearest double.
    EXPECT_EQ(n, (Vec2{3.0 / 5.0, 4.0 / 5.0}));
    const Vec2 m = normalized(Vec2{-2.0, 7.0});
    // Tolerance 1e-15: a unit vector's length after a division and a sqrt, a few ulps of 1.
    EXPECT_NEAR(length(m), 1.0, 1e-15);
    EXPECT_NEAR(cross(m, Vec2{-2.0, 7.0}), 0.0, 1e-15); // same direction
    EXPECT_GT(dot(m, Vec2{-2.0, 7.0}), 0.0);
}

TEST(Vec2, NormalizedZeroVectorStaysZero) {
    const Vec2 n = normalized(Vec2{});
    EXPECT_FALSE(std::isnan(n.x));
    EXPECT_FALSE(std::isnan(n.y));
    EXPECT_EQ(n, Vec2{});
}

TEST(Vec2, PerpendicularRotatesCounterClockwise) {
    EXPECT_EQ(perpendicular(Vec2{1.0, 0.0}), (Vec2{0.0, 1.0}));
    EXPECT_EQ(perpendicular(Vec2{0.0, 1.0}), (Vec2{-1.0, 0.0}));
    const Vec2 v{2.0, -3.0};
    EXPECT_EQ(dot(perpendicular(v), v), 0.0);
    EXPECT_GT(cross(v, perpendicular(v)), 0.0); // +90 degrees
    EXPECT_EQ(perpendicular(perpendicular(v)), -v);
}

TEST(Vec2, ApproxEqualUsesAnInclusiveAbsoluteTolerancePerComponent) {
    EXPECT_TRUE(approxEqual(Vec2{1.0, 2.0}, Vec2{1.0, 2.0}, 0.0));
    EXPECT_TRUE(approxEqual(Vec2{1.0, 2.0}, Vec2{1.5, 1.5}, 0.5)); // exactly at the tolerance
    EXPECT_FALSE(approxEqual(Vec2{1.0, 2.0}, Vec2{1.5, 2.0}, 0.25));
    EXPECT_FALSE(approxEqual(Vec2{1.0, 2.0}, Vec2{1.0, 2.75}, 0.5)); // y alone differs
    EXPECT_TRUE(approxEqual(Vec2{-1.0, 0.0}, Vec2{-1.0 + 1e-10, -1e-10}, 1e-9));
}

} // namespace
