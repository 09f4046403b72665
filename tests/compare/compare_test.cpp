// The comparison (app/compare/compare.h): the reference's own trace is the same, differences
// are found at their frame with their block and size, a resting block's velocity is excused,
// the default tolerance is a thousandth of the smallest block, and variants are told apart.
#include "compare.h"
#include "report.h"
#include "scene_json.h"
#include "settings_table.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

Scene loadScene(const std::string& name) {
    const SceneResult r = loadSceneFile(SANDBOX_SCENES_DIR "/" + name + ".json");
    EXPECT_TRUE(r.scene) << r.error.text();
    return *r.scene;
}

// The trace the scene gives under `settings`, every block, frames 1..frames (SI units), with
// `edit` applied to each row.
template <typename Edit>
Trace traceOf(const Scene& scene, const WorldSettings& settings, int frames, Edit edit) {
    Scene s = scene;
    s.settings = settings;
    World world = makeWorld(s);
    Trace trace;
    trace.source = "made.csv";
    for (int i = 0; i < static_cast<int>(scene.blocks.size()); ++i)
        if (scene.blocks[static_cast<std::size_t>(i)].kind != BodyKind::Static)
            trace.blocks.push_back(i);
    for (int f = 1; f <= frames; ++f) {
        world.step();
        TraceRow row;
        row.frame = f;
        row.line = f + 1;
        for (int b : trace.blocks) {
            row.position.push_back(world.blocks[static_cast<std::size_t>(b)].position);
            row.velocity.push_back(world.blocks[static_cast<std::size_t>(b)].velocity);
        }
        edit(row);
        trace.rows.push_back(row);
    }
    return trace;
}

Trace traceOf(const Scene& scene, const WorldSettings& settings, int frames) {
    return traceOf(scene, settings, frames, [](TraceRow&) {});
}

} // namespace

TEST(Compare, DefaultToleranceIsAThousandthOfTheSmallestBlock) {
    const Scene example = loadScene("lecture_example_1");
    const Tolerance t = traceTolerance(example, example.settings.dt);
    EXPECT_EQ(t.position, 0.001); // 1 m blocks
    EXPECT_EQ(t.velocity, 0.06);  // 0.001 m per 1/60 s frame
    const Scene bullet = loadScene("bullet_wall");
    EXPECT_EQ(traceTolerance(bullet, bullet.settings.dt).position, 0.0001);       // a 0.1 m bullet
    EXPECT_EQ(traceTolerance(example, example.settings.dt, 0.25).position, 0.25); // as given
}

TEST(Compare, TheReferencesOwnTraceIsTheSame) {
    for (const char* name : {"lecture_example_1", "bouncing_squares", "point_of_impact"}) {
        const Scene scene = loadScene(name);
        const WorldSettings ref = referenceSettings(scene, std::nullopt);
        const Trace trace = traceOf(scene, ref, 300);
        const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
        EXPECT_TRUE(c.same()) << name;
        EXPECT_EQ(c.match.maxPositionError, 0.0) << name; // bit for bit
        EXPECT_EQ(c.match.maxVelocityError, 0.0) << name;
        EXPECT_TRUE(c.explaining.empty()); // no diagnosis needed
    }
}

TEST(Compare, SinglePrecisionRoundingIsTheSame) {
    // Every number rounded to float, as a C# engine prints it: within the tolerance.
    const Scene scene = loadScene("bouncing_squares");
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    const Trace trace = traceOf(scene, ref, 600, [](TraceRow& row) {
        for (Vec2& p : row.position) p = {static_cast<float>(p.x), static_cast<float>(p.y)};
        for (Vec2& v : row.velocity) v = {static_cast<float>(v.x), static_cast<float>(v.y)};
    });
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    EXPECT_TRUE(c.same());
    EXPECT_GT(c.match.maxPositionError, 0.0);
    EXPECT_LT(c.match.maxPositionError, 1e-5); // half an ulp of a float near 12 m, at most
}

TEST(Compare, TheFirstDifferenceHasItsFrameBlockAndSize) {
    const Scene scene = loadScene("lecture_example_1");
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    // m2's y off by 0.002 m (twice the tolerance) from frame 20 on.
    const Trace trace = traceOf(scene, ref, 100, [](TraceRow& row) {
        if (row.frame >= 20) row.position[1].y += 0.002;
    });
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    ASSERT_FALSE(c.same());
    const Difference& d = c.match.first();
    EXPECT_EQ(d.frame, 20);
    EXPECT_EQ(d.block, 1);
    EXPECT_EQ(d.axis, 1);
    EXPECT_FALSE(d.velocity);
    EXPECT_NEAR(d.by(), 0.002, 1e-12); // the offset, to the rounding of adding it to 6
    EXPECT_FALSE(c.match.velocity.found());
    EXPECT_EQ(differenceName(scene, d), "m2 = 2 kg's y");
}

