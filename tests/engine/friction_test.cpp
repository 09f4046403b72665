// Coulomb friction (engine/methods/friction.cpp): a block sliding on the floor stops
// where the analytic answer says, a pushed pair accelerates at (F - μ·(m1 + m2)·g)/(m1 + m2), a
// block on a platform that moves off slips for Δv/(μ·g) and then rides, and friction never makes
// energy. The analytic answers hold to 1e-9 under the exact integrator (the motion is a parabola
// between events, so only rounding separates them), within one frame's travel under the Euler
// integrators (friction then acts once per substep).
#include "scene.h"
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using test_worlds::addBlock;
using test_worlds::makeWorld;

constexpr double kG = 9.81;
const Vec2 kGravity{0.0, -kG};
// 1e-9: the answers below are sums of a few hundred parabola pieces of numbers near 1..40, each
// rounded at 1e-16 relative; a wrong deceleration or a stop one substep late is off by > 1e-4.
constexpr double kExact = 1e-9;

World slideWorld(Method method, Integrator integrator, double mu, double v0) {
    World world = makeWorld(method, kGravity, 0.0, Bounds{{0.0, 0.0}, {40.0, 12.0}});
    world.settings.integrator = integrator;
    world.settings.friction = mu;
    addBlock(world, {2.0, 0.5}, {1.0, 1.0}, {v0, 0.0}, 2.0);
    return world;
}

std::string label(Method method, Integrator integrator) {
    return std::string(methodName(method)) + " " + integratorName(integrator);
}

// With the exact integrator a block launched at v0 on the floor decelerates at μ·g: at time t
// before it stops v = v0 - μ·g·t and x = x0 + v0·t - μ·g·t²/2; it stops after v0/(μ·g) s,
// v0²/(2·μ·g) m on, and stays. The perfect and turn-based methods find the stop inside the
// substep (an event, a stop within the turn).
TEST(Friction, BlockSlidesToRestExactlyWithTheExactIntegrator) {
    const double mu = 0.5, v0 = 5.0, stopTime = v0 / (mu * kG);
    const double distance = v0 * v0 / (2.0 * mu * kG);
    for (Method method : {Method::Perfect, Method::TurnBased}) {
        World world = slideWorld(method, Integrator::Exact, mu, v0);
        const std::string what = label(method, Integrator::Exact);
        for (int f = 1; f <= 120; ++f) {
            world.step();
            const Block& b = world.blocks[0];
            const double t = world.time;
            ASSERT_NEAR(b.position.y, 0.5, kExact) << what << ", frame " << f;
            ASSERT_NEAR(b.velocity.y, 0.0, kExact) << what << ", frame " << f;
            if (t < stopTime) {
                ASSERT_NEAR(b.velocity.x, v0 - mu * kG * t, kExact) << what << ", frame " << f;
                ASSERT_NEAR(b.position.x, 2.0 + v0 * t - 0.5 * mu * kG * t * t, kExact)
                    << what << ", frame " << f;
            } else {
                ASSERT_EQ(b.velocity.x, 0.0) << what << ", frame " << f;
                ASSERT_NEAR(b.position.x, 2.0 + distance, kExact) << what << ", frame " << f;
            }
        }
    }
}

// With semi-implicit Euler friction takes μ·g·h off per substep and the block moves on with what
// is left: it stops within one frame of v0/(μ·g) and within one frame's travel (v0·dt) of
// v0²/(2·μ·g). Explicit Euler moves with the velocity from before the forces, so gravity first
// presses the block on the floor (and friction first acts) one substep later: within two frames.
// Every method.
TEST(Friction, BlockSlidesToRestWithinOneFrameWithEuler) {
    const double mu = 0.4, v0 = 6.0, stopTime = v0 / (mu * kG);
    const double distance = v0 * v0 / (2.0 * mu * kG);
    for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::ExplicitEuler})
        for (Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
            World world = slideWorld(method, integrator, mu, v0);
            const double frames = integrator == Integrator::ExplicitEuler ? 2.0 : 1.0;
            const double dt = world.settings.dt;
            const std::string what = label(method, integrator);
            double stoppedAt = -1.0;
            for (int f = 1; f <= 150; ++f) {
                world.step();
                if (stoppedAt < 0.0 && world.blocks[0].velocity.x == 0.0) stoppedAt = world.time;
                ASSERT_GE(world.blocks[0].velocity.x, 0.0) << what << ": never past zero";
            }
            ASSERT_GT(stoppedAt, 0.0) << what << ": it stops";
            EXPECT_NEAR(stoppedAt, stopTime, frames * dt + 1e-12) << what;
            EXPECT_NEAR(world.blocks[0].position.x, 2.0 + distance, frames * v0 * dt) << what;
            EXPECT_NEAR(world.blocks[0].position.y, 0.5, 1e-9) << what;
        }
}

