// The Physics section's logic (no GL): the keyboard thrust (key routing with thrust on and off,
// the force only while held, a = F/m on one frame), issue 16's settings under R, Shift+R, save
// and the timeline, and a lesson step that turns the thrust on.
#include "app.h"
#include "app_log.h"
#include "input_map.h"
#include "lesson_session.h"
#include "save_naming.h"
#include "scene_geometry.h"
#include "test_fixtures.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

// No gravity, no drag: a 4 kg and a 1 kg block at rest, far apart (nothing collides).
Scene twoShips() {
    return weightlessScene("ships", {testBlock("big", {4, 4}, {2, 1}, 4.0),
                                     testBlock("small", {4, 8}), staticBlock("post", {16, 6})});
}

App shipsApp() {
    App app;
    setScene(app, twoShips(), "ships.json");
    app.sim.paused = false;
    return app;
}

bool held(int key, const std::set<int>& down) {
    return down.count(key) > 0;
}

Vec2 direction(const std::set<int>& down) {
    return heldThrustDirection([&down](int key) { return held(key, down); });
}

} // namespace

TEST(ThrustKeys, ArrowsStepTheLessonWithThrustOffAndPushWithItOn) {
    // Thrust off: Right and Left step the lesson, Up and Down do nothing.
    EXPECT_EQ(actionForKey(keys::kRight, false, false, false), Action::LessonNext);
    EXPECT_EQ(actionForKey(keys::kLeft, false, false, false), Action::LessonPrevious);
    EXPECT_EQ(actionForKey(keys::kUp, false, false, false), Action::None);
    EXPECT_EQ(actionForKey(keys::kDown, false, false, false), Action::None);
    // Thrust on: the four arrows push, and PageDown / PageUp still step.
    EXPECT_EQ(actionForKey(keys::kRight, false, false, true), Action::ThrustRight);
    EXPECT_EQ(actionForKey(keys::kLeft, false, false, true), Action::ThrustLeft);
    EXPECT_EQ(actionForKey(keys::kUp, false, false, true), Action::ThrustUp);
    EXPECT_EQ(actionForKey(keys::kDown, false, false, true), Action::ThrustDown);
    EXPECT_EQ(actionForKey(keys::kPageDown, false, false, true), Action::LessonNext);
    EXPECT_EQ(actionForKey(keys::kPageUp, false, false, true), Action::LessonPrevious);
    // Every other key is the same either way (S cycles the method, D the trails: no WASD).
    for (const KeyBinding& b : keyBindings()) {
        if (b.when != KeyWhen::Always) continue;
        EXPECT_EQ(actionForKey(b.key, b.ctrl, b.shift, true), b.action) << b.keyName;
        EXPECT_EQ(actionForKey(b.key, b.ctrl, b.shift, false), b.action) << b.keyName;
    }
}

TEST(ThrustKeys, TheHelpTableSaysWhatTheArrowsDo) {
    bool thrustRow = false;
    for (const KeyBinding& b : keyBindings()) {
        if (!b.listed) continue;
        const std::string d = b.description;
        if (b.when == KeyWhen::ThrustOn) {
            thrustRow = true;
            EXPECT_EQ(std::string(b.keyName), "Arrow keys");
            EXPECT_NE(d.find("PageDown / PageUp"), std::string::npos) << d;
        }
        if (b.when == KeyWhen::ThrustOff) {
            EXPECT_NE(d.find("(thrust off)"), std::string::npos) << d;
        }
    }
    EXPECT_TRUE(thrustRow);
}

TEST(ThrustKeys, HeldArrowsGiveAUnitDirection) {
    EXPECT_EQ(direction({}), Vec2{});
    EXPECT_EQ(direction({keys::kRight}), (Vec2{1.0, 0.0}));
    EXPECT_EQ(direction({keys::kDown}), (Vec2{0.0, -1.0}));
    EXPECT_EQ(direction({keys::kLeft, keys::kRight}), Vec2{}); // opposite keys cancel
    EXPECT_EQ(direction({keys::kP, keys::kR}), Vec2{});        // other keys do not push
    const Vec2 diagonal = direction({keys::kRight, keys::kUp});
    EXPECT_NEAR(length(diagonal), 1.0, 1e-15); // the set force, not sqrt(2) of it
    EXPECT_EQ(diagonal.x, diagonal.y);
}

