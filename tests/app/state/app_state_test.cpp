// App state without GL: load, reset, save, the fixed-step clock, settings and options.
#include "app.h"
#include "app_config.h"
#include "app_log.h"
#include "app_setup.h"
#include "edit_words.h"
#include "fixed_step.h"
#include "options.h"
#include "scene_library.h"
#include "test_fixtures.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("sandbox_app_test_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

Scene twoBlocks() {
    BlockDef a = testBlock("A", {4, 6});
    a.velocity = {6, 0};
    a.color = "#d04040";
    return weightlessScene("two", {a, testBlock("B", {12, 6}, {1, 1}, 2.0)});
}

TEST(FixedStepClock, RunsOneTickPerDtWhateverTheDisplayRate) {
    FixedStepClock clock;
    const double dt = 1.0 / 60.0;
    int ticks = 0;
    for (int i = 0; i < 144; ++i) ticks += clock.advance(1.0 / 144.0, dt, 1.0); // 144 Hz
    EXPECT_NEAR(ticks, 60, 1);
    ticks = 0;
    for (int i = 0; i < 30; ++i) ticks += clock.advance(1.0 / 30.0, dt, 1.0); // 30 Hz
    EXPECT_NEAR(ticks, 60, 1);
}

TEST(FixedStepClock, TimeScaleAndSlowMotion) {
    FixedStepClock clock;
    const double dt = 1.0 / 60.0;
    int ticks = 0;
    for (int i = 0; i < 60; ++i) ticks += clock.advance(1.0 / 60.0, dt, 0.5);
    EXPECT_NEAR(ticks, 30, 1);
    clock.reset();
    ticks = 0;
    for (int i = 0; i < 120; ++i) {
        ticks += clock.advance(1.0 / 60.0, dt, simulationRate(1.0, true, dt));
    }
    EXPECT_NEAR(ticks, 10, 1); // 5 frames per second for 2 s
}

TEST(FixedStepClock, CapsTicksPerFrameAndDropsTheBacklog) {
    FixedStepClock clock;
    EXPECT_EQ(clock.advance(0.25, 1.0 / 240.0, 1.0), clock.maxTicksPerFrame);
    EXPECT_LT(clock.accumulator, 1.0 / 240.0);
    EXPECT_EQ(clock.advance(-1.0, 0.01, 1.0), 0);
    EXPECT_EQ(clock.advance(0.1, 0.0, 1.0), 0);
}

TEST(AppState, AdvanceRunsFramesUnlessPaused) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    EXPECT_TRUE(app.sim.paused); // scenes open paused at t = 0
    EXPECT_EQ(advanceSimulation(app, 0.05), 0);
    app.sim.paused = false;
    EXPECT_EQ(advanceSimulation(app, 0.05), 3);
    EXPECT_EQ(app.sim.world().frame, 3u);
    app.sim.paused = true;
    EXPECT_EQ(advanceSimulation(app, 0.5), 0);
    EXPECT_EQ(app.sim.world().frame, 3u);
}

// A scene with a "duration" pauses once when a frame reaches it (within half a frame: 180 frames
// of 1/60 s end within rounding of 3 s); P then plays on past it.
TEST(AppState, PausesOnceAtTheScenesDuration) {
    App app;
    Scene scene = twoBlocks();
    scene.duration = 0.5; // 30 frames
    setScene(app, scene, "two.json");
    app.sim.paused = false;
    for (int i = 0; i < 40 && !app.sim.paused; ++i) stepSimulation(app);
    EXPECT_TRUE(app.sim.paused);
    EXPECT_EQ(app.sim.world().frame, 30u);
    // The session's notice, which the frame shows as the panel's note.
    EXPECT_NE(app.sim.notice.find("P plays on"), std::string::npos) << app.sim.notice;
    takeNotice(app);
    EXPECT_NE(app.ui.messages.note.find("P plays on"), std::string::npos) << app.ui.messages.note;
    EXPECT_TRUE(app.sim.notice.empty());
    app.sim.paused = false;
    for (int i = 0; i < 30; ++i) stepSimulation(app);
    EXPECT_FALSE(app.sim.paused);
    EXPECT_EQ(app.sim.world().frame, 60u);
    // Edges: a frame ending less than half a frame before the duration reaches it; one ending more
    // than half a frame before does not.
    const double dt = 1.0 / 60.0;
    EXPECT_TRUE(reachesSceneEnd(scene, 0.5 - 1.4 * dt, 0.5 - 0.4 * dt, dt));
    EXPECT_FALSE(reachesSceneEnd(scene, 0.5 - 1.6 * dt, 0.5 - 0.6 * dt, dt));
    EXPECT_FALSE(reachesSceneEnd(twoBlocks(), 0.0, 1e9, dt)); // no duration: runs on
}