// A block pushed by a constant force F into a crate, both on the floor: once F beats static
// friction, μ·(m1 + m2)·g, both move at a = (F - μ·(m1 + m2)·g)/(m1 + m2); below it neither
// moves. The perfect method (turn-based moves one block at a time, the other held still, so a
// pushed pair moves in turns).
TEST(Friction, PushingAcceleratesBothAtTheAnalyticRate) {
    const double mu = 0.5, m1 = 1.0, m2 = 3.0;
    for (Method method : {Method::Perfect}) {
        for (double force : {30.0, 15.0}) {
            World world = makeWorld(method, kGravity, 0.5, Bounds{{0.0, 0.0}, {60.0, 12.0}});
            world.settings.integrator = Integrator::Exact;
            world.settings.friction = mu;
            const int pusher = addBlock(world, {2.0, 0.5}, {1.0, 1.0}, {}, m1);
            const int crate = addBlock(world, {3.0, 0.5}, {1.0, 1.0}, {}, m2);
            world.blocks[pusher].force = {force, 0.0};
            const double a = std::max(0.0, (force - mu * (m1 + m2) * kG) / (m1 + m2));
            const std::string what =
                std::string(methodName(method)) + ", F = " + std::to_string(force);
            for (int f = 0; f < 30; ++f) world.step();
            const double t1 = world.time, v1 = world.blocks[crate].velocity.x;
            const double x1 = world.blocks[crate].position.x;
            for (int f = 0; f < 60; ++f) world.step();
            const double t2 = world.time;
            const Block &p = world.blocks[pusher], &c = world.blocks[crate];
            EXPECT_NEAR(c.velocity.x, v1 + a * (t2 - t1), kExact) << what;
            EXPECT_NEAR(p.velocity.x, c.velocity.x, kExact) << what << ": they move together";
            EXPECT_NEAR(c.position.x, x1 + v1 * (t2 - t1) + 0.5 * a * (t2 - t1) * (t2 - t1), kExact)
                << what;
            EXPECT_NEAR(c.position.x - p.position.x, 1.0, kExact) << what << ": touching";
            if (a == 0.0) {
                EXPECT_EQ(c.position.x, 3.0) << what << ": static friction holds";
            }
        }
    }
}

// A block at rest on a platform that moves off at vp: kinetic friction drags it at μ·g until it
// has the platform's velocity, after vp/(μ·g) s, and from then on it rides (static friction).
TEST(Friction, BlockOnAMovingPlatformSlipsThenRides) {
    const double mu = 0.5, vp = 2.0, slip = vp / (mu * kG);
    for (Method method : {Method::Perfect, Method::TurnBased}) {
        World world = makeWorld(method, kGravity, 0.0, Bounds{{0.0, 0.0}, {100.0, 12.0}});
        world.settings.integrator = Integrator::Exact;
        world.settings.friction = mu;
        addBlock(world, {20.0, 1.0}, {30.0, 1.0}, {vp, 0.0}, 1.0, BodyKind::Kinematic);
        const int block = addBlock(world, {10.0, 2.0}, {1.0, 1.0}, {}, 1.0);
        const std::string what = methodName(method);
        for (int f = 1; f <= 90; ++f) {
            world.step();
            const double t = world.time;
            const Block& b = world.blocks[block];
            const double ridden = t < slip ? 0.0 : t - slip, slipping = std::min(t, slip);
            ASSERT_NEAR(b.velocity.x, mu * kG * slipping, kExact) << what << ", frame " << f;
            ASSERT_NEAR(b.position.x, 10.0 + 0.5 * mu * kG * slipping * slipping + vp * ridden,
                        kExact)
                << what << ", frame " << f;
            ASSERT_NEAR(b.position.y, 2.0, kExact) << what << ", frame " << f;
        }
    }
}

// A block's own "friction" overrides the world's, and a pair mixes as sqrt(μ1·μ2) (Box2D): on
// a floor of world μ 0.64 a block of μ 0.25 decelerates at sqrt(0.64·0.25)·g = 0.4·g.
TEST(Friction, ABlocksOwnFrictionMixesWithTheWallsAsTheGeometricMean) {
    World world = slideWorld(Method::Perfect, Integrator::Exact, 0.64, 5.0);
    world.blocks[0].friction = 0.25;
    for (int f = 0; f < 30; ++f) world.step();
    EXPECT_NEAR(world.blocks[0].velocity.x, 5.0 - 0.4 * kG * world.time, kExact);
}

