// Collision math: overlap tests, penetration, swept boxes, the time of impact (lecture, "Point of
// Impact (POI) Calculation": t = a/b) and the walls. Coordinates are small binary fractions, so
// gaps, speeds and times are exact and most checks compare with ==.
#include "collision.h"

#include <gtest/gtest.h>

namespace {

Aabb box(double minX, double minY, double maxX, double maxY) {
    return {{minX, minY}, {maxX, maxY}};
}

// An impact (Impact or WallImpact) that hits at `time` on `axes`; the failure says what differs.
template <class AnImpact>
::testing::AssertionResult hitsAt(const AnImpact& impact, double time, int axes) {
    if (!impact.hit()) return ::testing::AssertionFailure() << "no hit";
    if (impact.time != time || impact.axes != axes)
        return ::testing::AssertionFailure()
               << "hit at " << impact.time << " s on axes " << int(impact.axes) << ", not at "
               << time << " s on axes " << axes;
    return ::testing::AssertionSuccess();
}

TEST(Aabb, AabbOfCentreAndSize) {
    const Aabb b = aabbOf(Vec2{5.0, 6.0}, Vec2{2.0, 1.0});
    EXPECT_EQ(b.min, (Vec2{4.0, 5.5}));
    EXPECT_EQ(b.max, (Vec2{6.0, 6.5}));
    Block block;
    block.position = {1.0, 1.0};
    block.size = {0.5, 0.25};
    const Aabb c = aabbOf(block);
    EXPECT_EQ(c.min, (Vec2{0.75, 0.875}));
    EXPECT_EQ(c.max, (Vec2{1.25, 1.125}));
}

TEST(Aabb, OverlapsNeedsPositiveAreaTouchingIsNotOverlap) {
    const Aabb p = box(0, 0, 1, 1);
    EXPECT_TRUE(overlaps(p, box(0.5, 0.5, 1.5, 1.5)));
    EXPECT_TRUE(overlaps(p, box(0.25, 0.25, 0.75, 0.75))); // contained
    EXPECT_FALSE(overlaps(p, box(1, 0, 2, 1)));            // touching on the right face
    EXPECT_FALSE(overlaps(p, box(-1, 0, 0, 1)));           // touching on the left face
    EXPECT_FALSE(overlaps(p, box(0, 1, 1, 2)));            // touching on the top face
    EXPECT_FALSE(overlaps(p, box(0, -1, 1, 0)));           // touching on the bottom face
    EXPECT_FALSE(overlaps(p, box(1, 1, 2, 2)));            // touching at a corner
    EXPECT_FALSE(overlaps(p, box(0.5, 2, 1.5, 3)));        // x overlaps, y apart
    EXPECT_FALSE(overlaps(p, box(2, 0.5, 3, 1.5)));        // y overlaps, x apart
}

TEST(Aabb, OverlapExtentsPerAxis) {
    const Aabb p = box(0, 0, 2, 1);
    EXPECT_EQ(overlapExtents(p, box(1.5, 0.75, 3, 2)), (Vec2{0.5, 0.25}));
    EXPECT_EQ(overlapExtents(p, box(0.5, 0.25, 1, 0.5)), (Vec2{0.5, 0.25})); // contained
    EXPECT_EQ(overlapExtents(p, box(2, 0, 3, 1)), (Vec2{0.0, 1.0}));         // touching: 0
    EXPECT_EQ(overlapExtents(p, box(3, 0, 4, 1)), (Vec2{-1.0, 1.0}));        // apart: negative
    EXPECT_EQ(overlapExtents(box(3, 0, 4, 1), p), (Vec2{-1.0, 1.0}));        // symmetric
}

TEST(Aabb, PenetrationIsTheSmallerAxisOverlap) {
    const Aabb p = box(0, 0, 2, 2);
    EXPECT_EQ(penetration(p, box(1.5, 1, 3, 3)), 0.5);   // x 0.5, y 1
    EXPECT_EQ(penetration(p, box(1, 1.75, 3, 3)), 0.25); // x 1, y 0.25
    EXPECT_EQ(penetration(p, box(2, 0, 3, 2)), 0.0);     // touching
    EXPECT_EQ(penetration(p, box(3, 0, 4, 2)), 0.0);     // apart (negative extent is not depth)
    EXPECT_EQ(penetration(p, box(0.5, 3, 1, 4)), 0.0);   // x overlaps only
}

TEST(Aabb, OutsideDepthPerWall) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 5.0}};
    EXPECT_EQ(outsideDepth(box(1, 1, 2, 2), bounds), 0.0);
    EXPECT_EQ(outsideDepth(box(0, 0, 10, 5), bounds), 0.0); // touching every wall is inside
    EXPECT_EQ(outsideDepth(box(-0.5, 1, 0.5, 2), bounds), 0.5);
    EXPECT_EQ(outsideDepth(box(9, 1, 10.25, 2), bounds), 0.25);
    EXPECT_EQ(outsideDepth(box(1, -0.75, 2, 0.25), bounds), 0.75);
    EXPECT_EQ(outsideDepth(box(1, 4, 2, 5.125), bounds), 0.125);
    EXPECT_EQ(outsideDepth(box(-0.25, -1, 0.75, 0), bounds), 1.0); // the largest of two
}

