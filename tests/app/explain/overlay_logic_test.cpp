// The teaching overlays' logic without GL: the inspector's formula strings for the lecture's
// first worked example, the timeline's scrub-and-replay (bit-exact, checked with stateHash), the
// plot widget's ticks and time window, the point of impact and the methods side by side.
#include "app.h"
#include "cost.h"
#include "inspector_format.h"
#include "plot_logic.h"
#include "poi.h"
#include "scene_library.h"
#include "side_by_side.h"
#include "test_fixtures.h"
#include "timeline.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

App lectureExample() {
    App app;
    EXPECT_TRUE(loadScene(app, resolveScenePath("lecture_example_1", SANDBOX_SCENES_DIR)))
        << app.ui.messages.error;
    return app;
}

// The first block-block collision recorded by the app's telemetry within `frames` frames.
const CollisionRecord* firstBlockCollision(App& app, int frames) {
    for (int i = 0; i < frames; ++i) stepSimulation(app);
    for (const CollisionRecord& r : app.sim.telemetry.recent) {
        if (r.other >= 0) return &r;
    }
    return nullptr;
}

TEST(InspectorFormat, LectureExampleOneFillsTheFormula) {
    App app = lectureExample();
    const CollisionRecord* r = firstBlockCollision(app, 45);
    ASSERT_NE(r, nullptr) << "no collision between the blocks in 45 frames";
    EXPECT_NEAR(r->time, 0.625, 1e-9);
    EXPECT_EQ(r->axis, 0);
    const CollisionFormula f = collisionFormula(*r, app.sim.blockDisplayName(r->block),
                                                app.sim.blockDisplayName(r->other));
    EXPECT_EQ(f.title, "m1 = 1 kg  hits  m2 = 2 kg  along x at t = 0.625 s");
    EXPECT_EQ(f.given, "m1 = 1, m2 = 2, v1 = 6, v2 = 0, C = 1");
    EXPECT_EQ(f.u, "u = (1·6 + 2·0)/(1 + 2) = 2");
    EXPECT_EQ(f.v1After, "v1' = 2 - 1·(6 - 2) = -2");
    EXPECT_EQ(f.v2After, "v2' = 2 - 1·(0 - 2) = 4");
    EXPECT_EQ(f.momentumBefore, "p before = 1·6 + 2·0 = 6 kg·m/s");
    EXPECT_EQ(f.momentumAfter, "p after  = 1·(-2) + 2·4 = 6 kg·m/s");
    EXPECT_TRUE(f.note.empty());
}

TEST(InspectorFormat, WallCollisionUsesTheWallsVelocity) {
    const CollisionFormula f = collisionFormula(rightWallHit(0, 1.0), "A", wallName(kWallRight));
    EXPECT_EQ(f.title, "A  hits  right wall  along x at t = 1.5 s");
    EXPECT_EQ(f.u, "u = 0   (the right wall's velocity: infinite mass)");
    EXPECT_EQ(f.v1After, "vA' = 0 - 0.5·(4 - 0) = -2");
    EXPECT_EQ(f.momentumBefore, "pA before = 1·4 = 4 kg·m/s");
    EXPECT_EQ(f.momentumAfter, "pA after  = 1·(-2) = -2 kg·m/s");
    EXPECT_FALSE(f.note.empty());
}

TEST(Inspector, PauseOnCollisionStopsAtTheCollisionFrame) {
    App app = lectureExample();
    app.sim.paused = false; // P
    app.sim.pauseOnCollision = true;
    int frames = 0;
    while (!app.sim.paused && frames < 100) {
        stepSimulation(app);
        ++frames;
    }
    EXPECT_TRUE(app.sim.paused);
    EXPECT_EQ(frames, 38); // the collision at t = 0.625 s falls in frame 38 (0.617 .. 0.633 s)
    ASSERT_FALSE(app.sim.run.lastLog.empty());
    EXPECT_NEAR(app.sim.run.lastLog.front().time, 0.625, 1e-9);
}

// A busy scene (gravity, bounciness < 1, many blocks) so that the replay has work to do.
App busyScene() {
    App app;
    EXPECT_TRUE(loadScene(app, resolveScenePath("bouncing_squares", SANDBOX_SCENES_DIR)))
        << app.ui.messages.error;
    app.sim.world().settings.bounciness = 0.8;
    return app;
}

