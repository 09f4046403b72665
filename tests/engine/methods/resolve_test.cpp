// The resolve formula (lecture, "Collisions on a Line – Full Formula"):
// u = (m1·v1 + m2·v2)/(m1 + m2), v' = u − C·(v − u); infinite masses; and the Resolver that the
// three methods share (pair and wall contacts, kinematic reversal, the rest rule).
#include "resolve.h"
#include "scratch.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using test_worlds::addBlock;
using test_worlds::makeWorld;

TEST(ResolveFormula, CenterOfMassVelocityLectureExamples) {
    EXPECT_EQ(centerOfMassVelocity(1.0, 6.0, 2.0, 0.0), 2.0);  // (6 + 0)/3
    EXPECT_EQ(centerOfMassVelocity(1.0, 4.0, 2.0, -2.0), 0.0); // (4 − 4)/3
    EXPECT_EQ(centerOfMassVelocity(3.0, 1.0, 1.0, 5.0), 2.0);  // (3 + 5)/4
    EXPECT_EQ(centerOfMassVelocity(2.0, -3.0, 2.0, 3.0), 0.0);
}

TEST(ResolveFormula, CenterOfMassVelocityWithInfiniteMassIsThatBodysVelocity) {
    EXPECT_EQ(centerOfMassVelocity(kInfiniteMass, 0.0, 1.0, 5.0), 0.0); // a wall
    EXPECT_EQ(centerOfMassVelocity(1.0, 5.0, kInfiniteMass, -1.5), -1.5);
    EXPECT_EQ(centerOfMassVelocity(kInfiniteMass, 2.0, 1e30, 7.0), 2.0);
    EXPECT_FALSE(std::isnan(centerOfMassVelocity(1.0, 5.0, kInfiniteMass, 0.0)));
}

TEST(ResolveFormula, VelocityAfterCollisionLectureExamples) {
    // Example 1: u = 2, C = 1: v1' = 2 − (6 − 2) = −2, v2' = 2 − (0 − 2) = 4.
    EXPECT_EQ(velocityAfterCollision(6.0, 2.0, 1.0), -2.0);
    EXPECT_EQ(velocityAfterCollision(0.0, 2.0, 1.0), 4.0);
    // Example 2: u = 0, C = 0: both stop.
    EXPECT_EQ(velocityAfterCollision(4.0, 0.0, 0.0), 0.0);
    EXPECT_EQ(velocityAfterCollision(-2.0, 0.0, 0.0), 0.0);
    // Same example with C = 1 (lecture, solution 1): −4 and 2.
    EXPECT_EQ(velocityAfterCollision(4.0, 0.0, 1.0), -4.0);
    EXPECT_EQ(velocityAfterCollision(-2.0, 0.0, 1.0), 2.0);
    // A wall (u = 0): v' = −C·v.
    EXPECT_EQ(velocityAfterCollision(8.0, 0.0, 0.5), -4.0);
    EXPECT_EQ(velocityAfterCollision(-8.0, 0.0, 0.75), 6.0);
    // C = 0 against a moving infinite mass: take its velocity.
    EXPECT_EQ(velocityAfterCollision(-3.0, 1.0, 0.0), 1.0);
}

TEST(ResolveFormula, MomentumConservedForRandomPairsAndEnergyWhenElastic) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> mass(0.01, 100.0), speed(-50.0, 50.0), c(0.0, 1.0);
    for (int i = 0; i < 10000; ++i) {
        const double m1 = mass(rng), m2 = mass(rng), v1 = speed(rng), v2 = speed(rng);
        const double C = i % 4 == 0 ? 1.0 : c(rng);
        const double u = centerOfMassVelocity(m1, v1, m2, v2);
        const double w1 = velocityAfterCollision(v1, u, C), w2 = velocityAfterCollision(v2, u, C);
        // Relative 1e-12 of the momentum scale m1|v1| + m2|v2|: the formula is a handful of
        // rounded operations (a few 1e-16 each); the total itself may cancel to near zero.
        const double scale = m1 * std::abs(v1) + m2 * std::abs(v2);
        ASSERT_NEAR(m1 * w1 + m2 * w2, m1 * v1 + m2 * v2, 1e-12 * scale)
            << "m1=" << m1 << " v1=" << v1 << " m2=" << m2 << " v2=" << v2 << " C=" << C;
        // Relative velocity is reversed and scaled by C.
        ASSERT_NEAR(w2 - w1, C * (v1 - v2), 1e-12 * (std::abs(v1) + std::abs(v2) + 1.0));
        if (C == 1.0) {
            const double before = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2);
            const double after = 0.5 * (m1 * w1 * w1 + m2 * w2 * w2);
            ASSERT_NEAR(after, before, 1e-12 * before);
        } else {
            // Energy never grows (within rounding).
            const double before = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2);
            const double after = 0.5 * (m1 * w1 * w1 + m2 * w2 * w2);
            ASSERT_LE(after, before * (1.0 + 1e-12));
        }
    }
}

