// Determinism (bit-identical states for the same scene) and substeps (K substeps of a frame are
// K frames of dt/K). No clock is read: only stateHash and positions are compared.
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace {

using test_worlds::addGas;
using test_worlds::GasOptions;
using test_worlds::makeWorld;

class DeterminismTest : public ::testing::TestWithParam<Method> {};

INSTANTIATE_TEST_SUITE_P(Methods, DeterminismTest, test_worlds::everyMethod(),
                         test_worlds::methodParamName);

// A 200-block gas with gravity and C = 0.9 in the default 20 m x 12 m bounds.
World gasWorld(Method method, std::uint64_t seed) {
    World world = makeWorld(method, {0.0, -9.81}, 0.9);
    GasOptions gas;
    gas.count = 200;
    gas.seed = seed;
    addGas(world, gas);
    return world;
}

std::uint64_t hashAfter(World world, int frames) {
    for (int f = 0; f < frames; ++f) world.step();
    return stateHash(world);
}

TEST_P(DeterminismTest, SameSceneGivesBitIdenticalStateTwice) {
    const World start = gasWorld(GetParam(), 42);
    const std::uint64_t first = hashAfter(start, 1000);
    const std::uint64_t second = hashAfter(start, 1000);
    EXPECT_EQ(first, second);
    EXPECT_NE(first, stateHash(start)) << "the scene must actually move";
}

TEST_P(DeterminismTest, DifferentSeedsGiveDifferentHashes) {
    const std::uint64_t a = hashAfter(gasWorld(GetParam(), 42), 100);
    const std::uint64_t b = hashAfter(gasWorld(GetParam(), 43), 100);
    EXPECT_NE(a, b);
}

TEST(StateHash, SeesEveryBitOfPositionVelocityAndTime) {
    World world = makeWorld(Method::Perfect);
    test_worlds::addBlock(world, {1.0, 2.0}, {1.0, 1.0}, {3.0, 4.0});
    const std::uint64_t h = stateHash(world);
    EXPECT_EQ(h, stateHash(world));
    World w = world;
    w.blocks[0].position.x = std::nextafter(1.0, 2.0);
    EXPECT_NE(stateHash(w), h);
    w = world;
    w.blocks[0].velocity.y = std::nextafter(4.0, 0.0);
    EXPECT_NE(stateHash(w), h);
    w = world;
    w.time = 1e-300;
    EXPECT_NE(stateHash(w), h);
}

// K substeps at dt equal K·frames at dt/K: the same substep length h = dt/K (dividing by 4 is
// exact), the same sequence of operations, so the same bits; positions are also compared to
// 1e-12 m so a failure shows how far apart they are.
TEST_P(DeterminismTest, SubstepsEqualFramesOfAShorterStep) {
    const double dt = 1.0 / 60.0;
    World sub = makeWorld(GetParam(), {0.0, 0.0}, 1.0);
    GasOptions gas;
    gas.count = 200;
    gas.seed = 7;
    addGas(sub, gas);
    World fine = sub;
    sub.settings.dt = dt;
    sub.settings.substeps = 4;
    fine.settings.dt = dt / 4.0;
    fine.settings.substeps = 1;
    for (int f = 0; f < 100; ++f) {
        sub.step();
        for (int k = 0; k < 4; ++k) fine.step();
    }
    for (size_t i = 0; i < sub.blocks.size(); ++i) {
        ASSERT_NEAR(sub.blocks[i].position.x, fine.blocks[i].position.x, 1e-12) << i;
        ASSERT_NEAR(sub.blocks[i].position.y, fine.blocks[i].position.y, 1e-12) << i;
    }
    EXPECT_EQ(stateHash(sub), stateHash(fine));
}

TEST_P(DeterminismTest, SubstepsEqualFramesOfAShorterStepWithGravity) {
    const double dt = 1.0 / 60.0;
    World sub = makeWorld(GetParam(), {0.0, -9.81}, 0.8);
    GasOptions gas;
    gas.count = 200;
    gas.seed = 8;
    addGas(sub, gas);
    World fine = sub;
    sub.settings.substeps = 4;
    fine.settings.dt = dt / 4.0;
    for (int f = 0; f < 100; ++f) {
        sub.step();
        for (int k = 0; k < 4; ++k) fine.step();
    }
    EXPECT_EQ(stateHash(sub), stateHash(fine));
}

} // namespace