TEST(Timeline, ScrubAndReplayEqualsTheOriginalRun) {
    for (const Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
        App app = busyScene();
        app.sim.world().settings.method = method;
        std::vector<std::uint64_t> original;
        original.push_back(stateHash(app.sim.world()));
        for (int i = 0; i < 300; ++i) {
            stepSimulation(app);
            original.push_back(stateHash(app.sim.world()));
        }
        // Every recorded frame rebuilds bit for bit.
        for (std::uint64_t f = 0; f <= 300; f += 7) {
            World w;
            ASSERT_TRUE(app.sim.history.stateAt(f, w)) << f;
            EXPECT_EQ(stateHash(w), original[f]) << methodName(method) << " frame " << f;
        }
        // Scrub back to frame 123 and step forward again: the same states as the first time.
        ASSERT_TRUE(scrubTo(app, 123));
        EXPECT_TRUE(app.sim.isReplaying());
        EXPECT_EQ(stateHash(app.sim.world()), original[123]);
        for (int f = 124; f <= 300; ++f) {
            stepSimulation(app);
            ASSERT_EQ(stateHash(app.sim.world()), original[static_cast<std::size_t>(f)])
                << methodName(method) << " replayed frame " << f;
        }
        EXPECT_FALSE(app.sim.isReplaying());
    }
}

// A reset or a jump on the timeline starts a new Run: what the old one derived from stepping
// (totals, trails, the log, the point of impact, the side-by-side worlds) goes with it; the
// recording (timeline, plots) stays across a jump.
TEST(Run, ResetAndScrubStartAFreshRun) {
    App app = lectureExample();
    app.view.show.sideBySide = true;
    for (int i = 0; i < 60; ++i) stepSimulation(app);
    ASSERT_GT(app.sim.run.totals.collisions, 0);
    ASSERT_EQ(app.sim.run.totals.steps, 60);
    ASSERT_TRUE(app.sim.run.methods.running);
    ASSERT_TRUE(app.sim.run.poi.valid);
    ASSERT_GT(app.sim.run.trails.length(), 0);
    const std::uint64_t frame20 = [&] {
        World w;
        EXPECT_TRUE(app.sim.history.stateAt(20, w));
        return stateHash(w);
    }();

    ASSERT_TRUE(scrubTo(app, 20));
    EXPECT_EQ(stateHash(app.sim.world()), frame20);
    EXPECT_EQ(app.sim.run.totals.steps, 0);
    EXPECT_EQ(app.sim.run.totals.collisions, 0);
    EXPECT_FALSE(app.sim.run.methods.running);
    EXPECT_FALSE(app.sim.run.poi.valid);
    EXPECT_EQ(app.sim.run.trails.length(), 0);
    EXPECT_TRUE(app.sim.run.lastLog.empty());
    EXPECT_EQ(app.sim.run.stats.kineticEnergy, kineticEnergy(app.sim.world()));
    EXPECT_FALSE(app.sim.history.empty()); // the recording stays
    EXPECT_EQ(app.sim.history.lastFrame(), 60u);

    for (int i = 0; i < 5; ++i) stepSimulation(app);
    EXPECT_EQ(app.sim.run.totals.steps, 5);
    resetScene(app);
    EXPECT_EQ(app.sim.world().frame, 0u);
    EXPECT_EQ(app.sim.run.totals.steps, 0);
    EXPECT_TRUE(app.sim.history.empty());
    EXPECT_EQ(stateHash(app.sim.world()), stateHash(makeWorld(app.sim.scene)));
}

TEST(Timeline, EditsBetweenStepsAreKeyframedSoReplayStaysExact) {
    App app = busyScene();
    std::vector<std::uint64_t> original{stateHash(app.sim.world())};
    for (int i = 1; i <= 100; ++i) {
        stepSimulation(app);
        // Edits while paused at frame i: the timeline keeps the edited state as frame i.
        if (i == 40) app.sim.apply(Edit::setWorld("bounciness", 0.3));               // a slider
        if (i == 55) app.sim.apply(Edit::setBlock({0, ""}, "velocity", {3.0, 7.0})); // a fling
        if (i == 70) app.sim.apply(Edit::setBlock({1, ""}, "mass", 5.0)); // the mass slider
        original.push_back(stateHash(app.sim.world()));
    }
    stepSimulation(app);
    for (std::uint64_t f = 0; f <= 100; ++f) {
        World w;
        ASSERT_TRUE(app.sim.history.stateAt(f, w));
        EXPECT_EQ(stateHash(w), original[f]) << "frame " << f;
    }
}

