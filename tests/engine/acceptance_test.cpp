// The accuracy acceptance number for the perfect method: in a gravity-free scene with C = 1,
// momentum and kinetic energy are conserved to a relative 1e-12 over 100,000 collisions, and
// nothing ever overlaps. Walls change momentum, so the test accounts for every wall impulse from
// the collision log: p(now) = p(start) + Σ m·(v' − v) over the wall collisions.
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace test_worlds;

TEST(PerfectAcceptance, HundredThousandCollisionsConserveMomentumAndEnergy) {
    World world = gasInBox(Method::Perfect, {0.0, 0.0}, 1.0, 2026, 400);

    const double startEnergy = kineticEnergy(world);
    const double scale = momentumScale(world); // Σ m·|v|: momentum errors are relative to it
    Vec2 expectedMomentum = totalMomentum(world);
    long collisions = 0;
    std::vector<CollisionRecord> log;
    for (int frame = 0; collisions < 100000; ++frame) {
        ASSERT_LT(frame, 100000) << "too few collisions";
        log.clear();
        const StepStats stats = world.step(&log);
        collisions += stats.collisions;
        ASSERT_EQ(stats.eventCapHits, 0) << "frame " << frame;
        // 1e-9 m: positions at a time of impact agree to rounding only.
        ASSERT_LE(stats.maxPenetration, 1e-9) << "frame " << frame;
        for (const CollisionRecord& r : log) {
            if (r.other >= 0) continue; // block pairs conserve momentum among themselves
            expectedMomentum[r.axis] += r.m1 * (r.v1After - r.v1);
        }
    }
    // Relative 1e-12: each resolve rounds at 1e-16; 100,000 of them drift far less.
    EXPECT_NEAR(kineticEnergy(world), startEnergy, 1e-12 * startEnergy);
    EXPECT_NEAR(totalMomentum(world).x, expectedMomentum.x, 1e-12 * scale);
    EXPECT_NEAR(totalMomentum(world).y, expectedMomentum.y, 1e-12 * scale);
}