// The lecture's "Spaceship thruster": the same force, a = F/m, on one frame. Semi-implicit Euler
// adds a·dt to the velocity: exact up to the rounding of F/m·dt (one ulp of the result).
TEST(Thrust, TheSameForceAcceleratesTheHeavyBlockSlowlyAndTheLightOneFast) {
    App app = shipsApp();
    const double dt = app.sim.world().settings.dt;
    app.sim.thrust.on = true;
    app.sim.thrust.force = 2.0;
    app.sim.thrust.direction = {1.0, 0.0};
    app.sim.selected = 0; // big, 4 kg
    stepSimulation(app);
    EXPECT_NEAR(app.sim.world().blocks[0].velocity.x, 2.0 / 4.0 * dt, 1e-17); // 0.5 m/s^2
    EXPECT_EQ(app.sim.world().blocks[0].velocity.y, 0.0);
    EXPECT_EQ(app.sim.world().blocks[1].velocity, Vec2{}); // not selected: not pushed
    EXPECT_EQ(app.sim.world().blocks[0].force, Vec2{});    // the thrust is never the block's own
    app.sim.selected = 1;                                  // small, 1 kg
    const Vec2 bigBefore = app.sim.world().blocks[0].velocity;
    stepSimulation(app);
    EXPECT_NEAR(app.sim.world().blocks[1].velocity.x, 2.0 / 1.0 * dt, 1e-16); // 2 m/s^2: four times
    EXPECT_EQ(app.sim.world().blocks[0].velocity, bigBefore); // released: no force, the speed stays
}

TEST(Thrust, OnlyWhileHeldOnlyWhenOnAndOnlyOnADynamicBlock) {
    App app = shipsApp();
    app.sim.thrust.force = 5.0;
    app.sim.selected = 1;
    app.sim.thrust.direction = {0.0, 1.0}; // held, but thrust is off
    EXPECT_EQ(app.sim.thrustedBlock(), -1);
    stepSimulation(app);
    EXPECT_EQ(app.sim.world().blocks[1].velocity, Vec2{});
    app.sim.thrust.on = true;
    app.sim.thrust.direction = {}; // on, nothing held
    EXPECT_EQ(app.sim.thrustedBlock(), -1);
    stepSimulation(app);
    EXPECT_EQ(app.sim.world().blocks[1].velocity, Vec2{});
    app.sim.selected = 2; // the static post
    app.sim.thrust.direction = {1.0, 0.0};
    EXPECT_EQ(app.sim.thrustedBlock(), -1);
    EXPECT_EQ(app.sim.thrustForce(), Vec2{});
    app.sim.selected = -1;
    EXPECT_EQ(app.sim.thrustedBlock(), -1);
    app.sim.selected = 1;
    EXPECT_EQ(app.sim.thrustedBlock(), 1);
    EXPECT_EQ(app.sim.thrustForce(), (Vec2{5.0, 0.0}));
    EXPECT_EQ(app.sim.appliedForce(1), (Vec2{5.0, 0.0})); // what the force arrow shows
    EXPECT_EQ(app.sim.appliedForce(0), Vec2{});
}

TEST(Thrust, IsAddedToTheBlocksOwnForceWhileHeld) {
    App app = shipsApp();
    app.sim.world().blocks[0].force = {4.0, 0.0}; // its own thruster, 4 N
    app.sim.selected = 0;
    app.sim.thrust.on = true;
    app.sim.thrust.force = 8.0;
    app.sim.thrust.direction = {1.0, 0.0};
    EXPECT_EQ(app.sim.appliedForce(0), (Vec2{12.0, 0.0}));
    const double dt = app.sim.world().settings.dt;
    stepSimulation(app);
    EXPECT_NEAR(app.sim.world().blocks[0].velocity.x, 12.0 / 4.0 * dt, 1e-16);
    EXPECT_EQ(app.sim.world().blocks[0].force, (Vec2{4.0, 0.0})); // its own force is back
    app.sim.thrust.direction = {};
    const double v1 = app.sim.world().blocks[0].velocity.x;
    stepSimulation(app);
    EXPECT_NEAR(app.sim.world().blocks[0].velocity.x - v1, 4.0 / 4.0 * dt, 1e-16); // its own only
}

