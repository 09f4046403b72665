// Scene files, format v1: every shipped scene loads and round-trips; every kind of bad file is
// rejected with an error naming its place.
#include "input_limits.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace {

const std::string kScenesDir = SANDBOX_SCENES_DIR;
const std::string kBadDir = std::string(SANDBOX_TEST_DATA_DIR) + "/bad/";

const char* const kShippedScenes[] = {
    "lecture_example_1.json", "lecture_example_2.json", "bouncing_squares.json",
    "newtons_cradle.json",    "resting_stack.json",     "bullet_wall.json",
    "moving_platform.json",   "gas_500.json",
};

Scene loadShipped(const std::string& file) {
    const SceneResult r = loadSceneFile(kScenesDir + "/" + file);
    EXPECT_TRUE(r.scene.has_value()) << r.error.text();
    return r.scene.value_or(Scene{});
}

// Parses `text` as "t.json" and expects an error whose `where` is exactly `where`.
void expectError(const std::string& text, const std::string& where) {
    const SceneResult r = parseScene(text, "t.json");
    ASSERT_FALSE(r.scene.has_value()) << "accepted: " << text;
    EXPECT_EQ(r.error.where, where) << r.error.text();
    EXPECT_FALSE(r.error.message.empty());
}

// A scene with the given world object text and block list text.
std::string sceneText(const std::string& world, const std::string& blocks) {
    return R"({"name": "t", "world": {)" + world + R"(}, "blocks": [)" + blocks + "]}";
}
std::string blocksText(const std::string& blocks) {
    return sceneText("", blocks);
}

TEST(SceneLoad, EveryShippedSceneLoads) {
    for (const char* file : kShippedScenes) {
        SCOPED_TRACE(file);
        const Scene s = loadShipped(file);
        EXPECT_FALSE(s.name.empty());
        EXPECT_FALSE(s.description.empty());
        EXPECT_FALSE(s.blocks.empty());
    }
}

TEST(SceneLoad, LectureExample1) {
    const Scene s = loadShipped("lecture_example_1.json");
    ASSERT_EQ(s.blocks.size(), 2u);
    EXPECT_EQ(s.settings.bounciness, 1.0);
    EXPECT_EQ(s.settings.gravity, Vec2(0, 0));
    EXPECT_EQ(s.blocks[0].mass, 1.0);
    EXPECT_EQ(s.blocks[0].velocity, Vec2(6, 0));
    EXPECT_EQ(s.blocks[1].mass, 2.0);
    EXPECT_EQ(s.blocks[1].velocity, Vec2(0, 0));
    EXPECT_EQ(s.blocks[0].position.y, s.blocks[1].position.y);
}

TEST(SceneLoad, GasHas500Blocks) {
    EXPECT_EQ(loadShipped("gas_500.json").blocks.size(), 500u);
}

TEST(SceneLoad, DefaultsAndKinds) {
    const SceneResult r = parseScene(
        R"({"name": "d", "blocks": [{"position": [1, 1], "size": 2},
            {"position": [5, 1], "size": [1, 2], "mass": "static", "velocity": [3, 0]},
            {"position": [8, 1], "size": 1, "mass": "kinematic", "velocity": [0, 1]}]})",
        "d.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    const Scene& s = *r.scene;
    EXPECT_EQ(s.bounds.min, Vec2(0, 0));
    EXPECT_EQ(s.bounds.max, Vec2(20, 12));
    EXPECT_EQ(s.settings.gravity, Vec2(0, -9.81));
    EXPECT_EQ(s.settings.bounciness, 1.0);
    EXPECT_EQ(s.settings.method, Method::Perfect);
    EXPECT_EQ(s.settings.dt, 1.0 / 60.0);
    EXPECT_EQ(s.settings.substeps, 1);
    EXPECT_EQ(s.blocks[0].size, Vec2(2, 2));
    EXPECT_EQ(s.blocks[0].mass, 1.0);
    EXPECT_EQ(s.blocks[0].kind, BodyKind::Dynamic);
    EXPECT_EQ(s.blocks[1].kind, BodyKind::Static);
    EXPECT_EQ(s.blocks[2].kind, BodyKind::Kinematic);

    const World w = makeWorld(s);
    ASSERT_EQ(w.blocks.size(), 3u);
    EXPECT_EQ(w.blocks[0].mass, 1.0);
    EXPECT_EQ(w.blocks[1].mass, kInfiniteMass);
    EXPECT_EQ(w.blocks[1].velocity, Vec2(0, 0)); // a static block never moves
    EXPECT_EQ(w.blocks[2].mass, kInfiniteMass);
    EXPECT_EQ(w.blocks[2].velocity, Vec2(0, 1));
    EXPECT_EQ(w.settings.dt, s.settings.dt);
    EXPECT_EQ(w.bounds.max, s.bounds.max);
}

