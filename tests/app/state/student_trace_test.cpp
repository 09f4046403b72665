// A student's trace in the app (docs/compare.md): opened on the current scene it goes to the
// first difference and shows the ghost overlay, the timeline and the inspector; the student's
// blocks at a frame; a bad file keeps what was open and says where; a new scene closes it; the
// command line's --compare.
#include "app.h"
#include "options.h"
#include "test_fixtures.h"

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
    EXPECT_NE(app.ui.messages.note.find("different from frame 5"), std::string::npos) << app.ui.messages.note;
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
    EXPECT_NE(app.ui.messages.error.find(":2:9: column 'mover_y': 'abc' is not a number"), std::string::npos)
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
