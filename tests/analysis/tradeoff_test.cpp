// The speed-versus-accuracy sweep: every engine runs every scene, and the exact method's errors
// are at rounding level where the answer is exact (no assertion on cost: that is a time).
#include "tradeoff.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

namespace {

const std::vector<TradeoffRow>& quickRows() {
    static const std::vector<TradeoffRow> rows = [] {
        TradeoffOptions options;
        options.scenesDir = SANDBOX_SCENES_DIR;
        options.quick = true;
        options.peers = false;
        return runTradeoff(options);
    }();
    return rows;
}

} // namespace

TEST(Tradeoff, EveryMethodRunsEveryScene) {
    std::set<std::pair<std::string, std::string>> seen;
    for (const TradeoffRow& r : quickRows()) {
        seen.insert({r.engine, r.scene});
        EXPECT_GT(r.dt, 0.0);
        EXPECT_GE(r.error, 0.0);
        EXPECT_FALSE(r.errorUnit.empty());
    }
    // 3 methods on 6 scenes, and with the exact integrator on the 3 scenes with gravity.
    EXPECT_EQ(seen.size(), 3u * 6u + 3u * 3u);
}

TEST(Tradeoff, PerfectMethodIsExactWhereTheAnswerIsExact) {
    // Tolerances: positions agree to rounding over ~1000 frames (1e-9 m is far above it); the gas
    // conserves energy to rounding and never overlaps (relative 1e-12); the stack never moves.
    for (const TradeoffRow& r : quickRows()) {
        if (r.engine != "perfect") continue;
        if (r.scene == "lecture_example_1" || r.scene == "newtons_cradle") {
            EXPECT_LT(r.error, 1e-9) << r.scene;
        } else if (r.scene == "gas_100") {
            EXPECT_LT(r.error, 1e-12);
        } else if (r.scene == "resting_stack") {
            EXPECT_EQ(r.error, 0.0);
        }
    }
}

TEST(Tradeoff, BounceEnergyErrorShrinksWithTheStep) {
    // Semi-implicit Euler's energy error is first order in dt: 16x smaller dt, clearly smaller.
    double coarse = -1, fine = -1;
    for (const TradeoffRow& r : quickRows())
        if (r.engine == "perfect" && r.scene == "single_bounce" && r.substeps == 1) {
            if (r.dt > 1.0 / 31) coarse = r.error;
            if (r.dt < 1.0 / 479) fine = r.error;
        }
    ASSERT_GT(coarse, 0.0);
    ASSERT_GE(fine, 0.0);
    EXPECT_LT(fine, coarse / 2);
}

TEST(Tradeoff, WritesCsvMarkdownAndChart) {
    std::ostringstream csv, md;
    writeTradeoffCsv(csv, quickRows());
    writeTradeoffMarkdown(md, quickRows());
    EXPECT_EQ(csv.str().rfind("method,scene,dt,substeps,cost_ms_per_simulated_second,error", 0),
              0u);
    EXPECT_NE(md.str().find("## gas_100"), std::string::npos);
    const std::string png = (std::filesystem::temp_directory_path() / "tradeoff_test.png").string();
    std::string error;
    ASSERT_TRUE(writeTradeoffChart(png, quickRows(), &error)) << error;
    EXPECT_GT(std::filesystem::file_size(png), 10000u);
    std::remove(png.c_str());
}

TEST(Tradeoff, TheExactIntegratorMakesThePerfectBounceExactAtEveryFrameRate) {
    // Semi-implicit Euler's bounce energy is off at every dt; the exact integrator's is at
    // rounding (relative 1e-9) at 30 Hz already.
    int exactRows = 0;
    for (const TradeoffRow& r : quickRows()) {
        if (r.scene != "single_bounce" || r.engine.rfind("perfect", 0) != 0) continue;
        if (r.integrator == "exact") {
            ++exactRows;
            EXPECT_EQ(r.engine, "perfect, exact");
            EXPECT_LT(r.error, 1e-9) << "dt " << r.dt;
        } else if (r.substeps == 1) {
            EXPECT_GT(r.error, 1e-4) << "dt " << r.dt;
        }
    }
    EXPECT_EQ(exactRows, 3); // the quick sweep's three frame rates
}

// The sliding block (issue 25): launched at v0 = 6 m/s on the floor with mu = 0.5, it stops
// d = v0^2 / (2·mu·g) = 3.670 m on (lecture, "Application: Platformer": friction).
TEST(Tradeoff, TheSlidingBlockStopsAtTheExactDistance) {
    int exact = 0, euler = 0;
    for (const TradeoffRow& r : quickRows()) {
        if (r.scene != "friction_slide") continue;
        EXPECT_EQ(r.errorUnit, "m, stopping-distance error");
        if (r.integrator == "exact" && r.engine.rfind("move-and-correct", 0) != 0) {
            // Perfect and turn-based find the stop as an event (a stop within a turn): to
            // rounding, 1e-9 m over ~100 frames.
            ++exact;
            EXPECT_LT(r.error, 1e-9) << r.engine << ", dt " << r.dt;
        } else if (r.substeps == 1) {
            // Semi-implicit Euler decelerates in whole steps of mu·g·dt: within one frame's
            // travel v0·dt of the exact stop (it is about half of it).
            ++euler;
            EXPECT_LT(r.error, 6.0 * r.dt) << r.engine << ", dt " << r.dt;
            EXPECT_GT(r.error, 0.0) << r.engine << ", dt " << r.dt;
        }
    }
    EXPECT_EQ(exact, 2 * 3); // perfect and turn-based at the quick sweep's three rates
    EXPECT_EQ(euler, 4 * 3); // every method, and move-and-correct with the exact integrator
}

TEST(Tradeoff, ThePeersSlideWithTheSameFrictionAsTheEngine) {
    // Box2D mixes friction as sqrt(f1·f2), Chipmunk as u1·u2: each is given its shapes' values so
    // the pair's mu is the engine's 0.5. With the same mu their semi-implicit stepping stops the
    // block within one frame's travel v0·dt of the exact distance, as ours does; with Chipmunk's
    // pair at 0.25 (mu on each shape) it would stop 3.67 m further, with Box2D's pair at 0 never.
    TradeoffOptions options;
    options.scenesDir = SANDBOX_SCENES_DIR;
    options.quick = true;
    options.scenes = {"friction_slide"};
    int peerRows = 0;
    for (const TradeoffRow& r : runTradeoff(options)) {
        EXPECT_EQ(r.scene, "friction_slide");
        if (r.engine != "box2d" && r.engine != "chipmunk") continue;
        ++peerRows;
        EXPECT_LT(r.error, 6.0 * r.dt)
            << r.engine << ", dt " << r.dt << ", substeps " << r.substeps;
    }
    if (peerRows == 0) GTEST_SKIP() << "built without Box2D and Chipmunk";
}
