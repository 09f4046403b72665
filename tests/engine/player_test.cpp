// The scene's player (engine/step/player.h): up makes it jump only when it stands on something, never
// in mid-air; the jump rises jump²/(2·|g|) and left/right push it with a force, both exactly
// (to 1e-9) under the exact integrator; the scene key "player" reads, saves and rejects bad
// values with their JSON path.
#include "player.h"
#include "scene.h"
#include "world.h"

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using test_worlds::addBlock;
using test_worlds::makeWorld;

// 1e-9: the answers are a parabola sampled at a few dozen frames of numbers near 1..10, each
// rounded at 1e-16 relative; a jump that lost or gained one frame of gravity (g·dt = 0.5 m/s) is
// off by more than 1e-2.
constexpr double kExact = 1e-9;
constexpr double kG = 10.0;

const Method kMethods[] = {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased};

// A 1 kg player of 1 m resting on the floor of a 20 x 12 m world, with a block of 2 m to stand
// on at x = 10 m.
World playerWorld(Method method, Integrator integrator) {
    World world = makeWorld(method, {0.0, -kG}, 0.0);
    world.settings.integrator = integrator;
    world.settings.dt = 1.0 / 20.0;
    addBlock(world, {3.0, 0.5}, {1.0, 1.0});
    addBlock(world, {10.0, 1.0}, {2.0, 2.0}, {}, 1.0, BodyKind::Static);
    return world;
}

TEST(Player, StandsOnTheFloorOrABlockNotInMidAir) {
    World world = playerWorld(Method::Perfect, Integrator::Exact);
    EXPECT_EQ(standsOn(world, 0), kFloorBelow);
    world.blocks[0].position = {10.0, 2.5}; // on the block
    EXPECT_EQ(standsOn(world, 0), 1);
    world.blocks[0].position = {10.0, 2.6}; // 0.1 m above it
    EXPECT_EQ(standsOn(world, 0), kNothingBelow);
    world.blocks[0].position = {11.5, 2.5}; // beside its top face, touching only at a corner
    EXPECT_EQ(standsOn(world, 0), kNothingBelow);
}

// Up held in every frame of a fall from 3 m: no frame in mid-air changes the velocity the fall
// gives it; the first frame after it lands jumps.
TEST(Player, UpDoesNothingInMidAir) {
    const PlayerDef player{0, 10.0, 5.0};
    for (Method method : kMethods)
        for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::Exact}) {
            World world = playerWorld(method, integrator);
            world.blocks[0].position.y = 3.5;
            int midAir = 0;
            bool jumped = false;
            for (int frame = 0; frame < 40 && !jumped; ++frame) {
                const bool inAir = standsOn(world, 0) == kNothingBelow;
                const double before = world.blocks[0].velocity.y;
                applyPlayerKeys(world, player, {false, false, true});
                if (inAir) {
                    ++midAir;
                    EXPECT_EQ(world.blocks[0].velocity.y, before) << "frame " << frame;
                } else {
                    EXPECT_EQ(world.blocks[0].velocity.y, 5.0) << "frame " << frame;
                    jumped = true;
                }
                world.step();
            }
            EXPECT_GT(midAir, 10) << methodName(method); // sqrt(2·2.5/10) s = 14 frames falling
            EXPECT_TRUE(jumped) << methodName(method) << " " << integratorName(integrator);
        }
}

// Jumping at 5 m/s under g = 10 m/s^2 from the floor: y = y0 + v·t - g·t²/2 at every frame, the
// top jump²/(2·g) = 1.25 m higher after exactly v/g = 0.5 s (10 frames of 1/20 s).
TEST(Player, JumpHeightIsJumpSquaredOverTwoGWithTheExactIntegrator) {
    const double jump = 5.0;
    const PlayerDef player{0, 10.0, jump};
    for (Method method : kMethods) {
        World world = playerWorld(method, Integrator::Exact);
        const double y0 = world.blocks[0].position.y;
        stepWithPlayer(world, player, {false, false, true});
        for (int frame = 2; frame <= 10; ++frame) stepWithPlayer(world, player, {});
        const double t = world.time;
        EXPECT_NEAR(t, 0.5, 1e-12);
        EXPECT_NEAR(world.blocks[0].position.y, y0 + jump * t - 0.5 * kG * t * t, kExact)
            << methodName(method);
        EXPECT_NEAR(world.blocks[0].position.y - y0, jump * jump / (2.0 * kG), kExact)
            << methodName(method);
        EXPECT_NEAR(world.blocks[0].velocity.y, 0.0, kExact) << methodName(method);
        // Up held at the top, 1.25 m in the air: nothing.
        stepWithPlayer(world, player, {false, false, true});
        EXPECT_LT(world.blocks[0].velocity.y, 0.0) << methodName(method);
    }
}

