// The velocity-space picture (velocity_space.h) and the plots' CSV export (csv.h, csv_export.h)
// without GL: collisions are the reflections the geometry says (checked against the engine's
// own collisions), the pi count follows from the angle between the reflection lines, and a CSV
// written reads back to the same numbers bit for bit.
#include "app.h"
#include "csv_export.h"
#include "scene_library.h"
#include "velocity_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

App sceneApp(const char* name) {
    App app;
    EXPECT_TRUE(loadScene(app, resolveScenePath(name, SANDBOX_SCENES_DIR)))
        << app.ui.messages.error;
    return app;
}

// Relative tolerance for a few floating-point operations on values of order 1 to 1000.
constexpr double kRounding = 1e-12;

void expectNear(Vec2 a, Vec2 b, double scale) {
    EXPECT_NEAR(a.x, b.x, kRounding * scale);
    EXPECT_NEAR(a.y, b.y, kRounding * scale);
}

// A CSV line split at commas (quoted fields may hold commas; the header's do not here).
std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    std::string field;
    bool quoted = false;
    for (const char c : line) {
        if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            out.push_back(field);
            field.clear();
        } else {
            field += c;
        }
    }
    out.push_back(field);
    return out;
}

// The table `text` holds: its header and its numbers (an empty cell reads NaN).
CsvTable parseCsv(const std::string& text) {
    CsvTable table;
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    table.columns = fields(line);
    while (std::getline(in, line)) {
        std::vector<double> row;
        for (const std::string& f : fields(line))
            row.push_back(f.empty() ? std::nan("") : std::strtod(f.c_str(), nullptr));
        table.rows.push_back(row);
    }
    return table;
}

} // namespace

TEST(VelocitySpace, LectureExampleOneCollisionIsTheReflection) {
    App app = sceneApp("lecture_example_1");
    const VelocitySpacePair& pair = app.sim.telemetry.velocitySpace.pair();
    ASSERT_TRUE(pair.valid());
    EXPECT_EQ(pair.m1, 1.0);
    EXPECT_EQ(pair.m2, 2.0);
    const Vec2 before = velocitySpacePoint(pair, 6.0, 0.0);
    // 2·KE = r², p on the line: 1·6 + 2·0 = 6 kg·m/s, KE = 18 J.
    EXPECT_NEAR(momentumOfPoint(pair, before), 6.0, kRounding);
    EXPECT_NEAR(kineticEnergyOfPoint(before), 18.0, kRounding);
    // The elastic collision (v1' = -2, v2' = 4) is the reflection across (1, sqrt(2)).
    expectNear(reflectBlockCollision(pair, before, 1.0), velocitySpacePoint(pair, -2.0, 4.0), 10);
    // C = 0: both at u = 2 (the point on the reflection line); C = 0.5: w' = -0.5·w.
    expectNear(reflectBlockCollision(pair, before, 0.0), velocitySpacePoint(pair, 2.0, 2.0), 10);
    expectNear(reflectBlockCollision(pair, before, 0.5), velocitySpacePoint(pair, 0.0, 3.0), 10);
    // A wall: one coordinate, times -C.
    EXPECT_EQ(reflectWallHit({3.0, 4.0}, true, 1.0), (Vec2{-3.0, 4.0}));
    EXPECT_EQ(reflectWallHit({3.0, 4.0}, false, 0.5), (Vec2{3.0, -2.0}));

    // The path the app records: the start, then the engine's collision, on the same circle
    // and line (C = 1).
    for (int i = 0; i < 60; ++i) stepSimulation(app);
    const auto& samples = app.sim.telemetry.velocitySpace.samples();
    ASSERT_EQ(samples.size(), 2u);
    EXPECT_EQ(samples[0].t, 0.0);
    EXPECT_NEAR(samples[1].t, 0.625, 1e-12); // the time of impact, not the frame's end
    expectNear(velocitySpacePoint(pair, samples[1].v1, samples[1].v2),
               reflectBlockCollision(pair, before, 1.0), 10);
}

TEST(VelocitySpace, HighMassRatioCountsPiFromTheAngle) {
    App app = sceneApp("high_mass_ratio");
    const VelocitySpacePair& pair = app.sim.telemetry.velocitySpace.pair();
    ASSERT_TRUE(pair.valid());
    // theta = atan(sqrt(1 / 1e6)); ceil(pi / theta) - 1 = 3141.
    EXPECT_NEAR(reflectionAngle(pair), std::atan(1e-3), 1e-15);
    EXPECT_EQ(predictedCollisions(pair), 3141);
    EXPECT_NE(velocitySpaceCaption(pair).find("= 3141 collisions"), std::string::npos);
    VelocitySpacePair equal = pair;
    equal.m1 = equal.m2 = 1.0; // theta = pi/4: 3 collisions
    EXPECT_EQ(predictedCollisions(equal), 3);
    VelocitySpacePair hundred = pair;
    hundred.m2 = 100.0; // 31
    EXPECT_EQ(predictedCollisions(hundred), 31);

    // The engine's 3141 collisions, each one a sample of the path, every one a reflection of
    // the one before: across (sqrt(m1), sqrt(m2)) or the small block's wall flipping x.
    for (int i = 0; i < 960; ++i) stepSimulation(app);
    ASSERT_EQ(app.sim.run.totals.collisions, 3141);
    const auto& s = app.sim.telemetry.velocitySpace.samples();
    ASSERT_EQ(s.size(), 3142u);
    int walls = 0, blocks = 0;
    for (std::size_t k = 1; k < s.size(); ++k) {
        const Vec2 a = velocitySpacePoint(pair, s[k - 1].v1, s[k - 1].v2);
        const Vec2 b = velocitySpacePoint(pair, s[k].v1, s[k].v2);
        // The scale of the coordinates: |X| = sqrt(2·KE) = 1000 (the giant at 1 m/s).
        const Vec2 wall = reflectWallHit(a, true, 1.0);
        const Vec2 block = reflectBlockCollision(pair, a, 1.0);
        if (length(b - wall) <= 1e-9 * 1000)
            ++walls;
        else if (length(b - block) <= 1e-9 * 1000)
            ++blocks;
        else
            ADD_FAILURE() << "sample " << k << " is no reflection of the one before";
    }
    EXPECT_EQ(walls + blocks, 3141);
    EXPECT_NEAR(walls, blocks, 1); // they alternate
}