TEST(AppState, ResetPutsTheBlocksBackAndKeepsTheChosenSettings) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    app.sim.world().settings.method = Method::TurnBased; // S
    app.sim.world().settings.bounciness = 0.5;           // C
    app.sim.world().settings.gravity = Vec2{0, -9.81};   // g
    app.sim.world().settings.dt = 1.0 / 120.0;           // frame rate
    app.sim.world().settings.substeps = 4;
    for (int i = 0; i < 10; ++i) stepSimulation(app);
    app.sim.world().blocks[1].mass = 7.0; // an edit of a block: R undoes it
    app.sim.selected = 1;
    resetScene(app); // R
    EXPECT_EQ(app.sim.world().frame, 0u);
    EXPECT_EQ(app.sim.world().time, 0.0);
    EXPECT_EQ(app.sim.world().blocks[0].position, (Vec2{4, 6}));
    EXPECT_EQ(app.sim.world().blocks[1].mass, 2.0);
    EXPECT_EQ(app.sim.world().settings.method, Method::TurnBased);
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.5);
    EXPECT_EQ(app.sim.world().settings.gravity, (Vec2{0, -9.81}));
    EXPECT_EQ(app.sim.world().settings.dt, 1.0 / 120.0);
    EXPECT_EQ(app.sim.world().settings.substeps, 4);
    EXPECT_EQ(app.sim.run.trails.length(), 0);
    EXPECT_EQ(app.sim.selected, 1);
    resetToFile(app); // Shift+R
    EXPECT_EQ(app.sim.world().settings.method, Method::Perfect);
    EXPECT_EQ(app.sim.world().settings.bounciness, 1.0);
    EXPECT_EQ(app.sim.world().settings.gravity, (Vec2{0, 0}));
    EXPECT_EQ(app.sim.world().settings.dt, 1.0 / 60.0);
    EXPECT_EQ(app.sim.world().settings.substeps, 1);
}

TEST(AppState, EditsAreUnsavedUntilSaved) {
    const fs::path dir = tempDir("unsaved");
    App app;
    setScene(app, twoBlocks(), "two.json");
    EXPECT_FALSE(app.sim.unsavedEdits());
    for (int i = 0; i < 5; ++i) stepSimulation(app); // running is not an edit
    EXPECT_FALSE(app.sim.unsavedEdits());
    app.sim.cycleMethod(); // a setting
    EXPECT_TRUE(app.sim.unsavedEdits());
    app.sim.cycleMethod();
    app.sim.cycleMethod();
    EXPECT_FALSE(app.sim.unsavedEdits()); // back to the scene's method
    ASSERT_TRUE(app.sim.setBlockSize(0, {0.5, 0.5}));
    EXPECT_TRUE(app.sim.unsavedEdits());
    ASSERT_TRUE(saveCurrentScene(app, (dir / "s.json").string())) << app.ui.messages.error;
    EXPECT_FALSE(app.sim.unsavedEdits());
    fs::remove_all(dir);
}

TEST(AppState, AnEditDuringReplaySaysANewFutureStarts) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    for (int i = 0; i < 30; ++i) stepSimulation(app);
    ASSERT_TRUE(scrubTo(app, 10));
    ASSERT_TRUE(app.sim.isReplaying());
    const Vec2 at = app.sim.world().blocks[1].position;
    ASSERT_TRUE(app.sim.apply(Edit::setBlock({1, ""}, "position", {at.x, 9.0})).empty()); // dragged
    EXPECT_NE(app.sim.notice.find("new future"), std::string::npos) << app.sim.notice;
    EXPECT_FALSE(app.sim.isReplaying());
    EXPECT_EQ(app.sim.history.lastFrame(), 10u);
    ASSERT_TRUE(scrubTo(app, app.sim.history.lastFrame())); // >| keeps the edit
    EXPECT_EQ(app.sim.world().blocks[1].position.y, 9.0);
}

// Issue 15: scrubbed back on the timeline, the inspector lists the last collisions up to the
// time shown (the same records, bit for bit, as when they happened), not the newest ones.
TEST(AppState, TheInspectorFollowsTheScrubbedTime) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    std::vector<CollisionRecord> all;            // every collision as it happened
    std::vector<std::size_t> countAfterFrame{0}; // collisions up to frame f
    for (int i = 0; i < 900; ++i) {
        stepSimulation(app);
        for (const CollisionRecord& r : app.sim.run.lastLog) {
            if (!r.rest) all.push_back(r);
        }
        countAfterFrame.push_back(all.size());
    }
    ASSERT_GE(all.size(), 4u); // A hits B, B the right wall, ...
    const std::uint64_t newest = app.sim.world().frame;
    auto expectUpTo = [&](std::uint64_t frame) {
        ASSERT_TRUE(scrubTo(app, frame));
        const std::size_t n = countAfterFrame[frame];
        const std::size_t first = n > kRecentCollisions ? n - kRecentCollisions : 0;
        const auto& recent = app.sim.telemetry.recent;
        ASSERT_EQ(recent.size(), n - first) << "frame " << frame;
        for (std::size_t k = first; k < n; ++k) {
            const CollisionRecord &want = all[k], &got = recent[k - first];
            EXPECT_EQ(got.time, want.time);
            EXPECT_EQ(got.block, want.block);
            EXPECT_EQ(got.other, want.other);
            EXPECT_EQ(got.v1After, want.v1After);
            EXPECT_LE(got.time, app.sim.world().time + 1e-12);
        }
    };
    // Just before the first collision's frame, just after it, between later ones, the newest.
    std::uint64_t firstHit = 0;
    while (countAfterFrame[firstHit] == 0) ++firstHit;
    expectUpTo(firstHit - 1);
    EXPECT_TRUE(app.sim.telemetry.recent.empty());
    expectUpTo(firstHit);
    expectUpTo(newest / 2);
    expectUpTo(newest - 1);
    expectUpTo(newest);
    EXPECT_EQ(app.sim.telemetry.recent.size(), std::min(all.size(), kRecentCollisions));
}

