// Kinetic plus potential energy in random piles (docs/physics.md, "Energy in piles"): contacts
// and friction only ever take energy away. N blocks of 0.9 m and 1 kg in a 16 m x 12 m box, in
// rows of 12 at x = 1 + 1.2·i, y = 1 + 1.3·j, each with a velocity drawn uniformly in ±3 m/s
// (vx, then vy) from Python's random.Random(seed), gravity -9.81 m/s², dt 1/60: the piles that
// tools/energy_piles.py writes and measures. Every frame is checked; no clock is read.
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

// Python's random.Random(seed) for a seed below 2^32: Mersenne Twister seeded by init_by_array
// with the one word `seed` (CPython's random_seed), and random() = (a·2^26 + b) / 2^53 from two
// words (a >> 5, b >> 6). The standard engine draws the words once its state is loaded.
class PythonRandom {
  public:
    explicit PythonRandom(std::uint32_t seed) {
        constexpr std::uint32_t n = 624;
        std::vector<std::uint32_t> s(n);
        s[0] = 19650218u;
        for (std::uint32_t i = 1; i < n; ++i)
            s[i] = 1812433253u * (s[i - 1] ^ (s[i - 1] >> 30)) + i;
        std::uint32_t i = 1;
        for (std::uint32_t k = n; k > 0; --k) { // the key is one word: j is always 0
            s[i] = (s[i] ^ ((s[i - 1] ^ (s[i - 1] >> 30)) * 1664525u)) + seed;
            if (++i >= n) s[0] = s[n - 1], i = 1;
        }
        for (std::uint32_t k = n - 1; k > 0; --k) {
            s[i] = (s[i] ^ ((s[i - 1] ^ (s[i - 1] >> 30)) * 1566083941u)) - i;
            if (++i >= n) s[0] = s[n - 1], i = 1;
        }
        s[0] = 0x80000000u;
        std::stringstream state;
        for (std::uint32_t word : s) state << word << ' ';
        state >> mt_;
    }
    double random() {
        const double a = mt_() >> 5, b = mt_() >> 6;
        return (a * 67108864.0 + b) / 9007199254740992.0;
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * random(); }

  private:
    std::mt19937 mt_;
};

struct Pile {
    std::uint32_t seed;
    int count;         // blocks
    double bounciness; // C
    double friction;   // μ
    int frames;
};

std::string label(const Pile& p) {
    std::ostringstream s;
    s << p.count << " blocks, seed " << p.seed << ", C = " << p.bounciness
      << ", mu = " << p.friction;
    return s.str();
}
void PrintTo(const Pile& p, std::ostream* out) {
    *out << label(p) << ", " << p.frames << " frames";
}

World makePile(const Pile& p, Method method, Integrator integrator) {
    World world = test_worlds::makeWorld(method, {0.0, -9.81}, p.bounciness,
                                         Bounds{{0.0, 0.0}, {16.0, 12.0}});
    world.settings.integrator = integrator;
    world.settings.friction = p.friction;
    PythonRandom random(p.seed);
    for (int k = 0; k < p.count; ++k) {
        const double vx = random.uniform(-3.0, 3.0);
        const double vy = random.uniform(-3.0, 3.0);
        test_worlds::addBlock(world, {1.0 + 1.2 * (k % 12), 1.0 + 1.3 * (k / 12)}, {0.9, 0.9},
                              {vx, vy});
    }
    return world;
}

double energyOf(const World& world) {
    return kineticEnergy(world) + potentialEnergy(world);
}
double energyOf(const StepStats& s) {
    return s.kineticEnergy + s.potentialEnergy;
}

// The piles, then more seeds, sizes, C from 0 to 1 and μ from 0 to 2. The extra ones run
// 300 frames (5 s: the landing, the pile and its settling); C = 0.9 on many blocks is left to the
// smaller piles, whose stacks chatter through thousands of real bounces a frame under the exact
// integrator (tools/energy_piles.py measures any pile: docs/physics.md).
const std::vector<Pile>& piles() {
    static const std::vector<Pile> all = [] {
        std::vector<Pile> p = {
            {1, 60, 0.6, 0.0, 600}, {1, 60, 0.6, 0.4, 600}, {7, 60, 0.9, 0.0, 600},
            {1, 60, 1.0, 0.0, 600}, {3, 60, 0.6, 0.4, 600},
        };
        const int counts[] = {12, 24, 40, 60, 96};
        const double bounciness[] = {0.0, 0.3, 0.5, 0.75, 0.9, 1.0};
        const double friction[] = {0.0, 0.2, 0.5, 1.0, 2.0, 0.1, 0.8};
        for (std::uint32_t seed = 2; seed <= 25; ++seed) {
            const int count = counts[seed % 5];
            double C = bounciness[seed % 6];
            if (count >= 60 && C == 0.9) C = 0.75;
            p.push_back({seed, count, C, friction[seed % 7], 300});
        }
        return p;
    }();
    return all;
}

class PileEnergy : public ::testing::TestWithParam<Pile> {};

