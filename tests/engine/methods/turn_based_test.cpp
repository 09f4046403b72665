// Turn-based contacts at one instant (issue 14): a block hit while it touches a body it is sent
// into resolves that contact at once, so no block at rest keeps a velocity growing with gravity;
// a sequence that would not end (a collapse at C < 1, a block squeezed between infinite masses)
// is merged by the rest rule, which reverses the platforms that press. Before, a 1000 kg block
// dropped on a 1 kg one ended with 26.9x the energy, a pile at C = 0 with 1.8x, and squeezed
// blocks reached 2,000-6,000 m/s while standing still.
#include "collision.h"
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using test_worlds::addBlock;
using test_worlds::makeWorld;

const Vec2 kGravity{0.0, -9.81};
// The bar: no block of these scenes may exceed it (they fall 1-12 m: 4.4-15.3 m/s).
constexpr double kSpeedBound = 30.0; // m/s

double totalEnergy(const World& world) {
    return kineticEnergy(world) + potentialEnergy(world);
}

double fastestDynamic(const World& world) {
    double v = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) v = std::max(v, length(b.velocity));
    return v;
}

// Steps `frames` frames; after each: no overlap, no dynamic block above kSpeedBound, and (when
// `energyBound`) the total energy at most the start's. 1e-9 relative: sums of a few thousand
// rounded terms; a real gain (the failures above) is orders of magnitude larger.
void stepBounded(World& world, int frames, bool energyBound, const std::string& label) {
    const double start = totalEnergy(world);
    for (int f = 0; f < frames; ++f) {
        const StepStats s = world.step();
        ASSERT_LE(s.maxPenetration, 1e-9) << label << ", frame " << f;
        ASSERT_LE(fastestDynamic(world), kSpeedBound) << label << ", frame " << f;
        if (energyBound) {
            ASSERT_LE(totalEnergy(world), start + 1e-9 * std::abs(start))
                << label << ", frame " << f;
        }
    }
}

// A 1000 kg block (2 m) dropped from 1 m onto a 1 kg block (1 m) resting on the floor, C = 0.5,
// normal gravity and dt. The light block, caught between the heavy one and the floor, collides
// without end at one instant (inelastic collapse): both come to rest, the heavy one on the light
// one. Exact answer: y = 0.5 and 2.0, velocities 0, energy m·g·y of both (19,624.905 J).
class HeavyOnLight : public ::testing::TestWithParam<bool> {};

INSTANTIATE_TEST_SUITE_P(Orders, HeavyOnLight, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                             return std::string(info.param ? "HeavyFirst" : "LightFirst");
                         });

TEST_P(HeavyOnLight, BothComeToRestAndEnergyNeverGrows) {
    World world = makeWorld(Method::TurnBased, kGravity, 0.5);
    const bool heavyFirst = GetParam();
    if (heavyFirst) addBlock(world, {10.0, 3.0}, {2.0, 2.0}, {}, 1000.0);
    addBlock(world, {10.0, 0.5}, {1.0, 1.0}, {}, 1.0);
    if (!heavyFirst) addBlock(world, {10.0, 3.0}, {2.0, 2.0}, {}, 1000.0);
    const int heavy = heavyFirst ? 0 : 1, light = 1 - heavy;
    stepBounded(world, 600, true, "heavy on light"); // 10 s
    // 1e-9 m: the point of impact's rounding; velocities exactly 0 after the rest rule.
    EXPECT_NEAR(world.blocks[light].position.y, 0.5, 1e-9);
    EXPECT_NEAR(world.blocks[heavy].position.y, 2.0, 1e-9);
    EXPECT_EQ(world.blocks[light].velocity, Vec2{});
    EXPECT_EQ(world.blocks[heavy].velocity, Vec2{});
    EXPECT_NEAR(totalEnergy(world), 9.81 * (1000.0 * 2.0 + 1.0 * 0.5), 1e-6);
}

// 300 blocks of 0.5-2 kg fall into a pile in a closed box, C = 0 (the 2000-block pile,
// smaller). Before: 2.1x the energy and a block at 109 m/s after 20 s, still growing.
TEST(TurnBasedPile, EnergyNeverGrowsAndNoBlockRunsAway) {
    World world =
        test_worlds::gasInBox(Method::TurnBased, kGravity, 0.0, 5, 300); // 20 m box, <= 5 m/s
    stepBounded(world, 1200, true, "pile");
}

