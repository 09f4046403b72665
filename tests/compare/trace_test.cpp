// The trace reader (app/compare/trace.h): the --trace columns, semicolons and decimal commas,
// gxp units, and every bad CSV refused with its place (line:column and the column's name).
#include "compare_command.h"
#include "trace.h"

#include "says.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace {

Scene lectureExample() {
    const SceneResult r = loadSceneFile(SANDBOX_SCENES_DIR "/lecture_example_1.json");
    EXPECT_TRUE(r.scene) << r.error.text();
    return *r.scene;
}

TraceResult read(const std::string& text, const TraceUnitsSpec& units = {}) {
    const Scene scene = lectureExample();
    std::istringstream in(text);
    return readTrace(in, "trace.csv", scene, scene.settings.dt, units);
}

std::string errorOf(const std::string& text) {
    const TraceResult r = read(text);
    EXPECT_FALSE(r.trace);
    return r.error.text();
}

// The error of reading `text` says `part` (somewhere in it).
::testing::AssertionResult errorSays(const std::string& text, const std::string& part) {
    return says(errorOf(text), part);
}

const char* kHeader = "t,m1 = 1 kg_x,m1 = 1 kg_y,m1 = 1 kg_vx,m1 = 1 kg_vy,m2 = 2 kg_x,"
                      "m2 = 2 kg_y,m2 = 2 kg_vx,m2 = 2 kg_vy\n";

} // namespace

TEST(TraceReader, ReadsTheTraceColumnsOfRun) {
    // As `sandbox-cli run --trace` writes them: quoted "NAME x" columns, totals after.
    const TraceResult r =
        read("t,\"m1 = 1 kg x\",\"m1 = 1 kg y\",\"m1 = 1 kg vx\",\"m1 = 1 kg vy\","
             "\"m2 = 2 kg x\",\"m2 = 2 kg y\",\"m2 = 2 kg vx\",\"m2 = 2 kg vy\","
             "momentum_x,momentum_y,kinetic_energy,potential_energy\n"
             "0.016666666666666666,4.1,6,6,0,8.75,6,0,0,6,0,18,0\n"
             "0.033333333333333333,4.2,6,6,0,8.75,6,0,0,6,0,18,0\n");
    ASSERT_TRUE(r.trace) << r.error.text();
    EXPECT_EQ(r.trace->blocks, (std::vector<int>{0, 1}));
    ASSERT_EQ(r.trace->rows.size(), 2u);
    EXPECT_EQ(r.trace->rows[0].frame, 1);
    EXPECT_EQ(r.trace->rows[1].frame, 2);
    EXPECT_EQ(r.trace->rows[1].line, 3);
    EXPECT_EQ(r.trace->rows[1].position[0].x, 4.2); // exactly as written
    EXPECT_EQ(r.trace->rows[0].velocity[0].x, 6.0);
    ASSERT_EQ(r.trace->notes.size(), 1u); // the totals are not compared, and it says so
    EXPECT_NE(r.trace->notes[0].find("momentum_x"), std::string::npos);
}

TEST(TraceReader, SemicolonsDecimalCommasTabsAndFrameNumbers) {
    const TraceResult semi = read("t;m1 = 1 kg_x;m1 = 1 kg_y;m1 = 1 kg_vx;m1 = 1 kg_vy;"
                                  "m2 = 2 kg.x;m2 = 2 kg.y;m2 = 2 kg.VX;m2 = 2 kg.VY\n"
                                  "0,0166667;4,1;6;6;0;8,75;6;0;0\n");
    ASSERT_TRUE(semi.trace) << semi.error.text();
    EXPECT_EQ(semi.trace->rows[0].frame, 1); // 0.0166667 s is frame 1 at 60 Hz (a float's t)
    EXPECT_EQ(semi.trace->rows[0].position[0].x, 4.1);
    const TraceResult tabs = read("frame\tm1 = 1 kg x\tm1 = 1 kg y\tm1 = 1 kg vx\tm1 = 1 kg vy\t"
                                  "m2 = 2 kg x\tm2 = 2 kg y\tm2 = 2 kg vx\tm2 = 2 kg vy\r\n"
                                  "0\t4\t6\t6\t0\t8,75\t6\t0\t0\r\n"
                                  "3\t4,3\t6\t6\t0\t8,75\t6\t0\t0\r\n");
    ASSERT_TRUE(tabs.trace) << tabs.error.text();
    EXPECT_EQ(tabs.trace->rows[0].frame, 0); // the start
    EXPECT_EQ(tabs.trace->rows[1].frame, 3); // frames may be left out
    EXPECT_EQ(tabs.trace->rows[1].position[0].x, 4.3);
}