INSTANTIATE_TEST_SUITE_P(Piles, PileEnergy, ::testing::ValuesIn(piles()),
                         [](const ::testing::TestParamInfo<Pile>& info) {
                             return "seed" + std::to_string(info.param.seed) + "_n" +
                                    std::to_string(info.param.count) + "_case" +
                                    std::to_string(info.index);
                         });

// The perfect method with the exact integrator is exact under gravity between events, so only
// contacts could change the energy, and they may only take it away: no frame gains more than
// 1e-9 of the total. The tolerance is rounding: positions and velocities of a few hundred
// parabola pieces a frame, each rounded at 1e-16 relative, measured at most 2.7e-12 J on 5500 J
// (5e-16); the gains this test was written against were 2e-6 to 1e-2 J on 2300 J (1e-9 to 4e-6).
TEST_P(PileEnergy, PerfectWithTheExactIntegratorNeverGainsInAFrame) {
    const Pile& p = GetParam();
    World world = makePile(p, Method::Perfect, Integrator::Exact);
    const double start = energyOf(world);
    const double tolerance = 1e-9 * std::abs(start);
    double before = start;
    for (int f = 1; f <= p.frames; ++f) {
        const double after = energyOf(world.step());
        ASSERT_LE(after - before, tolerance) << label(p) << ", frame " << f;
        before = after;
    }
    if (p.bounciness == 1.0 && p.friction == 0.0) { // nothing takes energy: it is kept
        EXPECT_NEAR(before, start, tolerance) << label(p);
    }
}

// With semi-implicit Euler energy may rise in a frame by the integrator's own error: a block whose
// velocity along gravity an infinite mass changes by Δv at time t within the substep (a bounce
// off the floor, a wall or a static block; the rest rule stopping it on the floor) had been given
// the substep's whole g·h before, and moves on for h - t as if it had fallen with it: m·g·Δv·(h -
// t) (docs/physics.md, "Energy in piles"). Between two blocks of finite mass the changes cancel
// (momentum is kept). Friction must add no rising frame of its own: every frame of the pile with
// friction is stepped again from the same state without it, and may rise more than that twin only
// by the integrator's error at its own bounces off infinite masses (friction changes which
// contacts a chain of collisions reaches within the frame, and so which bounces it has).
double integratorAllowance(const World& world, const std::vector<CollisionRecord>& log) {
    const double h = world.settings.dt / world.settings.substeps;
    const Vec2 g = world.settings.gravity;
    double allowance = 0.0;
    for (const CollisionRecord& r : log) {
        const bool infinite = r.other < 0 || std::isinf(r.m2);
        if (r.rule != ResolveRule::Formula || !infinite || g[r.axis] == 0.0) continue;
        allowance += r.m1 * std::abs(g[r.axis] * (r.v1After - r.v1)) * (1.0 - r.toi) * h;
    }
    return allowance;
}

TEST_P(PileEnergy, FrictionAddsNoRisingFrameWithSemiImplicitEuler) {
    Pile p = GetParam();
    if (p.friction == 0.0) p.friction = 0.5; // every pile, with friction
    World world = makePile(p, Method::Perfect, Integrator::SemiImplicitEuler);
    const double tolerance = 1e-9 * std::abs(energyOf(world));
    std::vector<CollisionRecord> log;
    for (int f = 1; f <= p.frames; ++f) {
        World bare = world;
        bare.settings.friction = 0.0;
        const double before = energyOf(world);
        const double bareRise = energyOf(bare.step()) - before;
        log.clear();
        const double rise = energyOf(world.step(&log)) - before;
        const double allowed = std::max(bareRise, 0.0) + integratorAllowance(world, log);
        ASSERT_LE(rise, allowed + tolerance)
            << label(p) << ", frame " << f << ": without friction " << bareRise;
    }
}

// Turn-based and move-and-correct are not exact, but with C < 1 neither may end a run with more
// energy than it started with (a method that makes energy runs away in the end), with either
// integrator that keeps energy in free flight. The piles' own C and μ; move-and-correct also at
// C = 0.99, where its corrections made energy under the exact integrator. Turn-based with
// semi-implicit Euler still gains at C = 1 and near it (0.95 and 0.99 ended up to 14% above the
// start): a known failure of the method, measured in docs/physics.md, "Energy in piles".
TEST_P(PileEnergy, TurnBasedAndMoveAndCorrectNeverEndAboveTheirStart) {
    const Pile& p = GetParam();
    if (p.bounciness >= 1.0) GTEST_SKIP() << "C = 1";
    struct Run {
        Method method;
        double bounciness;
    };
    const Run runs[] = {{Method::TurnBased, p.bounciness},
                        {Method::MoveAndCorrect, p.bounciness},
                        {Method::MoveAndCorrect, 0.99}};
    for (const Run& run : runs)
        for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::Exact}) {
            Pile pile = p;
            pile.bounciness = run.bounciness;
            World world = makePile(pile, run.method, integrator);
            const double start = energyOf(world);
            for (int f = 0; f < p.frames; ++f) world.step();
            EXPECT_LE(energyOf(world), start) << label(pile) << ", " << methodName(run.method)
                                              << ", " << integratorName(integrator);
        }
}

} // namespace