TEST(Compare, ARestingBlocksVelocityIsJudgedApartFromItsPosition) {
    // A student printing the velocity before the floor took gravity's g·dt away: the blocks
    // never move, and that is the same.
    const Scene scene = loadScene("resting_stack");
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    const double gdt = 9.81 * ref.dt;
    const Trace trace = traceOf(scene, ref, 120, [&](TraceRow& row) {
        for (Vec2& v : row.velocity) v.y -= gdt;
    });
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    EXPECT_TRUE(c.same());
    EXPECT_TRUE(c.match.resting.found());
    EXPECT_EQ(c.match.resting.frame, 1);
    // The same velocity error on a moving block is a difference.
    const Scene falling = loadScene("bouncing_squares");
    const WorldSettings fref = referenceSettings(falling, std::nullopt);
    const Trace moving = traceOf(falling, fref, 10, [&](TraceRow& row) {
        for (Vec2& v : row.velocity) v.y -= gdt;
    });
    EXPECT_FALSE(compareTrace(falling, fref, moving, traceTolerance(falling, fref.dt)).same());
}

TEST(Compare, AVariantIsDiagnosedWithTheLecturesWords) {
    // The point-of-impact scene run turn-based with move-back, against the perfect reference.
    const Scene scene = loadScene("point_of_impact");
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    WorldSettings student = ref;
    student.method = Method::TurnBased;
    student.set(Mistake::MoveBack, true);
    const Trace trace = traceOf(scene, student, 60);
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    ASSERT_FALSE(c.same());
    ASSERT_FALSE(c.explaining.empty());
    EXPECT_EQ(variantName(c.explaining.front().variant.changes),
              "method turn-based + mistake move-back");
    EXPECT_EQ(c.explaining.front().match.maxPositionError, 0.0);
    // The parting collision: the mover hits the step along y in frame 5; moved back along y.
    EXPECT_TRUE(c.parting.inPartingFrame);
    EXPECT_EQ(c.parting.frame, 5);
    EXPECT_EQ(c.parting.record.axis, 1);
    ASSERT_EQ(c.parting.findings.size(), 1u);
    EXPECT_EQ(c.parting.findings[0].id, "move-back");
    EXPECT_EQ(c.parting.findings[0].slide, mistakeSlide(Mistake::MoveBack));
    const std::vector<std::string> lines = diagnosisLines(c);
    ASSERT_FALSE(lines.empty());
    EXPECT_NE(lines[0].find("pushed back along one axis instead of being put at the point of "
                            "impact"),
              std::string::npos)
        << lines[0];
}

TEST(Compare, NothingExplainsAnInventedTrace) {
    // Blocks that drift sideways for no reason: no variant, no rule.
    const Scene scene = loadScene("lecture_example_1");
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    const Trace trace = traceOf(scene, ref, 60, [](TraceRow& row) {
        row.position[0].y += 0.01 * static_cast<double>(row.frame);
        row.velocity[0].y = 0.6;
    });
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    ASSERT_FALSE(c.same());
    EXPECT_TRUE(c.explaining.empty());
    const std::vector<std::string> lines = diagnosisLines(c);
    bool plain = false;
    for (const std::string& l : lines) plain |= l.find("Nothing the sandbox models") == 0;
    EXPECT_TRUE(plain);
}

TEST(Compare, TheReportNamesEveryWorldKeyOfTheSettingsTable) {
    // The reference's settings are the table's rows (settings_table::cliOrder), in the text and
    // in the JSON as sandbox-cli run --json writes them: a new world key is in the report too.
    Scene scene = loadScene("friction_slide");
    scene.settings.drag = 0.25;
    const WorldSettings ref = referenceSettings(scene, std::nullopt);
    const Trace trace = traceOf(scene, ref, 30);
    const TraceComparison c = compareTrace(scene, ref, trace, traceTolerance(scene, ref.dt));
    const ReportContext context{"friction_slide.json", &scene, &trace};
    const std::string text = reportText(c, context);
    const std::string reference = text.substr(text.find("reference  "));
    const std::string line = reference.substr(0, reference.find('\n'));
    const nlohmann::json json = nlohmann::json::parse(reportJson(c, context));
    for (const settings_table::WorldKey* row : settings_table::cliOrder()) {
        EXPECT_NE(line.find(std::string(row->key) + " "), std::string::npos)
            << row->key << ": " << line;
        ASSERT_TRUE(json["reference"].contains(row->key)) << row->key;
        EXPECT_EQ(json["reference"][row->key], settingJson(*row, ref)) << row->key;
    }
    EXPECT_NE(line.find("friction 0.5"), std::string::npos) << line;
    EXPECT_NE(line.find("drag 0.25"), std::string::npos) << line;
    EXPECT_NE(line.find("dt 0.017 s"), std::string::npos) << line; // seconds, not a rate
    EXPECT_NE(line.find("mistakes none"), std::string::npos) << line;
}
