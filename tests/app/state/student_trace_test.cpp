// A student's trace in the app (docs/compare.md): opened on the current scene it goes to the
// first difference and shows the ghost overlay, the timeline and the inspector; the student's
// blocks at a frame; a bad file keeps what was open and says where; a new scene closes it; the
// command line's --compare.
#include "app.h"
#include "options.h"
#include "test_fixtures.h"
#include "trace_opening.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const std::string kScenes = SANDBOX_SCENES_DIR;

// The point-of-impact scene run turn-based (a student's usual engine), `frames` rows, in SI.
std::string writeTurnBasedTrace(const std::string& name, int frames) {
    const fs::path path = fs::temp_directory_path() / ("sandbox_student_trace_" + name + "_" +
                                                       std::to_string(::getpid()) + ".csv");
    SceneResult r = loadSceneFile(kScenes + "/point_of_impact.json");
    EXPECT_TRUE(r.scene);
    r.scene->settings.method = Method::TurnBased;
    World world = makeWorld(*r.scene);
    std::ofstream out(path);
    out << std::setprecision(17) << "t,mover_x,mover_y,mover_vx,mover_vy\n";
    for (int f = 0; f < frames; ++f) {
        world.step();
        const Block& b = world.blocks[0];
        out << world.time << ',' << b.position.x << ',' << b.position.y << ',' << b.velocity.x
            << ',' << b.velocity.y << '\n';
    }
    return path.string();
}

App appOn(const std::string& scene) {
    App app;
    EXPECT_TRUE(loadScene(app, kScenes + "/" + scene + ".json")) << app.ui.messages.error;
    return app;
}

} // namespace

TEST(StudentTrace, OpensAtTheFirstDifferenceWithTheGhostTimelineAndInspector) {
    const std::string trace = writeTurnBasedTrace("open", 40);
    App app = appOn("point_of_impact"); // the perfect method: the turn-based trace parts at 5
    ASSERT_TRUE(openTrace(app, trace)) << app.ui.messages.error;
    ASSERT_TRUE(app.studentTrace.open());
    EXPECT_EQ(app.studentTrace.firstDifference(), 5);
    EXPECT_EQ(app.sim.world().frame, 5u);
    EXPECT_TRUE(app.sim.paused);
    EXPECT_TRUE(app.view.show.ghost);
    EXPECT_TRUE(app.view.show.timeline);
    EXPECT_TRUE(app.view.show.inspector);
    EXPECT_NE(app.ui.messages.note.find("different from frame 5"), std::string::npos)
        << app.ui.messages.note;
    // The diagnosis: the turn-based method.
    ASSERT_FALSE(app.studentTrace.comparison->explaining.empty());
    EXPECT_EQ(variantName(app.studentTrace.comparison->explaining.front().variant.changes),
              "method turn-based");
    // The student's mover at frame 5 stopped at the point of impact (8.75, 3.75); the
    // reference's went on to (10, 5).
    World ghost = app.sim.world();
    ASSERT_TRUE(app.studentTrace.ghostAt(5, ghost));
    EXPECT_NEAR(ghost.blocks[0].position.x, 8.75, 1e-12); // as printed, 17 digits
    EXPECT_NEAR(ghost.blocks[0].position.y, 3.75, 1e-12);
    EXPECT_NEAR(app.sim.world().blocks[0].position.x, 10.0, 1e-12);
    EXPECT_FALSE(app.studentTrace.ghostAt(41, ghost)); // beyond the trace
    // Stepping on, then back to the first difference (the timeline has it).
    for (int i = 0; i < 10; ++i) stepSimulation(app);
    EXPECT_EQ(app.sim.world().frame, 15u);
    ASSERT_TRUE(goToFirstDifference(app));
    EXPECT_EQ(app.sim.world().frame, 5u);
    std::remove(trace.c_str());
}

// The browser opens a trace a step a frame (issue 41): read, then one simulated run a step, the
// progress saying which; at the end the app shows what openTrace shows, the same comparison.
TEST(StudentTrace, TheBrowserComparesOneRunAStepWithTheSameResult) {
    const std::string trace = writeTurnBasedTrace("steps", 40);
    App atOnce = appOn("point_of_impact");
    ASSERT_TRUE(openTrace(atOnce, trace)) << atOnce.ui.messages.error;
    App app = appOn("point_of_impact");
    std::unique_ptr<TraceOpening> opening;
    std::vector<std::string> progress;
    std::string said;
    while (!openFileStep(app, opening, trace, said)) {
        ASSERT_TRUE(opening);
        EXPECT_FALSE(app.studentTrace.open()); // nothing shown before the comparison is over
        progress.push_back(said);
        ASSERT_LT(progress.size(), 200u);
    }
    EXPECT_FALSE(opening);
    ASSERT_GE(progress.size(), 3u); // the reference and the variants, a step each
    const int runs = static_cast<int>(progress.size());
    EXPECT_NE(progress.front().find("Comparing sandbox_student_trace_steps_"), std::string::npos)
        << progress.front();
    EXPECT_NE(progress.front().find(": run 1 of "), std::string::npos) << progress.front();
    const std::string last = ": run " + std::to_string(runs) + " of " + std::to_string(runs);
    EXPECT_NE(progress.back().find(last), std::string::npos) << progress.back();
    ASSERT_TRUE(app.studentTrace.open());
    EXPECT_EQ(app.studentTrace.firstDifference(), atOnce.studentTrace.firstDifference());
    EXPECT_EQ(app.sim.world().frame, atOnce.sim.world().frame);
    EXPECT_TRUE(app.view.show.ghost && app.view.show.timeline && app.view.show.inspector);
    EXPECT_EQ(app.ui.messages.note, atOnce.ui.messages.note);
    const TraceComparison& a = *app.studentTrace.comparison;
    const TraceComparison& b = *atOnce.studentTrace.comparison;
    ASSERT_EQ(a.explaining.size(), b.explaining.size());
    for (std::size_t i = 0; i < a.explaining.size(); ++i) {
        EXPECT_EQ(variantName(a.explaining[i].variant.changes),
                  variantName(b.explaining[i].variant.changes));
        EXPECT_EQ(a.explaining[i].match.hash, b.explaining[i].match.hash);
    }
    EXPECT_EQ(a.match.hash, b.match.hash);
    std::remove(trace.c_str());
}

