// Randomized soak over methods x parameters (issue 7): fixed seeds, bounded by step counts (no
// clock is read), with the invariants checked after every single step:
//   - every position, velocity and statistic is finite;
//   - static blocks never move, kinematic blocks keep the magnitude of each velocity component;
//   - under perfect and turn-based no block leaves the bounds and no two blocks overlap (1e-9 m);
//   - the statistics are consistent: StepStats::events stays under the event cap, and the frame
//     advances less than dt only when eventCapHits says the cap held time back;
//   - in gravity-free worlds of dynamic blocks only, a perfect step without wall contacts (and
//     without rest-rule merges, which a wall may anchor) conserves momentum.
// Parameters covered: mass ratios up to 1e12, gravity of +-1000 on either axis, dt up to 0.1,
// speeds up to 1e5, C of 0, 0.5 and 1, substeps 1..8, static and kinematic blocks mixed in, and a
// jammed box of 10,000 blocks packed edge to edge.
#include "collision.h"
#include "test_worlds.h"
#include "world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr double kTolerance = 1e-9; // m: rounding allowed at walls and between blocks

using test_worlds::methodTestName;

bool exactMethod(Method method) {
    return method == Method::Perfect || method == Method::TurnBased;
}

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

int addBlock(World& world, Vec2 position, Vec2 size, Vec2 velocity, double mass, BodyKind kind) {
    Block b;
    b.position = position;
    b.size = size;
    b.velocity = kind == BodyKind::Static ? Vec2{} : velocity;
    b.kind = kind;
    b.mass = kind == BodyKind::Dynamic ? mass : kInfiniteMass;
    world.blocks.push_back(b);
    return static_cast<int>(world.blocks.size()) - 1;
}

// A description of the world for failure messages: enough to rebuild the case by hand.
std::string describe(const World& world, const std::string& label) {
    std::ostringstream out;
    const WorldSettings& s = world.settings;
    out << label << ": method " << methodName(s.method) << ", " << world.blocks.size()
        << " blocks, bounds [" << world.bounds.min.x << ", " << world.bounds.min.y << ", "
        << world.bounds.max.x << ", " << world.bounds.max.y << "], gravity (" << s.gravity.x << ", "
        << s.gravity.y << "), C " << s.bounciness << ", dt " << s.dt << ", substeps " << s.substeps
        << ", frame " << world.frame << ", time " << world.time;
    return out.str();
}

struct Snapshot {
    std::vector<Block> blocks;
    double time = 0.0;
};

Snapshot snapshot(const World& world) {
    return {world.blocks, world.time};
}

struct CheckOptions {
    bool checkMomentum = false; // gravity-free, dynamic blocks only, perfect method
};