TEST(HistoryForTheInspector, TheWalkBackStopsAtItsBudget) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    std::vector<std::size_t> countAfterFrame{0};
    std::size_t count = 0;
    for (int i = 0; i < 900; ++i) {
        stepSimulation(app);
        for (const CollisionRecord& r : app.sim.run.lastLog) count += r.rest ? 0 : 1;
        countAfterFrame.push_back(count);
    }
    // A budget of one block-step: only the frames since the last keyframe (every 12 frames, no
    // edits here) are stepped again, nothing older is searched.
    for (std::uint64_t f = 1; f <= 900; ++f) {
        const std::uint64_t keyframe = f / 12 * 12 == f ? f - 12 : f / 12 * 12;
        const std::size_t want = countAfterFrame[f] - countAfterFrame[keyframe];
        EXPECT_EQ(app.sim.history.collisionsUpTo(f, 24, 1).size(), std::min<std::size_t>(want, 24))
            << "frame " << f;
    }
}

TEST(AppState, CycleMethodVisitsAllThree) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    app.sim.cycleMethod();
    EXPECT_EQ(app.sim.world().settings.method, Method::MoveAndCorrect);
    app.sim.cycleMethod();
    EXPECT_EQ(app.sim.world().settings.method, Method::TurnBased);
    app.sim.cycleMethod();
    EXPECT_EQ(app.sim.world().settings.method, Method::Perfect);
}

TEST(AppState, ABadSceneFileKeepsTheCurrentSceneAndShowsTheError) {
    const fs::path dir = tempDir("bad");
    const fs::path bad = dir / "bad.json";
    std::ofstream(bad)
        << "{\"name\": \"x\", \"blocks\": [ {\"position\": [1, 2], \"mass\": \"heavy\"} ]}";
    App app;
    setScene(app, twoBlocks(), "two.json");
    EXPECT_FALSE(loadScene(app, bad.string()));
    EXPECT_EQ(app.sim.scene.name, "two");
    EXPECT_EQ(app.sim.world().blocks.size(), 2u);
    EXPECT_NE(app.ui.messages.error.find("bad.json"), std::string::npos) << app.ui.messages.error;
    EXPECT_FALSE(loadScene(app, (dir / "missing.json").string()));
    EXPECT_EQ(app.sim.scene.name, "two");
    fs::remove_all(dir);
}

TEST(AppState, SaveWritesAV1SceneThatLoadsBackAsTheCurrentState) {
    const fs::path dir = tempDir("save");
    App app;
    setScene(app, twoBlocks(), "two.json");
    for (int i = 0; i < 20; ++i) stepSimulation(app);
    app.sim.world().settings.bounciness = 0.5;
    app.sim.world().settings.method = Method::TurnBased;
    const std::string path = (dir / "saved.json").string();
    ASSERT_TRUE(saveCurrentScene(app, path)) << app.ui.messages.error;

    const SceneResult loaded = loadSceneFile(path);
    ASSERT_TRUE(loaded.scene) << loaded.error.text();
    const Scene& s = *loaded.scene;
    ASSERT_EQ(s.blocks.size(), 2u);
    EXPECT_EQ(s.blocks[0].name, "A");
    EXPECT_EQ(s.blocks[0].color, "#d04040");
    EXPECT_TRUE(approxEqual(s.blocks[0].position, app.sim.world().blocks[0].position, 1e-9));
    EXPECT_TRUE(approxEqual(s.blocks[1].velocity, app.sim.world().blocks[1].velocity, 1e-9));
    EXPECT_EQ(s.blocks[1].mass, 2.0);
    EXPECT_EQ(s.settings.bounciness, 0.5);
    EXPECT_EQ(s.settings.method, Method::TurnBased);
    fs::remove_all(dir);
}

TEST(AppState, SaveKeepsNamesInStepAfterAddAndDelete) {
    const fs::path dir = tempDir("save2");
    App app;
    setScene(app, twoBlocks(), "two.json");
    app.sim.selected = 0;
    deleteSelected(app);
    ASSERT_GE(app.sim.addBlockAt({16, 3}), 0);
    const std::string path = (dir / "saved.json").string();
    ASSERT_TRUE(saveCurrentScene(app, path)) << app.ui.messages.error;
    const SceneResult loaded = loadSceneFile(path);
    ASSERT_TRUE(loaded.scene) << loaded.error.text();
    ASSERT_EQ(loaded.scene->blocks.size(), 2u);
    EXPECT_EQ(loaded.scene->blocks[0].name, "B");
    EXPECT_EQ(loaded.scene->blocks[0].mass, 2.0);
    fs::remove_all(dir);
}