// A kinematic platform at 2 m/s pushes a block (touching a wall, or a static block) into it:
// the block is crushed at once, the platform reverses as on a wall, and the block never moves.
// Before: the block stood still while its speed grew to 2,400 m/s in 10 s.
struct Squeeze {
    const char* name;
    bool staticBlock; // against a static block rather than the wall
};

class SqueezedAgainst : public ::testing::TestWithParam<Squeeze> {};

INSTANTIATE_TEST_SUITE_P(Cases, SqueezedAgainst,
                         ::testing::Values(Squeeze{"Wall", false}, Squeeze{"StaticBlock", true}),
                         [](const ::testing::TestParamInfo<Squeeze>& info) {
                             return std::string(info.param.name);
                         });

TEST_P(SqueezedAgainst, BlockIsCrushedAndPlatformReverses) {
    for (const double C : {0.0, 0.5, 1.0}) {
        // A 6 m box: the platform comes back from the far wall every 2.5 s to crush again.
        World world = makeWorld(Method::TurnBased, {0.0, 0.0}, C, Bounds{{0.0, 0.0}, {6.0, 4.0}});
        const double blockX = GetParam().staticBlock ? 1.5 : 0.5;
        if (GetParam().staticBlock)
            addBlock(world, {0.5, 2.0}, {1.0, 1.0}, {}, 1.0, BodyKind::Static);
        const int block = addBlock(world, {blockX, 2.0}, {1.0, 1.0}, {}, 1.0);
        // Left face 0.5 m from the block: contact after 0.25 s (frame 15).
        const int platform =
            addBlock(world, {blockX + 2.0, 2.0}, {2.0, 2.0}, {-2.0, 0.0}, 1.0, BodyKind::Kinematic);
        const std::string label = std::string(GetParam().name) + ", C " + std::to_string(C);
        stepBounded(world, 17, false, label);
        EXPECT_EQ(world.blocks[platform].velocity.x, 2.0) << label << ": reversed";
        stepBounded(world, 600 - 17, false, label);
        // The block never moves: exactly where it was, at rest.
        EXPECT_EQ(world.blocks[block].position, (Vec2{blockX, 2.0})) << label;
        EXPECT_EQ(world.blocks[block].velocity, Vec2{}) << label;
        EXPECT_EQ(std::abs(world.blocks[platform].velocity.x), 2.0) << label;
    }
}

// A block held between two platforms closing in at 2 and 3 m/s: both reverse, as two platforms
// that met would, and the block stays where it was, at rest. A wide box: they do not come back
// within the 10 s (when they do, with a gap, the block rattles between them and takes speed from
// them, as it would in reality, until the gap closes).
TEST(TurnBasedSqueeze, BlockBetweenTwoPlatformsIsCrushedAndBothReverse) {
    for (const double C : {0.0, 0.5, 1.0}) {
        World world =
            makeWorld(Method::TurnBased, {0.0, 0.0}, C, Bounds{{0.0, 0.0}, {200.0, 12.0}});
        addBlock(world, {99.0, 6.0}, {2.0, 2.0}, {2.0, 0.0}, 1.0, BodyKind::Kinematic);
        addBlock(world, {100.5, 6.0}, {1.0, 1.0}, {}, 1.0);
        addBlock(world, {102.0, 6.0}, {2.0, 2.0}, {-3.0, 0.0}, 1.0, BodyKind::Kinematic);
        const std::string label = "two platforms, C " + std::to_string(C);
        stepBounded(world, 600, false, label);
        EXPECT_EQ(world.blocks[0].velocity.x, -2.0) << label;
        EXPECT_EQ(world.blocks[2].velocity.x, 3.0) << label;
        EXPECT_EQ(world.blocks[1].position, (Vec2{100.5, 6.0})) << label;
        EXPECT_EQ(world.blocks[1].velocity, Vec2{}) << label;
    }
}

