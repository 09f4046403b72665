// Contacts at one instant under the perfect method (issue 14): bodies that touch when an impact
// arrives collide many times at that instant, and the sequence is carried out as the same scene
// with a vanishing gap would carry it out. At C = 1 energy and momentum are kept to rounding and
// the count is Galperin's; only what never ends is merged (collapse at C < 1, a trap between
// infinite masses), and the merge keeps momentum.
#include "scene.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using test_worlds::addBlock;
using test_worlds::makeWorld;

// Galperin (2003): a light block m between a wall and a block M coming at it collides
// ceil(pi / atan(sqrt(m / M))) - 1 times in all, walls included.
int galperinCount(double massRatio) {
    const double pi = std::acos(-1.0);
    return static_cast<int>(std::ceil(pi / std::atan(std::sqrt(1.0 / massRatio)))) - 1;
}

struct Outcome {
    long collisions = 0;
    double kineticEnergy = 0.0;
    double totalEnergy = 0.0;
    int capHits = 0;
    World world;
};

Outcome run(World world, int frames) {
    Outcome o;
    for (int f = 0; f < frames; ++f) {
        const StepStats s = world.step();
        o.collisions += s.collisions;
        o.capHits += s.eventCapHits;
        EXPECT_LE(s.maxPenetration, 1e-9) << "frame " << f; // rounding of the point of impact
    }
    o.kineticEnergy = kineticEnergy(world);
    o.totalEnergy = o.kineticEnergy + potentialEnergy(world);
    o.world = world;
    return o;
}

// The shipped pi scene (app/scenes/high_mass_ratio.json) with the small block at x, the giant's
// mass `ratio` times the small one's.
World piScene(double x, double ratio) {
    SceneResult loaded = loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/high_mass_ratio.json");
    EXPECT_TRUE(loaded.scene) << loaded.error.text();
    Scene scene = *loaded.scene;
    scene.blocks[0].position.x = x;
    scene.blocks[1].mass = ratio * scene.blocks[0].mass;
    return makeWorld(scene);
}

class PerfectTouchingPi : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(MassRatios, PerfectTouchingPi, ::testing::Values(1e4, 1e6),
                         [](const ::testing::TestParamInfo<double>& info) {
                             return "Ratio1e" + std::to_string(std::lround(std::log10(info.param)));
                         });

TEST_P(PerfectTouchingPi, SmallBlockTouchingTheWallCountsPiAndKeepsEnergy) {
    // 0.5 m block at x = 0.25: its left face on the wall. 20 s: the giant comes back and leaves.
    const double ratio = GetParam();
    const World start = piScene(0.25, ratio);
    const double e0 = kineticEnergy(start);
    const Outcome touching = run(start, 1200);
    // 314 for 1e4, 3141 for 1e6: exact integers.
    EXPECT_EQ(touching.collisions, galperinCount(ratio));
    EXPECT_EQ(touching.capHits, 0);
    // 1e-9 relative (docs/physics.md): each of the ~3141 resolves rounds at 1e-16.
    EXPECT_NEAR(touching.kineticEnergy, e0, 1e-9 * e0);
    // The limit of a vanishing gap: the same count as with the block 1e-7 m off the wall.
    const Outcome gap = run(piScene(0.2500001, ratio), 1200);
    EXPECT_EQ(touching.collisions, gap.collisions);
    EXPECT_NEAR(gap.kineticEnergy, e0, 1e-9 * e0);
}

// A heavy block at `speed` (downward) whose bottom face is `gap` above a 1 kg block resting on the
// floor.
World heavyOntoLight(double heavyMass, double speed, Vec2 gravity, double gap) {
    World world = makeWorld(Method::Perfect, gravity, 1.0);
    addBlock(world, {10.0, 0.5}, {1.0, 1.0}, {0.0, 0.0}, 1.0);
    addBlock(world, {10.0, 2.0 + gap}, {2.0, 2.0}, {0.0, -speed}, heavyMass);
    return world;
}

TEST(ContactsAtOneInstant, HeavyOntoLightRestingOnTheFloorKeepsEnergyWithoutGravity) {
    // 1000 kg at 2 m/s onto 1 kg on the floor, C = 1: 99 collisions at the instant of impact
    // (Galperin), the heavy block leaves upward, kinetic energy kept to 1e-9 relative.
    const World start = heavyOntoLight(1000.0, 2.0, {0.0, 0.0}, 0.0);
    const double e0 = kineticEnergy(start);
    const Outcome touching = run(start, 1);
    EXPECT_EQ(touching.collisions, galperinCount(1000.0));
    EXPECT_NEAR(touching.kineticEnergy, e0, 1e-9 * e0);
    EXPECT_GT(touching.world.blocks[1].velocity.y, 0.0);
    // 1e-12 kg·m/s per unit of Σ m|v|: the floor absorbs momentum, the pair keeps the rest; the
    // x components never change.
    EXPECT_EQ(totalMomentum(touching.world).x, 0.0);
    // With a 10 kg block (fewer collisions, never past the old repeat limit) the same holds.
    const World light = heavyOntoLight(10.0, 2.0, {0.0, 0.0}, 0.0);
    const Outcome ten = run(light, 1);
    EXPECT_EQ(ten.collisions, galperinCount(10.0));
    EXPECT_NEAR(ten.kineticEnergy, kineticEnergy(light), 1e-9 * kineticEnergy(light));
}