// A one-substep context around a world, as the methods build it.
struct ResolverHarness {
    World world;
    StepScratch scratch;
    BroadPhase& grid = scratch.broadPhase;
    StepStats stats;
    std::vector<CollisionRecord> log;
    SubstepContext ctx;
    Resolver resolver;

    explicit ResolverHarness(World w, double h = 1.0 / 60.0)
        : world(std::move(w)), ctx{world, scratch, grid, stats, &log, h, 0.0}, resolver(ctx) {
        grid.build(world.bounds, world.blocks, [this](int i) { return aabbOf(world.blocks[i]); });
        resolver.setNow(0.0);
    }
};

TEST(Resolver, PairResolveConservesMomentumForRandomMassesAndVelocities) {
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> mass(0.01, 100.0), speed(0.0, 40.0), c(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        // A = [4.5,5.5] touches B = [5.5,6.5] along x; A closes on B (v1 > v2 by at least 0.01).
        World w = makeWorld(Method::Perfect, {0.0, 0.0}, i % 3 == 0 ? 1.0 : c(rng));
        const double m1 = mass(rng), m2 = mass(rng);
        const double v2 = speed(rng) - 20.0, v1 = v2 + 0.01 + speed(rng);
        const double vy1 = speed(rng), vy2 = -speed(rng);
        addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {v1, vy1}, m1);
        addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {v2, vy2}, m2);
        const double C = w.settings.bounciness;
        ResolverHarness h(std::move(w));
        ASSERT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::Bounce);
        const Block& a = h.world.blocks[0];
        const Block& b = h.world.blocks[1];
        const double scale = m1 * std::abs(v1) + m2 * std::abs(v2);
        // Relative 1e-12: see ResolveFormula.MomentumConserved...
        ASSERT_NEAR(m1 * a.velocity.x + m2 * b.velocity.x, m1 * v1 + m2 * v2, 1e-12 * scale);
        EXPECT_EQ(a.velocity.y, vy1); // the other component is unchanged
        EXPECT_EQ(b.velocity.y, vy2);
        if (C == 1.0) {
            const double before = 0.5 * (m1 * v1 * v1 + m2 * v2 * v2);
            const double after =
                0.5 * (m1 * a.velocity.x * a.velocity.x + m2 * b.velocity.x * b.velocity.x);
            ASSERT_NEAR(after, before, 1e-12 * before);
        }
        ASSERT_EQ(h.log.size(), 1u);
        EXPECT_EQ(h.stats.collisions, 1);
    }
}

TEST(Resolver, PairRecordCarriesTheFormulasNumbers) {
    World w = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {6.0, 1.0}, 1.0);
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {0.0, -1.0}, 2.0);
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::Bounce);
    ASSERT_EQ(h.log.size(), 1u);
    const CollisionRecord& r = h.log[0];
    EXPECT_EQ(r.block, 0);
    EXPECT_EQ(r.other, 1);
    EXPECT_EQ(r.axis, 0);
    EXPECT_EQ(r.m1, 1.0);
    EXPECT_EQ(r.m2, 2.0);
    EXPECT_EQ(r.v1, 6.0);
    EXPECT_EQ(r.v2, 0.0);
    EXPECT_EQ(r.u, 2.0);
    EXPECT_EQ(r.C, 1.0);
    EXPECT_EQ(r.v1After, -2.0);
    EXPECT_EQ(r.v2After, 4.0);
    EXPECT_FALSE(r.rest);
    EXPECT_EQ(h.world.blocks[0].velocity, (Vec2{-2.0, 1.0}));
    EXPECT_EQ(h.world.blocks[1].velocity, (Vec2{4.0, -1.0}));
}

TEST(Resolver, PairThatIsNotApproachingIsNotResolved) {
    // The lecture's "collision that is not really a collision": touching, relative velocity
    // opening. Argument order must not matter.
    World w = makeWorld(Method::Perfect);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {-1.0, 0.0});
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {1.0, 0.0});
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::None);
    EXPECT_EQ(h.resolver.resolvePair(1, 0, 0), Resolution::None);
    EXPECT_EQ(h.world.blocks[0].velocity, (Vec2{-1.0, 0.0}));
    EXPECT_EQ(h.world.blocks[1].velocity, (Vec2{1.0, 0.0}));
    EXPECT_TRUE(h.log.empty());
    EXPECT_EQ(h.stats.collisions, 0);
}

TEST(Resolver, PairWithReversedArgumentsGivesTheSameResult) {
    World w = makeWorld(Method::Perfect, {0.0, 0.0}, 0.5);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {3.0, 0.0}, 1.0);
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {-3.0, 0.0}, 1.0);
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(1, 0, 0), Resolution::Bounce);
    // u = 0, C = 0.5: ±3 -> ∓1.5.
    EXPECT_EQ(h.world.blocks[0].velocity.x, -1.5);
    EXPECT_EQ(h.world.blocks[1].velocity.x, 1.5);
}