TEST(Aabb, SweptAabbCoversStartAndEnd) {
    const Aabb s = sweptAabb(Vec2{1.0, 1.0}, Vec2{1.0, 2.0}, Vec2{4.0, -2.0}, 0.5);
    // Start [0.5,1.5]x[0,2], end (3,0): [2.5,3.5]x[-1,1].
    EXPECT_EQ(s.min, (Vec2{0.5, -1.0}));
    EXPECT_EQ(s.max, (Vec2{3.5, 2.0}));
    const Aabb still = sweptAabb(Vec2{1.0, 1.0}, Vec2{1.0, 2.0}, Vec2{}, 0.5);
    EXPECT_EQ(still.min, (Vec2{0.5, 0.0}));
    EXPECT_EQ(still.max, (Vec2{1.5, 2.0}));
    const Aabb back = sweptAabb(Vec2{1.0, 1.0}, Vec2{1.0, 1.0}, Vec2{-2.0, 4.0}, 0.25);
    EXPECT_EQ(back.min, (Vec2{0.0, 0.5}));
    EXPECT_EQ(back.max, (Vec2{1.5, 2.5}));
}

TEST(Aabb, ContainsIsInclusive) {
    EXPECT_TRUE(contains(box(0, 0, 2, 2), box(0, 0, 2, 2)));
    EXPECT_TRUE(contains(box(0, 0, 2, 2), box(0.5, 0.5, 1, 1)));
    EXPECT_FALSE(contains(box(0, 0, 2, 2), box(0.5, 0.5, 2.5, 1)));
}

// --- time of impact ---

TEST(TimeOfImpact, HeadOnBothMovingMatchesLectureTEqualsAOverB) {
    // A = [0,1] moving right at 10 m/s, B = [1.5,2.5] moving left at 6 m/s, same y range.
    // Lecture: a = gap before moving = 0.5 m, b = how far the faces close within the frame =
    // (10 + 6) m/s · dt. With dt = 1/16 s: b = 1 m, t = a/b = 0.5 of the frame = 1/32 s.
    const double dt = 0.0625;
    const double a = 0.5, b = (10.0 + 6.0) * dt;
    const double t = a / b;
    ASSERT_EQ(t, 0.5);
    const Impact impact =
        timeOfImpact(box(0, 0, 1, 1), Vec2{10.0, 0.0}, box(1.5, 0, 2.5, 1), Vec2{-6.0, 0.0}, dt);
    // In seconds; exact: every number is a binary fraction.
    EXPECT_TRUE(hitsAt(impact, t * dt, kAxisX));
    // Swapping the roles gives the same time.
    const Impact swapped =
        timeOfImpact(box(1.5, 0, 2.5, 1), Vec2{-6.0, 0.0}, box(0, 0, 1, 1), Vec2{10.0, 0.0}, dt);
    EXPECT_EQ(swapped.time, t * dt);
    EXPECT_EQ(swapped.axes, kAxisX);
}

TEST(TimeOfImpact, HeadOnVertical) {
    // A above B, falling at 4 m/s onto B rising at 4 m/s: gap 1 m, closing 8 m/s: 1/8 s.
    const Impact impact =
        timeOfImpact(box(0, 3, 1, 4), Vec2{0.0, -4.0}, box(0, 1, 1, 2), Vec2{0.0, 4.0}, 1.0);
    EXPECT_TRUE(hitsAt(impact, 0.125, kAxisY));
}

TEST(TimeOfImpact, OneMovingAgainstOneAtRest) {
    const Impact impact =
        timeOfImpact(box(0, 0, 1, 1), Vec2{4.0, 0.0}, box(2, 0.5, 3, 1.5), Vec2{}, 1.0);
    EXPECT_TRUE(hitsAt(impact, 0.25, kAxisX)); // gap 1 m at 4 m/s
    // The one at rest can be the first argument: it is hit from behind.
    const Impact other =
        timeOfImpact(box(2, 0.5, 3, 1.5), Vec2{}, box(0, 0, 1, 1), Vec2{4.0, 0.0}, 1.0);
    EXPECT_TRUE(hitsAt(other, 0.25, kAxisX));
}