// The scene keys: the world's "friction" (a row of the settings table, which its own tests read
// and write like every row) and a block's own, which survives a file and reaches the engine;
// absent, the block has the world's (< 0); a bad value is refused at its JSON path.
TEST(Friction, ABlocksOwnFrictionIsASceneKey) {
    const std::string text = R"({"name": "t", "world": {"friction": 0.64},
        "blocks": [{"position": [2, 0.5], "size": 1, "velocity": [5, 0], "friction": 0.25},
                   {"position": [6, 0.5], "size": 1}]})";
    const SceneResult r = parseScene(text, "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    EXPECT_EQ(r.scene->settings.friction, 0.64);
    EXPECT_EQ(r.scene->blocks[0].friction, 0.25);
    EXPECT_LT(r.scene->blocks[1].friction, 0.0) << "absent: the world's";
    const std::string saved = sceneToJson(*r.scene);
    EXPECT_NE(saved.find("\"friction\": 0.25"), std::string::npos) << saved;
    const SceneResult back = parseScene(saved, "t.json");
    ASSERT_TRUE(back.scene) << back.error.text();
    EXPECT_TRUE(*back.scene == *r.scene);
    World world = makeWorld(*r.scene);
    EXPECT_EQ(world.blocks[0].friction, 0.25);
    EXPECT_EQ(sceneFromWorld(world, *r.scene).blocks[0].friction, 0.25);
    const SceneResult bad = parseScene(
        R"({"name": "t", "blocks": [{"position": [2, 0.5], "size": 1, "friction": -1}]})",
        "t.json");
    ASSERT_FALSE(bad.scene);
    EXPECT_NE(bad.error.text().find("blocks[0].friction"), std::string::npos) << bad.error.text();
}

// The mixing rule, written once (world.h) and read by the engine, the tradeoff's answer and the
// peers: a face's μ is its block's own or the world's; a contact's, sqrt(μ1·μ2); a peer that
// multiplies its shapes' values gets sqrt(μ) per face. Exact to rounding (1e-15 on numbers near 1).
TEST(Friction, TheMixingRule) {
    EXPECT_EQ(faceFriction(-1.0, 0.3), 0.3); // none of its own: the world's
    EXPECT_EQ(faceFriction(0.0, 0.3), 0.0);  // its own, even 0
    EXPECT_EQ(faceFriction(0.8, 0.3), 0.8);
    EXPECT_NEAR(mixedFriction(0.5, 0.5), 0.5, 1e-15);
    EXPECT_NEAR(mixedFriction(0.25, 1.0), 0.5, 1e-15);
    EXPECT_EQ(mixedFriction(0.0, 2.0), 0.0);
    EXPECT_NEAR(frictionFactor(0.25) * frictionFactor(1.0), mixedFriction(0.25, 1.0), 1e-15);
    // The engine's contact uses it: a block of μ 0.25 on a floor of the world's 1.0 slides at
    // mixedFriction(0.25, 1) = 0.5 (decelerates at 0.5·g, exact integrator).
    World world = slideWorld(Method::Perfect, Integrator::Exact, 1.0, 5.0);
    world.blocks[0].friction = 0.25;
    for (int f = 0; f < 30; ++f) world.step();
    EXPECT_NEAR(world.blocks[0].velocity.x, 5.0 - mixedFriction(0.25, 1.0) * kG * world.time,
                kExact);
}

double totalEnergy(const World& world) {
    return kineticEnergy(world) + potentialEnergy(world);
}

// Friction never makes energy: in piles (a gas falling under gravity), stacks and gases (no
// gravity) with C <= 1 and μ > 0, under every method and both the semi-implicit Euler and the
// exact integrator, with several seeds, KE + PE never rises above the start's. (Not from frame to
// frame: without friction a frame's energy already rises a little at times, by the integrator
// (semi-implicit Euler's kick before a bounce just above the floor adds m·|v|·g·h of kinetic
// energy that the short fall does not take back) and by move-and-correct's pushes.) 1e-9 of the
// energy: sums of a hundred rounded terms; a real gain (friction pushed past zero, a load counted
// twice, a block held in the air while gravity adds to its speed) is orders of magnitude larger.
TEST(Friction, NeverMakesEnergy) {
    struct Case {
        const char* name;
        Vec2 gravity;
        double bounciness;
    };
    const Case cases[] = {
        {"pile", kGravity, 0.5}, {"gas", {0.0, 0.0}, 1.0}, {"stack", kGravity, 0.0}};
    for (const Case& c : cases)
        for (Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased})
            for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::Exact})
                for (std::uint64_t seed : {1u, 2u, 3u}) {
                    World world;
                    if (std::string(c.name) == "stack") {
                        world = makeWorld(method, c.gravity, c.bounciness);
                        std::mt19937_64 rng(seed);
                        std::uniform_real_distribution<double> speed(-3.0, 3.0);
                        for (int column = 0; column < 6; ++column)
                            for (int level = 0; level < 4; ++level)
                                addBlock(world, {2.0 + 3.0 * column, 0.5 + level}, {1.0, 1.0},
                                         {speed(rng), 0.0}, 1.0 + level);
                    } else {
                        world = test_worlds::gasInBox(method, c.gravity, c.bounciness, seed, 100);
                    }
                    world.settings.integrator = integrator;
                    world.settings.friction = 0.3 + 0.2 * static_cast<double>(seed);
                    const std::string what = std::string(c.name) + " " + label(method, integrator) +
                                             " seed " + std::to_string(seed);
                    const double start = totalEnergy(world);
                    const double scale = kineticEnergy(world) + std::abs(potentialEnergy(world));
                    for (int f = 0; f < 300; ++f) {
                        world.step();
                        ASSERT_LE(totalEnergy(world), start + 1e-9 * scale)
                            << what << ", frame " << f;
                    }
                }
}