// A block's own friction set while paused (the field the timeline's comparison of fields used
// to miss): scrubbed back and forth, every frame is the fresh run with that edit at its frame.
TEST(Timeline, ABlocksFrictionSetWhilePausedReplaysAsAFreshRunWithTheEdit) {
    const SceneResult r = parseScene(R"({"name": "slide", "world": {"friction": 0.4},
        "blocks": [{"name": "slider", "position": [2, 0.5], "size": 1, "velocity": [9, 0]},
                   {"name": "box", "position": [12, 0.5], "size": 1, "mass": 2}]})",
                                     "slide.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    const Edit friction = Edit::setBlock({-1, "slider"}, "friction", 1.5);
    for (const Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
        Scene scene = *r.scene;
        scene.settings.method = method;
        // The fresh run: 20 frames, the edit, 70 more.
        std::vector<std::uint64_t> fresh, unedited;
        World w = makeWorld(scene), plain = w;
        std::vector<BlockLabel> labels{{"slider", ""}, {"box", ""}};
        for (int f = 0; f <= 90; ++f) {
            if (f == 20) {
                ASSERT_TRUE(applyEdit({w, labels}, friction).applied);
            }
            fresh.push_back(stateHash(w));
            unedited.push_back(stateHash(plain));
            w.step();
            plain.step();
        }
        ASSERT_NE(fresh[90], unedited[90]) << methodName(method); // the edit matters
        // The app: paused at frame 20, the friction set, played on to 90, scrubbed about.
        App app;
        setScene(app, scene, "slide.json");
        for (int f = 0; f < 20; ++f) stepSimulation(app);
        ASSERT_TRUE(app.sim.apply(friction).empty());
        for (int f = 20; f < 90; ++f) stepSimulation(app);
        for (std::uint64_t f : {10u, 25u, 19u, 20u, 21u, 63u, 90u, 33u, 89u}) {
            ASSERT_TRUE(scrubTo(app, f)) << f;
            EXPECT_EQ(stateHash(app.sim.world()), fresh[f]) << methodName(method) << " frame " << f;
            EXPECT_EQ(app.sim.world().blocks[0].friction, f >= 20 ? 1.5 : -1.0) << f;
        }
    }
}

TEST(Timeline, HoldsSixtySecondsOfAThousandBlocksCompactly) {
    World world;
    world.settings.gravity = Vec2{0.0, 0.0};
    world.settings.method = Method::MoveAndCorrect;
    world.bounds = Bounds{{0.0, 0.0}, {100.0, 100.0}};
    for (int i = 0; i < 1000; ++i) {
        Block b;
        b.position = Vec2{1.0 + (i % 40) * 2.4, 1.0 + (i / 40) * 3.5};
        b.size = Vec2{0.5, 0.5};
        b.velocity = Vec2{0.0, 0.0}; // at rest: cheap steps; the memory is what is measured
        world.blocks.push_back(b);
    }
    WorldHistory history(3600, 12);
    for (int i = 0; i < 3700; ++i) {
        history.beforeStep(world);
        world.step();
        history.afterStep(world);
    }
    EXPECT_GE(history.lastFrame() - history.firstFrame(), 3600u);
    EXPECT_LT(history.bytes(), 40u * 1024u * 1024u);
}

TEST(PlotLogic, NiceTicks) {
    EXPECT_DOUBLE_EQ(niceTickStep(10.0, 5), 2.0);
    EXPECT_DOUBLE_EQ(niceTickStep(1.0, 4), 0.5);
    EXPECT_DOUBLE_EQ(niceTickStep(7.0, 7), 1.0);
    const std::vector<double> t = niceTicks(-0.3, 4.1, 5);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_DOUBLE_EQ(t.front(), 0.0);
    EXPECT_DOUBLE_EQ(t.back(), 4.0);
    EXPECT_TRUE(niceTicks(1.0, 1.0, 5).empty());
    EXPECT_EQ(tickLabel(0.5, 0.5), "0.5");
    EXPECT_EQ(tickLabel(2.0, 1.0), "2");
    EXPECT_EQ(tickLabel(-1e-17, 0.2), "0.0");
    const std::vector<double> d = decadeTicks(-2.3, 1.5, 8);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_DOUBLE_EQ(d.front(), -2.0);
    EXPECT_EQ(decadeLabel(-2.0), "0.01");
    EXPECT_EQ(decadeLabel(6.0), "1e+06");
}

