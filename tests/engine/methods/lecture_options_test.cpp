// The settings issue 16 adds (resolve, integrator, forces, drag, mistakes), each against an exact
// or analytic answer, and the defaults unchanged. No clock is read.
#include "scene.h"
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace {

using test_worlds::addBlock;

constexpr Method kMethods[] = {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased};
constexpr Integrator kIntegrators[] = {Integrator::SemiImplicitEuler, Integrator::ExplicitEuler,
                                       Integrator::Exact};

Scene loadShipped(const std::string& name) {
    const SceneResult r = loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/" + name + ".json");
    EXPECT_TRUE(r.scene) << r.error.text();
    return r.scene ? *r.scene : Scene{};
}

void run(World& world, double seconds, std::vector<CollisionRecord>* log = nullptr) {
    const long frames = std::lround(seconds / world.settings.dt);
    for (long f = 0; f < frames; ++f) world.step(log);
}

// Blocks 0's and 1's x velocities (m/s) after `seconds` of `world`.
std::pair<double, double> xVelocitiesAfter(World world, double seconds) {
    run(world, seconds);
    return {world.blocks[0].velocity.x, world.blocks[1].velocity.x};
}

// The shipped scene `name` as it is (its mistake on) and the same world with `mistake` off.
std::pair<World, World> withAndWithout(const std::string& name, Mistake mistake) {
    World wrong = makeWorld(loadShipped(name));
    World right = wrong;
    right.settings.set(mistake, false);
    return {wrong, right};
}

// ---- Resolve ----

TEST(Resolve, ReflectReversesEachBodyAsOffAWallInLectureExample1) {
    // Without Newton: v' = -C·v for each body, so m1 leaves at -6 m/s and m2 stays at rest;
    // exact (a sign change), in every method.
    for (Method method : kMethods) {
        World world = makeWorld(loadShipped("lecture_example_1"));
        world.settings.method = method;
        world.settings.resolve = Resolve::Reflect;
        run(world, 1.0);
        EXPECT_EQ(world.blocks[0].velocity.x, -6.0) << methodName(method);
        EXPECT_EQ(world.blocks[1].velocity.x, 0.0) << methodName(method);
        EXPECT_EQ(totalMomentum(world).x, -6.0) << "momentum is not conserved without Newton";
    }
}

TEST(Resolve, MomentumStaysTheDefault) {
    World world = makeWorld(loadShipped("lecture_example_1"));
    EXPECT_EQ(world.settings.resolve, Resolve::Momentum);
    EXPECT_EQ(xVelocitiesAfter(world, 1.0), std::make_pair(-2.0, 4.0));
}

TEST(Resolve, TheShippedSceneWithoutNewtonIsLectureExample1Reflected) {
    World world = makeWorld(loadShipped("without_newton"));
    EXPECT_EQ(world.settings.resolve, Resolve::Reflect);
    EXPECT_EQ(xVelocitiesAfter(world, 1.0), std::make_pair(-6.0, 0.0));
}

// ---- Forces ----

TEST(Forces, ThrusterGivesVEqualsFOverMTimesTExactlyInEveryMethodAndIntegrator) {
    // Mass 4 kg, force 2 N, no gravity: a = 0.5 m/s^2. 0.5·h is exact (a power of two times h),
    // so the sum of the steps' 0.5·h is exactly 0.5 times the sum of the h: equality, not a
    // tolerance.
    for (Method method : kMethods) {
        for (Integrator integrator : kIntegrators) {
            World world =
                test_worlds::makeWorld(method, {0.0, 0.0}, 1.0, Bounds{{0, 0}, {100, 12}});
            world.settings.integrator = integrator;
            const int ship = addBlock(world, {2.0, 6.0}, {1.0, 1.0}, {}, 4.0);
            world.blocks[ship].force = {2.0, 0.0};
            run(world, 5.0);
            const std::string label =
                std::string(methodName(method)) + ", " + integratorName(integrator);
            EXPECT_EQ(world.blocks[ship].velocity.x, 0.5 * world.time) << label;
            EXPECT_EQ(world.blocks[ship].velocity.y, 0.0) << label;
            // x = x0 + a·t²/2: exact with the exact integrator (to rounding, 1e-12 m); Euler is
            // off by a·t·h/2 (semi-implicit ahead, explicit behind).
            const double exact = 2.0 + 0.25 * world.time * world.time;
            const double expected = integrator == Integrator::Exact ? 0.0
                                    : integrator == Integrator::SemiImplicitEuler
                                        ? 0.25 * world.time * world.settings.dt
                                        : -0.25 * world.time * world.settings.dt;
            EXPECT_NEAR(world.blocks[ship].position.x - exact, expected, 1e-11) << label;
        }
    }
}

TEST(Forces, TheSameThrustMovesTheLightShipFourTimesFaster) {
    World world = makeWorld(loadShipped("thruster"));
    run(world, 2.0);
    // v = F/m·t, exactly (the factors are powers of two): 2 N / 1 kg and 2 N / 4 kg.
    EXPECT_EQ(world.blocks[0].velocity.x, 2.0 * world.time);
    EXPECT_EQ(world.blocks[1].velocity.x, 0.5 * world.time);
    EXPECT_NEAR(world.time, 2.0, 1e-12);
}

TEST(Drag, AFallingBlockReachesTheTerminalSpeed) {
    // Terminal speed sqrt(m·g/(k·A)): 1 kg, 0.5 m x 0.5 m, k = 1.2 kg/m^3 gives 5.72 m/s. After
    // 10 s (35 time constants v_t/g) the approach is complete to far below 1e-3 relative; each
    // integrator's fixed point is the exact terminal speed (drag = weight), so 1e-6 holds.
    const double m = 1.0, k = 1.2, side = 0.5, g = 9.81;
    const double terminal = std::sqrt(m * g / (k * side * side));
    for (Integrator integrator : kIntegrators) {
        World world =
            test_worlds::makeWorld(Method::Perfect, {0.0, -g}, 1.0, Bounds{{0, 0}, {10, 200}});
        world.settings.integrator = integrator;
        world.settings.drag = k;
        const int b = addBlock(world, {5.0, 190.0}, {side, side}, {}, m);
        run(world, 10.0);
        EXPECT_GT(world.blocks[b].position.y, 10.0) << "still falling";
        EXPECT_NEAR(-world.blocks[b].velocity.y / terminal, 1.0, 1e-6)
            << integratorName(integrator);
    }
}

TEST(Drag, TheFeatherFallsSlowerThanTheStone) {
    World world = makeWorld(loadShipped("feather_and_stone"));
    run(world, 0.5);
    const Block& feather = world.blocks[0];
    const Block& stone = world.blocks[1];
    EXPECT_LT(stone.velocity.y, 3.0 * feather.velocity.y); // more than 3 times faster
    EXPECT_NEAR(-feather.velocity.y, std::sqrt(0.05 * 9.81 / 1.2), 1e-3);
}

TEST(Drag, NeverReversesAVelocityWithinAStep) {
    // k·A·|v|·h/m = 1e6 · 1 · 10 / 60 / 1e-3 >> 2: without the cap an explicit step would flip
    // and grow the velocity without bound. With it the block stops and stays finite.
    for (Integrator integrator : kIntegrators) {
        World world = test_worlds::makeWorld(Method::Perfect);
        world.settings.integrator = integrator;
        world.settings.drag = 1e6;
        const int b = addBlock(world, {5.0, 6.0}, {1.0, 1.0}, {10.0, 0.0}, 1e-3);
        for (int f = 0; f < 10; ++f) {
            world.step();
            EXPECT_GE(world.blocks[b].velocity.x, 0.0);
            EXPECT_TRUE(std::isfinite(world.blocks[b].position.x));
        }
    }
}

// ---- The exact integrator ----

struct Drop {
    std::vector<double> impactSpeeds; // m/s, the floor bounces in order (speed before)
    double restTime = -1.0;           // s, the first rest-rule contact with the floor
};

Drop dropBlock(double h, double C, double dt, Integrator integrator, double seconds) {
    World world = test_worlds::makeWorld(Method::Perfect, {0.0, -9.81}, C);
    world.settings.dt = dt;
    world.settings.integrator = integrator;
    addBlock(world, {10.0, h + 0.5}, {1.0, 1.0});
    std::vector<CollisionRecord> log;
    run(world, seconds, &log);
    Drop d;
    for (const CollisionRecord& r : log) {
        if (r.other != kWallBottom) continue;
        if (r.rest) {
            if (d.restTime < 0.0) d.restTime = r.time;
        } else {
            d.impactSpeeds.push_back(-r.v1);
        }
    }
    return d;
}

TEST(ExactIntegrator, BounceApexesAreHTimesCToThe2nAtAnyFrameRate) {
    // Apex after n bounces: (C^n·v0)²/(2g) = h·C^(2n) with v0 = sqrt(2gh). The speeds come from
    // the collision log; relative 1e-9 (the roots are computed without cancellation, so the
    // error is a few roundings per bounce).
    const double h = 4.0, C = 0.8, g = 9.81;
    for (double dt : {1.0 / 30.0, 1.0 / 60.0, 1.0 / 240.0}) {
        const Drop d = dropBlock(h, C, dt, Integrator::Exact, 10.0);
        ASSERT_GT(d.impactSpeeds.size(), 20u);
        for (size_t n = 0; n < 20; ++n) {
            const double speedAfter = C * d.impactSpeeds[n];
            const double apex = speedAfter * speedAfter / (2.0 * g);
            const double expected = h * std::pow(C, 2.0 * (n + 1));
            EXPECT_NEAR(apex / expected, 1.0, 1e-9) << "bounce " << n + 1 << ", dt " << dt;
        }
    }
}

TEST(ExactIntegrator, TimeToRestIsTheZenoSumWithinTheRestRulesBound) {
    // Rest at sqrt(2h/g)·(1+C)/(1-C). The rest rule ends the tail at the first impact slower than
    // restSpeed (1e-6 m/s, the exact integrator's threshold); the flights it cuts off last
    // 2·C·v/(g·(1-C)) in all, for v below restSpeed: at most 8e-7 s here (relative 1e-7).
    const double h = 4.0, C = 0.8, g = 9.81, restSpeed = 1e-6;
    const double expected = std::sqrt(2.0 * h / g) * (1.0 + C) / (1.0 - C);
    const double bound = 2.0 * C * restSpeed / (g * (1.0 - C));
    for (double dt : {1.0 / 30.0, 1.0 / 60.0, 1.0 / 240.0}) {
        const Drop d = dropBlock(h, C, dt, Integrator::Exact, 10.0);
        ASSERT_GT(d.restTime, 0.0);
        EXPECT_LE(d.restTime, expected + 1e-12) << "dt " << dt;
        EXPECT_GE(d.restTime, expected - bound - 1e-12) << "dt " << dt;
        EXPECT_LT(std::abs(d.restTime - expected) / expected, 1e-6);
    }
}

TEST(ExactIntegrator, SemiImplicitEulerMissesTheApexesThatExactGets) {
    // The measurement: at dt 1/60 Euler's energy after 4 bounces is percent off C^(2n).
    const double h = 4.0, C = 0.8, g = 9.81;
    const Drop d = dropBlock(h, C, 1.0 / 60.0, Integrator::SemiImplicitEuler, 10.0);
    ASSERT_GT(d.impactSpeeds.size(), 4u);
    const double speedAfter = C * d.impactSpeeds[3];
    EXPECT_GT(std::abs(speedAfter * speedAfter / (2.0 * g) / (h * std::pow(C, 8.0)) - 1.0), 1e-3);
}

TEST(ExactIntegrator, ElasticBouncesKeepTheirHeightForEver) {
    // The rest rule's edge: with C = 1 no bounce may be cut short or lose energy. Energy is
    // conserved to 1e-9 relative over 40 bounces (rounding only).
    World world = test_worlds::makeWorld(Method::Perfect, {0.0, -9.81}, 1.0);
    world.settings.integrator = Integrator::Exact;
    const int b = addBlock(world, {10.0, 2.5}, {1.0, 1.0});
    const double start = kineticEnergy(world) + potentialEnergy(world);
    for (int f = 0; f < 1800; ++f) {
        world.step();
        const double e = kineticEnergy(world) + potentialEnergy(world);
        ASSERT_NEAR(e / start, 1.0, 1e-9) << "frame " << f;
    }
    EXPECT_GT(world.blocks[b].position.y, 0.5);
}

TEST(ExactIntegrator, ARestingStackStaysExactlyStillUnderExactMethods) {
    // A stack on the floor: the contacts accelerate into each other with no relative velocity;
    // the rest rule holds them (acceleration 0) and nothing moves by a single bit.
    for (Method method : {Method::Perfect, Method::TurnBased}) {
        World world = test_worlds::makeWorld(method, {0.0, -9.81}, 0.5);
        world.settings.integrator = Integrator::Exact;
        for (int k = 0; k < 4; ++k) addBlock(world, {10.0, 0.5 + k}, {1.0, 1.0});
        const World start = world;
        run(world, 5.0);
        for (size_t i = 0; i < world.blocks.size(); ++i) {
            EXPECT_EQ(world.blocks[i].position.y, start.blocks[i].position.y) << methodName(method);
            EXPECT_EQ(world.blocks[i].velocity.y, 0.0) << methodName(method);
        }
    }
}

TEST(ExactIntegrator, ABlockSlidesOnTheFloorItRestsOn) {
    for (Method method : {Method::Perfect, Method::TurnBased}) {
        World world = test_worlds::makeWorld(method, {0.0, -9.81}, 0.5);
        world.settings.integrator = Integrator::Exact;
        const int b = addBlock(world, {2.0, 0.5}, {1.0, 1.0}, {1.0, 0.0});
        run(world, 2.0);
        EXPECT_NEAR(world.blocks[b].position.x, 4.0, 1e-9) << methodName(method);
        EXPECT_EQ(world.blocks[b].position.y, 0.5) << methodName(method);
    }
}

TEST(ExplicitEuler, MovesWithTheOldVelocity) {
    // One frame from rest: explicit Euler does not move (x += v_old·h = 0), then v = g·h;
    // semi-implicit moves by g·h².
    World world = test_worlds::makeWorld(Method::Perfect, {0.0, -9.81}, 1.0);
    world.settings.integrator = Integrator::ExplicitEuler;
    const int b = addBlock(world, {10.0, 6.0}, {1.0, 1.0});
    world.step();
    EXPECT_EQ(world.blocks[b].position.y, 6.0);
    EXPECT_EQ(world.blocks[b].velocity.y, -9.81 * world.settings.dt);
}

// ---- Mistakes: each fails with it on and not with it off ----

// Whether block 0 was ever seen on the other side of block 1 along x.
bool crosses(World world, double seconds) {
    const double side = world.blocks[1].position.x - world.blocks[0].position.x;
    const long frames = std::lround(seconds / world.settings.dt);
    for (long f = 0; f < frames; ++f) {
        world.step();
        if ((world.blocks[1].position.x - world.blocks[0].position.x) * side < 0.0) return true;
    }
    return false;
}

TEST(Mistakes, DiscreteLetsTheBulletTunnelUnderPerfectAndTurnBased) {
    for (Method method : {Method::Perfect, Method::TurnBased}) {
        World world = makeWorld(loadShipped("bullet_wall"));
        world.settings.method = method;
        EXPECT_FALSE(crosses(world, 1.0)) << methodName(method);
        world.settings.set(Mistake::Discrete, true);
        EXPECT_TRUE(crosses(world, 1.0)) << methodName(method);
    }
    World shipped = makeWorld(loadShipped("mistake_discrete"));
    EXPECT_TRUE(shipped.settings.has(Mistake::Discrete));
    EXPECT_TRUE(crosses(shipped, 1.0));
}

TEST(Mistakes, MoveBackGivesTheCrookedResult) {
    // The frame of impact (t = 0.4107 s into 0.4..0.5): the right answer puts the mover at the
    // point of impact, x = 3 + 14·0.4107 = 8.75; moving back along y only leaves x where the
    // whole frame took it, 3 + 14·0.5 = 10: 1.25 m off.
    auto [wrong, right] = withAndWithout("mistake_move_back", Mistake::MoveBack);
    ASSERT_TRUE(wrong.settings.has(Mistake::MoveBack));
    run(wrong, 0.5);
    run(right, 0.5);
    EXPECT_NEAR(right.blocks[0].position.x, 3.0 + 14.0 * (5.75 / 14.0), 1e-9);
    EXPECT_NEAR(wrong.blocks[0].position.x, 10.0, 1e-9);
    EXPECT_EQ(wrong.blocks[0].position.y, right.blocks[0].position.y); // on the step, both
}

TEST(Mistakes, FirstFoundResolvesTheFartherBlockAndOverlapsTheNearOne) {
    auto [wrong, right] = withAndWithout("mistake_first_found", Mistake::FirstFound);
    ASSERT_TRUE(wrong.settings.has(Mistake::FirstFound));
    double wrongOverlap = 0.0, rightOverlap = 0.0;
    for (int f = 0; f < 10; ++f) {
        wrongOverlap = std::max(wrongOverlap, wrong.step().maxPenetration);
        rightOverlap = std::max(rightOverlap, right.step().maxPenetration);
    }
    EXPECT_NEAR(wrongOverlap, 0.5, 1e-9); // red sits inside the 0.5 m gate
    EXPECT_EQ(rightOverlap, 0.0);
}

TEST(Mistakes, NoApproachTestResolvesSeparatingBlocks) {
    auto [wrong, right] = withAndWithout("mistake_no_approach_test", Mistake::NoApproachTest);
    ASSERT_TRUE(wrong.settings.has(Mistake::NoApproachTest));
    int wrongCollisions = 0, rightCollisions = 0;
    for (int f = 0; f < 60; ++f) {
        wrongCollisions += wrong.step().collisions;
        rightCollisions += right.step().collisions;
    }
    EXPECT_EQ(rightCollisions, 0);
    EXPECT_EQ(right.blocks[1].velocity.x, 4.0);
    EXPECT_EQ(wrongCollisions, 2);
    EXPECT_EQ(wrong.blocks[0].velocity.x, 3.375); // C = 0.5: 3 -> 3.75 -> 3.375
    EXPECT_EQ(wrong.blocks[1].velocity.x, 3.625);
}

TEST(Mistakes, NamesAndSlidesComeFromOneTable) {
    for (int m = 0; m < static_cast<int>(Mistake::Count); ++m) {
        Mistake parsed{};
        EXPECT_TRUE(parseMistake(mistakeName(static_cast<Mistake>(m)), parsed));
        EXPECT_EQ(parsed, static_cast<Mistake>(m));
        EXPECT_GT(std::string(mistakeSlide(parsed)).size(), 10u);
    }
    Mistake m{};
    EXPECT_FALSE(parseMistake("typo", m));
}

} // namespace