TEST(SceneLoad, TouchingBlocksAndOverlappingStaticsAreFine) {
    const std::string stack = R"({"position": [5, 0.5], "size": 1}, {"position": [5, 1.5],
        "size": 1}, {"position": [6, 0.5], "size": 1}, {"position": [5.5, 2.5], "size": 1})";
    EXPECT_TRUE(parseScene(blocksText(stack), "t.json").scene);
    const std::string statics = R"({"position": [5, 5], "size": 2, "mass": "static"},
        {"position": [5.5, 5.5], "size": 2, "mass": "static"})";
    EXPECT_TRUE(parseScene(blocksText(statics), "t.json").scene);
    // Flush against every wall.
    const std::string corners = R"({"position": [0.5, 0.5], "size": 1},
        {"position": [19.5, 11.5], "size": 1})";
    EXPECT_TRUE(parseScene(blocksText(corners), "t.json").scene);
}

// ---- Round trips ----

TEST(SceneRoundTrip, ShippedScenes) {
    for (const char* file : kShippedScenes) {
        SCOPED_TRACE(file);
        const Scene s = loadShipped(file);
        const SceneResult again = parseScene(sceneToJson(s), "saved.json");
        ASSERT_TRUE(again.scene) << again.error.text();
        EXPECT_TRUE(*again.scene == s);
    }
}

// Random blocks, one per cell of a grid (so none overlap), with awkward numbers and names.
Scene randomScene(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene s;
    s.name = "random \"scene\" \\ with ünïcode";
    s.description = "line one\nline two\ttab";
    s.bounds.min = {-3.1 * unit(rng), -2.7 * unit(rng)};
    s.bounds.max = {s.bounds.min.x + 50.0, s.bounds.min.y + 30.0};
    s.settings.gravity = {unit(rng) - 0.5, -9.81 * unit(rng)};
    s.settings.bounciness = unit(rng);
    s.settings.dt = 1.0 / (30.0 + 90.0 * unit(rng));
    s.settings.substeps = 1 + static_cast<int>(rng() % 8);
    s.settings.method = static_cast<Method>(rng() % 3);
    for (int i = 0; i < 10; ++i) {
        for (int j = 0; j < 6; ++j) {
            BlockDef b;
            const Vec2 cell = s.bounds.min + Vec2(5.0 * i + 2.5, 5.0 * j + 2.5);
            b.size = {0.1 + 3.0 * unit(rng), 0.1 + 3.0 * unit(rng)};
            b.position = cell + Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
            b.velocity = {1e3 * (unit(rng) - 0.5), 1e-3 * (unit(rng) - 0.5)};
            const auto kind = rng() % 4;
            b.kind = kind == 1 ? BodyKind::Static
                               : (kind == 2 ? BodyKind::Kinematic : BodyKind::Dynamic);
            b.mass = b.kind == BodyKind::Dynamic ? 1e-3 + 1e3 * unit(rng) : 1.0;
            if (rng() % 2) b.name = "b" + std::to_string(i) + "," + std::to_string(j);
            if (rng() % 2) b.color = "#a0B0c0";
            s.blocks.push_back(b);
        }
    }
    return s;
}

TEST(SceneRoundTrip, RandomSceneThroughText) {
    for (unsigned seed = 1; seed <= 5; ++seed) {
        const Scene s = randomScene(seed);
        const SceneResult again = parseScene(sceneToJson(s), "random.json");
        ASSERT_TRUE(again.scene) << again.error.text();
        EXPECT_TRUE(*again.scene == s) << "seed " << seed;
    }
}

TEST(SceneRoundTrip, EmptyScene) {
    Scene s;
    s.name = "nothing here";
    const SceneResult again = parseScene(sceneToJson(s), "empty.json");
    ASSERT_TRUE(again.scene) << again.error.text();
    EXPECT_TRUE(*again.scene == s);
}

TEST(SceneRoundTrip, RandomSceneThroughFile) {
    const Scene s = randomScene(42);
    const std::string path = testing::TempDir() + "scene_roundtrip.json";
    std::string error;
    ASSERT_TRUE(saveSceneFile(s, path, &error)) << error;
    const SceneResult again = loadSceneFile(path);
    ASSERT_TRUE(again.scene) << again.error.text();
    EXPECT_TRUE(*again.scene == s);
    std::remove(path.c_str());
}