// ---- Friction 0 ----
//
// Friction 0, or no "friction" key at all, changes nothing: every shipped scene under each method
// and integrator ends 120 frames in the state it reached before friction existed (the state hashes
// in tests/data/frictionless_hashes.txt, recorded with the engine of main 1621575, before
// friction). A scene edited since (its bytes' hash differs from the recorded one) is left out, and
// said so; the test fails if more than a few are. To record the table again (after a deliberate
// change of the physics without friction):  SANDBOX_RECORD_HASHES=1 build/tests/engine_tests
//   --gtest_filter='Frictionless.*'  writes it.
const std::string kTable = std::string(SANDBOX_TEST_DATA_DIR) + "/frictionless_hashes.txt";

std::uint64_t bytesHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::uint64_t hash = 1469598103934665603ull; // FNV-1a
    for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
    return hash;
}

std::uint64_t hashAfter(World world, int frames) {
    for (int f = 0; f < frames; ++f) world.step();
    return stateHash(world);
}

// "scene method integrator" -> (file hash, state hash) as text.
std::map<std::string, std::string> readTable() {
    std::map<std::string, std::string> rows;
    std::ifstream in(kTable);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string scene, method, integrator, file, state;
        if (fields >> scene >> method >> integrator >> file >> state)
            rows[scene + " " + method + " " + integrator] = file + " " + state;
    }
    return rows;
}

TEST(Frictionless, EveryShippedSceneKeepsItsStateHashWithFrictionZeroOrAbsent) {
    const bool record = std::getenv("SANDBOX_RECORD_HASHES") != nullptr;
    const std::map<std::string, std::string> table = readTable();
    std::ostringstream recorded;
    int compared = 0, edited = 0;
    std::vector<std::filesystem::path> scenes;
    for (const auto& entry : std::filesystem::directory_iterator(SANDBOX_SCENES_DIR))
        if (entry.path().extension() == ".json") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    for (const auto& path : scenes) {
        const SceneResult loaded = loadSceneFile(path.string());
        ASSERT_TRUE(loaded.scene) << path;
        const std::string name = path.stem().string();
        const std::string file = std::to_string(bytesHash(path.string()));
        for (int m = 0; m < static_cast<int>(Method::Count); ++m)
            for (int k = 0; k < static_cast<int>(Integrator::Count); ++k) {
                World absent = makeWorld(*loaded.scene);
                absent.settings.method = static_cast<Method>(m);
                absent.settings.integrator = static_cast<Integrator>(k);
                absent.settings.friction = 0.0;
                for (Block& b : absent.blocks) b.friction = -1.0; // the world's: 0
                World zero = absent;
                for (Block& b : zero.blocks) b.friction = 0.0; // every block's own 0
                const std::string key = name + " " + methodName(static_cast<Method>(m)) + " " +
                                        integratorName(static_cast<Integrator>(k));
                const std::uint64_t hash = hashAfter(absent, 120);
                EXPECT_EQ(hashAfter(zero, 120), hash) << key << ": friction 0 as absent";
                recorded << key << " " << file << " " << hash << "\n";
                const auto row = table.find(key);
                if (row == table.end() || row->second.substr(0, row->second.find(' ')) != file) {
                    ++edited;
                    continue;
                }
                ++compared;
                EXPECT_EQ(row->second, file + " " + std::to_string(hash)) << key;
            }
    }
    if (record) {
        std::ofstream(kTable) << recorded.str();
        GTEST_SKIP() << "recorded " << kTable;
    }
    if (edited > 0)
        std::cout << edited << " scene x method x integrator cases left out: the scene was added "
                  << "or edited after the table was recorded\n";
    EXPECT_GE(compared, 20 * 9) << "most shipped scenes are in the table";
}

} // namespace