TEST(AppState, SaveRecordsTheCurrentMassSettingsAndAnAbsolutePath) {
    const fs::path dir = tempDir("save3");
    App app;
    ASSERT_TRUE(loadScene(app, resolveScenePath("lecture_example_1", SANDBOX_SCENES_DIR)));
    EXPECT_TRUE(fs::path(app.sim.scenePath).is_absolute());
    app.sim.world().blocks[0].mass = 3.0;
    EXPECT_EQ(app.sim.blockDisplayName(0), "m1 = 3 kg"); // the label follows the mass
    app.sim.world().settings.gravity = Vec2{0, -9.81};
    // The offered name comes from the scene's name, outside the shipped scenes, never taken.
    const std::string offered = suggestedSavePath(app);
    EXPECT_EQ(fs::path(offered).stem().string().rfind("lecture_example_1", 0), 0u) << offered;
    EXPECT_FALSE(fs::exists(offered));
    EXPECT_NE(fs::path(offered).parent_path(), fs::path(SANDBOX_SCENES_DIR));
    const fs::path cwd = fs::current_path();
    fs::current_path(dir);
    ASSERT_TRUE(saveCurrentScene(app, "mine")) << app.ui.messages.error; // relative, no extension
    fs::current_path(cwd);
    const std::string saved = (dir / "mine.json").string();
    EXPECT_EQ(app.sim.scenePath, saved);
    const SceneResult loaded = loadSceneFile(saved);
    ASSERT_TRUE(loaded.scene) << loaded.error.text();
    EXPECT_EQ(loaded.scene->blocks[0].name, "m1 = 3 kg");
    EXPECT_EQ(loaded.scene->blocks[0].mass, 3.0);
    EXPECT_EQ(loaded.scene->settings.gravity, (Vec2{0, -9.81}));
    EXPECT_NE(loaded.scene->description.find("no gravity"), std::string::npos); // kept as written
    EXPECT_NE(loaded.scene->description.find("Saved with changed settings: gravity (0, -9.81)"),
              std::string::npos)
        << loaded.scene->description;
    // Offered again: the file exists now, so another name.
    app.sim.scenePath = saved;
    const std::string next = suggestedSavePath(app);
    EXPECT_EQ(fs::path(next).parent_path(), dir);
    EXPECT_NE(next, saved);
    fs::remove_all(dir);
}

TEST(AppState, SaveToABadPathFailsWithAMessage) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    EXPECT_FALSE(saveCurrentScene(app, "/nonexistent-dir/x/y.json"));
    EXPECT_FALSE(app.ui.messages.error.empty());
    EXPECT_FALSE(saveCurrentScene(app, ""));
}

TEST(AppState, BlockKindAndSizeEdits) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    app.sim.setBlockKind(0, BodyKind::Static);
    EXPECT_EQ(app.sim.world().blocks[0].velocity, Vec2{});
    EXPECT_EQ(app.sim.world().blocks[0].mass, kInfiniteMass);
    app.sim.setBlockKind(0, BodyKind::Dynamic);
    EXPECT_EQ(app.sim.world().blocks[0].mass, 1.0);
    EXPECT_TRUE(app.sim.setBlockSize(0, {2, 2}));
    EXPECT_FALSE(app.sim.setBlockSize(0, {30, 1})); // out of bounds
    EXPECT_FALSE(app.sim.setBlockSize(0, {17, 1})); // would overlap B
    EXPECT_FALSE(app.sim.setBlockSize(0, {-1, 1}));
    EXPECT_EQ(app.sim.world().blocks[0].size, (Vec2{2, 2}));
}

TEST(AppState, ViewportLeavesRoomForThePanel) {
    App app;
    const ScreenRect withUi = sceneViewport(app.view, app.lesson.active(), 1280, 720);
    EXPECT_GT(withUi.x, 0.0);
    EXPECT_DOUBLE_EQ(withUi.x + withUi.width, 1280.0);
    app.view.uiVisible = false;
    const ScreenRect full = sceneViewport(app.view, app.lesson.active(), 1280, 720);
    EXPECT_DOUBLE_EQ(full.x, 0.0);
    EXPECT_DOUBLE_EQ(full.width, 1280.0);
}

TEST(AppState, ShowListSetsTheOverlays) {
    App app;
    ShowSet show;
    std::string error;
    ASSERT_TRUE(parseShowList("trails,plots", show, &error));
    applyShowSet(app.view, show);
    EXPECT_TRUE(app.view.show.trails);
    EXPECT_FALSE(app.view.show.vectors);
    EXPECT_TRUE(app.view.uiVisible);
    ASSERT_TRUE(parseShowList("none", show, &error));
    applyShowSet(app.view, show);
    EXPECT_FALSE(app.view.uiVisible);
}