TEST(SceneRoundTrip, SaveToMissingDirectoryFailsCleanly) {
    std::string error;
    EXPECT_FALSE(saveSceneFile(Scene{}, "/nonexistent-dir/x/scene.json", &error));
    EXPECT_NE(error.find("/nonexistent-dir/x/scene.json"), std::string::npos) << error;
}

TEST(SceneRoundTrip, WorldBackToScene) {
    const Scene s = loadShipped("moving_platform.json");
    World w = makeWorld(s);
    EXPECT_TRUE(sceneFromWorld(w, s) == s);
    w.blocks[1].position.y += 0.25;
    const Scene moved = sceneFromWorld(w, s);
    EXPECT_EQ(moved.blocks[1].position.y, s.blocks[1].position.y + 0.25);
    EXPECT_EQ(moved.blocks[1].name, s.blocks[1].name);
    EXPECT_EQ(moved.blocks[1].color, s.blocks[1].color);
    EXPECT_EQ(moved.blocks[0].kind, BodyKind::Kinematic);
}

// ---- Bad files: each names its place ----

TEST(SceneBadFile, MissingFile) {
    const SceneResult r = loadSceneFile(kBadDir + "does_not_exist.json");
    ASSERT_FALSE(r.scene);
    EXPECT_EQ(r.error.where, kBadDir + "does_not_exist.json");
    const SceneResult dir = loadSceneFile(kBadDir);
    ASSERT_FALSE(dir.scene);
    EXPECT_EQ(dir.error.where, kBadDir);
}

// The fixtures in tests/data/bad/ (also used by the sandbox-cli tests).
TEST(SceneBadFile, Fixtures) {
    const std::pair<const char*, const char*> cases[] = {
        {"empty.json", ":1:1"},
        {"truncated.json", ":4:25"},
        {"not_json.json", ":1:2"},
        {"binary.json", ":1:1"},
        {"number_overflow.json", ":4:50"},
        {"wrong_type.json", ": blocks[1].position"},
        {"missing_name.json", ": (top level)"},
        {"missing_position.json", ": blocks[0]"},
        {"unknown_key_block.json", ": blocks[1].friction"},
        {"bounciness_out_of_range.json", ": world.bounciness"},
        {"overlap.json", ": blocks[2]"},
        {"out_of_bounds.json", ": blocks[1]"},
    };
    for (const auto& [file, place] : cases) {
        SCOPED_TRACE(file);
        const SceneResult r = loadSceneFile(kBadDir + file);
        ASSERT_FALSE(r.scene);
        EXPECT_EQ(r.error.where, kBadDir + file + place) << r.error.text();
    }
}

TEST(SceneBadFile, OverlapNamesBothBlocks) {
    const SceneResult r = loadSceneFile(kBadDir + "overlap.json");
    ASSERT_FALSE(r.scene);
    EXPECT_NE(r.error.message.find("blocks[1]"), std::string::npos) << r.error.text();
    EXPECT_NE(r.error.message.find("\"B\""), std::string::npos) << r.error.text();
}

TEST(SceneBadFile, SyntaxErrors) {
    expectError("{\"name\": \"x\",\n \"blocks\": [}", "t.json:2:13");
    expectError("{\"name\": \"x\", \"blocks\": [],}", "t.json:1:28");
    expectError("   \n\t ", "t.json:2:3");
    expectError(std::string("{\"name\": \"a\0b\", \"blocks\": []}", 29), "t.json:1:12");
    expectError("{\"name\": \"x\", \"blocks\": [], \"name\": \"y\"}", "t.json:1:29"); // duplicate
    expectError("{\"name\": NaN, \"blocks\": []}", "t.json:1:10");
    expectError("{\"name\": \"x\", \"blocks\": [{\"position\": [1, Infinity]", "t.json:1:43");
}

TEST(SceneBadFile, JunkAfterANulByteIsNotIgnored) {
    // nlohmann stops reading at a NUL byte; the loader must not accept the text before it.
    expectError(std::string("{\"name\": \"x\", \"blocks\": []}\0junk", 31), "t.json:1:28");
}

TEST(SceneBadFile, AbsurdMagnitudesNameTheirField) {
    expectError(R"({"name": "x", "world": {"dt": 1e300}, "blocks": []})", "t.json: world.dt");
    expectError(R"({"name": "x", "blocks": [{"position": [1, 1], "size": 1, "mass": 1e300}]})",
                "t.json: blocks[0].mass");
    expectError(
        R"({"name": "x", "blocks": [{"position": [1, 1], "size": 1, "velocity": [1e10, 0]}]})",
        "t.json: blocks[0].velocity[0]");
    expectError(R"({"name": "x", "world": {"gravity": [0, -1e12]}, "blocks": []})",
                "t.json: world.gravity[1]");
}