// The timeline rebuilds frames by stepping keyframes: the thrust frames (an input the world does
// not hold) and a drag or force changed between frames must come back bit for bit.
TEST(Thrust, TheTimelineReplaysThrustAndEditedSettingsBitForBit) {
    App app = shipsApp();
    app.sim.selected = 1;
    app.sim.thrust.on = true;
    app.sim.thrust.force = 3.0;
    std::vector<std::uint64_t> hashes{stateHash(app.sim.world())};
    for (int f = 0; f < 30; ++f) {
        app.sim.thrust.direction = (f % 10) < 4 ? Vec2{1.0, 0.0} : Vec2{}; // held 4 of each 10
        if (f == 13) app.sim.apply(Edit::setWorld("drag", 2.0));           // edits through the door
        if (f == 17) app.sim.apply(Edit::setWorld("resolve", "reflect"));
        if (f == 21) app.sim.apply(Edit::setBlock({0, ""}, "force", {0.0, 1.0}));
        if (f == 25) app.sim.apply(Edit::setWorld("integrator", "exact"));
        stepSimulation(app);
        hashes.push_back(stateHash(app.sim.world()));
    }
    for (std::uint64_t f = 0; f < hashes.size(); ++f) {
        World w;
        ASSERT_TRUE(app.sim.history.stateAt(f, w)) << f;
        EXPECT_EQ(stateHash(w), hashes[f]) << "frame " << f;
        for (const Block& b : w.blocks) EXPECT_NE(b.force, (Vec2{3.0, 0.0})) << f; // no thrust
    }
}

TEST(PhysicsSettings, RKeepsThemAndShiftRRestoresTheFiles) {
    Scene scene = twoShips();
    scene.settings.drag = 0.5;
    App app;
    setScene(app, scene, "ships.json");
    WorldSettings& s = app.sim.world().settings;
    s.resolve = Resolve::Reflect;
    s.integrator = Integrator::ExplicitEuler;
    s.set(Mistake::Discrete, true);
    s.set(Mistake::NoApproachTest, true);
    s.drag = 3.0;
    app.sim.thrust.on = true;
    app.sim.thrust.force = 7.0;
    app.sim.world().blocks[1].force = {1.0, 2.0}; // a block's force is the block's: R puts it back
    resetScene(app);                              // R
    EXPECT_EQ(app.sim.world().settings.resolve, Resolve::Reflect);
    EXPECT_EQ(app.sim.world().settings.integrator, Integrator::ExplicitEuler);
    EXPECT_TRUE(app.sim.world().settings.has(Mistake::Discrete));
    EXPECT_TRUE(app.sim.world().settings.has(Mistake::NoApproachTest));
    EXPECT_FALSE(app.sim.world().settings.has(Mistake::MoveBack));
    EXPECT_EQ(app.sim.world().settings.drag, 3.0);
    EXPECT_EQ(app.sim.world().blocks[1].force, Vec2{});
    EXPECT_TRUE(app.sim.thrust.on);
    resetToFile(app); // Shift+R
    EXPECT_EQ(app.sim.world().settings.resolve, Resolve::Momentum);
    EXPECT_EQ(app.sim.world().settings.integrator, Integrator::SemiImplicitEuler);
    EXPECT_EQ(app.sim.world().settings.mistakes, 0);
    EXPECT_EQ(app.sim.world().settings.drag, 0.5);
    EXPECT_TRUE(app.sim.thrust.on); // the app's, not the file's
    EXPECT_EQ(app.sim.thrust.force, 7.0);
}

TEST(PhysicsSettings, ChangesAreUnsavedAndTheSavedNoteNamesThem) {
    const WorldSettings original;
    WorldSettings now;
    EXPECT_FALSE(settingsDiffer(original, now));
    EXPECT_EQ(changedSettingsNote(original, now), "");
    now.resolve = Resolve::Reflect;
    EXPECT_TRUE(settingsDiffer(original, now));
    now = original;
    now.integrator = Integrator::Exact;
    EXPECT_TRUE(settingsDiffer(original, now));
    now = original;
    now.set(Mistake::FirstFound, true);
    EXPECT_TRUE(settingsDiffer(original, now));
    now = original;
    now.drag = 1.2;
    EXPECT_TRUE(settingsDiffer(original, now));
    now.resolve = Resolve::Reflect;
    now.integrator = Integrator::Exact;
    now.set(Mistake::Discrete, true);
    now.set(Mistake::MoveBack, true);
    EXPECT_EQ(changedSettingsNote(original, now),
              "Saved with changed settings: resolve reflect, integrator exact, mistakes discrete "
              "and move-back, drag 1.2 kg/m³.");
    App app;
    setScene(app, twoShips(), "ships.json");
    EXPECT_FALSE(app.sim.unsavedEdits());
    app.sim.world().settings.drag = 2.0;
    EXPECT_TRUE(app.sim.unsavedEdits()); // quitting asks
}