// The overlay table (overlays.h) is what --show, the checkboxes and the log read: every row's
// name turns on its own flag and no other, and toggling a row logs "NAME: on".
TEST(OverlayTable, EachShowNameTurnsOnItsOwnFlagOnly) {
    for (const OverlayInfo& row : kOverlays) {
        ShowSet show;
        std::string error;
        ASSERT_TRUE(parseShowList(row.name, show, &error)) << row.name << ": " << error;
        for (const OverlayInfo& other : kOverlays) {
            EXPECT_EQ(show.overlays.*other.flag, &other == &row) << row.name << " / " << other.name;
        }
    }
}

TEST(OverlayTable, NamesAndFlagsAreUniqueAndWindowsHaveRoom) {
    for (std::size_t i = 0; i < kOverlayCount; ++i) {
        const OverlayInfo& a = kOverlays[i];
        EXPECT_NE(std::string(a.name), "none");
        EXPECT_NE(showNames().find(a.name), std::string::npos);
        if (a.title != nullptr) {
            EXPECT_GT(a.place.minExtent, 0.0) << a.name;
            EXPECT_GT(a.place.weight, 0.0) << a.name;
            EXPECT_GT(a.place.crossExtent, 0.0) << a.name;
        }
        for (std::size_t j = i + 1; j < kOverlayCount; ++j) {
            EXPECT_NE(std::string(a.name), kOverlays[j].name);
            EXPECT_NE(a.flag, kOverlays[j].flag) << a.name;
        }
    }
    EXPECT_EQ(overlayInfo(OverlayId::plots).flag, &Overlays::plots);
    EXPECT_EQ(overlayInfo(OverlayId::cost).flag, &Overlays::cost);
}

TEST(AppLog, LogsEveryOverlayByItsShowName) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    for (const OverlayInfo& row : kOverlays) {
        const LoggedState before = snapshotForLog(app.sim, app.view, app.lesson);
        app.view.show.*row.flag = !(app.view.show.*row.flag);
        const auto lines = describeChanges(before, snapshotForLog(app.sim, app.view, app.lesson));
        ASSERT_EQ(lines.size(), 1u) << row.name;
        EXPECT_EQ(lines[0], std::string(row.name) + (app.view.show.*row.flag ? ": on" : ": off"));
    }
}

TEST(AppLog, DescribesWhatChanged) {
    App app;
    setScene(app, twoBlocks(), "two.json");
    app.sim.paused = false;
    const LoggedState before = snapshotForLog(app.sim, app.view, app.lesson);
    app.sim.paused = true;
    app.sim.verbose = true;
    // An edit prints its own line where it is applied (the one door), not found by comparing.
    testing::internal::CaptureStdout();
    app.sim.cycleMethod();
    app.sim.apply(Edit::setWorld("bounciness", 0.25));
    app.sim.apply(Edit::setBlock({1, ""}, "mass", 4));
    app.sim.undo();
    EXPECT_EQ(testing::internal::GetCapturedStdout(),
              "method: move-and-correct\nbounciness: 0.25\nB mass: 4\n"
              "undo: B mass: 4 kg -> 2 kg\n");
    const auto lines = describeChanges(before, snapshotForLog(app.sim, app.view, app.lesson));
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0], "paused");
    EXPECT_TRUE(describeChanges(before, before).empty());
}

TEST(Trails, KeepTheNewestPointsAndRestartWhenBlocksChange) {
    Trails trails(3, 1);
    World w;
    w.blocks.resize(2);
    for (int i = 0; i < 5; ++i) {
        w.blocks[0].position = {double(i), 0};
        trails.record(w);
    }
    EXPECT_EQ(trails.length(), 3);
    EXPECT_EQ(trails.point(0, 0), (Vec2{4, 0}));
    EXPECT_EQ(trails.point(0, 2), (Vec2{2, 0}));
    EXPECT_EQ(trails.point(0, 3), Vec2{}); // out of range: zero, no crash
    w.blocks.resize(3);
    trails.record(w);
    EXPECT_EQ(trails.length(), 1);
    trails.clear();
    EXPECT_EQ(trails.length(), 0);
}

// Issue 24: a trail draws the path that happened. A block at 6 m/s meets the right wall within
// a frame; the perfect method's frame ends are both off the wall, but its trail (and turn-based's,
// whose frame ends at the bounce) passes through where it touched: its centre half its width from
// the wall, x = 20 - 0.5 = 19.5 exactly (the record keeps the centre as resolved). Move-and-correct
// resolves after the overlap, at no point of the path: no point of impact is kept.
TEST(Trails, PassThroughThePointOfImpactWithinTheFrame) {
    for (Method method : {Method::Perfect, Method::TurnBased, Method::MoveAndCorrect}) {
        SCOPED_TRACE(methodName(method));
        World w;
        w.settings.gravity = {0.0, 0.0};
        w.settings.method = method;
        Block b;
        b.position = {17.0, 6.0};
        b.size = {1.0, 1.0};
        b.velocity = {6.0, 0.0};
        w.blocks.push_back(b);
        Trails trails(200, 1);
        std::vector<CollisionRecord> log;
        trails.record(w, &log);
        int impacts = 0;
        for (int frame = 0; frame < 60; ++frame) {
            log.clear();
            w.step(&log);
            trails.record(w, &log);
        }
        for (int age = 0; age + 1 < trails.length(); ++age) {
            Vec2 at;
            if (!trails.impact(0, age, at)) continue;
            ++impacts;
            EXPECT_EQ(at.x, 19.5);
            EXPECT_EQ(at.y, 6.0);
            EXPECT_LT(trails.point(0, age + 1).x, 19.5);
            if (method == Method::Perfect) {
                // Neither end of that frame is at the wall: without the point the trail would cut
                // the corner.
                EXPECT_LT(trails.point(0, age).x, 19.5);
            } else {
                // Turn-based loses the rest of the frame at the bounce: it ends where it touched.
                EXPECT_EQ(trails.point(0, age).x, 19.5);
            }
        }
        EXPECT_EQ(impacts, method == Method::MoveAndCorrect ? 0 : 1);
    }
}