TEST(TraceReader, GxpUnitsArePixelsYDownPerFrame) {
    // 50 px/m, the world's top-left corner (0, 12) at pixel (40, 30), dt 1/60 s: m1 at (4.1, 6)
    // is pixel (40 + 4.1·50, 30 + 6·50) = (245, 330); 6 m/s is 6·50/60 = 5 px per frame.
    TraceUnitsSpec units{TraceUnits::Gxp, 50.0, {40.0, 30.0}};
    const TraceResult r =
        read(std::string(kHeader) + "0.0166667,245,330,5,0,477.5,330,0,-2\n", units);
    ASSERT_TRUE(r.trace) << r.error.text();
    const TraceRow& row = r.trace->rows[0];
    // Tolerance: the conversion's own rounding (a few ulps of numbers near 10).
    EXPECT_NEAR(row.position[0].x, 4.1, 1e-12);
    EXPECT_NEAR(row.position[0].y, 6.0, 1e-12);
    EXPECT_NEAR(row.velocity[0].x, 6.0, 1e-12);
    EXPECT_NEAR(row.velocity[1].y, 2.4, 1e-12); // -2 px/frame down is 2.4 m/s up
    const Scene scene = lectureExample();
    const Vec2 px = positionToPixels({4.1, 6.0}, scene.bounds, units);
    EXPECT_NEAR(px.x, 245.0, 1e-9);
    EXPECT_NEAR(px.y, 330.0, 1e-9);
}

TEST(TraceReader, BadFilesNameTheirPlace) {
    EXPECT_EQ(errorOf(""), "trace.csv:1:1: empty file: a trace has a header row (t, then NAME_x, "
                           "NAME_y, NAME_vx, NAME_vy per block) and one row per frame");
    EXPECT_TRUE(errorSays("0.1,4,6,6,0\n", "trace.csv:1:1: no header row"));
    EXPECT_TRUE(errorSays("time_s,m1 = 1 kg_x\n1,2\n", "trace.csv:1:1: no time column"));
    // A block of the scene missing from the trace is named.
    EXPECT_TRUE(errorSays("t,m1 = 1 kg_x,m1 = 1 kg_y,m1 = 1 kg_vx,m1 = 1 kg_vy\n0.1,1,2,3,4\n",
                          "trace.csv:1: no columns for block 'm2 = 2 kg'"));
    EXPECT_TRUE(errorSays("t,m1 = 1 kg_x,m1 = 1 kg_y,m1 = 1 kg_vx,m2 = 2 kg_x,m2 = 2 kg_y,"
                          "m2 = 2 kg_vx,m2 = 2 kg_vy\n",
                          "block 'm1 = 1 kg' has no column 'm1 = 1 kg_vy'"));
    // Text in a number: line 3, column 14 (the field's first byte), the column's name.
    EXPECT_EQ(errorOf(std::string(kHeader) + "0.0166667,4.1,6,6,0,8.75,6,0,0\n" +
                      "0.0333333,4.2,six,6,0,8.75,6,0,0\n"),
              "trace.csv:3:15: column 'm1 = 1 kg_y': 'six' is not a number");
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.0166667,NaN,6,6,0,8.75,6,0,0\n",
                          "trace.csv:2:11: column 'm1 = 1 kg_x': 'NaN' is not a number (NaN"));
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.0166667,inf,6,6,0,8.75,6,0,0\n",
                          "trace.csv:2:11: column 'm1 = 1 kg_x': 'inf' is not a finite number"));
    EXPECT_EQ(errorOf(std::string(kHeader) + "0.0166667,,6,6,0,8.75,6,0,0\n"),
              "trace.csv:2:11: column 'm1 = 1 kg_x': empty");
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.0166667,1e300,6,6,0,8.75,6,0,0\n",
                          "trace.csv:2:11: column 'm1 = 1 kg_x': must be from -1e9 to 1e9 m"));
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.0166667,4,6,6,0,8.75\n",
                          "trace.csv:2:23: 6 fields, the header (line 1) has 9"));
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.0333333,4,6,6,0,8.75,6,0,0\n" +
                              "0.0166667,4,6,6,0,8.75,6,0,0\n",
                          "trace.csv:3:1: column 't': frame 1 does not come after frame 2"));
    EXPECT_TRUE(errorSays(std::string(kHeader) + "0.025,4,6,6,0,8.75,6,0,0\n",
                          "trace.csv:2:1: column 't': 0.025 s is not the end of a frame"));
    EXPECT_TRUE(errorSays("t,\"m1 = 1 kg_x\n", "trace.csv:1:3: a quote that does not close"));
    EXPECT_TRUE(errorSays(kHeader, "trace.csv:2: no rows after the header"));
    // Control bytes in a column's name are never echoed raw.
    const std::string escaped =
        errorOf(std::string(kHeader) + "0.0166667,\x1b]0;owned\x07,6,6,0,8.75,6,0,0\n");
    EXPECT_EQ(escaped.find('\x1b'), std::string::npos);
    EXPECT_NE(escaped.find("\\x1b"), std::string::npos);
}

TEST(TraceReader, TenMegabytesOfColumnsAreRefusedAtTheFirstMebibyte) {
    std::string wide = "t";
    while (wide.size() < 10'000'000) wide += ",column_that_names_no_block";
    const std::string error = errorOf(wide + "\n0.1\n");
    EXPECT_NE(error.find("trace.csv:1:1048577: a line longer than 1 MiB"), std::string::npos)
        << error;
}