TEST(TimeOfImpact, CatchingUpFromBehind) {
    // Both move right; A is faster: closing 2 m/s over a 1 m gap.
    const Impact impact =
        timeOfImpact(box(0, 0, 1, 1), Vec2{5.0, 0.0}, box(2, 0, 3, 1), Vec2{3.0, 0.0}, 1.0);
    EXPECT_TRUE(hitsAt(impact, 0.5, kAxisX));
}

TEST(TimeOfImpact, MovingApartNeverHits) {
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{-4.0, 0.0}, box(2, 0, 3, 1), Vec2{}, 10.0).hit());
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{-1.0, 0.0}, box(2, 0, 3, 1), Vec2{1.0, 0.0}, 10.0)
            .hit());
    // Same velocity: no relative motion, never hits.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{3.0, 1.0}, box(2, 0, 3, 1), Vec2{3.0, 1.0}, 10.0).hit());
}

TEST(TimeOfImpact, ParallelPathsMiss) {
    // Both move along x on separate lanes (y ranges [0,1] and [2,3]): they pass each other.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{5.0, 0.0}, box(2, 2, 3, 3), Vec2{-5.0, 0.0}, 10.0)
            .hit());
    // Lanes that touch (y faces equal) also pass: touching is not a collision.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{5.0, 0.0}, box(2, 1, 3, 2), Vec2{}, 10.0).hit());
}

TEST(TimeOfImpact, DiagonalPathThatMissesTheBox) {
    // A moves up-right at (1,1); B = [2,3]x[0,1]. A's x faces meet at t = 1, but by then A's
    // bottom (y = 1) has just left B's top: only the corners touch as they part: no hit.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 1.0}, box(2, 0, 3, 1), Vec2{}, 10.0).hit());
    // Moving up-right faster in y: A is already above B when the x faces meet.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 2.0}, box(2, 0, 3, 1), Vec2{}, 10.0).hit());
}

TEST(TimeOfImpact, TheAxisWhoseEntryComesLastIsTheCollisionAxis) {
    // A moves (2,1); B = [3,4]x[0.5,1.5]. x entry 2/2 = 1 s; y already overlaps (entry < 0):
    // the x faces meet while y overlaps: axis x only.
    const Impact x =
        timeOfImpact(box(0, 0, 1, 1), Vec2{2.0, 1.0}, box(3, 0.5, 4, 1.5), Vec2{}, 10.0);
    EXPECT_TRUE(hitsAt(x, 1.0, kAxisX));
    // A moves (1,2); B = [0.5,1.5]x[3,4]: y entry at 1 s, x overlaps all along: axis y.
    const Impact y =
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 2.0}, box(0.5, 3, 1.5, 4), Vec2{}, 10.0);
    EXPECT_TRUE(hitsAt(y, 1.0, kAxisY));
    // x entry at 0.5 s, y entry at 0.75 s (later): axis y.
    const Impact late =
        timeOfImpact(box(0, 0, 1, 1), Vec2{2.0, 4.0}, box(2, 4, 3, 5), Vec2{}, 10.0);
    EXPECT_TRUE(hitsAt(late, 0.75, kAxisY));
}

TEST(TimeOfImpact, TouchingAndApproachingHitsAtTimeZero) {
    const Impact impact =
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 0.0}, box(1, 0, 2, 1), Vec2{}, 1.0);
    EXPECT_TRUE(hitsAt(impact, 0.0, kAxisX));
    // Resting on top of another, pushed down by gravity: y at time 0.
    const Impact onTop =
        timeOfImpact(box(0, 1, 1, 2), Vec2{0.0, -0.1635}, box(0, 0, 1, 1), Vec2{}, 1.0);
    EXPECT_TRUE(hitsAt(onTop, 0.0, kAxisY));
}

TEST(TimeOfImpact, TouchingAndPartingDoesNotHit) {
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{-1.0, 0.0}, box(1, 0, 2, 1), Vec2{}, 1.0).hit());
    EXPECT_FALSE(
        timeOfImpact(box(0, 1, 1, 2), Vec2{0.0, 3.0}, box(0, 0, 1, 1), Vec2{0.0, 1.0}, 1.0).hit());
    // Touching with no relative motion: resting side by side.
    EXPECT_FALSE(
        timeOfImpact(box(0, 0, 1, 1), Vec2{0.0, -2.0}, box(1, 0, 2, 1), Vec2{0.0, -2.0}, 1.0)
            .hit());
}