// Issue 23: a plot's y axis labels at least three values. Step 9's energy (0 to 18 J, padded to
// [-1.8, 19.8]) with room for three parts got a step of 10: only 0 and 10.
TEST(PlotLogic, AxisTickStepLabelsAtLeastThreeValues) {
    EXPECT_EQ(niceTicks(-1.8, 19.8, 3).size(), 2u); // what the plots drew before
    const double step = axisTickStep(-1.8, 19.8, 3, 3);
    EXPECT_DOUBLE_EQ(step, 5.0);
    EXPECT_EQ(ticksEvery(-1.8, 19.8, step), (std::vector<double>{0, 5, 10, 15}));
    // Step 9's momentum after the collision: +6 to -6, padded; -5, 0 and 5 at least.
    EXPECT_GE(ticksEvery(-7.2, 7.2, axisTickStep(-7.2, 7.2, 3, 2)).size(), 3u);
    // A flat series (paddedRange gives +-1 around it) and a tiny range still get three.
    for (const PlotRange r : {paddedRange(0.0, 0.0), PlotRange{1e-7, 3e-7}, PlotRange{-2.4, 0.2}}) {
        EXPECT_GE(ticksEvery(r.lo, r.hi, axisTickStep(r.lo, r.hi, 3, 2)).size(), 3u)
            << r.lo << " " << r.hi;
    }
    // Where enough fit, the step is niceTickStep's.
    EXPECT_DOUBLE_EQ(axisTickStep(-0.3, 4.1, 3, 5), niceTickStep(4.4, 5));
}

TEST(PlotLogic, WhileReplayingTheWindowFollowsTheScrubbedTime) {
    // Live (nothing recorded after now): the scrolling window, now at its right edge.
    EXPECT_DOUBLE_EQ(timelineWindow(25.0, 25.0, 10.0).lo, 15.0);
    EXPECT_DOUBLE_EQ(timelineWindow(25.0, 25.0, 10.0).hi, 25.0);
    // Scrubbed back to 20 s of a 40 s recording: now in the middle of the window.
    EXPECT_DOUBLE_EQ(timelineWindow(20.0, 40.0, 10.0).lo, 15.0);
    EXPECT_DOUBLE_EQ(timelineWindow(20.0, 40.0, 10.0).hi, 25.0);
    // Near the newest frame: the window ends at the recording's end, now inside it.
    EXPECT_DOUBLE_EQ(timelineWindow(38.0, 40.0, 10.0).hi, 40.0);
    // Near the start: [0, span].
    EXPECT_DOUBLE_EQ(timelineWindow(1.0, 40.0, 10.0).lo, 0.0);
    EXPECT_DOUBLE_EQ(timelineWindow(1.0, 40.0, 10.0).hi, 10.0);
}

TEST(PlotLogic, ScrollingWindowAndRanges) {
    EXPECT_DOUBLE_EQ(scrollingWindow(3.0, 10.0).lo, 0.0);
    EXPECT_DOUBLE_EQ(scrollingWindow(3.0, 10.0).hi, 10.0);
    EXPECT_DOUBLE_EQ(scrollingWindow(25.0, 10.0).lo, 15.0);
    EXPECT_DOUBLE_EQ(scrollingWindow(25.0, 10.0).hi, 25.0);
    const PlotRange flat = paddedRange(6.0, 6.0);
    EXPECT_LT(flat.lo, 6.0);
    EXPECT_GT(flat.hi, 6.0);
    const PlotRange zero = paddedRange(0.0, 0.0);
    EXPECT_DOUBLE_EQ(zero.lo, -1.0);
}

TEST(PlotLogic, TimeSeriesRingAndTruncate) {
    TimeSeries s(2, 4);
    for (int i = 0; i < 6; ++i) {
        const double v[2] = {double(i), double(-i)};
        s.push(i * 0.5, v);
    }
    ASSERT_EQ(s.size(), 4u);
    EXPECT_DOUBLE_EQ(s.time(0), 1.0);
    EXPECT_DOUBLE_EQ(s.value(3, 1), -5.0);
    EXPECT_EQ(s.firstAtOrAfter(1.6), 2u);
    s.truncateAfter(1.6);
    EXPECT_EQ(s.size(), 2u);
    EXPECT_DOUBLE_EQ(s.time(1), 1.5);
}