TEST(SceneBadFile, DeepNesting) {
    // 100,000 levels must neither overflow the stack nor take long.
    expectError(std::string(100000, '['), "t.json:1:65");
    expectError("{\"name\": \"x\", \"blocks\": [" + std::string(100000, '{'), "t.json:1:88");
}

TEST(SceneBadFile, WrongTypes) {
    expectError("[]", "t.json: (top level)");
    expectError(R"({"name": 3, "blocks": []})", "t.json: name");
    expectError(R"({"name": "x", "description": [], "blocks": []})", "t.json: description");
    expectError(R"({"name": "x", "blocks": {}})", "t.json: blocks");
    expectError(R"({"name": "x", "world": [], "blocks": []})", "t.json: world");
    expectError(blocksText("3"), "t.json: blocks[0]");
    expectError(blocksText(R"({"position": [1], "size": 1})"), "t.json: blocks[0].position");
    expectError(blocksText(R"({"position": [1, "2"], "size": 1})"),
                "t.json: blocks[0].position[1]");
    expectError(blocksText(R"({"position": [1, 1], "size": "big"})"), "t.json: blocks[0].size");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "velocity": null})"),
                "t.json: blocks[0].velocity");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "mass": "heavy"})"),
                "t.json: blocks[0].mass");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "color": "red"})"),
                "t.json: blocks[0].color");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "name": 7})"),
                "t.json: blocks[0].name");
    expectError(sceneText(R"("method": "exact")", ""), "t.json: world.method");
    expectError(sceneText(R"("substeps": 2.5)", ""), "t.json: world.substeps");
    expectError(sceneText(R"("gravity": "down")", ""), "t.json: world.gravity");
}

TEST(SceneBadFile, MissingRequiredKeys) {
    expectError(R"({"blocks": []})", "t.json: (top level)");
    expectError(R"({"name": "x"})", "t.json: (top level)");
    expectError(blocksText(R"({"size": 1})"), "t.json: blocks[0]");
    expectError(blocksText(R"({"position": [1, 1]})"), "t.json: blocks[0]");
}

TEST(SceneBadFile, UnknownKeys) {
    expectError(R"({"name": "x", "blocks": [], "gravity": [0, 0]})", "t.json: gravity");
    expectError(sceneText(R"("friction": 0.5)", ""), "t.json: world.friction");
    expectError(blocksText(R"({"position": [1, 1], "size": 1}, {"position": [3, 1], "size": 1,
        "angle": 0})"),
                "t.json: blocks[1].angle");
}

TEST(SceneBadFile, NumbersOutOfRange) {
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "velocity": [1e400, 0]})"),
                "t.json:1:84");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "mass": 0})"),
                "t.json: blocks[0].mass");
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "mass": -2})"),
                "t.json: blocks[0].mass");
    expectError(blocksText(R"({"position": [1, 1], "size": 0})"), "t.json: blocks[0].size");
    expectError(blocksText(R"({"position": [1, 1], "size": [1, -1]})"),
                "t.json: blocks[0].size[1]");
    expectError(sceneText(R"("bounciness": -0.1)", ""), "t.json: world.bounciness");
    expectError(sceneText(R"("bounciness": 1.01)", ""), "t.json: world.bounciness");
    expectError(sceneText(R"("dt": 0)", ""), "t.json: world.dt");
    expectError(sceneText(R"("dt": -0.01)", ""), "t.json: world.dt");
    expectError(sceneText(R"("dt": 5)", ""), "t.json: world.dt");
    expectError(sceneText(R"("substeps": 0)", ""), "t.json: world.substeps");
    expectError(sceneText(R"("substeps": 1001)", ""), "t.json: world.substeps");
    expectError(sceneText(R"("bounds": [0, 0, 0, 10])", ""), "t.json: world.bounds");
    expectError(sceneText(R"("bounds": [10, 0, 0, 10])", ""), "t.json: world.bounds");
    expectError(sceneText(R"("bounds": [0, 0, 10])", ""), "t.json: world.bounds");
}