TEST(TimeOfImpact, CornerHitSetsBothAxes) {
    // A's top-right corner (1,1) meets B's bottom-left corner (2,2) at t = 1 s exactly.
    const Impact impact =
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 1.0}, box(2, 2, 3, 3), Vec2{}, 10.0);
    EXPECT_TRUE(hitsAt(impact, 1.0, kAxisX | kAxisY));
    // Both moving toward each other diagonally: the corners meet at 0.5 s.
    const Impact both =
        timeOfImpact(box(0, 0, 1, 1), Vec2{1.0, 1.0}, box(2, 2, 3, 3), Vec2{-1.0, -1.0}, 10.0);
    EXPECT_TRUE(hitsAt(both, 0.5, kAxisX | kAxisY));
}

TEST(TimeOfImpact, WindowTooShortMeansNoHit) {
    // Impact at 0.25 s: hit within a 0.25 s window (inclusive), not within 0.2 s.
    const Aabb a = box(0, 0, 1, 1), b = box(2, 0, 3, 1);
    EXPECT_FALSE(timeOfImpact(a, Vec2{4.0, 0.0}, b, Vec2{}, 0.2).hit());
    const Impact exact = timeOfImpact(a, Vec2{4.0, 0.0}, b, Vec2{}, 0.25);
    ASSERT_TRUE(exact.hit());
    EXPECT_EQ(exact.time, 0.25);
}

TEST(TimeOfImpact, NoImpactReportsNever) {
    const Impact none =
        timeOfImpact(box(0, 0, 1, 1), Vec2{-1.0, 0.0}, box(2, 0, 3, 1), Vec2{}, 1.0);
    EXPECT_FALSE(none.hit());
    EXPECT_EQ(none.axes, 0);
    EXPECT_EQ(none.time, kNever);
}

// --- walls ---

TEST(TimeOfWallImpact, EachWall) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    const Aabb b = box(4, 4, 6, 6);
    const WallImpact right = timeOfWallImpact(b, Vec2{2.0, 0.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(right, 2.0, kAxisX)); // 4 m to the right wall at 2 m/s
    EXPECT_EQ(wallOnAxis(0, 2.0), kWallRight);

    const WallImpact left = timeOfWallImpact(b, Vec2{-8.0, 0.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(left, 0.5, kAxisX));

    const WallImpact top = timeOfWallImpact(b, Vec2{0.0, 4.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(top, 1.0, kAxisY));

    const WallImpact bottom = timeOfWallImpact(b, Vec2{0.0, -1.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(bottom, 4.0, kAxisY));
}

TEST(TimeOfWallImpact, DiagonalPicksTheEarlierWall) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    // 4 m to the right wall at 2 m/s (2 s), 4 m to the top at 4 m/s (1 s): top first.
    const WallImpact w = timeOfWallImpact(box(4, 4, 6, 6), Vec2{2.0, 4.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(w, 1.0, kAxisY));
}

TEST(TimeOfWallImpact, CornerOfTheBoundsHitsBothWalls) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    const WallImpact upRight = timeOfWallImpact(box(4, 4, 6, 6), Vec2{2.0, 2.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(upRight, 2.0, kAxisX | kAxisY));
    const WallImpact downLeft = timeOfWallImpact(box(1, 2, 2, 3), Vec2{-1.0, -2.0}, bounds, 10.0);
    EXPECT_TRUE(hitsAt(downLeft, 1.0, kAxisX | kAxisY));
}

TEST(TimeOfWallImpact, TouchingAndMovingIntoTheWallIsTimeZero) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    const WallImpact floor = timeOfWallImpact(box(4, 0, 5, 1), Vec2{0.0, -0.5}, bounds, 0.1);
    EXPECT_TRUE(hitsAt(floor, 0.0, kAxisY));
    // Touching the floor but moving up or sideways: no wall within a short window.
    EXPECT_FALSE(timeOfWallImpact(box(4, 0, 5, 1), Vec2{0.0, 0.5}, bounds, 0.1).hit());
    EXPECT_FALSE(timeOfWallImpact(box(4, 0, 5, 1), Vec2{1.0, 0.0}, bounds, 0.1).hit());
}

TEST(TimeOfWallImpact, WindowTooShortOrAtRest) {
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    EXPECT_FALSE(timeOfWallImpact(box(4, 4, 6, 6), Vec2{2.0, 0.0}, bounds, 1.999).hit());
    EXPECT_TRUE(timeOfWallImpact(box(4, 4, 6, 6), Vec2{2.0, 0.0}, bounds, 2.0).hit());
    EXPECT_FALSE(timeOfWallImpact(box(4, 4, 6, 6), Vec2{}, bounds, 1e9).hit());
}

TEST(WallOnAxis, SignPicksTheSide) {
    EXPECT_EQ(wallOnAxis(0, 1.0), kWallRight);
    EXPECT_EQ(wallOnAxis(0, -1.0), kWallLeft);
    EXPECT_EQ(wallOnAxis(1, 1.0), kWallTop);
    EXPECT_EQ(wallOnAxis(1, -1.0), kWallBottom);
}

} // namespace