// A scene opened while the browser compares a trace (the opening's changesAtStart): the
// comparison starts again from its first run on the world as it is now, and ends as openTrace.
TEST(StudentTrace, TheBrowserStartsTheComparisonAgainWhenTheSceneChangesMeanwhile) {
    const std::string trace = writeTurnBasedTrace("again", 40);
    App atOnce = appOn("point_of_impact");
    ASSERT_TRUE(openTrace(atOnce, trace)) << atOnce.ui.messages.error;
    App app = appOn("point_of_impact");
    std::unique_ptr<TraceOpening> opening;
    std::string said;
    ASSERT_FALSE(openFileStep(app, opening, trace, said));
    ASSERT_FALSE(openFileStep(app, opening, trace, said));
    EXPECT_NE(said.find(": run 2 of "), std::string::npos) << said;
    ASSERT_TRUE(loadScene(app, kScenes + "/point_of_impact.json")) << app.ui.messages.error;
    ASSERT_FALSE(openFileStep(app, opening, trace, said));
    EXPECT_NE(said.find(": run 1 of "), std::string::npos) << said; // started again
    int steps = 0;
    while (!openFileStep(app, opening, trace, said)) ASSERT_LT(++steps, 200);
    ASSERT_TRUE(app.studentTrace.open());
    EXPECT_EQ(app.studentTrace.firstDifference(), atOnce.studentTrace.firstDifference());
    EXPECT_EQ(app.studentTrace.comparison->match.hash, atOnce.studentTrace.comparison->match.hash);
    std::remove(trace.c_str());
}

TEST(StudentTrace, TheReferenceIsTheChosenMethodWithoutTheTipsMistakes) {
    const std::string trace = writeTurnBasedTrace("same", 40);
    App app = appOn("mistake_move_back"); // turn-based with move-back
    ASSERT_TRUE(openTrace(app, trace)) << app.ui.messages.error;
    EXPECT_TRUE(app.studentTrace.comparison->same()); // against turn-based without the mistake
    EXPECT_EQ(app.sim.world().settings.mistakes, 0);
    EXPECT_EQ(app.studentTrace.firstDifference(), -1);
    EXPECT_FALSE(goToFirstDifference(app));
    std::remove(trace.c_str());
}

TEST(StudentTrace, ABadFileKeepsWhatWasOpenAndSaysWhere) {
    const std::string trace = writeTurnBasedTrace("bad", 40);
    App app = appOn("point_of_impact");
    ASSERT_TRUE(openTrace(app, trace));
    const fs::path bad =
        fs::temp_directory_path() / ("sandbox_bad_trace_" + std::to_string(::getpid()) + ".csv");
    std::ofstream(bad) << "t,mover_x,mover_y,mover_vx,mover_vy\n0.1,4.4,abc,14,-14\n";
    EXPECT_FALSE(openTrace(app, bad.string()));
    EXPECT_NE(app.ui.messages.error.find(":2:9: column 'mover_y': 'abc' is not a number"),
              std::string::npos)
        << app.ui.messages.error;
    EXPECT_TRUE(app.studentTrace.open()); // the one before stays
    EXPECT_EQ(app.studentTrace.path, trace);
    // A dropped .csv is a trace, anything else a scene; a new scene closes the trace.
    EXPECT_TRUE(isTraceFile("A/B/My_Trace.CSV"));
    EXPECT_FALSE(isTraceFile("scene.json"));
    EXPECT_TRUE(openFile(app, kScenes + "/lecture_example_1.json"));
    EXPECT_FALSE(app.studentTrace.open()); // the ghost overlay draws nothing then
    std::remove(trace.c_str());
    std::remove(bad.c_str());
}

TEST(StudentTrace, TheCommandLineOpensATraceInGxpUnits) {
    const ParsedOptions p =
        parseCommandLine({"sandbox", "point_of_impact", "--compare", "t.csv", "--trace-units",
                          "gxp", "--px-per-m", "50", "--px-origin", "40,30"});
    ASSERT_FALSE(p.exit);
    EXPECT_EQ(p.options.compareTrace, "t.csv");
    EXPECT_EQ(p.options.traceUnits.units, TraceUnits::Gxp);
    EXPECT_EQ(p.options.traceUnits.pxPerM, 50.0);
    EXPECT_EQ(p.options.traceUnits.originPx.x, 40.0);
    EXPECT_EQ(p.options.traceUnits.originPx.y, 30.0);
    const char* noScale[] = {"sandbox", "--compare", "t.csv", "--trace-units", "gxp"};
    EXPECT_EQ(parseOptions(5, noScale).exitCode, 2);
    const char* badOrigin[] = {"sandbox", "--compare",  "t.csv", "--trace-units",
                               "gxp",     "--px-per-m", "50",    "--px-origin",
                               "40"};
    EXPECT_EQ(parseOptions(9, badOrigin).exitCode, 2);
}