// A force is refused when F/m exceeds what gravity may be (1e9 m/s^2): the app's force and mass
// fields check the same rule (limits::accelerationViolation), so what it saves loads back.
TEST(SceneBadFile, ForceOverMassBeyondTheLimit) {
    expectError(blocksText(R"({"position": [1, 1], "size": 1, "mass": 1e-12, "force": [1000, 0]})"),
                "t.json: blocks[0].force");
    const SceneResult ok = parseScene(
        blocksText(R"({"position": [1, 1], "size": 1, "mass": 1e-6, "force": [1000, 0]})"),
        "t.json");
    EXPECT_TRUE(ok.scene) << ok.error.text(); // exactly 1e9 m/s^2
    EXPECT_EQ(limits::accelerationViolation(1000.0, 1e-6), "");
    EXPECT_NE(limits::accelerationViolation(1000.0, 1e-12).find("force / mass"), std::string::npos);
}

// "duration" (s): optional, positive, finite; it round-trips through the writer.
TEST(SceneDuration, ParsedCheckedAndSaved) {
    EXPECT_EQ(loadShipped("lecture_example_1.json").duration, 3.0);
    EXPECT_FALSE(loadShipped("newtons_cradle.json").duration.has_value());
    const std::string blocks = R"("blocks": [{"position": [1, 1], "size": 1}]})";
    expectError(R"({"name": "t", "duration": 0, )" + blocks, "t.json: duration");
    expectError(R"({"name": "t", "duration": -1, )" + blocks, "t.json: duration");
    expectError(R"({"name": "t", "duration": "3 s", )" + blocks, "t.json: duration");
    expectError(R"({"name": "t", "duration": 1e300, )" + blocks, "t.json: duration");
    const SceneResult r = parseScene(R"({"name": "t", "duration": 2.5, )" + blocks, "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    EXPECT_EQ(r.scene->duration, 2.5);
    const SceneResult again = parseScene(sceneToJson(*r.scene), "saved.json");
    ASSERT_TRUE(again.scene) << again.error.text();
    EXPECT_EQ(*again.scene, *r.scene);
}

TEST(SceneBadFile, Overlaps) {
    // Dynamic on dynamic, dynamic in a static, kinematic in a static; the later block is named.
    expectError(blocksText(R"({"position": [5, 5], "size": 1}, {"position": [5.9, 5.9],
        "size": 1})"),
                "t.json: blocks[1]");
    expectError(blocksText(R"({"position": [10, 1], "size": [20, 2], "mass": "static"},
        {"position": [3, 5], "size": 1}, {"position": [8, 2.4], "size": 1})"),
                "t.json: blocks[2]");
    expectError(blocksText(R"({"position": [8, 2.4], "size": 1, "mass": "kinematic"},
        {"position": [3, 5], "size": 1}, {"position": [10, 1], "size": [20, 2],
        "mass": "static"})"),
                "t.json: blocks[2]");
    // A small block inside a big one, deep in a tall column of touching blocks.
    std::string column;
    for (int i = 0; i < 11; ++i)
        column += R"({"position": [1, )" + std::to_string(i + 0.5) + R"(], "size": 1}, )";
    expectError(blocksText(column + R"({"position": [1.2, 7.3], "size": 0.1})"),
                "t.json: blocks[11]");
}

TEST(SceneBadFile, OutOfBounds) {
    expectError(blocksText(R"({"position": [0.4, 5], "size": 1})"), "t.json: blocks[0]");
    expectError(blocksText(R"({"position": [5, 11.6], "size": 1})"), "t.json: blocks[0]");
    expectError(blocksText(R"({"position": [5, 5], "size": 1, "mass": "static"},
        {"position": [30, 5], "size": 1, "mass": "static"})"),
                "t.json: blocks[1]");
}

// 200,000 blocks in one touching column: the overlap check must not be quadratic.
TEST(SceneLimits, TwoHundredThousandBlocks) {
    std::string blocks;
    blocks.reserve(200000 * 40);
    for (int i = 0; i < 200000; ++i)
        blocks += (i ? "," : "") + std::string(R"({"position": [0.5, )") + std::to_string(i) +
                  R"(.5], "size": 1})";
    const std::string text =
        R"({"name": "tall", "world": {"bounds": [0, 0, 1, 200000]}, "blocks": [)" + blocks + "]}";
    const SceneResult ok = parseScene(text, "t.json");
    ASSERT_TRUE(ok.scene) << ok.error.text();
    EXPECT_EQ(ok.scene->blocks.size(), 200000u);
    const std::string tooMany =
        text.substr(0, text.size() - 2) + R"(, {"position": [0.5, 0.5], "size": 1}]})";
    expectError(tooMany, "t.json: blocks");
}

TEST(SceneLimits, FileOver64MiB) {
    const std::string text = R"({"name": "big", "blocks": []})" + std::string(64 << 20, ' ');
    expectError(text, "t.json");
}

} // namespace