// Steps the world once and checks every invariant. Returns false (after reporting the failures
// through gtest) when one does not hold, so the caller can stop early instead of flooding the log.
bool stepAndCheck(World& world, const std::string& label, const CheckOptions& options = {},
                  StepStats* statsOut = nullptr) {
    const Snapshot before = snapshot(world);
    const Vec2 momentumBefore = totalMomentum(world);
    double momentumScale = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic())
            momentumScale += b.mass * (std::abs(b.velocity.x) + std::abs(b.velocity.y));
    std::vector<CollisionRecord> log;
    const StepStats stats = world.step(options.checkMomentum ? &log : nullptr);
    const WorldSettings& s = world.settings;
    bool ok = true;
    auto fail = [&](const std::string& what) {
        ADD_FAILURE() << describe(world, label) << ": " << what;
        ok = false;
    };

    // 1. Finite state and statistics.
    for (size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        if (!finite(b.position) || !finite(b.velocity)) {
            std::ostringstream m;
            m << "block " << i << " is not finite: position (" << b.position.x << ", "
              << b.position.y << "), velocity (" << b.velocity.x << ", " << b.velocity.y
              << "), before: position (" << before.blocks[i].position.x << ", "
              << before.blocks[i].position.y << "), velocity (" << before.blocks[i].velocity.x
              << ", " << before.blocks[i].velocity.y << ")";
            fail(m.str());
            break;
        }
    }
    if (!finite(stats.momentum) || !std::isfinite(stats.kineticEnergy) ||
        !std::isfinite(stats.potentialEnergy) || !std::isfinite(stats.maxPenetration) ||
        !std::isfinite(stats.simulatedTime) || !std::isfinite(world.time))
        fail("a statistic is not finite");
    if (stats.collisions < 0 || stats.events < 0 || stats.eventCapHits < 0)
        fail("a count is negative");

    // 2. Static blocks never move; kinematic blocks keep their speed per axis.
    for (size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        const Block& a = before.blocks[i];
        if (b.kind == BodyKind::Static &&
            (b.position.x != a.position.x || b.position.y != a.position.y || b.velocity.x != 0.0 ||
             b.velocity.y != 0.0)) {
            fail("static block " + std::to_string(i) + " moved");
            break;
        }
        if (b.kind == BodyKind::Kinematic && (std::abs(b.velocity.x) != std::abs(a.velocity.x) ||
                                              std::abs(b.velocity.y) != std::abs(a.velocity.y))) {
            fail("kinematic block " + std::to_string(i) + " changed speed");
            break;
        }
    }

    // 3. Perfect and turn-based: inside the bounds, no overlap.
    if (exactMethod(s.method)) {
        for (size_t i = 0; i < world.blocks.size(); ++i) {
            const double out = outsideDepth(aabbOf(world.blocks[i]), world.bounds);
            if (!(out <= kTolerance)) {
                std::ostringstream m;
                m << "block " << i << " sticks out of the bounds by " << out << " m at ("
                  << world.blocks[i].position.x << ", " << world.blocks[i].position.y << ")";
                fail(m.str());
                break;
            }
        }
        const double overlap = maxOverlap(world);
        if (!(overlap <= kTolerance)) fail("maxOverlap " + std::to_string(overlap) + " m");
        if (!(stats.maxPenetration <= kTolerance))
            fail("stats.maxPenetration " + std::to_string(stats.maxPenetration) + " m");
    }

    // 4. Event cap and simulated time. The cap is per substep and a capped substep ends the frame.
    const int substeps = std::max(1, s.substeps);
    if (static_cast<long long>(stats.events) > static_cast<long long>(s.eventCap) * substeps)
        fail("stats.events " + std::to_string(stats.events) + " above the cap");
    if (stats.eventCapHits > 1) fail("more than one capped substep in a frame");
    if (s.method != Method::Perfect && (stats.eventCapHits != 0 || stats.events != 0))
        fail("event statistics from a method without events");
    const double timeRounding = 1e-12 * s.dt;
    if (stats.simulatedTime < -timeRounding || stats.simulatedTime > s.dt + timeRounding)
        fail("simulatedTime " + std::to_string(stats.simulatedTime) + " outside [0, dt]");
    if (stats.eventCapHits == 0 && !(std::abs(stats.simulatedTime - s.dt) <= timeRounding))
        fail("time held back (simulatedTime " + std::to_string(stats.simulatedTime) +
             ") without eventCapHits");
    if (!(std::abs((world.time - before.time) - stats.simulatedTime) <=
          1e-12 * std::max(1.0, world.time)))
        fail("world.time did not advance by simulatedTime");

    // 5. Momentum: without walls (and with no infinite masses, no gravity) it is conserved.
    if (options.checkMomentum) {
        // A rest-rule cluster touching a wall is anchored by it (its record names two blocks), so
        // frames with rest-rule merges are left out too.
        const bool wallOrRest = std::any_of(
            log.begin(), log.end(), [](const CollisionRecord& r) { return r.other < 0 || r.rest; });
        if (!wallOrRest) {
            const Vec2 after = totalMomentum(world);
            const double error = length(after - momentumBefore);
            if (!(error <= 1e-12 * momentumScale + 1e-300)) {
                std::ostringstream m;
                m << "momentum changed without wall contact by " << error << " (scale "
                  << momentumScale << ")";
                fail(m.str());
            }
        }
    }
    if (statsOut) *statsOut = stats;
    return ok;
}

// Steps the world up to `steps` times, or until the perfect method has processed `eventBudget`
// collision events in all (a frame at the event cap costs tens of milliseconds to half a second
// with fast blocks crossing the world many times per frame; the budget bounds the soak's run time
// by a count, never by a clock). Stops at the first step that breaks an invariant.
void soak(World& world, const std::string& label, int steps, const CheckOptions& options = {},
          long long eventBudget = 100000) {
    long long events = 0;
    for (int step = 0; step < steps && events < eventBudget; ++step) {
        StepStats stats;
        if (!stepAndCheck(world, label, options, &stats)) return;
        events += stats.events;
    }
}