TEST(Trails, AgeWithinLengthCutsAllTrailsAtTheSameAge) {
    // Two moving blocks, each 1 m further per recorded point, and a static one that never counts.
    Trails trails(10, 1);
    World w;
    w.blocks.resize(3);
    w.blocks[2].kind = BodyKind::Static;
    EXPECT_EQ(trails.ageWithinLength(w, 100.0), 0); // nothing recorded: nothing to draw
    for (int i = 0; i < 6; ++i) {
        w.blocks[0].position = {double(i), 0};
        w.blocks[1].position = {0, double(i)};
        w.blocks[2].position = {5.0 * i, 0}; // (static blocks do not move; ignored either way)
        trails.record(w);
    }
    ASSERT_EQ(trails.length(), 6);
    // Each age adds 2 m (1 m per moving block).
    EXPECT_EQ(trails.ageWithinLength(w, 100.0), 5); // everything fits: the oldest point
    EXPECT_EQ(trails.ageWithinLength(w, 6.0), 3);   // 2 + 2 + 2 = 6 m
    EXPECT_EQ(trails.ageWithinLength(w, 5.9), 2);
    EXPECT_EQ(trails.ageWithinLength(w, 0.5), 1); // never less than one segment
    w.blocks.resize(2);                           // another world: no trail to draw
    EXPECT_EQ(trails.ageWithinLength(w, 100.0), 0);
}

TEST(AppFrame, FramesShownAreCountedAndSmoothed) {
    // The window's pace for Statistics: the first frame sets the average, later ones move it by
    // 1/30 of the difference; offscreen runs never call this (the readout stays hidden at 0).
    App app;
    EXPECT_EQ(app.ui.frameMsSmoothed, 0.0);
    noteFrameShown(app.ui, 0.020);
    EXPECT_DOUBLE_EQ(app.ui.frameMsSmoothed, 20.0);
    noteFrameShown(app.ui, 0.050);
    EXPECT_DOUBLE_EQ(app.ui.frameMsSmoothed, 21.0);
    noteFrameShown(app.ui, 0.0); // no time passed: not a frame
    EXPECT_EQ(app.ui.framesShown, 2);
    EXPECT_DOUBLE_EQ(app.ui.secondsShown, 0.070);
}

TEST(AppConfig, RoundTripsAndIgnoresNonsense) {
    AppConfig c;
    c.lastScene = "/home/me/scenes/x.json";
    c.uiScale = 1.5f;
    c.windowWidth = 1920;
    c.windowHeight = 1080;
    const AppConfig back = parseAppConfig(formatAppConfig(c));
    EXPECT_EQ(back.lastScene, c.lastScene);
    EXPECT_EQ(back.uiScale, 1.5f);
    EXPECT_EQ(back.windowWidth, 1920);
    EXPECT_EQ(back.windowHeight, 1080);
    const AppConfig bad = parseAppConfig("ui_scale = banana\nwindow_width = -5\nfoo = bar\n=\n");
    EXPECT_EQ(bad.uiScale, 1.0f);
    EXPECT_EQ(bad.windowWidth, 320);
    EXPECT_EQ(parseAppConfig("ui_scale = 99").uiScale, kMaxUiScale);
}

TEST(AppConfig, SavesUnderTheConfigDirectory) {
    const fs::path dir = tempDir("cfg") / "collision-sandbox";
    AppConfig c;
    c.lastScene = (dir / "a.json").string(); // the last scene must still be there
    fs::create_directories(dir);
    std::ofstream(c.lastScene) << "{}";
    ASSERT_TRUE(saveAppConfig(dir.string(), c));
    EXPECT_EQ(loadAppConfig(dir.string()).lastScene, c.lastScene);
    EXPECT_EQ(loadAppConfig((dir / "nope").string()).lastScene, "");
    fs::remove_all(dir.parent_path());
}

