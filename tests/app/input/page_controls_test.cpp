// The browser page's text and form controls (page_controls.h), without a browser: the state the
// page shows, and each control driving the same state as the panel, refusing what it refuses.
#include "app.h"
#include "page_controls.h"
#include "settings_table.h"
#include "test_fixtures.h"

#include <nlohmann/json.hpp>

#include <algorithm>

#include <gtest/gtest.h>

namespace {

using json = nlohmann::json;

App lectureExample() {
    App app;
    EXPECT_TRUE(loadScene(app, SANDBOX_SCENES_DIR "/lecture_example_1.json"))
        << app.ui.messages.error;
    return app;
}

TEST(PageControls, TheStateThePageShows) {
    App app = lectureExample();
    const json state = json::parse(pageStateJson(app));
    EXPECT_EQ(state["screen"]["scene"], "Lecture example 1");
    EXPECT_EQ(state["screen"]["status"], "perfect method, t = 0 s, paused, 0 collisions");
    const json& c = state["controls"];
    auto world = [&c](const char* key) {
        for (const json& row : c["world"])
            if (row["key"] == key) return row;
        return json();
    };
    EXPECT_EQ(world("method")["value"], "perfect");
    EXPECT_EQ(world("method")["names"].size(), 3u);
    EXPECT_EQ(world("bounciness")["value"], 1.0);
    EXPECT_EQ(world("bounciness")["label"], "Bounciness C");
    EXPECT_EQ(world("gravity")["value"][1], app.sim.world().settings.gravity.y);
    EXPECT_EQ(world("gravity")["labels"][1], "Gravity g, y in m/s²");
    EXPECT_EQ(world("dt")["label"], "Time step dt in s");
    EXPECT_EQ(c["paused"], true);
    EXPECT_EQ(c["lesson"], false);
    EXPECT_EQ(c["block"], -1);
    EXPECT_TRUE(c["mass"].is_null()); // no block selected: no mass to set
    ASSERT_EQ(c["blocks"].size(), app.sim.world().blocks.size());
    EXPECT_EQ(c["blockCount"], app.sim.world().blocks.size());
    EXPECT_EQ(c["blocks"][0], json::array({0, app.sim.blockDisplayName(0)}));
}

TEST(PageControls, SettingCChangesTheWorldsC) {
    App app = lectureExample();
    EXPECT_EQ(applyPageControl(app, "bounciness", "0.5").error, "");
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.5);
    EXPECT_EQ(json::parse(pageStateJson(app))["controls"]["world"][1]["key"], "bounciness");
    EXPECT_EQ(json::parse(pageStateJson(app))["controls"]["world"][1]["value"], 0.5);
    // Refused as the panel refuses it, with the panel's warning; C is kept.
    const PageControlOutcome out = applyPageControl(app, "bounciness", "1.5");
    EXPECT_NE(out.error.find("bounciness C: must be from 0 to 1"), std::string::npos) << out.error;
    EXPECT_EQ(app.ui.typedWarning.message, out.error);
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.5);
    EXPECT_EQ(applyPageControl(app, "bounciness", "half").error, "bounciness C: not a number");
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.5);
}

TEST(PageControls, MethodGravityBlockAndMass) {
    App app = lectureExample();
    EXPECT_EQ(applyPageControl(app, "method", "turn-based").error, "");
    EXPECT_EQ(app.sim.world().settings.method, Method::TurnBased);
    EXPECT_EQ(applyPageControl(app, "method", "fastest").error,
              "method: 'fastest' must be perfect, move-and-correct or turn-based");
    EXPECT_EQ(applyPageControl(app, "gravity-y", "-1.62").error, "");
    EXPECT_EQ(app.sim.world().settings.gravity.y, -1.62);
    EXPECT_NE(applyPageControl(app, "mass", "2").error, ""); // nothing selected
    EXPECT_EQ(applyPageControl(app, "block", "1").error, "");
    EXPECT_EQ(app.sim.selected, 1);
    EXPECT_EQ(applyPageControl(app, "mass", "2").error, "");
    EXPECT_EQ(app.sim.world().blocks[1].mass, 2.0);
    EXPECT_TRUE(app.sim.blocksEdited);
    EXPECT_NE(applyPageControl(app, "mass", "0").error, "");
    EXPECT_EQ(app.sim.world().blocks[1].mass, 2.0);
    EXPECT_NE(applyPageControl(app, "block", "7").error, "");
    EXPECT_EQ(applyPageControl(app, "block", "-1").error, "");
    EXPECT_EQ(app.sim.selected, -1);
}

TEST(PageControls, ButtonsAreTheKeysActions) {
    App app = lectureExample();
    EXPECT_EQ(applyPageControl(app, "play", "").action, Action::TogglePause);
    EXPECT_EQ(applyPageControl(app, "step", "").action, Action::StepOnce);
    EXPECT_EQ(applyPageControl(app, "reset", "").action, Action::Reset);
    EXPECT_EQ(applyPageControl(app, "lesson-next", "").action, Action::LessonNext);
    EXPECT_EQ(applyPageControl(app, "lesson-previous", "").action, Action::LessonPrevious);
    EXPECT_EQ(applyPageControl(app, "no-such", "").error, "no page control 'no-such'");
}