// Right held for 1 s on a frictionless floor: the push F = 10 N on 1 kg moves it F/(2m)·t² = 5 m,
// and is not kept by the block (its own force stays 0).
TEST(Player, RightPushesWithItsForceForTheFramesHeld) {
    const PlayerDef player{0, 10.0, 5.0};
    for (Method method : kMethods) {
        World world = playerWorld(method, Integrator::Exact);
        world.blocks[1].position.x = 18.0; // the block out of the way
        const double x0 = world.blocks[0].position.x;
        for (int frame = 0; frame < 20; ++frame)
            stepWithPlayer(world, player, {false, true, false});
        EXPECT_NEAR(world.blocks[0].position.x - x0, 5.0, kExact) << methodName(method);
        EXPECT_NEAR(world.blocks[0].velocity.x, 10.0, kExact) << methodName(method);
        EXPECT_EQ(world.blocks[0].force, Vec2{});
        stepWithPlayer(world, player, {true, true, false}); // both: no push
        EXPECT_NEAR(world.blocks[0].velocity.x, 10.0, kExact) << methodName(method);
    }
}

// On a lift rising at 1.5 m/s the jump is relative to it: 1.5 + 5 m/s upward.
TEST(Player, JumpsRelativeToTheLiftItStandsOn) {
    World world = makeWorld(Method::TurnBased, {0.0, -kG}, 0.0);
    addBlock(world, {3.0, 1.0}, {2.0, 0.5}, {0.0, 1.5}, 1.0, BodyKind::Kinematic);
    addBlock(world, {3.0, 1.75}, {1.0, 1.0}, {0.0, 1.5});
    applyPlayerKeys(world, PlayerDef{1, 10.0, 5.0}, {false, false, true});
    EXPECT_EQ(world.blocks[1].velocity.y, 6.5);
}

std::string playerScene(const std::string& player) {
    return R"({"name": "p", "blocks": [
        {"name": "hero", "position": [2, 0.5], "size": 1, "mass": 1},
        {"name": "wall", "position": [8, 0.5], "size": 1, "mass": "static"}],
      "player": )" +
           player + "}";
}

TEST(Player, SceneKeyReadsAndRoundTrips) {
    const SceneResult r =
        parseScene(playerScene(R"({"block": "hero", "force": 20, "jump": 6})"), "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    ASSERT_TRUE(r.scene->player);
    EXPECT_EQ(*r.scene->player, (PlayerDef{0, 20.0, 6.0}));
    const SceneResult again = parseScene(sceneToJson(*r.scene), "saved.json");
    ASSERT_TRUE(again.scene) << again.error.text();
    EXPECT_EQ(*again.scene, *r.scene);
    EXPECT_EQ(sceneFromWorld(makeWorld(*r.scene), *r.scene), *r.scene);
}

TEST(Player, BadSceneKeysNameTheirPlace) {
    const struct {
        const char* player;
        const char* where;
        const char* says;
    } cases[] = {
        {R"({"block": "nobody", "force": 20, "jump": 6})", "t.json: player.block", "no block"},
        {R"({"block": "wall", "force": 20, "jump": 6})", "t.json: player.block", "dynamic"},
        {R"({"block": "hero", "jump": 6})", "t.json: player", "missing \"force\""},
        {R"({"block": "hero", "force": -1, "jump": 6})", "t.json: player.force", "must be"},
        {R"({"block": "hero", "force": 20, "jump": 1e9})", "t.json: player.jump", "must be"},
        {R"({"block": "hero", "force": 20, "jump": 6, "fly": 1})", "t.json: player.fly", "unknown"},
        {R"("hero")", "t.json: player", "object"},
    };
    for (const auto& c : cases) {
        const SceneResult r = parseScene(playerScene(c.player), "t.json");
        ASSERT_FALSE(r.scene) << c.player;
        EXPECT_EQ(r.error.where.rfind(c.where, 0), 0u) << c.player << " -> " << r.error.text();
        EXPECT_NE(r.error.message.find(c.says), std::string::npos) << r.error.text();
    }
}

} // namespace