TEST(TraceReader, BadFilesThroughTheCommand) {
    // sandbox-cli compare on files: exit 1, the place on stderr.
    struct Case {
        const char* file;
        const char* place;
    } cases[] = {{"empty.csv", "empty.csv:1:1: empty file"},
                 {"no_header.csv", "no_header.csv:1:1: no header row"},
                 {"missing_block.csv", "missing_block.csv:1: no columns for block 'm2 = 2 kg'"},
                 {"text_in_number.csv", "text_in_number.csv:3:15: column 'm1 = 1 kg_y': 'six'"},
                 {"nan.csv", "nan.csv:3:22: column 'm1 = 1 kg x': 'NaN' is not a number"},
                 {"no_such_file.csv", "no_such_file.csv: no such file"}};
    for (const Case& c : cases) {
        CompareRequest request;
        request.scene = SANDBOX_SCENES_DIR "/lecture_example_1.json";
        request.trace = std::string(SANDBOX_BAD_TRACES_DIR) + "/" + c.file;
        std::ostringstream out, err;
        EXPECT_EQ(compareCommand(request, out, err), 1) << c.file;
        EXPECT_NE(err.str().find(c.place), std::string::npos) << err.str();
        EXPECT_EQ(out.str(), "");
    }
    // A directory and a FIFO are not read (a FIFO could block for ever).
    CompareRequest request;
    request.scene = SANDBOX_SCENES_DIR "/lecture_example_1.json";
    request.trace = SANDBOX_BAD_TRACES_DIR;
    std::ostringstream out, err;
    EXPECT_EQ(compareCommand(request, out, err), 1);
    EXPECT_NE(err.str().find("not a regular file"), std::string::npos) << err.str();
    // 10 MB of columns in a file: refused, nothing hangs.
    const std::string wide = testing::TempDir() + "/wide_trace.csv";
    {
        std::ofstream f(wide);
        f << "t";
        for (int i = 0; i < 800'000; ++i) f << ",column_" << i;
        f << "\n0.1\n";
    }
    request.trace = wide;
    std::ostringstream out2, err2;
    EXPECT_EQ(compareCommand(request, out2, err2), 1);
    EXPECT_NE(err2.str().find("wide_trace.csv:1:1048577: a line longer than 1 MiB"),
              std::string::npos)
        << err2.str();
    std::remove(wide.c_str());
}

TEST(TraceReader, UsageErrorsExitTwo) {
    CompareRequest request;
    request.scene = SANDBOX_SCENES_DIR "/lecture_example_1.json";
    request.trace = std::string(SANDBOX_BAD_TRACES_DIR) + "/empty.csv";
    std::ostringstream out, err;
    request.units = "gxp"; // without --px-per-m
    EXPECT_EQ(compareCommand(request, out, err), 2);
    request.units = "furlongs";
    EXPECT_EQ(compareCommand(request, out, err), 2);
    request.units.reset();
    request.pxPerM = "50"; // without gxp
    EXPECT_EQ(compareCommand(request, out, err), 2);
    request.pxPerM.reset();
    request.method = "exact"; // a bad value: bad input, as run's --method
    EXPECT_EQ(compareCommand(request, out, err), 1);
    EXPECT_NE(err.str().find("--method exact: must be"), std::string::npos);
}

// One rule for the trace's units on both command lines (sandbox-cli compare's --units, the app's
// --trace-units): what is refused, as usage or as a bad value, and what is read.
TEST(TraceUnitsOptions, OneRuleForBothCommandLines) {
    TraceUnitsSpec spec;
    auto refusal = [&](TraceUnitsOptions given) {
        return readTraceUnitsOptions(given, "--trace-units", spec);
    };
    auto r = refusal({"gxp", std::nullopt, std::nullopt});
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->usage);
    EXPECT_EQ(r->flag + " " + r->expected,
              "--trace-units gxp needs --px-per-m N (pixels per metre)");
    r = refusal({"furlongs", std::nullopt, std::nullopt});
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->usage);
    EXPECT_EQ(r->text, "furlongs");
    r = refusal({std::nullopt, std::nullopt, "40,30"});
    ASSERT_TRUE(r);
    EXPECT_TRUE(r->usage);
    EXPECT_EQ(r->expected, "are for --trace-units gxp");
    r = refusal({"gxp", "-5", std::nullopt});
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->usage); // a bad value
    EXPECT_EQ(r->flag, "--px-per-m");
    r = refusal({"gxp", "50", "40"});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->flag, "--px-origin");
    EXPECT_EQ(spec.units, TraceUnits::Si); // nothing read from refused options
    EXPECT_FALSE(refusal({"gxp", "50", "40,30"}));
    EXPECT_EQ(spec.units, TraceUnits::Gxp);
    EXPECT_EQ(spec.pxPerM, 50.0);
    EXPECT_EQ(spec.originPx.x, 40.0);
    EXPECT_EQ(spec.originPx.y, 30.0);
    EXPECT_FALSE(refusal({}));
    EXPECT_EQ(spec.units, TraceUnits::Si);
}