// ----------------------------------------------------------------------------------------------
// Random worlds over the parameter grid.

struct Scenario {
    Method method = Method::Perfect;
    double bounciness = 1.0;
    int substeps = 1;
    double dt = 1.0 / 60.0;
    Vec2 gravity;
    double maxSpeed = 5.0;    // m/s per component
    double maxMassLog = 0.0;  // masses are 10^[0, maxMassLog] kg
    bool twoMasses = false;   // masses are 1 or 10^maxMassLog only (the extreme ratio)
    double infiniteShare = 0; // share of static and kinematic blocks
    int blocks = 50;
    int eventCap = WorldSettings{}.eventCap;
    Bounds bounds;
    int steps = 200;
};

// Every seed picks one value of each parameter; the choices cycle with different periods, so a
// few dozen seeds cover every value of every parameter, each with several partners.
Scenario scenarioFor(Method method, int seed) {
    static const std::array<double, 3> kBounciness{0.0, 0.5, 1.0};
    static const std::array<double, 5> kDt{1.0 / 60.0, 0.1, 0.001, 0.05, 0.1};
    static const std::array<Vec2, 7> kGravity{
        Vec2{0.0, 0.0},    Vec2{0.0, -9.81},   Vec2{0.0, -1000.0}, Vec2{1000.0, 0.0},
        Vec2{0.0, 1000.0}, Vec2{-1000.0, 0.0}, Vec2{0.0, 0.0}};
    static const std::array<double, 4> kSpeed{5.0, 100.0, 1e5, 1e3};
    static const std::array<double, 4> kMassLog{0.0, 3.0, 12.0, 12.0};
    static const std::array<double, 3> kInfinite{0.0, 0.1, 0.25};
    static const std::array<Bounds, 3> kBounds{Bounds{}, Bounds{{-50.0, -3.0}, {50.0, 40.0}},
                                               Bounds{{1e3, 1e3}, {1e3 + 8.0, 1e3 + 6.0}}};
    Scenario sc;
    sc.method = method;
    sc.bounciness = kBounciness[seed % 3];
    sc.substeps = 1 + (seed * 3) % 8;
    sc.dt = kDt[seed % 5];
    sc.gravity = kGravity[seed % 7];
    sc.maxSpeed = kSpeed[(seed / 2) % 4];
    sc.maxMassLog = kMassLog[seed % 4];
    sc.twoMasses = seed % 8 == 2;
    sc.infiniteShare = kInfinite[(seed / 3) % 3];
    sc.bounds = kBounds[(seed / 4) % 3];
    sc.blocks = 20 + (seed * 37) % 180;
    if (seed % 5 == 3) sc.eventCap = 500; // a small cap: the capped path, cheaply
    return sc;
}

World buildWorld(const Scenario& sc, std::uint64_t seed) {
    World world;
    world.settings.method = sc.method;
    world.settings.bounciness = sc.bounciness;
    world.settings.substeps = sc.substeps;
    world.settings.dt = sc.dt;
    world.settings.gravity = sc.gravity;
    world.settings.eventCap = sc.eventCap;
    world.bounds = sc.bounds;

    // One block per cell of a grid over the bounds, at a random place inside its cell, so no two
    // blocks overlap at the start. Some cells get a block that fills the cell exactly (touching
    // its neighbours): contacts at time zero.
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const test_worlds::CellGrid grid =
        test_worlds::cellGridFor(sc.blocks, sc.bounds.max - sc.bounds.min);
    const Vec2 cell = grid.cell;
    for (int k = 0; k < sc.blocks; ++k) {
        const int cx = k % grid.columns, cy = k / grid.columns;
        const bool full = unit(rng) < 0.1;
        const Vec2 fill =
            full ? Vec2{1.0, 1.0} : Vec2{0.2 + 0.7 * unit(rng), 0.2 + 0.7 * unit(rng)};
        const Vec2 size{cell.x * fill.x, cell.y * fill.y};
        const Vec2 slack = cell - size;
        const Vec2 position{sc.bounds.min.x + cx * cell.x + size.x * 0.5 + slack.x * unit(rng),
                            sc.bounds.min.y + cy * cell.y + size.y * 0.5 + slack.y * unit(rng)};
        // Keep the rounding of the placement inside the bounds.
        Vec2 p = position;
        for (int axis = 0; axis < 2; ++axis)
            p[axis] = std::clamp(p[axis], sc.bounds.min[axis] + size[axis] * 0.5,
                                 sc.bounds.max[axis] - size[axis] * 0.5);
        const double speedScale = unit(rng) < 0.2 ? sc.maxSpeed : sc.maxSpeed * unit(rng);
        Vec2 velocity{speedScale * (2.0 * unit(rng) - 1.0), speedScale * (2.0 * unit(rng) - 1.0)};
        if (unit(rng) < 0.1) velocity = Vec2{}; // some start at rest
        double mass = std::pow(10.0, sc.maxMassLog * unit(rng));
        if (sc.twoMasses) mass = unit(rng) < 0.5 ? 1.0 : std::pow(10.0, sc.maxMassLog);
        BodyKind kind = BodyKind::Dynamic;
        const double r = unit(rng);
        if (r < sc.infiniteShare * 0.5)
            kind = BodyKind::Static;
        else if (r < sc.infiniteShare)
            kind = BodyKind::Kinematic;
        addBlock(world, p, size, velocity, mass, kind);
    }
    return world;
}