TEST(Options, ParsesTheContract) {
    const char* argv[] = {"sandbox", "scene.json", "--screenshot", "a.png",  "--frames",
                          "120",     "--size",     "1920x1080",    "--show", "none"};
    const ParsedOptions p = parseOptions(10, argv);
    ASSERT_FALSE(p.exit);
    EXPECT_EQ(p.options.scene, "scene.json");
    EXPECT_EQ(p.options.screenshot, "a.png");
    EXPECT_EQ(p.options.frames, 120);
    EXPECT_EQ(p.options.width, 1920);
    EXPECT_EQ(p.options.height, 1080);
    EXPECT_TRUE(p.options.show.none);
    EXPECT_TRUE(wantsOffscreen(p.options));
}

TEST(Options, RejectsBadValues) {
    const char* badShow[] = {"sandbox", "--show", "vectors,bogus"};
    EXPECT_TRUE(parseOptions(3, badShow).exit);
    EXPECT_NE(parseOptions(3, badShow).exitCode, 0);
    const char* badSize[] = {"sandbox", "--size", "12x"};
    EXPECT_NE(parseOptions(3, badSize).exitCode, 0);
    const char* recordNoFrames[] = {"sandbox", "--record", "dir"};
    EXPECT_NE(parseOptions(3, recordNoFrames).exitCode, 0);
    const char* unknown[] = {"sandbox", "--frobnicate"};
    EXPECT_NE(parseOptions(2, unknown).exitCode, 0);
    int w = 0, h = 0;
    EXPECT_FALSE(parseSize("100x100x3", w, h));
    EXPECT_TRUE(parseSize("640x480", w, h));
    EXPECT_EQ(w, 640);
}

// Issue 28's outside suite: every file a run writes is refused onto an input of the run (exit
// 2), --text-json included (it once overwrote the scene it was given).
TEST(Options, NoOutputMayOverwriteTheScene) {
    const fs::path dir =
        fs::temp_directory_path() / ("sandbox_outputs_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string scene = (dir / "scene.json").string();
    const std::string bySpelling = (dir / "." / "scene.json").string();
    std::ofstream(scene) << "{}";
    const std::vector<OutputFile> outputs = outputFiles(Options{});
    EXPECT_EQ(outputs.size(), 4u);
    for (const OutputFile& output : outputs) {
        std::vector<const char*> argv = {"sandbox", scene.c_str()};
        if (std::string(output.flag) != "--screenshot")
            argv.insert(argv.end(), {"--screenshot", "a.png"});
        argv.insert(argv.end(), {output.flag, bySpelling.c_str()});
        const ParsedOptions p = parseOptions(static_cast<int>(argv.size()), argv.data());
        EXPECT_TRUE(p.exit) << output.flag;
        EXPECT_EQ(p.exitCode, 2) << output.flag;
    }
    fs::remove_all(dir);
}

// Issue 28's outside suite: a last scene (a saved setting) that is a file but does not load
// opened the default without a word. The default opens and the panel's message says why.
TEST(AppState, ALastSceneThatDoesNotLoadOpensTheDefaultAndSaysWhy) {
    const fs::path bad =
        fs::temp_directory_path() / ("sandbox_last_scene_" + std::to_string(::getpid()) + ".json");
    std::ofstream(bad)
        << R"({"name": "x", "blocks": [{"position": [1, 1], "size": 1, "mass": "heavy"}]})";
    App app;
    std::string error;
    ASSERT_TRUE(setupApp(app, Options{}, bad.string(), &error)) << error;
    EXPECT_NE(app.sim.scenePath, bad.string());
    EXPECT_NE(app.ui.messages.error.find("blocks[0].mass"), std::string::npos)
        << app.ui.messages.error;
    fs::remove(bad);
}

// Issue 13: every option error exits 2, as sandbox-cli's bad usage (CLI11's own code for a
// failed check is 105); a UI scale must be a number in range (NaN passed CLI::Range); a
// benchmark does not silently drop --record.
TEST(Options, ErrorsExitTwo) {
    const std::vector<std::vector<const char*>> cases = {
        {"sandbox", "--show", "vectors,bogus"},
        {"sandbox", "--size", "12x"},
        {"sandbox", "--record", "dir"},
        {"sandbox", "--frobnicate"},
        {"sandbox", "--ui-scale", "nan"},
        {"sandbox", "--ui-scale", "inf"},
        {"sandbox", "--ui-scale", "5"},
        {"sandbox", "--ui-scale", "0x1"},
        {"sandbox", "--frames", "-1"},
        {"sandbox", "--frames", "1e8"},
        {"sandbox", "--frames", "2.5"},
        {"sandbox", "--frames", "0x10"},
        {"sandbox", "--benchmark-frames", "0"},
        {"sandbox", "--benchmark-frames", "1e8"},
        {"sandbox", "--record", "d", "--frames", "3", "--benchmark-frames", "3"}};
    for (const auto& argv : cases) {
        const ParsedOptions p = parseOptions(static_cast<int>(argv.size()), argv.data());
        EXPECT_TRUE(p.exit) << argv[1];
        EXPECT_EQ(p.exitCode, 2) << argv[1] << " " << argv[2];
    }
    const char* scale[] = {"sandbox", "--ui-scale", "1.5"};
    const ParsedOptions ok = parseOptions(3, scale);
    ASSERT_FALSE(ok.exit);
    EXPECT_EQ(ok.options.uiScale, 1.5f);
    // Counts of frames as sandbox-cli reads them: an exponent is a number (the limits table).
    const char* frames[] = {"sandbox", "--frames", "1e3", "--benchmark-frames", "2E1"};
    const ParsedOptions counted = parseOptions(5, frames);
    ASSERT_FALSE(counted.exit);
    EXPECT_EQ(counted.options.frames, 1000);
    EXPECT_EQ(counted.options.benchmarkFrames, 20);
    const char* help[] = {"sandbox", "--help"};
    EXPECT_EQ(parseOptions(2, help).exitCode, 0);
}

TEST(SceneLibrary, FindsShippedScenesByName) {
    const fs::path dir = tempDir("lib");
    std::ofstream(dir / "b_scene.json") << "{}";
    std::ofstream(dir / "a_scene.json") << "{}";
    std::ofstream(dir / "notes.txt") << "x";
    const auto list = listScenes(dir.string());
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0].title, "a scene");
    EXPECT_EQ(resolveScenePath("b_scene", dir.string()), (dir / "b_scene.json").string());
    EXPECT_EQ(resolveScenePath("b_scene.json", dir.string()), (dir / "b_scene.json").string());
    EXPECT_EQ(resolveScenePath("zzz", dir.string()), "zzz");
    fs::remove_all(dir);
}

} // namespace