TEST(PlotLogic, ColumnExtremesKeepSpikesAndTheLastPoint) {
    // 600 samples across 300 px (two per pixel) of a flat line with one spike up and one down:
    // at most two points per 2 px column survive, the spikes and the last sample among them.
    std::vector<float> xs, ys;
    for (int i = 0; i < 600; ++i) {
        xs.push_back(0.5f * static_cast<float>(i));
        ys.push_back(i == 201 ? 90.0f : i == 402 ? -70.0f : 10.0f);
    }
    const std::vector<std::size_t> kept = columnExtremes(xs, ys, 2.0f);
    EXPECT_LE(kept.size(), 2u * 150u + 1u);
    EXPECT_GE(kept.size(), 150u); // one per column at least
    EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
    EXPECT_EQ(kept.front(), 0u);
    EXPECT_EQ(kept.back(), 599u);
    EXPECT_NE(std::find(kept.begin(), kept.end(), 201u), kept.end());
    EXPECT_NE(std::find(kept.begin(), kept.end(), 402u), kept.end());
    // A short series (points farther apart than a column) is kept whole.
    const std::vector<float> sx{0, 10, 20, 30}, sy{1, 5, 2, 8};
    EXPECT_EQ(columnExtremes(sx, sy, 2.0f), (std::vector<std::size_t>{0, 1, 2, 3}));
    EXPECT_TRUE(columnExtremes({}, {}, 2.0f).empty());
}

TEST(PointOfImpact, TimeOfImpactIsAOverB) {
    // A block moving diagonally towards a wall on the right: the lecture's slide.
    std::vector<Block> blocks(1);
    blocks[0].position = Vec2{9.3, 5.0};
    blocks[0].size = Vec2{1.0, 1.0};
    blocks[0].velocity = Vec2{30.0, 30.0};
    WorldSettings s;
    s.gravity = Vec2{0.0, 0.0};
    s.dt = 0.1;
    Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    const PoiView p = computePoi(blocks, bounds, s, 0.0, 0);
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.axis, 0);
    EXPECT_EQ(p.other, kWallRight);
    EXPECT_NEAR(p.a, 0.2, 1e-12); // face at 9.8, wall at 10
    EXPECT_NEAR(p.b, 3.0, 1e-12);
    EXPECT_NEAR(p.t, 0.2 / 3.0, 1e-12);
    EXPECT_NEAR(p.ghost.x, 9.5, 1e-12);
    EXPECT_NEAR(p.ghost.y, 5.0 + 0.2, 1e-12); // moved along the velocity, not straight back
    EXPECT_NEAR(p.crooked.x, 9.5, 1e-12);
    EXPECT_NEAR(p.crooked.y, 8.0, 1e-12); // moving back along x only keeps the whole y motion
}

// The point of impact uses the velocity the engine moves the block with: gravity, the block's own
// force and drag (v + a·dt), so a thruster's hit is where the engine puts it.
TEST(PointOfImpact, AForcedBlockMovesWithItsFrameVelocity) {
    std::vector<Block> blocks(1);
    blocks[0].position = Vec2{9.2, 5.0};
    blocks[0].size = Vec2{1.0, 1.0};
    blocks[0].mass = 2.0;
    blocks[0].velocity = Vec2{4.0, 0.0};
    blocks[0].force = Vec2{20.0, 0.0}; // a = 10 m/s^2
    WorldSettings s;
    s.gravity = Vec2{0.0, 0.0};
    s.dt = 0.1;
    const Bounds bounds{{0.0, 0.0}, {10.0, 10.0}};
    const PoiView p = computePoi(blocks, bounds, s, 0.0, 0);
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.other, kWallRight);
    EXPECT_NEAR(p.velocity.x, 5.0, 1e-12);      // 4 + 10 * 0.1
    EXPECT_NEAR(p.t, 0.3 / (5.0 * 0.1), 1e-12); // a = 0.3 m to the wall, b = 0.5 m: t = 0.6
    EXPECT_NEAR(p.ghost.x, 9.5, 1e-12);
    // The engine agrees (perfect method, C = 1): at the wall after 0.06 s, then back at 5 m/s for
    // the frame's other 0.04 s, to 9.3. Without the force the POI would have said t = 0.75.
    World world;
    world.bounds = bounds;
    world.settings = s;
    world.blocks = blocks;
    world.step();
    EXPECT_NEAR(world.blocks[0].position.x, 9.3, 1e-12);
    EXPECT_NEAR(world.blocks[0].velocity.x, -5.0, 1e-12);
}