TEST(PhysicsSettings, CtrlSSavesThemAndTheBlocksForceButNeverTheHeldThrust) {
    namespace fs = std::filesystem;
    const fs::path file = fs::temp_directory_path() /
                          ("sandbox_physics_save_" + std::to_string(::getpid()) + ".json");
    App app = shipsApp();
    app.sim.world().settings.resolve = Resolve::Reflect;
    app.sim.world().settings.integrator = Integrator::Exact;
    app.sim.world().settings.set(Mistake::MoveBack, true);
    app.sim.world().settings.drag = 0.25;
    app.sim.world().blocks[0].force = {1.5, -0.5};
    app.sim.selected = 1;
    app.sim.thrust.on = true;
    app.sim.thrust.direction = {0.0, 1.0};
    stepSimulation(app); // a frame with the thrust held
    ASSERT_TRUE(saveCurrentScene(app, file.string())) << app.ui.messages.error;
    const SceneResult back = loadSceneFile(file.string());
    fs::remove(file);
    ASSERT_TRUE(back.scene) << back.error.text();
    EXPECT_EQ(back.scene->settings.resolve, Resolve::Reflect);
    EXPECT_EQ(back.scene->settings.integrator, Integrator::Exact);
    EXPECT_EQ(back.scene->settings.mistakes, app.sim.world().settings.mistakes);
    EXPECT_EQ(back.scene->settings.drag, 0.25);
    EXPECT_EQ(back.scene->blocks[0].force, (Vec2{1.5, -0.5}));
    EXPECT_EQ(back.scene->blocks[1].force, Vec2{});   // the thrust was held, not set
    EXPECT_GT(back.scene->blocks[1].velocity.y, 0.0); // ...and it did push
}