TEST(VelocitySpace, OtherScenesSayWhy) {
    App app = sceneApp("newtons_cradle");
    EXPECT_FALSE(app.sim.telemetry.velocitySpace.pair().valid());
    EXPECT_NE(velocitySpacePair(app.sim.world()).why.find("exactly two dynamic blocks"),
              std::string::npos);
    EXPECT_TRUE(app.sim.telemetry.velocitySpace.samples().empty());
    // Deleting down to two blocks starts a path.
    while (app.sim.world().blocks.size() > 2) {
        app.sim.selected = 0;
        deleteSelected(app);
    }
    stepSimulation(app);
    EXPECT_TRUE(app.sim.telemetry.velocitySpace.pair().valid());
    EXPECT_FALSE(app.sim.telemetry.velocitySpace.samples().empty());
}

TEST(CsvExport, WritesWhatReadsBackExactly) {
    CsvTable t;
    t.columns = {"t (s)", "say \"hi\", then", "v"};
    t.rows = {{0.0, 1.0 / 3.0, -2.5e-300}, {1.0 / 60.0, std::nan(""), 6.02214076e23}};
    const std::string text = csvText(t);
    const std::string header = R"csv("t (s)","say ""hi"", then","v")csv";
    EXPECT_EQ(text.substr(0, text.find('\n')), header);
    const CsvTable back = parseCsv(text);
    ASSERT_EQ(back.rows.size(), 2u);
    EXPECT_EQ(back.rows[0][1], 1.0 / 3.0); // bit for bit (17 significant digits)
    EXPECT_EQ(back.rows[0][2], -2.5e-300);
    EXPECT_EQ(back.rows[1][0], 1.0 / 60.0);
    EXPECT_TRUE(std::isnan(back.rows[1][1]));
    EXPECT_EQ(back.rows[1][2], 6.02214076e23);
}

TEST(CsvExport, PlotsExportNextToSavesWithoutOverwriting) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("sandbox-csv-test-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // A scene file of its own directory: the exports go there.
    const fs::path scene = dir / "example.json";
    fs::copy_file(resolveScenePath("lecture_example_1", SANDBOX_SCENES_DIR), scene);
    App app;
    ASSERT_TRUE(loadScene(app, scene.string())) << app.ui.messages.error;
    for (int i = 0; i < 60; ++i) stepSimulation(app);

    const std::string first =
        exportCsv(app, "momentum", timeSeriesTable(app.sim.telemetry.momentum, {"px", "py"}));
    EXPECT_EQ(first, (dir / "lecture_example_1_momentum.csv").string());
    EXPECT_EQ(app.ui.savedFile, first); // the browser downloads it
    EXPECT_NE(app.ui.messages.note.find(first), std::string::npos);
    const std::string second =
        exportCsv(app, "momentum", timeSeriesTable(app.sim.telemetry.momentum, {"px", "py"}));
    EXPECT_EQ(second, (dir / "lecture_example_1_momentum-2.csv").string()); // never overwritten

    std::ifstream in(first);
    std::stringstream text;
    text << in.rdbuf();
    const CsvTable back = parseCsv(text.str());
    EXPECT_EQ(back.columns, (std::vector<std::string>{"t (s)", "px", "py"}));
    ASSERT_EQ(back.rows.size(), 61u); // the start and 60 frames
    for (std::size_t i = 0; i < back.rows.size(); ++i) {
        EXPECT_EQ(back.rows[i][0], app.sim.telemetry.momentum.time(i));
        EXPECT_NEAR(back.rows[i][1], 6.0, 1e-12); // momentum kept, to rounding
        EXPECT_EQ(back.rows[i][2], 0.0);
    }

    const std::string path = exportCsv(
        app, "velocity space", velocitySpaceTable(app.sim.telemetry.velocitySpace, "m1", "m2"));
    EXPECT_EQ(path, (dir / "lecture_example_1_velocity_space.csv").string());
    std::ifstream vin(path);
    std::stringstream vtext;
    vtext << vin.rdbuf();
    const CsvTable vs = parseCsv(vtext.str());
    ASSERT_EQ(vs.rows.size(), 2u);
    EXPECT_EQ(vs.columns[0], "t (s)");
    EXPECT_EQ(vs.rows[1][1], -2.0);
    EXPECT_EQ(vs.rows[1][2], 4.0);
    EXPECT_EQ(vs.rows[1][4], std::sqrt(2.0) * 4.0);

    // An unwritable place is an error in the panel, and nothing else changes.
    app.sim.scenePath = (dir / "missing" / "x.json").string();
    EXPECT_EQ(exportCsv(app, "energy", timeSeriesTable(app.sim.telemetry.energy, {"k", "p", "t"})),
              "");
    EXPECT_NE(app.ui.messages.error.find("Export failed"), std::string::npos);
    fs::remove_all(dir);
}