// Issue 15: high_mass_ratio ends as its description says: exactly 3141 collisions, paused at its
// "duration" (20 s) before the giant comes back from the far wall (about 26 s).
TEST(AppState, HighMassRatioStopsAtItsDurationWith3141) {
    App app;
    const SceneResult loaded =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/high_mass_ratio.json");
    ASSERT_TRUE(loaded.scene) << loaded.error.text();
    ASSERT_TRUE(loaded.scene->duration);
    setScene(app, *loaded.scene, "high_mass_ratio.json");
    app.sim.paused = false;
    int frames = 0;
    while (!app.sim.paused && frames < 3000) {
        advanceSimulation(app, 1.0 / 60.0);
        ++frames;
    }
    ASSERT_TRUE(app.sim.paused);
    EXPECT_EQ(app.sim.world().frame, 1200u); // 20 s at 60 frames/s
    EXPECT_EQ(app.sim.run.totals.collisions, 3141u);
    // Played on, the giant comes back from the far wall: the count goes on (why it ends at 20 s).
    for (int i = 0; i < 900; ++i) stepSimulation(app);
    EXPECT_GT(app.sim.run.totals.collisions, 3141u);
}

// --theme starts with the light theme (issue 15: bright rooms); --timeline-frame shows the replay
// offscreen and cannot go past the frames simulated.
TEST(Options, ThemeAndTimelineFrame) {
    const char* light[] = {"sandbox", "--theme",          "light", "--frames",
                           "90",      "--timeline-frame", "30"};
    const ParsedOptions p = parseOptions(7, light);
    ASSERT_FALSE(p.exit);
    EXPECT_EQ(p.options.theme, "light");
    EXPECT_EQ(p.options.timelineFrame, 30);
    const char* badTheme[] = {"sandbox", "--theme", "pink"};
    EXPECT_EQ(parseOptions(3, badTheme).exitCode, 2);
    const char* pastTheEnd[] = {"sandbox", "--frames", "10", "--timeline-frame", "20"};
    EXPECT_EQ(parseOptions(5, pastTheEnd).exitCode, 2);
    const char* none[] = {"sandbox"};
    EXPECT_TRUE(parseOptions(1, none).options.theme.empty()); // the saved setting decides
}

// Undo notes and edit lines call a block as a student does: "m2" for "m2 = 2 kg", the whole name
// when two blocks would be called alike, the place when it has no name.
TEST(EditWords, ABlockIsCalledByItsShortName) {
    const std::vector<BlockLabel> labels{{"m1 = 1 kg", ""}, {"m2 = 2 kg", ""},
                                         {"A", ""},         {"A (2 kg)", ""},
                                         {"", ""},          {"feather, 50 g", ""}};
    EXPECT_EQ(spokenBlockName(labels, 1), "m2");
    EXPECT_EQ(spokenBlockName(labels, 2), "A");
    EXPECT_EQ(spokenBlockName(labels, 3), "A (2 kg)");
    EXPECT_EQ(spokenBlockName(labels, 4), "blocks[4]");
    EXPECT_EQ(spokenBlockName(labels, 5), "feather");
    AppliedEdit mass;
    mass.edit = Edit::setBlock({-1, "m2 = 2 kg"}, "mass", 2);
    mass.index = 1;
    mass.before.mass = 4;
    mass.after.mass = 2;
    EXPECT_EQ(editChangeText(mass, false, labels), "m2 mass: 4 kg -> 2 kg");
    EXPECT_EQ(editChangeText(mass, true, labels), "m2 mass: 2 kg -> 4 kg");
    World world;
    EXPECT_EQ(editLogLine(mass.edit, 1, world, labels), "m2 mass: 2");
}