TEST(PointOfImpact, LectureExampleRecordsThePoiOfTheCollision) {
    App app = lectureExample();
    for (int i = 0; i < 45; ++i) stepSimulation(app);
    ASSERT_TRUE(app.sim.run.poi.valid);
    EXPECT_EQ(app.sim.run.poi.block, 0);
    EXPECT_EQ(app.sim.run.poi.other, 1);
    EXPECT_NEAR(app.sim.run.poi.frameStart + app.sim.run.poi.t * app.sim.run.poi.dt, 0.625, 1e-9);
    EXPECT_NEAR(app.sim.run.poi.ghost.x, 7.75, 1e-9); // its right face at 8.25 meets m2's left face
}

TEST(SideBySide, ThreeMethodsFromOneStart) {
    App app = busyScene();
    app.view.show.sideBySide = true;
    for (int i = 0; i < 60; ++i) stepSimulation(app);
    ASSERT_TRUE(app.sim.run.methods.running);
    // The perfect run is the live run when the live method is perfect.
    EXPECT_EQ(stateHash(app.sim.run.methods.run(Method::Perfect).world),
              stateHash(app.sim.world()));
    EXPECT_DOUBLE_EQ(app.sim.run.methods.divergence(Method::Perfect), 0.0);
    EXPECT_EQ(app.sim.run.methods.run(Method::TurnBased).world.settings.method, Method::TurnBased);
    app.view.show.sideBySide = false;
    stepSimulation(app);
    EXPECT_FALSE(app.sim.run.methods.running);
}

// The run of the live method takes the live world's step while it is the live world bit for bit:
// every run's state and figures are those of the three methods stepped on their own, also after
// an edit of the live world parts it from that run (from then on it is stepped by itself).
TEST(SideBySide, TheRunsAreTheMethodsSteppedOnTheirOwn) {
    for (const Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
        App app = busyScene();
        app.sim.world().settings.method = method;
        app.view.show.sideBySide = true;
        MethodsSideBySide own;
        own.start(app.sim.world());
        for (int i = 0; i < 90; ++i) {
            if (i == 40) app.sim.world().blocks[0].velocity.x += 0.5; // a lecturer's edit
            own.step(app.sim.world().settings);
            stepSimulation(app);
            for (const Method m : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
                const MethodRun& a = app.sim.run.methods.run(m);
                const MethodRun& b = own.run(m);
                ASSERT_EQ(stateHash(a.world), stateHash(b.world))
                    << methodName(m) << " frame " << i;
                EXPECT_EQ(a.totals.collisions, b.totals.collisions);
                EXPECT_EQ(a.totals.contacts, b.totals.contacts);
                EXPECT_EQ(a.totals.maxPenetration, b.totals.maxPenetration);
                EXPECT_EQ(a.stats.kineticEnergy, b.stats.kineticEnergy);
                EXPECT_EQ(a.stats.potentialEnergy, b.stats.potentialEnergy);
            }
        }
        // The edit parted the live world from its method's run.
        EXPECT_NE(stateHash(app.sim.run.methods.run(method).world), stateHash(app.sim.world()));
    }
}

// The cost overlay's measurement: a copy of the world is stepped under each method, the world
// itself is left as it was, and the measurement is kept per scene. (What a step costs is not
// asserted: no test reads a clock.)
TEST(CostMeasurement, MeasuresACopyUnderEachMethod) {
    App app = lectureExample();
    const std::uint64_t before = stateHash(app.sim.world());
    CostMeasurement cost;
    EXPECT_FALSE(cost.measured(app.sim.scenePath));
    EXPECT_LT(cost.msPerStep(Method::Perfect), 0.0); // none yet
    cost.measure(app.sim.world(), app.sim.scenePath, 3);
    EXPECT_TRUE(cost.measured(app.sim.scenePath));
    EXPECT_FALSE(cost.measured("other.json"));
    for (const Method m : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
        EXPECT_GE(cost.msPerStep(m), 0.0) << methodName(m);
    }
    EXPECT_EQ(stateHash(app.sim.world()), before);
    EXPECT_EQ(app.sim.world().frame, 0u);
}