// The rule's edge at C = 1 (no gravity): a sequence at one instant that ends is carried out, not
// merged, so energy is kept. The pi scene with the small block touching the wall (a 1e6 or 1e4
// mass ratio): 3141 and 314 collisions, as with a gap (Galperin 2003), energy to 1e-9 relative.
class TouchingPi : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(MassRatios, TouchingPi, ::testing::Values(1e4, 1e6),
                         [](const ::testing::TestParamInfo<double>& info) {
                             return std::string(info.param == 1e4 ? "TenThousand" : "Million");
                         });

TEST_P(TouchingPi, CountsPiAndKeepsEnergy) {
    World world = makeWorld(Method::TurnBased, {0.0, 0.0}, 1.0);
    addBlock(world, {0.25, 6.0}, {0.5, 0.5}, {}, 1.0);
    addBlock(world, {10.0, 6.0}, {2.0, 2.0}, {-1.0, 0.0}, GetParam());
    const double start = kineticEnergy(world);
    long collisions = 0;
    for (int f = 0; f < 1200; ++f) collisions += world.step().collisions;
    EXPECT_EQ(collisions, GetParam() == 1e4 ? 314 : 3141);
    EXPECT_NEAR(kineticEnergy(world), start, 1e-9 * start);
}

// A 1000 kg block at 2 m/s onto a 1 kg block resting on the floor, C = 1, no gravity: the light
// block rattles between floor and heavy block at one instant, floor(pi / atan(sqrt(1/1000))) =
// 99 collisions, and the heavy block leaves upward; kinetic energy kept to 1e-9 relative.
TEST(TurnBasedSequence, HeavyOntoLightAtRestKeepsEnergyWhenElastic) {
    World world = makeWorld(Method::TurnBased, {0.0, 0.0}, 1.0);
    addBlock(world, {10.0, 0.5}, {1.0, 1.0}, {}, 1.0);
    addBlock(world, {10.0, 3.0}, {2.0, 2.0}, {0.0, -2.0}, 1000.0);
    const double start = kineticEnergy(world);
    long collisions = 0;
    for (int f = 0; f < 60; ++f) { // 1 s: contact at 0.5 s, the heavy block is then on its way up
        collisions += world.step().collisions;
        ASSERT_NEAR(kineticEnergy(world), start, 1e-9 * start) << "frame " << f;
    }
    EXPECT_EQ(collisions, 99);
    EXPECT_GT(world.blocks[1].velocity.y, 1.9); // nearly all of its 2 m/s, reversed
    EXPECT_GT(world.blocks[1].velocity.y, world.blocks[0].velocity.y); // they part
}

// A merge at C < 1 without infinite masses keeps momentum: a row of touching blocks of
// alternating masses (1 and 1000 kg), hit at one end; its pairs meet without end at one instant,
// so the row and the striker merge and move on at u = total momentum / total mass.
TEST(TurnBasedSequence, MergeKeepsMomentum) {
    for (const double C : {0.0, 0.2, 0.9}) {
        World world = makeWorld(Method::TurnBased, {0.0, 0.0}, C);
        for (int i = 0; i < 6; ++i)
            addBlock(world, {5.5 + i, 6.0}, {1.0, 1.0}, {}, i % 2 ? 1e3 : 1);
        addBlock(world, {3.0, 6.0}, {1.0, 1.0}, {5.0, 0.0}, 10.0);
        const double start = kineticEnergy(world);
        std::vector<CollisionRecord> log;
        for (int f = 0; f < 60; ++f) world.step(&log);
        // The sequence was merged, by the rest rule (after the striker's own bounce, whose
        // sequence waits for the struck block's turn: no gravity).
        ASSERT_FALSE(log.empty()) << "C " << C;
        EXPECT_TRUE(log.back().rest) << "C " << C;
        // 1e-9 kg·m/s: the sums of a few hundred rounded products of size ~50.
        EXPECT_NEAR(totalMomentum(world).x, 50.0, 1e-9) << "C " << C;
        EXPECT_NEAR(totalMomentum(world).y, 0.0, 1e-12) << "C " << C;
        EXPECT_LE(kineticEnergy(world), start * (1.0 + 1e-12)) << "C " << C;
        EXPECT_LE(maxOverlap(world), 1e-9) << "C " << C;
    }
}

} // namespace
