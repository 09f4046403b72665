// The browser page's text and form controls (page_controls.h), without a browser: the state the
// page shows, and each control driving the same state as the panel, refusing what it refuses.
#include "app.h"
#include "page_controls.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

using json = nlohmann::json;

App lectureExample() {
    App app;
    EXPECT_TRUE(loadScene(app, SANDBOX_SCENES_DIR "/lecture_example_1.json")) << app.ui.messages.error;
    return app;
}

TEST(PageControls, TheStateThePageShows) {
    App app = lectureExample();
    const json state = json::parse(pageStateJson(app));
    EXPECT_EQ(state["screen"]["scene"], "Lecture example 1");
    EXPECT_EQ(state["screen"]["status"], "perfect method, t = 0 s, paused, 0 collisions");
    const json& c = state["controls"];
    EXPECT_EQ(c["method"], "perfect");
    EXPECT_EQ(c["methods"].size(), 3u);
    EXPECT_EQ(c["bounciness"], 1.0);
    EXPECT_EQ(c["gravity-y"], app.sim.world().settings.gravity.y);
    EXPECT_EQ(c["paused"], true);
    EXPECT_EQ(c["lesson"], false);
    EXPECT_EQ(c["block"], -1);
    EXPECT_TRUE(c["mass"].is_null()); // no block selected: no mass to set
    ASSERT_EQ(c["blocks"].size(), app.sim.world().blocks.size());
    EXPECT_EQ(c["blocks"][0], app.sim.blockDisplayName(0));
}

TEST(PageControls, SettingCChangesTheWorldsC) {
    App app = lectureExample();
    EXPECT_EQ(applyPageControl(app, "bounciness", "0.5").error, "");
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.5);
    EXPECT_EQ(json::parse(pageStateJson(app))["controls"]["bounciness"], 0.5);
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
    EXPECT_EQ(applyPageControl(app, "method", "fastest").error, "method: unknown 'fastest'");
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