// A world built for the soak must be valid at the start (what the scene loader guarantees).
void expectValidStart(const World& world, const std::string& label) {
    ASSERT_LE(maxOverlap(world), kTolerance) << label;
}

class Soak : public ::testing::TestWithParam<std::tuple<Method, int>> {};

TEST_P(Soak, InvariantsHoldAfterEveryStep) {
    const auto [method, seed] = GetParam();
    const Scenario sc = scenarioFor(method, seed);
    World world = buildWorld(sc, 1000 + static_cast<std::uint64_t>(seed));
    const std::string label = "seed " + std::to_string(seed);
    expectValidStart(world, label);
    CheckOptions options;
    options.checkMomentum = method == Method::Perfect && sc.gravity.x == 0.0 &&
                            sc.gravity.y == 0.0 && sc.infiniteShare == 0.0;
    soak(world, label, sc.steps, options);
}

constexpr int kSeeds = 40;

INSTANTIATE_TEST_SUITE_P(Methods, Soak,
                         ::testing::Combine(::testing::Values(Method::Perfect,
                                                              Method::MoveAndCorrect,
                                                              Method::TurnBased),
                                            ::testing::Range(0, kSeeds)),
                         [](const ::testing::TestParamInfo<Soak::ParamType>& info) {
                             return methodTestName(std::get<0>(info.param)) + "_seed" +
                                    std::to_string(std::get<1>(info.param));
                         });

// The soak's parameter grid covers every extreme the issue names.
TEST(SoakCoverage, EveryParameterValueIsUsed) {
    bool c0 = false, c05 = false, c1 = false, dt01 = false, speed1e5 = false, ratio1e12 = false;
    bool gUp = false, gDown = false, gLeft = false, gRight = false, mixed = false;
    std::array<bool, 9> substeps{};
    for (int seed = 0; seed < kSeeds; ++seed) {
        const Scenario sc = scenarioFor(Method::Perfect, seed);
        c0 |= sc.bounciness == 0.0, c05 |= sc.bounciness == 0.5, c1 |= sc.bounciness == 1.0;
        dt01 |= sc.dt == 0.1, speed1e5 |= sc.maxSpeed == 1e5, ratio1e12 |= sc.maxMassLog == 12.0;
        gUp |= sc.gravity.y == 1000.0, gDown |= sc.gravity.y == -1000.0;
        gRight |= sc.gravity.x == 1000.0, gLeft |= sc.gravity.x == -1000.0;
        mixed |= sc.infiniteShare > 0.0;
        substeps[sc.substeps] = true;
    }
    EXPECT_TRUE(c0 && c05 && c1 && dt01 && speed1e5 && ratio1e12 && mixed);
    EXPECT_TRUE(gUp && gDown && gLeft && gRight);
    for (int k = 1; k <= 8; ++k) EXPECT_TRUE(substeps[k]) << "substeps " << k;
}

// ----------------------------------------------------------------------------------------------
// The jammed box: 10,000 blocks packed edge to edge (touching, and overlapping by rounding only),
// filling most of a box, with random velocities. A few steps per method.