TEST(Resolver, DynamicAgainstStaticAndKinematic) {
    World w = makeWorld(Method::Perfect, {0.0, 0.0}, 0.5);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {4.0, 0.0}, 3.0);
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {}, 1.0, BodyKind::Static);
    addBlock(w, {5.0, 8.0}, {1.0, 3.0}, {0.0, -2.0}, 1.0, BodyKind::Kinematic); // on top of 0
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[0].velocity.x, -2.0); // u = 0: −C·v
    EXPECT_EQ(h.world.blocks[1].velocity, Vec2{}); // a static block never moves
    // The kinematic block comes down at 2 m/s onto block 0 (at rest in y): u = −2,
    // v' = −2 − 0.5·(0 − (−2)) = −3; the kinematic keeps its velocity.
    EXPECT_EQ(h.resolver.resolvePair(2, 0, 1), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[0].velocity.y, -3.0);
    EXPECT_EQ(h.world.blocks[2].velocity.y, -2.0);
    ASSERT_EQ(h.log.size(), 2u);
    EXPECT_EQ(h.log[1].u, -2.0);
    EXPECT_TRUE(std::isinf(h.log[1].m1));
}

TEST(Resolver, KinematicReversesOnStaticBlockAndWall) {
    World w = makeWorld(Method::Perfect);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {2.0, 0.5}, 1.0, BodyKind::Kinematic);
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {}, 1.0, BodyKind::Static);
    addBlock(w, {19.5, 2.0}, {1.0, 1.0}, {3.0, 0.0}, 1.0, BodyKind::Kinematic); // at the wall
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[0].velocity, (Vec2{-2.0, 0.5}));
    EXPECT_EQ(h.resolver.resolveWall(2, 0), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[2].velocity, (Vec2{-3.0, 0.0}));
    ASSERT_EQ(h.log.size(), 2u);
    EXPECT_EQ(h.log[1].other, kWallRight);
}

TEST(Resolver, WallBounceIsMinusCTimesV) {
    World w = makeWorld(Method::Perfect, {0.0, 0.0}, 0.75);
    addBlock(w, {0.5, 6.0}, {1.0, 1.0}, {-8.0, 1.0}, 2.0);  // touching the left wall
    addBlock(w, {10.0, 0.5}, {1.0, 1.0}, {0.0, -4.0}, 1.0); // touching the floor
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolveWall(0, 0), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[0].velocity, (Vec2{6.0, 1.0}));
    EXPECT_EQ(h.resolver.resolveWall(1, 1), Resolution::Bounce);
    EXPECT_EQ(h.world.blocks[1].velocity, (Vec2{0.0, 3.0}));
    ASSERT_EQ(h.log.size(), 2u);
    EXPECT_EQ(h.log[0].other, kWallLeft);
    EXPECT_EQ(h.log[1].other, kWallBottom);
    EXPECT_EQ(h.log[1].u, 0.0);
    EXPECT_EQ(h.log[1].v1After, 3.0);
    EXPECT_EQ(h.stats.collisions, 2);
}

TEST(Resolver, SlowContactFollowsTheRestRule) {
    // Closing slower than restSpeed (1e-6 m/s, no gravity): perfectly inelastic even with C = 1.
    World w = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0);
    addBlock(w, {5.0, 6.0}, {1.0, 1.0}, {5e-7, 0.0}, 1.0);
    addBlock(w, {6.0, 6.0}, {1.0, 1.0}, {0.0, 0.0}, 3.0);
    ResolverHarness h(std::move(w));
    EXPECT_EQ(h.resolver.resolvePair(0, 1, 0), Resolution::Rest);
    // u = 5e-7 / 4: both take it. Tolerance 1e-20 m/s: a few ulps of 1.25e-7.
    EXPECT_NEAR(h.world.blocks[0].velocity.x, 1.25e-7, 1e-20);
    EXPECT_NEAR(h.world.blocks[1].velocity.x, 1.25e-7, 1e-20);
    ASSERT_EQ(h.log.size(), 1u);
    EXPECT_TRUE(h.log[0].rest);
    EXPECT_EQ(h.log[0].C, 0.0);
}

TEST(Resolver, RestRuleStopsAWholeStackOnTheFloor) {
    // Three blocks resting on each other on the floor, all falling at g·h after gravity: the
    // floor contact takes the stack to rest at once (velocities exactly 0).
    const double h = 1.0 / 60.0;
    World w = makeWorld(Method::Perfect, {0.0, -9.81}, 0.5);
    for (int i = 0; i < 3; ++i) addBlock(w, {10.0, 0.5 + i}, {1.0, 1.0}, {0.0, -9.81 * h});
    ResolverHarness harness(std::move(w), h);
    EXPECT_EQ(harness.resolver.resolveWall(0, 1), Resolution::Rest);
    for (const Block& b : harness.world.blocks) EXPECT_EQ(b.velocity, Vec2{});
    EXPECT_EQ(harness.stats.collisions, 0); // a resting contact: counted apart
    EXPECT_EQ(harness.stats.contacts, 1);
}

} // namespace
