// The scene keys of issue 16 (world: resolve, integrator, mistakes, drag; block: force): parsed,
// rejected with their JSON path, written back and read again to the same scene.
#include "scene.h"

#include <gtest/gtest.h>

#include <string>

namespace {

std::string sceneText(const std::string& world, const std::string& block = "") {
    return R"({"name": "t", "world": {)" + world +
           R"(}, "blocks": [{"position": [5, 5], "size": 1, "mass": 2)" + block + "}]}";
}

SceneError errorOf(const std::string& text) {
    const SceneResult r = parseScene(text, "t.json");
    EXPECT_FALSE(r.scene) << "expected an error for " << text;
    return r.error;
}

TEST(SceneKeys, DefaultsReproduceTheOldBehaviour) {
    const SceneResult r = parseScene(sceneText(""), "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    const WorldSettings& s = r.scene->settings;
    EXPECT_EQ(s.resolve, Resolve::Momentum);
    EXPECT_EQ(s.integrator, Integrator::SemiImplicitEuler);
    EXPECT_EQ(s.mistakes, 0);
    EXPECT_EQ(s.drag, 0.0);
    EXPECT_EQ(r.scene->blocks[0].force, Vec2{});
}

TEST(SceneKeys, EveryKeyParses) {
    const SceneResult r =
        parseScene(sceneText(R"("resolve": "reflect", "integrator": "exact", "drag": 1.2,
                     "mistakes": ["no-approach-test", "discrete"])",
                             R"(, "force": [2, -1])"),
                   "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    const WorldSettings& s = r.scene->settings;
    EXPECT_EQ(s.resolve, Resolve::Reflect);
    EXPECT_EQ(s.integrator, Integrator::Exact);
    EXPECT_EQ(s.drag, 1.2);
    EXPECT_TRUE(s.has(Mistake::Discrete));
    EXPECT_TRUE(s.has(Mistake::NoApproachTest));
    EXPECT_FALSE(s.has(Mistake::MoveBack));
    EXPECT_FALSE(s.has(Mistake::FirstFound));
    EXPECT_EQ(r.scene->blocks[0].force, Vec2(2, -1));
    EXPECT_EQ(makeWorld(*r.scene).blocks[0].force, Vec2(2, -1));
}

TEST(SceneKeys, BadValuesNameTheirPlace) {
    EXPECT_EQ(errorOf(sceneText(R"("resolve": "newton")")).where, "t.json: world.resolve");
    EXPECT_EQ(errorOf(sceneText(R"("resolve": 1)")).where, "t.json: world.resolve");
    EXPECT_EQ(errorOf(sceneText(R"("integrator": "rk4")")).where, "t.json: world.integrator");
    EXPECT_EQ(errorOf(sceneText(R"("mistakes": "discrete")")).where, "t.json: world.mistakes");
    EXPECT_EQ(errorOf(sceneText(R"("mistakes": ["discrete", "typo"])")).where,
              "t.json: world.mistakes[1]");
    const SceneError twice = errorOf(sceneText(R"("mistakes": ["discrete", "discrete"])"));
    EXPECT_EQ(twice.where, "t.json: world.mistakes[1]");
    EXPECT_NE(twice.message.find("twice"), std::string::npos);
    EXPECT_EQ(errorOf(sceneText(R"("drag": -1)")).where, "t.json: world.drag");
    EXPECT_EQ(errorOf(sceneText(R"("drag": 1e7)")).where, "t.json: world.drag");
    EXPECT_EQ(errorOf(sceneText("", R"(, "force": [1])")).where, "t.json: blocks[0].force");
    EXPECT_EQ(errorOf(sceneText("", R"(, "force": [1e10, 0])")).where,
              "t.json: blocks[0].force[0]");
    // F/m beyond 1e9 m/s^2: 5e8 N on 0.1 kg.
    EXPECT_EQ(errorOf(R"({"name": "t", "blocks": [{"position": [5, 5], "size": 1, "mass": 0.1,
                          "force": [5e8, 0]}]})")
                  .where,
              "t.json: blocks[0].force");
    EXPECT_EQ(errorOf(R"({"name": "t", "blocks": [{"position": [5, 5], "size": 1,
                          "mass": "static", "force": [1, 0]}]})")
                  .where,
              "t.json: blocks[0].force");
    EXPECT_EQ(errorOf(sceneText(R"("friction": 1)")).message, "unknown key");
}

TEST(SceneKeys, SaveWritesTheNewKeysAndReadsThemBack) {
    const SceneResult r =
        parseScene(sceneText(R"("resolve": "reflect", "integrator": "explicit-euler", "drag": 0.25,
                     "mistakes": ["move-back", "first-found"])",
                             R"(, "force": [0.5, 3])"),
                   "t.json");
    ASSERT_TRUE(r.scene) << r.error.text();
    const std::string text = sceneToJson(*r.scene);
    for (const char* key :
         {"\"resolve\"", "\"integrator\"", "\"mistakes\"", "\"drag\"", "\"force\""})
        EXPECT_NE(text.find(key), std::string::npos) << key;
    const SceneResult again = parseScene(text, "saved.json");
    ASSERT_TRUE(again.scene) << again.error.text();
    EXPECT_TRUE(*again.scene == *r.scene);
    // And the state of a world keeps the forces.
    const Scene fromWorld = sceneFromWorld(makeWorld(*r.scene), *r.scene);
    EXPECT_TRUE(fromWorld == *r.scene);
}

TEST(SceneKeys, EveryValueOfEveryNameRoundTrips) {
    for (int i = 0; i < static_cast<int>(Integrator::Count); ++i) {
        Scene s;
        s.name = "n";
        s.settings.integrator = static_cast<Integrator>(i);
        s.settings.resolve = static_cast<Resolve>(i % static_cast<int>(Resolve::Count));
        s.settings.mistakes = static_cast<std::uint8_t>(i * 5 % 16);
        const SceneResult again = parseScene(sceneToJson(s), "saved.json");
        ASSERT_TRUE(again.scene) << again.error.text();
        EXPECT_TRUE(*again.scene == s) << i;
    }
}

} // namespace