TEST(PageControls, ASceneByItsPath) {
    App app = lectureExample();
    EXPECT_EQ(applyPageControl(app, "scene", SANDBOX_SCENES_DIR "/newtons_cradle.json").error, "");
    EXPECT_EQ(app.sim.scene.name, json::parse(pageStateJson(app))["screen"]["scene"]);
    EXPECT_NE(applyPageControl(app, "scene", "/no/such.json").error, "");
    EXPECT_NE(app.sim.scenePath.find("newtons_cradle"), std::string::npos); // kept
}

} // namespace

namespace {

TEST(PageControls, ManyBlocksListTheFirstHundredAndTheSelectedOne) {
    std::vector<BlockDef> blocks;
    for (int i = 0; i < 300; ++i)
        blocks.push_back(
            testBlock("b" + std::to_string(i), {1.0 + 2.0 * (i % 30), 1.0 + 2.0 * (i / 30)}));
    Scene scene = weightlessScene("many", blocks);
    scene.bounds = Bounds{{0, 0}, {60, 20}};
    App app;
    setScene(app, scene, "many.json");
    app.sim.selected = 250;
    const json c = json::parse(pageStateJson(app))["controls"];
    EXPECT_EQ(c["blockCount"], 300);
    ASSERT_EQ(c["blocks"].size(), kListedBlocks + 1);
    EXPECT_EQ(c["blocks"][99], json::array({99, "b99"}));
    EXPECT_EQ(c["blocks"][100], json::array({250, "b250"}));
}

} // namespace

namespace {

// Issue 37: the page's hidden form has a labelled control for every world key of the settings
// table, and each drives the world as the panel does (refusing what it refuses).
TEST(PageControls, EveryWorldKeyOfTheSettingsTableHasALabelledControl) {
    App app = lectureExample();
    const json world = json::parse(pageStateJson(app))["controls"]["world"];
    std::vector<std::string> keys;
    for (const json& row : world) {
        keys.push_back(row["key"]);
        EXPECT_FALSE(row["label"].get<std::string>().empty()) << row.dump();
    }
    for (const settings_table::WorldKey& row : settings_table::worldKeys())
        EXPECT_EQ(std::count(keys.begin(), keys.end(), row.key), row.inScene ? 1 : 0) << row.key;
}

TEST(PageControls, EachWorldKeysControlSetsItsKey) {
    App app = lectureExample();
    const WorldSettings& w = app.sim.world().settings;
    EXPECT_EQ(applyPageControl(app, "friction", "0.4").error, "");
    EXPECT_EQ(w.friction, 0.4);
    EXPECT_EQ(applyPageControl(app, "drag", "1.2").error, "");
    EXPECT_EQ(w.drag, 1.2);
    EXPECT_EQ(applyPageControl(app, "dt", "0.01").error, "");
    EXPECT_EQ(w.dt, 0.01);
    EXPECT_EQ(applyPageControl(app, "substeps", "4").error, "");
    EXPECT_EQ(w.substeps, 4);
    EXPECT_EQ(applyPageControl(app, "integrator", "exact").error, "");
    EXPECT_EQ(w.integrator, Integrator::Exact);
    EXPECT_EQ(applyPageControl(app, "resolve", "reflect").error, "");
    EXPECT_EQ(w.resolve, Resolve::Reflect);
    EXPECT_EQ(applyPageControl(app, "mistakes", "discrete,move-back").error, "");
    EXPECT_TRUE(w.has(Mistake::Discrete) && w.has(Mistake::MoveBack));
    EXPECT_EQ(applyPageControl(app, "mistakes", "discrete").error, ""); // the set, not an addition
    EXPECT_FALSE(w.has(Mistake::MoveBack));
    const json state = json::parse(pageStateJson(app))["controls"]["world"];
    for (const json& row : state) {
        if (row["key"] == "mistakes") {
            EXPECT_EQ(row["value"], json::array({"discrete"}));
        }
    }
    EXPECT_EQ(applyPageControl(app, "mistakes", "none").error, "");
    EXPECT_EQ(w.mistakes, 0);
    // Refused as the panel refuses, the setting kept.
    EXPECT_EQ(applyPageControl(app, "substeps", "2.5").error,
              "substeps: must be a whole number from 1 to 1000, not 2.5");
    EXPECT_EQ(w.substeps, 4);
    EXPECT_NE(applyPageControl(app, "dt", "5").error.find("dt: must be from 1e-6 to 1 s"),
              std::string::npos);
    EXPECT_EQ(w.dt, 0.01);
    EXPECT_EQ(
        applyPageControl(app, "mistakes", "discrete,typo").error,
        "mistakes: 'typo' must be discrete, move-back, first-found, no-approach-test or none");
    EXPECT_EQ(w.mistakes, 0);
    EXPECT_EQ(applyPageControl(app, "gravity", "0,0").error, "no page control 'gravity'");
}

} // namespace
