// Chains of contacts at one instant under the perfect method: exact while each pair meets a few
// times, and bounded (merged perfectly inelastic) when a pair would meet without end.
#include "test_worlds.h"

#include <gtest/gtest.h>

using namespace test_worlds;

// A block knocked against one resting on the wall: B hits A, A hits the wall, A hits B again,
// all at one instant. With C = 1 the exact answer is A at rest and B back at 3 m/s: the second
// A-B collision must stay elastic. Tolerance 1e-12 m/s: one formula evaluation's rounding.
TEST(PerfectChains, BlockKnockedAgainstOneRestingOnTheWallBouncesBackElastically) {
    World world = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0);
    addBlock(world, {0.5, 6.0}, {1.0, 1.0}, {0.0, 0.0}, 1.0);
    addBlock(world, {5.0, 6.0}, {1.0, 1.0}, {-3.0, 0.0}, 1.0);
    for (int f = 0; f < 120; ++f) world.step();
    EXPECT_NEAR(world.blocks[0].velocity.x, 0.0, 1e-12);
    EXPECT_NEAR(world.blocks[1].velocity.x, 3.0, 1e-12);
    EXPECT_NEAR(kineticEnergy(world), 4.5, 1e-12);
}

// A row packed edge to edge between two walls cannot move: every collision at that instant runs
// back and forth without end. The pairs merge after a few repeats, so the frame completes with
// no event-cap hit, no overlap, and the row at rest.
TEST(PerfectChains, RowJammedBetweenWallsMergesInsteadOfStorming) {
    World world = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0, Bounds{{0.0, 0.0}, {5.0, 2.0}});
    for (int i = 0; i < 5; ++i)
        addBlock(world, {i + 0.5, 1.0}, {1.0, 1.0}, {i % 2 ? 2.0 : -1.0, 0.0}, 1.0);
    const StepStats stats = world.step();
    EXPECT_EQ(stats.eventCapHits, 0);
    EXPECT_DOUBLE_EQ(stats.simulatedTime, world.settings.dt);
    EXPECT_LE(stats.maxPenetration, 1e-9);
    for (const Block& b : world.blocks) EXPECT_EQ(b.velocity.x, 0.0);
}