World jammedBox(Method method, Vec2 gravity, double bounciness, std::uint64_t seed) {
    World world;
    world.settings.method = method;
    world.settings.gravity = gravity;
    world.settings.bounciness = bounciness;
    world.bounds = Bounds{{0.0, 0.0}, {11.0, 12.0}};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double size = 0.1; // not a binary fraction: the faces touch only to rounding
    for (int row = 0; row < 100; ++row) {
        for (int column = 0; column < 100; ++column) {
            const Vec2 position{0.5 + size * 0.5 + column * size, size * 0.5 + row * size};
            const Vec2 velocity{20.0 * (2.0 * unit(rng) - 1.0), 20.0 * (2.0 * unit(rng) - 1.0)};
            const double mass = std::pow(10.0, 3.0 * unit(rng));
            addBlock(world, position, {size, size}, velocity, mass, BodyKind::Dynamic);
        }
    }
    return world;
}

class JammedBox : public ::testing::TestWithParam<Method> {};

TEST_P(JammedBox, TenThousandBlocksStayFiniteAndApart) {
    const Method method = GetParam();
    struct Case {
        Vec2 gravity;
        double bounciness;
    };
    const std::array<Case, 2> cases{Case{{0.0, 0.0}, 1.0}, Case{{0.0, -1000.0}, 0.0}};
    int k = 0;
    for (const Case& c : cases) {
        World world = jammedBox(method, c.gravity, c.bounciness, 77 + k);
        const std::string label = "jammed box " + std::to_string(k++);
        expectValidStart(world, label);
        for (int step = 0; step < 3; ++step)
            if (!stepAndCheck(world, label)) return;
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, JammedBox, test_worlds::everyMethod(),
                         test_worlds::methodParamName);

// ----------------------------------------------------------------------------------------------
// Hand-made extremes.

class Extremes : public ::testing::TestWithParam<Method> {};

// A block of 1e12 kg pushes a 1 kg block against a wall: the light block bounces between them
// floor(pi * 1e6) = 3,141,592 times (the "digits of pi" collisions) before the heavy block turns
// back. Under the perfect method that takes well over a hundred capped frames; every frame stays
// bounded and says when the cap held time back, and the count comes out exact.
TEST_P(Extremes, MassRatio1e12AgainstAWall) {
    World world;
    world.settings.method = GetParam();
    world.settings.gravity = {0.0, 0.0};
    world.settings.bounciness = 1.0;
    addBlock(world, {2.0, 6.0}, {1.0, 1.0}, {0.0, 0.0}, 1.0, BodyKind::Dynamic);
    addBlock(world, {8.0, 6.0}, {1.0, 1.0}, {-1.0, 0.0}, 1e12, BodyKind::Dynamic);
    int cappedFrames = 0;
    long long collisions = 0;
    for (int step = 0; step < 1000; ++step) {
        StepStats stats;
        if (!stepAndCheck(world, "mass ratio 1e12", {}, &stats)) return;
        cappedFrames += stats.eventCapHits;
        collisions += stats.collisions;
    }
    if (world.settings.method == Method::Perfect) {
        EXPECT_GT(cappedFrames, 100);
        EXPECT_NEAR(static_cast<double>(collisions), 3141592.0, 2.0);
        EXPECT_GT(world.blocks[1].velocity.x, 0.0); // the heavy block turned back
    }
}

// A light block falls on a heavy one under strong gravity with big steps and substeps.
TEST_P(Extremes, HeavyStackUnderStrongGravity) {
    for (const Vec2 gravity :
         {Vec2{0.0, -1000.0}, Vec2{0.0, 1000.0}, Vec2{1000.0, 0.0}, Vec2{-1000.0, 0.0}}) {
        for (const double C : {0.0, 0.5, 1.0}) {
            World world;
            world.settings.method = GetParam();
            world.settings.gravity = gravity;
            world.settings.bounciness = C;
            world.settings.dt = 0.1;
            world.settings.substeps = 3;
            world.bounds = Bounds{{0.0, 0.0}, {4.0, 4.0}};
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    addBlock(world, {0.5 + 1.2 * i, 0.5 + 1.2 * j}, {1.0, 1.0},
                             {1e5 * (j - 1), 1e5 * (i - 1)}, std::pow(10.0, 6.0 * (i + j) / 2.0),
                             BodyKind::Dynamic);
            soak(world, "heavy stack, C " + std::to_string(C), 100, {}, 40000);
            if (::testing::Test::HasFailure()) return;
        }
    }
}

// A kinematic platform and static ledges in a closed box under gravity.
TEST_P(Extremes, PlatformsAndLedges) {
    World world;
    world.settings.method = GetParam();
    world.settings.bounciness = 0.5;
    world.bounds = Bounds{{0.0, 0.0}, {10.0, 10.0}};
    addBlock(world, {5.0, 1.0}, {3.0, 0.4}, {3.0, 0.0}, 1.0, BodyKind::Kinematic);
    addBlock(world, {1.0, 4.0}, {2.0, 0.5}, {}, 1.0, BodyKind::Static);
    addBlock(world, {9.0, 4.0}, {2.0, 0.5}, {}, 1.0, BodyKind::Static);
    addBlock(world, {9.0, 4.1}, {1.0, 0.5}, {}, 1.0, BodyKind::Static); // static pairs may overlap
    addBlock(world, {5.0, 6.0}, {0.5, 3.0}, {0.0, -8.0}, 1.0, BodyKind::Kinematic);
    for (int i = 0; i < 8; ++i)
        addBlock(world, {0.6 + 1.1 * i, 8.0 + 0.2 * (i % 3)}, {0.5, 0.5}, {2.0 * (i - 4), 0.0},
                 1.0 + i, BodyKind::Dynamic);
    soak(world, "platforms and ledges", 600);
}

INSTANTIATE_TEST_SUITE_P(Methods, Extremes, test_worlds::everyMethod(),
                         test_worlds::methodParamName);

// ----------------------------------------------------------------------------------------------
// Jams: a dynamic block caught between a kinematic block and something it cannot push (a wall, a
// static block, another kinematic block). Each case is the smallest reproduction of a failure the
// soak found; the soak's random worlds meet them too.

class Jams : public ::testing::TestWithParam<Method> {};

// A kinematic platform sliding along the floor pushes a block into the right wall. The platform
// should reverse (as it does when a slow contact jams it: the rest rule) and time should go on.
// Perfect method today: from t = 2.5 s every frame ends at the event cap with no time advanced,
// forever (the world freezes), and at C = 1 the trapped block gains about 2 m/s per event.
TEST_P(Jams, KinematicPushesBlockIntoWall) {
    for (const double C : {0.0, 0.5, 1.0}) {
        World world;
        world.settings.method = GetParam();
        world.settings.bounciness = C;
        world.bounds = Bounds{{0.0, 0.0}, {10.0, 4.0}};
        addBlock(world, {3.0, 0.5}, {2.0, 1.0}, {2.0, 0.0}, 1.0, BodyKind::Kinematic);
        addBlock(world, {7.0, 0.5}, {1.0, 1.0}, {0.0, 0.0}, 1.0, BodyKind::Dynamic);
        const std::string label = "platform pushes a block into the wall, C " + std::to_string(C);
        const int frames = 300; // 5 s: the platform reaches the block at 1.5 s, the wall at 2.5 s
        soak(world, label, frames, {}, 1LL << 40);
        if (::testing::Test::HasFailure()) return;
        EXPECT_GT(world.time, 0.9 * frames * world.settings.dt) << label << ": time froze";
        if (GetParam() == Method::Perfect) {
            EXPECT_LT(std::abs(world.blocks[1].velocity.x), 100.0)
                << label << ": the trapped block gained speed";
        }
    }
}

// A block between two kinematic blocks moving left at different speeds (no gravity, no walls
// involved). Perfect method today: the block bounces between them at one instant; after 8 repeats
// the rest rule merges the cluster with the velocity of the lower-index kinematic block, and the
// faster one drives through the block (overlap 0.067 m at t = 0.5 s, growing to 2 m).
TEST_P(Jams, BlockSqueezedBetweenTwoKinematics) {
    for (const bool slowFirst : {true, false}) {
        for (const double C : {0.0, 0.5, 1.0}) {
            World world;
            world.settings.method = GetParam();
            world.settings.gravity = {0.0, 0.0};
            world.settings.bounciness = C;
            const auto slow = [&] {
                addBlock(world, {8.0, 2.0}, {2.0, 2.0}, {-1.0, 0.0}, 1.0, BodyKind::Kinematic);
            };
            const auto fast = [&] {
                addBlock(world, {14.0, 2.0}, {2.0, 2.0}, {-5.0, 0.0}, 1.0, BodyKind::Kinematic);
            };
            if (slowFirst)
                slow();
            else
                fast();
            addBlock(world, {10.0, 2.0}, {2.0, 2.0}, {-1.0, 0.0}, 1.0, BodyKind::Dynamic);
            if (slowFirst)
                fast();
            else
                slow();
            soak(world, "squeezed, C " + std::to_string(C) + (slowFirst ? ", slow first" : ""),
                 120);
            if (::testing::Test::HasFailure()) return;
        }
    }
}

// The rest rule finds a cluster jammed against a static block and reverses the kinematic block
// pressing it, but no dynamic member changes velocity. Resolver::restCluster then reports
// Resolution::None (changedBefore is taken after the reversal), so the perfect method does not
// re-predict the reversed kinematic block, and it drives through the block riding on it
// (overlap 0.125 m after one step). Found by the soak (perfect, seed 3); shrunk to 5 blocks.
TEST_P(Jams, JammedKinematicReversalIsRepredicted) {
    World world;
    world.settings.method = GetParam();
    world.settings.gravity = {1000.0, 0.0};
    world.settings.bounciness = 0.0;
    world.settings.dt = 0.05;
    world.settings.substeps = 2;
    world.settings.eventCap = 500;
    addBlock(world, {5.4812894766346822, 7.9592225458407118},
             {0.61498642124070302, 1.1571748122405578}, {45.98012516829553, 36.704918565201972},
             1.0, BodyKind::Kinematic);
    addBlock(world, {4.9169163911457456, 7.5633930326019554},
             {0.51375974973717087, 1.1942465828545585}, {45.98012516829553, 55.059972862865969},
             212546589.66728634, BodyKind::Dynamic);
    addBlock(world, {8.2523990303977648, 8.8478992326369212},
             {1.3333333333333333, 1.3333333333333333}, {0.0, 0.0}, 5.9563929984093571,
             BodyKind::Dynamic);
    addBlock(world, {10.450383905879548, 8.8210368501368652},
             {0.3959697509635734, 0.99803270653552656}, {}, 1.0, BodyKind::Static);
    addBlock(world, {9.5857323637310969, 8.1834284413761065},
             {1.3333333333333333, 1.3333333333333333}, {0.0, 15.637642062353761},
             4310.9136536714668, BodyKind::Dynamic);
    expectValidStart(world, "jammed kinematic");
    soak(world, "jammed kinematic", 5);
}

// A 20 x 20 jam of 0.1 m blocks (touching, random velocities up to 20 m/s, masses 1 to 1000 kg) in
// a box with a little room around it. Move-and-correct and turn-based advance. The perfect method
// meets an event storm at the first instant (corner contacts of the lattice couple every row and
// column) and, as the event cap allows, ends each frame at the event cap with time held back:
// bounded work per frame, no overlap, and every such frame says so in eventCapHits (checked by
// soak()). Known limitation: it does not get past that instant (the shipped 36-block
// jammed_box.json does).
TEST_P(Jams, JammedBoxOf400BlocksAdvances) {
    for (const double C : {0.0, 1.0}) {
        World world;
        world.settings.method = GetParam();
        world.settings.gravity = {0.0, 0.0};
        world.settings.bounciness = C;
        world.bounds = Bounds{{0.0, 0.0}, {3.0, 4.0}};
        std::mt19937_64 rng(77);
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        for (int row = 0; row < 20; ++row) {
            for (int column = 0; column < 20; ++column) {
                const double vx = 20.0 * (2.0 * unit(rng) - 1.0); // drawn in this order
                const double vy = 20.0 * (2.0 * unit(rng) - 1.0);
                const double mass = std::pow(10.0, 3.0 * unit(rng));
                addBlock(world, {0.55 + column * 0.1, 0.05 + row * 0.1}, {0.1, 0.1}, {vx, vy}, mass,
                         BodyKind::Dynamic);
            }
        }
        const std::string label = "jam of 400, C " + std::to_string(C);
        expectValidStart(world, label);
        const bool perfect = GetParam() == Method::Perfect;
        const int frames = perfect ? 3 : 60;
        soak(world, label, frames, {}, 1LL << 40);
        if (::testing::Test::HasFailure()) return;
        if (!perfect) {
            EXPECT_GT(world.time, 0.5 * frames * world.settings.dt) << label << ": time froze";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Methods, Jams, test_worlds::everyMethod(), test_worlds::methodParamName);

} // namespace