// The app with lecture3 open; returns the index of its platformer step (the steps' count when the
// lesson does not open or has none).
static std::size_t openPlatformerLesson(App& app) {
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    if (!openLesson(app, std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json")) return 0;
    const std::vector<LessonStep>& steps = app.lesson.lesson->steps;
    std::size_t platformer = steps.size();
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (steps[i].title.find("platformer") != std::string::npos) platformer = i;
    return platformer;
}

TEST(PhysicsSettings, TheLessonsPlatformerPlaysItsScriptAndTheArrowsDoNotStep) {
    App app;
    const std::size_t platformer = openPlatformerLesson(app);
    ASSERT_TRUE(app.lesson.lesson) << app.ui.messages.error;
    const std::vector<LessonStep>& steps = app.lesson.lesson->steps;
    ASSERT_LT(platformer + 1, steps.size());
    ASSERT_TRUE(enterStep(app, platformer));
    EXPECT_FALSE(app.sim.thrust.on); // the scene's player, not the thrust
    ASSERT_TRUE(app.sim.scene.player);
    EXPECT_FALSE(app.sim.script.empty()); // the step's "input" plays it
    ASSERT_GE(app.sim.selected, 0);
    EXPECT_EQ(app.sim.labels[static_cast<std::size_t>(app.sim.selected)].name, "player");
    EXPECT_EQ(std::filesystem::path(app.sim.scenePath).filename(), "platformer.json");
    // With a player the arrows are its keys (appFrame passes arrowsPush): Right does not step
    // the lesson; PageDown steps.
    const bool arrowsPush = app.sim.thrust.on || app.sim.scene.player.has_value();
    const Action right = actionForKey(keys::kRight, false, false, arrowsPush);
    EXPECT_FALSE(applyLessonAction(app, right));
    EXPECT_EQ(app.lesson.current, platformer);
    const Action pageDown = actionForKey(keys::kPageDown, false, false, arrowsPush);
    EXPECT_TRUE(applyLessonAction(app, pageDown)); // plays the step from its setup
    EXPECT_EQ(app.lesson.current, platformer);
    EXPECT_TRUE(applyLessonAction(app, pageDown)); // its moment: the script played in the app
    // The window's run ends where sandbox-cli lesson's does: the player on the shelf (its top
    // at 6 m), the coin on the floor.
    const World& w = app.sim.world();
    EXPECT_NEAR(w.blocks[0].position.y - w.blocks[0].halfSize().y, 6.0, 1e-9);
    EXPECT_NEAR(w.blocks[6].position.y, 0.25, 1e-9);
    EXPECT_TRUE(applyLessonAction(app, pageDown)); // the next step
    EXPECT_EQ(app.lesson.current, platformer + 1);
    EXPECT_TRUE(app.sim.script.empty()); // the next step has no script
}

// The force arrow shows the player's push while a key pushes it, as it shows the thrust: the
// platformer step's script holds Right from t = 0 (25 N), and the player's keys when no script.
TEST(ForceArrows, ShowThePlayersPushWhileAKeyPushesIt) {
    App app;
    const std::size_t platformer = openPlatformerLesson(app);
    ASSERT_TRUE(app.lesson.lesson) << app.ui.messages.error;
    ASSERT_LT(platformer, app.lesson.lesson->steps.size());
    ASSERT_TRUE(enterStep(app, platformer));
    ASSERT_TRUE(app.sim.scene.player);
    const int player = app.sim.scene.player->block;
    EXPECT_EQ(app.sim.pushedBlock(), player); // the script holds Right at t = 0
    EXPECT_EQ(app.sim.pushForce(), (Vec2{25.0, 0.0}));
    EXPECT_EQ(app.sim.appliedForce(player), (Vec2{25.0, 0.0}));
    app.sim.script.clear(); // the keys held by hand
    app.sim.playerKeys = {true, false, false};
    EXPECT_EQ(app.sim.pushForce(), (Vec2{-25.0, 0.0}));
    app.sim.playerKeys = {true, true, true}; // both: no push (a jump is no force)
    EXPECT_EQ(app.sim.pushedBlock(), -1);
    EXPECT_EQ(app.sim.appliedForce(player), Vec2{});
    app.sim.playerKeys = {};
    EXPECT_EQ(app.sim.pushedBlock(), -1);
    EXPECT_EQ(app.sim.pushForce(), Vec2{});
}

// What the scene renderer draws for forces: a block's own force with the arrows overlay, the
// held thrust on its block with or without it, nothing for a block with neither.
TEST(ForceArrows, OwnForceWithTheArrowsAndTheHeldThrustAlways) {
    World w;
    Block pushed;
    pushed.position = {4, 4};
    pushed.mass = 2.0;
    Block thruster = pushed;
    thruster.position = {12, 4};
    thruster.force = {2.0, 0.0};
    w.blocks = {pushed, thruster};
    Camera camera;
    camera.setViewport({0.0, 0.0, 1280.0, 720.0});
    camera.fit(w.bounds, 20.0);
    SceneView view;
    view.world = &w;
    view.camera = &camera;
    view.blockColors = {Color{}, Color{}};
    SceneGeometry g;
    g.build(view, 1.0); // arrows off, no thrust: no arrow at all
    EXPECT_EQ(shownForce(view, 1), Vec2{});
    EXPECT_TRUE(g.over.vertices().empty());
    view.thrustBlock = 0;
    view.thrust = {0.0, 10.0};
    g.build(view, 1.0); // the thrust alone: one force arrow (shaft and head: 3 triangles)
    EXPECT_EQ(shownForce(view, 0), (Vec2{0.0, 10.0}));
    EXPECT_EQ(shownForce(view, 1), Vec2{});
    EXPECT_EQ(g.over.vertices().size(), 9u);
    view.vectors = true;
    EXPECT_EQ(shownForce(view, 1), (Vec2{2.0, 0.0})); // its own force, with the arrows on
    view.thrustBlock = 1;
    view.thrust = {3.0, 0.0};
    EXPECT_EQ(shownForce(view, 1), (Vec2{5.0, 0.0})); // added while held
    EXPECT_EQ(shownForce(view, 0), Vec2{});
}

// --verbose logs the Physics settings and the held thrust (the window test reads these lines).
TEST(PhysicsLog, SettingsAndTheHeldThrust) {
    App app = shipsApp();
    const LoggedState before = snapshotForLog(app.sim, app.view, app.lesson);
    app.sim.verbose = true;
    testing::internal::CaptureStdout();
    app.sim.apply(Edit::setWorld("resolve", "reflect"));
    app.sim.apply(Edit::setWorld("drag", 1.5));
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "resolve: reflect\ndrag: 1.5\n");
    app.sim.thrust.on = true;
    app.sim.thrust.force = 20.0;
    app.sim.selected = 1;
    app.sim.thrust.direction = {-1.0, 0.0};
    const LoggedState held = snapshotForLog(app.sim, app.view, app.lesson);
    const std::vector<std::string> lines = describeChanges(before, held);
    for (const char* line : {"thrust: on", "thrust held: -20,0 N"})
        EXPECT_NE(std::find(lines.begin(), lines.end(), line), lines.end()) << line;
    app.sim.thrust.direction = {};
    EXPECT_EQ(describeChanges(held, snapshotForLog(app.sim, app.view, app.lesson)),
              std::vector<std::string>{"thrust released"});
}