TEST(ContactsAtOneInstant, HeavyOntoLightWithGravityLosesNoMoreThanAVanishingGap) {
    // With gravity, the same drop. What the physics gives is the limit of a small gap (1e-7 m):
    // semi-implicit Euler's own share (the frame's gravity kick comes before the bounce) and the
    // rest rule ending the light block's last slow contact are common to both. 1e-6 of the total
    // energy covers the gap's own effect (the heavy block falls 1e-7 m more).
    const Vec2 g{0.0, -9.81};
    const World start = heavyOntoLight(1000.0, 2.0, g, 0.0);
    const double e0 = kineticEnergy(start) + potentialEnergy(start);
    const Outcome touching = run(start, 1);
    const Outcome gap = run(heavyOntoLight(1000.0, 2.0, g, 1e-7), 1);
    EXPECT_NEAR(touching.totalEnergy, gap.totalEnergy, 1e-6 * e0);
    // Not 62.5% lost: the heavy block leaves upward at the speed it arrived with after the
    // frame's kick, 2 + g·dt, less what the light block keeps (at most its share of the energy,
    // m/M: 0.1% of the speed; 0.5% allowed).
    const double arrived = 2.0 + 9.81 * start.settings.dt;
    EXPECT_NEAR(touching.world.blocks[1].velocity.y, arrived, 0.005 * arrived);
}

// The edge of the collapse rule at C = 1: a pair meeting more often than the repeat limit (8) at
// one instant is not merged when the bodies can give way. Mass ratios from 1 to 100 give 3 to 31
// collisions (2 to 16 meetings of the pair), below and above the limit: every count is
// Galperin's, every energy kept to 1e-12 (at most 31 roundings of 1e-16).
TEST(ContactsAtOneInstant, RepeatLimitDoesNotMergeElasticSequencesThatEnd) {
    for (double ratio : {1.0, 4.0, 16.0, 25.0, 36.0, 49.0, 100.0}) {
        const World start = heavyOntoLight(ratio, 2.0, {0.0, 0.0}, 0.0);
        const double e0 = kineticEnergy(start);
        const Outcome o = run(start, 1);
        EXPECT_EQ(o.collisions, galperinCount(ratio)) << "ratio " << ratio;
        EXPECT_NEAR(o.kineticEnergy, e0, 1e-12 * e0) << "ratio " << ratio;
    }
}

// The trap rule's edge: a row of three touching blocks against the left wall, struck from the
// right at C = 1, gives way to the right and stays exact (Newton's cradle against a wall: the
// striker leaves at its speed). Packed between both walls, the same row is caught: no finite
// sequence exists, and the trap merges it at rest.
TEST(ContactsAtOneInstant, RowAgainstOneWallStaysElasticBetweenTwoWallsIsTrapped) {
    World open = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0, Bounds{{0.0, 0.0}, {6.0, 2.0}});
    for (int i = 0; i < 3; ++i) addBlock(open, {0.5 + i, 1.0}, {1.0, 1.0}, {0.0, 0.0}, 1.0);
    addBlock(open, {4.5, 1.0}, {1.0, 1.0}, {-2.0, 0.0}, 1.0);
    const Outcome o = run(open, 60);
    EXPECT_NEAR(o.kineticEnergy, 2.0, 1e-12); // 1/2·1·2²
    EXPECT_NEAR(o.world.blocks[3].velocity.x, 2.0, 1e-12);

    World trapped = makeWorld(Method::Perfect, {0.0, 0.0}, 1.0, Bounds{{0.0, 0.0}, {4.0, 2.0}});
    for (int i = 0; i < 4; ++i)
        addBlock(trapped, {0.5 + i, 1.0}, {1.0, 1.0}, {i == 3 ? -2.0 : 0.0, 0.0}, 1.0);
    const Outcome t = run(trapped, 1);
    EXPECT_EQ(t.capHits, 0);
    for (const Block& b : t.world.blocks) EXPECT_EQ(b.velocity.x, 0.0);
}

// The collapse rule keeps momentum: three equal blocks touching in free space, C = 0.05 (below
// McNamara and Young's 7 - 4·sqrt(3) = 0.072 for three bodies), the first one moving into the
// others: the sequence at that instant converges to one velocity, 1/3 of the striker's, which the
// merge gives. No wall or infinite mass is involved, so momentum is kept to rounding (1e-12).
TEST(ContactsAtOneInstant, CollapseMergesKeepingMomentum) {
    World world = makeWorld(Method::Perfect, {0.0, 0.0}, 0.05, Bounds{{0.0, 0.0}, {40.0, 4.0}});
    addBlock(world, {10.5, 2.0}, {1.0, 1.0}, {3.0, 0.0}, 1.0);
    addBlock(world, {11.5, 2.0}, {1.0, 1.0}, {0.0, 0.0}, 1.0);
    addBlock(world, {12.5, 2.0}, {1.0, 1.0}, {0.0, 0.0}, 1.0);
    const Outcome o = run(world, 1);
    EXPECT_NEAR(totalMomentum(o.world).x, 3.0, 1e-12);
    for (const Block& b : o.world.blocks) EXPECT_NEAR(b.velocity.x, 1.0, 1e-12);
    EXPECT_LE(o.kineticEnergy, 4.5);
}

} // namespace