TradeoffRow row(const char* engine, const char* scene, double cost, double error) {
    TradeoffRow r;
    r.engine = engine;
    r.scene = scene;
    r.msPerSimulatedSecond = cost;
    r.error = error;
    return r;
}

// The sweep runs on another thread; pollSweep takes its rows (or its error) once it is done.
TEST(CostMeasurement, BackgroundSweepDeliversRowsOrItsError) {
    CostMeasurement cost;
    EXPECT_FALSE(cost.pollSweep());
    cost.startSweep([] { return std::vector<TradeoffRow>{row("perfect", "a", 2.0, 0.1)}; });
    EXPECT_TRUE(cost.sweepRunning());
    EXPECT_TRUE(cost.pollSweep(true));
    EXPECT_FALSE(cost.sweepRunning());
    ASSERT_EQ(cost.rows().size(), 1u);
    EXPECT_EQ(cost.rows()[0].engine, "perfect");
    EXPECT_TRUE(cost.error().empty());

    cost.startSweep([]() -> std::vector<TradeoffRow> { throw std::runtime_error("no scenes"); });
    EXPECT_TRUE(cost.pollSweep(true));
    EXPECT_EQ(cost.error(), "no scenes");
    EXPECT_EQ(cost.rows().size(), 1u); // the last good rows stay

    cost.runSweepNow([] { return std::vector<TradeoffRow>{}; });
    EXPECT_TRUE(cost.rows().empty());
    EXPECT_TRUE(cost.error().empty());
}

TEST(CostMeasurement, ChartRowsByScene) {
    const std::vector<TradeoffRow> rows = {
        row("perfect", "b", 3.0, 0.1), row("turn-based", "a", 1.0, 0.2),
        row("perfect", "b", 1.0, 0.3), row("box2d", "b", 2.0, 0.4)};
    EXPECT_EQ(tradeoffScenes(rows), (std::vector<std::string>{"b", "a"}));
    const auto b = tradeoffRowsOf(rows, "b");
    ASSERT_EQ(b.size(), 3u);
    EXPECT_EQ(b[0]->msPerSimulatedSecond, 1.0);
    EXPECT_EQ(b[1]->msPerSimulatedSecond, 2.0);
    EXPECT_EQ(b[2]->msPerSimulatedSecond, 3.0);
    EXPECT_TRUE(tradeoffRowsOf(rows, "c").empty());
}

} // namespace

// Dash patterns (the plots' second cue besides colour): exact lengths along the line.
TEST(PlotLogic, DashPiecesFollowThePatternAlongTheLine) {
    const std::vector<PlotPoint> straight{{0.0f, 0.0f}, {100.0f, 0.0f}};
    EXPECT_EQ(dashPieces(straight, Dash::Solid, 2.0f).size(), 1u);
    // Dashed, unit 2: 6 px drawn, 4 px left out, so ten dashes [10k, 10k + 6].
    const auto dashes = dashPieces(straight, Dash::Dashed, 2.0f);
    ASSERT_EQ(dashes.size(), 10u);
    for (std::size_t k = 0; k < dashes.size(); ++k) {
        ASSERT_EQ(dashes[k].size(), 2u);
        EXPECT_FLOAT_EQ(dashes[k][0].x, 10.0f * static_cast<float>(k));
        EXPECT_FLOAT_EQ(dashes[k][1].x, 10.0f * static_cast<float>(k) + 6.0f);
    }
    // Dotted, unit 2: 2 px drawn, 3 px left out: twenty dots.
    EXPECT_EQ(dashPieces(straight, Dash::Dotted, 2.0f).size(), 20u);
    // Around a corner the dash goes on: 4 px along x, then 2 px up (6 in all).
    const auto corner = dashPieces({{0.0f, 0.0f}, {4.0f, 0.0f}, {4.0f, 10.0f}}, Dash::Dashed, 2.0f);
    ASSERT_EQ(corner.size(), 2u);
    ASSERT_EQ(corner[0].size(), 3u);
    EXPECT_FLOAT_EQ(corner[0][2].x, 4.0f);
    EXPECT_FLOAT_EQ(corner[0][2].y, 2.0f);
    EXPECT_FLOAT_EQ(corner[1][0].y, 6.0f);  // 4 px left out
    EXPECT_FLOAT_EQ(corner[1][1].y, 10.0f); // cut at the line's end
}
