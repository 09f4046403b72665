// What the browser build adds to the app's logic (no browser needed): a link's URL parameters,
// the two-finger gesture, and wide lines drawn as quads where WebGL 2 has 1 px lines only.
#include "app.h"
#include "app_setup.h"
#include "browser_input.h"
#include "browser_limits.h"
#include "input_map.h"
#include "lesson_session.h"
#include "link.h"
#include "mouse_tool.h"
#include "scene_json.h"
#include "settings_table.h"
#include "shape_batch.h"
#include "test_fixtures.h"
#include "touch_input.h"
#include "url_params.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace {

App setUpApp() {
    App app;
    std::string error;
    Options options;
    EXPECT_TRUE(setupApp(app, options, "", &error)) << error;
    return app;
}

TEST(UrlParams, TheLecturersLink) {
    const UrlParams p =
        parseUrlParams("?scene=newtons_cradle&method=turn-based&show=plots,inspector");
    EXPECT_TRUE(p.errors.empty());
    EXPECT_EQ(p.scene, "newtons_cradle");
    ASSERT_EQ(p.worldGiven.size(), 1u);
    EXPECT_STREQ(p.worldGiven[0]->key, "method");
    EXPECT_EQ(p.world.method, Method::TurnBased);
    ASSERT_TRUE(p.showGiven);
    EXPECT_TRUE(p.show.overlays.plots);
    EXPECT_TRUE(p.show.overlays.inspector);
    EXPECT_FALSE(p.show.overlays.cost);
}

TEST(UrlParams, EveryWorldKeyOfTheSettingsTableIsAParameter) {
    // Issue 37: a link sets any world key as a scene file has it; one out of its range is not
    // applied, said with its range, and the rest opens.
    App app = setUpApp();
    applyUrlParams(app,
                   parseUrlParams("?scene=friction_slide&friction=0.8&drag=1.2&dt=0.01&"
                                  "substeps=4&integrator=exact&resolve=reflect&"
                                  "mistakes=discrete,move-back&gravity=0,-1.62&bounciness=0.44"));
    EXPECT_EQ(app.ui.messages.error, "");
    const WorldSettings& w = app.sim.world().settings;
    EXPECT_NE(app.sim.scenePath.find("friction_slide"), std::string::npos);
    EXPECT_EQ(w.friction, 0.8);
    EXPECT_EQ(w.drag, 1.2);
    EXPECT_EQ(w.dt, 0.01);
    EXPECT_EQ(w.substeps, 4);
    EXPECT_EQ(w.integrator, Integrator::Exact);
    EXPECT_EQ(w.resolve, Resolve::Reflect);
    EXPECT_TRUE(w.has(Mistake::Discrete) && w.has(Mistake::MoveBack));
    EXPECT_EQ(w.gravity.x, 0.0);
    EXPECT_EQ(w.gravity.y, -1.62);
    EXPECT_EQ(w.bounciness, 0.44);
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        // Every key of a scene file is a parameter: a bad value is refused for its value.
        const UrlParams p = parseUrlParams(std::string("?") + row.key + "=%3F");
        ASSERT_EQ(p.errors.size(), 1u) << row.key;
        EXPECT_EQ(p.errors[0].find("URL parameter " + std::string(row.key) + ": '?' must be"),
                  row.inScene ? 0u : std::string::npos)
            << p.errors[0];
    }
    App bad = setUpApp();
    applyUrlParams(bad, parseUrlParams("?scene=friction_slide&friction=5000&substeps=2"));
    EXPECT_EQ(bad.ui.messages.error,
              "URL parameter friction: '5000' must be from 0 to 1000, not 5000: not applied");
    EXPECT_EQ(bad.sim.world().settings.friction, bad.sim.scene.settings.friction);
    EXPECT_EQ(bad.sim.world().settings.substeps, 2);
}

TEST(UrlParams, EmptyAndPercentEncoded) {
    EXPECT_TRUE(parseUrlParams("").errors.empty());
    EXPECT_TRUE(parseUrlParams("?").errors.empty());
    const UrlParams p = parseUrlParams("show=plots%2Ccom&&method=move%2Dand%2Dcorrect");
    EXPECT_TRUE(p.errors.empty()) << p.errors.front();
    EXPECT_TRUE(p.show.overlays.plots && p.show.overlays.com);
    EXPECT_EQ(p.world.method, Method::MoveAndCorrect);
}

TEST(UrlParams, EachBadParameterIsNamedAndTheGoodOnesStillCount) {
    const UrlParams p =
        parseUrlParams("?method=fast&scene=../etc/passwd&show=plots,bogus&zoom=2&scene=x");
    ASSERT_EQ(p.errors.size(), 5u);
    EXPECT_EQ(p.errors[0], "URL parameter method: 'fast' must be perfect, move-and-correct or "
                           "turn-based: not applied");
    EXPECT_NE(p.errors[1].find("URL parameter scene: '../etc/passwd' is not a scene name"),
              std::string::npos);
    EXPECT_NE(p.errors[2].find("URL parameter show"), std::string::npos);
    EXPECT_NE(p.errors[3].find("URL parameter scene: given twice"), std::string::npos);
    EXPECT_EQ(p.errors[4], "unknown URL parameter 'zoom' ignored (known: scene, lesson, step, "
                           "show, frame, method, bounciness, gravity, dt, substeps, resolve, "
                           "integrator, drag, friction, mistakes)");
    EXPECT_TRUE(p.worldGiven.empty());
    EXPECT_TRUE(p.scene.empty());
}

TEST(UrlParams, TrackersAreIgnoredWithoutAWord) {
    const UrlParams p = parseUrlParams("?utm_source=x&fbclid=y&scene=newtons_cradle&gclid=z&"
                                       "utm_campaign=spring&msclkid=1&_ga=2");
    EXPECT_TRUE(p.errors.empty()) << p.errors.front();
    EXPECT_EQ(p.scene, "newtons_cradle");
    EXPECT_TRUE(isTrackerParam("utm_anything"));
    EXPECT_FALSE(isTrackerParam("utm")); // only the utm_ family
    EXPECT_FALSE(isTrackerParam("scene"));
}

TEST(UrlParams, ThousandsOfUnknownParametersTakeOneShortLine) {
    std::string query = "?scene=newtons_cradle";
    for (int i = 0; i < 5000; ++i) query += "&p" + std::to_string(i) + "=1";
    const UrlParams p = parseUrlParams(query);
    ASSERT_EQ(p.errors.size(), 1u);
    EXPECT_EQ(p.errors[0], "5000 unknown URL parameters ignored: 'p0', 'p1', 'p2', ... (known: "
                           "scene, lesson, step, show, frame, method, bounciness, gravity, dt, "
                           "substeps, resolve, integrator, drag, friction, mistakes)");
    EXPECT_EQ(p.scene, "newtons_cradle"); // the known one still counts
}

TEST(UrlParams, ThousandsOfBadValuesTakeAFewLines) {
    std::string query;
    for (int i = 0; i < 5000; ++i) query += "&method=x" + std::to_string(i);
    const UrlParams p = parseUrlParams(query);
    ASSERT_EQ(p.errors.size(), kMaxUrlErrors + 1);
    EXPECT_NE(p.errors[0].find("URL parameter method: 'x0' must be"), std::string::npos);
    EXPECT_EQ(p.errors.back(), "... and 4995 more problems in the URL");
}

TEST(UrlParams, TheReadmeListsEveryParameter) {
    std::ifstream in(SANDBOX_README);
    const std::string readme((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
    ASSERT_FALSE(readme.empty()) << SANDBOX_README;
    for (const UrlParamInfo& p : kUrlParams)
        EXPECT_NE(readme.find("| `" + std::string(p.name) + "`"), std::string::npos) << p.name;
}

TEST(UrlParams, ControlBytesAreNotEchoed) {
    const UrlParams p = parseUrlParams("?method=%1b%5b2J" + std::string(100, 'a'));
    ASSERT_EQ(p.errors.size(), 1u);
    for (const char c : p.errors[0]) EXPECT_GE(static_cast<unsigned char>(c), 0x20);
    EXPECT_EQ(p.errors[0].find(std::string(50, 'a')), std::string::npos); // shortened
    EXPECT_NE(p.errors[0].find("'\\x1b[2Jaaa"), std::string::npos)
        << p.errors[0]; // as printable() writes it
}

TEST(UrlParams, AppliedToTheApp) {
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?scene=newtons_cradle&method=turn-based&show=plots"));
    EXPECT_EQ(app.ui.messages.error, "");
    EXPECT_NE(app.sim.scenePath.find("newtons_cradle.json"), std::string::npos);
    EXPECT_EQ(app.sim.world().settings.method, Method::TurnBased);
    EXPECT_TRUE(app.view.show.plots);
}

TEST(UrlParams, TheCentreOfMassFrame) {
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?scene=lecture_example_1&frame=com"));
    EXPECT_EQ(app.ui.messages.error, "");
    EXPECT_EQ(app.view.frame, ViewFrame::CentreOfMass);
    const UrlParams bad = parseUrlParams("?frame=moving");
    EXPECT_FALSE(bad.frame.has_value());
    ASSERT_EQ(bad.errors.size(), 1u);
    EXPECT_EQ(bad.errors[0], "URL parameter frame: unknown frame 'moving' (world, com)");
}

TEST(UrlParams, AnUnknownSceneKeepsTheCurrentOneAndSaysWhy) {
    App app = setUpApp();
    const std::string before = app.sim.scenePath;
    const std::size_t blocks = app.sim.world().blocks.size();
    applyUrlParams(app, parseUrlParams("?scene=no_such_scene&method=perfect"));
    EXPECT_EQ(app.sim.scenePath, before);
    EXPECT_EQ(app.sim.world().blocks.size(), blocks);
    EXPECT_NE(
        app.ui.messages.error.find("URL parameter scene: no scene 'no_such_scene' is shipped"),
        std::string::npos)
        << app.ui.messages.error;
}

TEST(UrlParams, ALessonAtAStep) {
    const UrlParams p = parseUrlParams("?lesson=lecture3&step=5");
    EXPECT_TRUE(p.errors.empty());
    EXPECT_EQ(p.lesson, "lecture3");
    EXPECT_EQ(p.step, 5);
    App app = setUpApp();
    applyUrlParams(app, p);
    EXPECT_EQ(app.ui.messages.error, "");
    ASSERT_TRUE(app.lesson.active());
    EXPECT_EQ(app.lesson.current, 4u);
}

TEST(UrlParams, BadLessonParameters) {
    const UrlParams p = parseUrlParams("?step=3");
    ASSERT_EQ(p.errors.size(), 1u);
    EXPECT_NE(p.errors[0].find("URL parameter step: needs a lesson"), std::string::npos);
    EXPECT_EQ(p.step, 0);
    // One rule for a value out of its range: not applied, said with the range, the rest opens
    // (the lesson at its first step), whether the step is one past the last or has 17 digits.
    for (const char* step : {"1000", "0", "-2", "99999999999", "five", ""}) {
        SCOPED_TRACE(step);
        App app = setUpApp();
        applyUrlParams(app, parseUrlParams(std::string("?lesson=lecture3&step=") + step));
        ASSERT_TRUE(app.lesson.active());
        EXPECT_EQ(app.lesson.current, 0u);
        const std::size_t steps = app.lesson.lesson->steps.size();
        EXPECT_EQ(app.ui.messages.error, "URL parameter step: '" + std::string(step) +
                                             "' is not a step of 'lecture3' (1 to " +
                                             std::to_string(steps) + "): it opens at step 1");
    }
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?lesson=lecture3&step=2"));
    const std::size_t last = app.lesson.lesson->steps.size();
    applyUrlParams(app, parseUrlParams("?lesson=lecture3&step=" + std::to_string(last)));
    EXPECT_EQ(app.ui.messages.error, "");
    EXPECT_EQ(app.lesson.current, last - 1);
    app = setUpApp();
    applyUrlParams(app, parseUrlParams("?lesson=no_such_lesson"));
    EXPECT_NE(app.ui.messages.error.find("no lesson 'no_such_lesson' is shipped"),
              std::string::npos);
    EXPECT_FALSE(app.lesson.active());
}

TEST(Link, NamesTheShippedSceneAndWhatDiffersFromOpeningIt) {
    App app = setUpApp();
    EXPECT_EQ(linkQuery(app), "scene=bouncing_squares"); // named: a bare link opens the last one
    EXPECT_FALSE(linkCarriesScene(app));
    app.sim.cycleMethod();
    app.view.show.plots = true;
    setViewFrame(app.view, ViewFrame::CentreOfMass);
    EXPECT_EQ(linkQuery(app),
              "scene=bouncing_squares&method=move-and-correct&show=vectors,plots&frame=com");
    app.view.show.vectors = false;
    app.view.show.plots = false;
    EXPECT_EQ(linkQuery(app), "scene=bouncing_squares&method=move-and-correct&show=&frame=com");
}

TEST(Link, OpeningTheQueryGivesTheSameQuery) {
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?scene=newtons_cradle&method=turn-based&show=plots"));
    setViewFrame(app.view, ViewFrame::CentreOfMass);
    const std::string query = linkQuery(app);
    App opened = setUpApp();
    applyUrlParams(opened, parseUrlParams(query));
    EXPECT_EQ(opened.ui.messages.error, "");
    EXPECT_EQ(linkQuery(opened), query);
    applyUrlParams(opened, parseUrlParams("show="));
    EXPECT_EQ(opened.ui.messages.error, "");
    EXPECT_FALSE(opened.view.show.vectors); // an empty list: no overlay at all
}

TEST(Link, AnEditedSceneTravelsInsideTheLink) {
    App app = setUpApp();
    ASSERT_TRUE(app.sim.apply(Edit::setBlock({0, ""}, "velocity", {1.25, -3.5})).empty());
    EXPECT_TRUE(linkCarriesScene(app));
    EXPECT_EQ(linkQuery(app), ""); // the scene, its method and settings are in the fragment
    App moved = setUpApp();
    stepSimulation(moved); // run on: the blocks are no longer the file's
    EXPECT_TRUE(linkCarriesScene(moved));
    App settings = setUpApp();
    settings.sim.world().settings.bounciness = 0.5;
    EXPECT_TRUE(linkCarriesScene(settings));
}

TEST(Link, ALessonStepIsItsLink) {
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?lesson=lecture3&step=5"));
    EXPECT_EQ(linkQuery(app), "lesson=lecture3&step=5");
    EXPECT_FALSE(linkCarriesScene(app)); // the step as written: its number says it all
}

// A link copied inside a lesson carries the student's changes (issue 38): the step, and its setup
// as changed; opening it gives that step at its setup in that world, and the answer says so.
TEST(Link, ALessonStepsChangesTravelInsideTheLink) {
    App app = setUpApp();
    applyUrlParams(app, parseUrlParams("?lesson=lecture3&step=13"));
    app.sim.world().blocks[1].mass = 4.0;
    app.sim.world().settings.bounciness = 0.5;
    EXPECT_TRUE(linkCarriesScene(app));
    EXPECT_EQ(linkQuery(app), "lesson=lecture3&step=13");
    const std::vector<std::string> changes = lessonChanges(app.lesson, app.sim);
    // The page writes the fragment's scene to a file before the app starts.
    const std::string carried = testing::TempDir() + "/link_lesson_scene.json";
    {
        std::ofstream out(carried);
        out << sceneToJson(linkedScene(app));
    }
    App opened = setUpApp();
    UrlParams params = parseUrlParams("?lesson=lecture3&step=13");
    params.linkScene = carried;
    applyUrlParams(opened, params);
    EXPECT_EQ(opened.ui.messages.error, "");
    ASSERT_TRUE(opened.lesson.active());
    EXPECT_EQ(opened.lesson.current, 12u);
    EXPECT_EQ(opened.lesson.phase, LessonSession::Phase::Setup);
    EXPECT_EQ(opened.sim.world().time, 0.0);
    EXPECT_EQ(opened.sim.world().blocks[1].mass, 4.0);
    EXPECT_EQ(opened.sim.world().settings.bounciness, 0.5);
    EXPECT_EQ(lessonChanges(opened.lesson, opened.sim), changes);
    EXPECT_EQ(linkQuery(opened), "lesson=lecture3&step=13");
    EXPECT_TRUE(linkCarriesScene(opened));
    // Shift+R: the step as written again, and the link says only its number.
    applyLessonAction(opened, Action::ResetToFile);
    EXPECT_FALSE(linkCarriesScene(opened));
}

// Touch: frames as the web main asks them (frame, then resolveStart after a Waiting frame).
TouchInput::Frame touchFrame(TouchInput& t, double now, bool overUi, bool onBlock = false) {
    const TouchInput::Frame f = t.frame(now);
    if (t.waitingForStart()) t.resolveStart(overUi, onBlock);
    return f;
}

TEST(TouchInput, ATapOnThePanelIsACtrlClickThenThePointerLeaves) {
    TouchInput t;
    t.event(TouchPhase::Start, 7, {100, 200}, 0.0);
    TouchInput::Frame f = touchFrame(t, 0.016, true);
    EXPECT_TRUE(f.pointer); // hovering where it went down: the UI is there
    EXPECT_FALSE(f.down);
    EXPECT_EQ(t.mode(), TouchInput::Mode::Pending);
    t.event(TouchPhase::End, 7, {102, 201}, 0.1);
    f = touchFrame(t, 0.116, true);
    EXPECT_TRUE(f.down && f.ctrl); // Ctrl+click: a number field opens for typing
    EXPECT_EQ(f.pos.x, 100.0);
    f = touchFrame(t, 0.132, true);
    EXPECT_TRUE(f.pointer && !f.down); // released: the click
    f = touchFrame(t, 0.148, true);
    EXPECT_FALSE(f.pointer); // then nothing is hovered: no tooltip stays
}

TEST(TouchInput, ASwipeOnThePanelScrollsAndNeverPresses) {
    TouchInput t;
    t.event(TouchPhase::Start, 1, {100, 500}, 0.0);
    touchFrame(t, 0.016, true);
    t.event(TouchPhase::Move, 1, {101, 470}, 0.03);
    EXPECT_EQ(t.mode(), TouchInput::Mode::Scroll);
    TouchInput::Frame f = touchFrame(t, 0.033, true);
    EXPECT_FALSE(f.down);
    EXPECT_FALSE(f.pointer);
    EXPECT_EQ(f.scrollY, -30.0); // the content follows the finger from where it went down
    t.event(TouchPhase::Move, 1, {101, 400}, 0.05);
    f = touchFrame(t, 0.05, true);
    EXPECT_EQ(f.scrollY, -70.0);
    t.event(TouchPhase::Move, 1, {101, 380}, 0.055);
    t.event(TouchPhase::End, 1, {101, 370}, 0.06); // lifted before a frame showed the last move
    f = touchFrame(t, 0.066, true);
    EXPECT_EQ(f.scrollY, -30.0);
    for (int i = 0; i < 3; ++i) {
        f = touchFrame(t, 0.07 + i * 0.016, true);
        EXPECT_FALSE(f.down);
    }
}

TEST(TouchInput, HeldThenSlidDragsASlider) {
    TouchInput t;
    t.event(TouchPhase::Start, 1, {100, 500}, 0.0);
    touchFrame(t, 0.016, true);
    TouchInput::Frame f = touchFrame(t, 0.2, true);
    EXPECT_FALSE(f.down);
    f = touchFrame(t, 0.4, true); // still for the hold time: pressing
    EXPECT_TRUE(f.down);
    t.event(TouchPhase::Move, 1, {160, 505}, 0.45);
    f = touchFrame(t, 0.46, true);
    EXPECT_TRUE(f.down);
    EXPECT_EQ(f.pos.x, 160.0);
    t.event(TouchPhase::End, 1, {160, 505}, 0.5);
    f = touchFrame(t, 0.52, true);
    EXPECT_TRUE(f.pointer && !f.down);
}

TEST(TouchInput, OnTheSceneABlockIsDraggedAndEmptySpacePans) {
    TouchInput t;
    t.event(TouchPhase::Start, 1, {400, 300}, 0.0);
    touchFrame(t, 0.016, false, true); // on a block
    t.event(TouchPhase::Move, 1, {440, 300}, 0.02);
    TouchInput::Frame f = touchFrame(t, 0.033, false);
    EXPECT_TRUE(f.down);
    EXPECT_EQ(f.pos.x, 400.0); // pressed where it went down
    f = touchFrame(t, 0.05, false);
    EXPECT_EQ(f.pos.x, 440.0); // then dragging
    t.event(TouchPhase::End, 1, {440, 300}, 0.06);
    f = touchFrame(t, 0.066, false);
    EXPECT_FALSE(f.down);

    TouchInput e;
    e.event(TouchPhase::Start, 2, {400, 300}, 1.0);
    touchFrame(e, 1.016, false, false); // empty space
    e.event(TouchPhase::Move, 2, {430, 320}, 1.02);
    f = touchFrame(e, 1.033, false); // beyond the slop: the press lets go, a pan begins
    EXPECT_FALSE(f.down);
    f = touchFrame(e, 1.05, false);
    EXPECT_EQ(f.pan.x, 30.0);
    EXPECT_EQ(f.pan.y, 20.0);
}

TEST(TouchInput, ASwipeQuickerThanAFrameStillScrolls) {
    TouchInput t;
    t.event(TouchPhase::Start, 1, {100, 500}, 0.0);
    t.event(TouchPhase::Move, 1, {100, 450}, 0.005);
    t.event(TouchPhase::End, 1, {100, 400}, 0.01);
    TouchInput::Frame f = touchFrame(t, 0.016, true);
    EXPECT_FALSE(f.down);
    f = touchFrame(t, 0.033, true);
    EXPECT_EQ(f.scrollY, -100.0);
    EXPECT_FALSE(f.down);
}

TEST(TouchInput, ATapOnTheSceneIsAPlainClick) {
    TouchInput t;
    t.event(TouchPhase::Start, 1, {400, 300}, 0.0);
    t.event(TouchPhase::End, 1, {400, 300}, 0.01); // lifted before a frame showed where
    touchFrame(t, 0.016, false);
    const TouchInput::Frame f = touchFrame(t, 0.033, false);
    EXPECT_TRUE(f.down);
    EXPECT_FALSE(f.ctrl);
}

TEST(SheetLayout, NarrowScreensGetTheSceneAndABarOfButtons) {
    EXPECT_TRUE(sheetLayout(390.0 * 3, 3.0f)); // a phone held upright, ratio 3
    EXPECT_FALSE(sheetLayout(1024.0, 1.0f));
    // A tablet held sideways (1024x768 at ratio 2) with touch: the sheet too; with a mouse, or
    // as tall as a 1366x1024 tablet, the panel column.
    EXPECT_TRUE(sheetLayout(2048.0, 2.0f, 1536.0, true));
    EXPECT_FALSE(sheetLayout(2048.0, 2.0f, 1536.0, false));
    EXPECT_FALSE(sheetLayout(2732.0, 2.0f, 2048.0, true));
    App app = setUpApp();
    app.view.uiScale = 3.0f;
    updateCamera(app, 1170.0, 2532.0);
    ASSERT_TRUE(app.view.layout.sheet);
    const ScreenRect& scene = app.view.layout.scene;
    EXPECT_GE(scene.width * scene.height, 0.6 * 1170.0 * 2532.0);
    EXPECT_EQ(app.view.layout.panel.height, kSheetBarPx * 3.0);
    // The first view shows the whole scene (20 x 12 m): the world's corners inside the scene's
    // rectangle, the width (the tighter side, upright) filled but for the fit's margins. Exact
    // up to rounding: 1e-9 px.
    const Camera& camera = app.view.camera;
    const Vec2 low = camera.worldToScreen(app.sim.world().bounds.min);
    const Vec2 high = camera.worldToScreen(app.sim.world().bounds.max);
    EXPECT_GE(low.x, scene.x - 1e-9);
    EXPECT_LE(high.x, scene.x + scene.width + 1e-9);
    EXPECT_GE(high.y, scene.y - 1e-9);
    EXPECT_LE(low.y, scene.y + scene.height + 1e-9);
    EXPECT_NEAR(high.x - low.x, scene.width - 2.0 * kFitMarginPx * 3.0, 1e-9);
    app.view.sheetOpen = true;
    updateCamera(app, 1170.0, 2532.0);
    EXPECT_EQ(app.view.layout.panel.y, std::round(2532.0 * (1.0 - kSheetOpenShare)));
}

TEST(WheelNotches, OneNotchIsOneStepTheDesktopsWay) {
    // Chromium: about 100 px per notch, positive down; the desktop's GLFW: 1 per notch, up.
    EXPECT_EQ(wheelNotches(0.0, -100.0, 0).y, 1.0);
    EXPECT_EQ(wheelNotches(0.0, 100.0, 0).y, -1.0);
    EXPECT_EQ(wheelNotches(0.0, 3.0, 1).y, -1.0);   // Firefox: 3 lines
    EXPECT_EQ(wheelNotches(0.0, -1.0, 2).y, 1.0);   // a page
    EXPECT_EQ(wheelNotches(100.0, 0.0, 0).x, -1.0); // right: GLFW's negative x
    // A touchpad's small deltas are fractions of a notch: smooth.
    EXPECT_DOUBLE_EQ(wheelNotches(0.0, -4.0, 0).y, 0.04);
    // Nonsense stays bounded.
    EXPECT_EQ(wheelNotches(0.0, -1e9, 0).y, kMaxWheelNotches);
    EXPECT_EQ(wheelNotches(std::nan(""), INFINITY, 0).x, 0.0);
    EXPECT_EQ(wheelNotches(std::nan(""), INFINITY, 0).y, 0.0);
}

TEST(WheelPans, ATouchpadsScrollPansAMouseNotchAndAPinchZoom) {
    EXPECT_FALSE(wheelPans(0.0, -100.0, 0, false)); // a mouse wheel's notch (Chromium)
    EXPECT_FALSE(wheelPans(0.0, 3.0, 1, false));    // Firefox's 3 lines
    EXPECT_FALSE(wheelPans(0.0, 1.0, 2, false));    // a page
    EXPECT_TRUE(wheelPans(0.0, -4.0, 0, false));    // a touchpad's small steps
    EXPECT_TRUE(wheelPans(12.0, 0.0, 0, false));    // sideways
    EXPECT_TRUE(wheelPans(30.0, 140.0, 0, false));  // a quick diagonal swipe
    EXPECT_FALSE(wheelPans(0.0, -4.0, 0, true));    // a pinch (Ctrl): zoom
    EXPECT_FALSE(wheelPans(std::nan(""), 1.0, 0, false));
}

TEST(BrowserKeys, TheBrowsersOwnKeysAreNotBoundThere) {
    EXPECT_EQ(actionForKey(keys::kQ, true, false, false, true), Action::None); // close the tab
    EXPECT_EQ(actionForKey(keys::kQ, true, false, false, false), Action::Quit);
    EXPECT_EQ(actionForKey(keys::kEqual, true, false, false, true), Action::None); // page zoom
    EXPECT_EQ(actionForKey(keys::kS, true, false, false, true), Action::Save);
    EXPECT_EQ(actionForKey(keys::kP, false, false, false, true), Action::TogglePause);
}

TEST(BrowserSave, TheDownloadIsNamedAfterTheScene) {
    App app = setUpApp();
    EXPECT_EQ(browserDownloadPath(app), std::string(kBrowserDownloads) + "/bouncing_squares.json");
}

TEST(TouchGesture, PansByTheMidpointAndZoomsAboutIt) {
    App app = setUpApp();
    app.view.camera.setViewport({0, 0, 800, 600});
    app.view.camera.setPixelsPerMetre(50.0);
    app.view.camera.setCentre({10.0, 6.0});
    const Vec2 grabbed = app.view.camera.screenToWorld({300, 200});
    touchPanZoom(app.view, {300, 200}, {340, 260}, 2.0);
    EXPECT_FALSE(app.view.autoFit);
    EXPECT_DOUBLE_EQ(app.view.camera.pixelsPerMetre(), 100.0);
    // The world point under the fingers stays under them (exact up to rounding: 1e-9 m).
    const Vec2 now = app.view.camera.screenToWorld({340, 260});
    EXPECT_NEAR(now.x, grabbed.x, 1e-9);
    EXPECT_NEAR(now.y, grabbed.y, 1e-9);
    const double ppm = app.view.camera.pixelsPerMetre();
    touchPanZoom(app.view, {0, 0}, {0, 0}, std::nan(""));
    EXPECT_EQ(app.view.camera.pixelsPerMetre(), ppm);
}

TEST(BrowserLimits, LargeFilesAreRefusedAtOnceNamingTheLimit) {
    EXPECT_EQ(browserOpenRefusal("/opened/cradle.json", kMaxBrowserSceneBytes), "");
    EXPECT_EQ(browserOpenRefusal("/opened/my_trace.csv", kMaxBrowserTraceBytes), "");
    EXPECT_EQ(browserOpenRefusal("/opened/big.json", 20u << 20),
              "big.json is 20.0 MB: the browser opens scene files of up to " +
                  byteSize(kMaxBrowserSceneBytes) +
                  " (it has one thread, which the page's keys would wait for). Open it in the "
                  "sandbox's window or with sandbox-cli run, which take larger files.");
    const std::string trace = browserOpenRefusal("/opened/run.CSV", kMaxBrowserTraceBytes + 1);
    EXPECT_NE(trace.find("the browser opens traces of up to " + byteSize(kMaxBrowserTraceBytes)),
              std::string::npos)
        << trace;
    EXPECT_NE(trace.find("sandbox-cli compare"), std::string::npos) << trace;
    // The file's name is echoed printable.
    EXPECT_EQ(browserOpenRefusal("/opened/\x1b]0;x\x07.json", 1u << 30).find('\x1b'),
              std::string::npos);
    EXPECT_EQ(openingMessage("/opened/gas_500.json", 94208), "Opening gas_500.json (92 KB)...");
    EXPECT_EQ(byteSize(812), "812 bytes");
    EXPECT_EQ(byteSize(20u << 20), "20.0 MB");
}

TEST(Link, AScenesOfManyBlocksIsNotCarried) {
    App app = setUpApp();
    std::vector<BlockDef> blocks;
    for (std::size_t i = 0; i <= kMaxLinkBlocks; ++i)
        blocks.push_back(
            testBlock("", {0.5 + static_cast<double>(i % 100), 0.5 + static_cast<double>(i / 100)},
                      {0.5, 0.5}));
    Scene scene = weightlessScene("many", blocks);
    scene.bounds = Bounds{{0, 0}, {100, 100}};
    setScene(app, scene, "/opened/many.json");
    EXPECT_TRUE(linkCarriesScene(app));
    EXPECT_TRUE(linkSceneTooLarge(app));
    EXPECT_NE(linkTooManyBlocksMessage(kMaxLinkBlocks + 1).find("2001 blocks"), std::string::npos);
    app.sim.world().blocks.pop_back();
    EXPECT_FALSE(linkSceneTooLarge(app));
}

TEST(WideLineQuads, AsOpenGLRasterisesAWideLine) {
    ShapeBatch batch;
    batch.segment({0.0, 0.0}, {4.0, 1.0}, Color{1, 0, 0, 1}, Color{0, 0, 1, 1}); // x-major
    batch.segment({0.0, 0.0}, {1.0, -3.0}, Color{0, 1, 0, 1});                   // y-major
    std::vector<ShapeVertex> tris(wideLineQuadVertices(batch.segmentVertices(), 20.0));
    ASSERT_EQ(tris.size(), 12u);
    writeWideLineQuads(batch.segmentVertices(), 4.0, 20.0, tris.data()); // 4 px at 20 px/m: 0.2 m
    // The x-major one is widened up and down by half the width; its ends keep their colours.
    EXPECT_FLOAT_EQ(tris[0].x, 0.0f);
    EXPECT_FLOAT_EQ(tris[0].y, -0.1f);
    EXPECT_FLOAT_EQ(tris[1].y, 0.1f);
    EXPECT_FLOAT_EQ(tris[2].x, 4.0f);
    EXPECT_FLOAT_EQ(tris[2].y, 1.1f);
    EXPECT_EQ(tris[0].r, 1.0f);
    EXPECT_EQ(tris[2].b, 1.0f);
    // The y-major one left and right.
    EXPECT_FLOAT_EQ(tris[6].x, -0.1f);
    EXPECT_FLOAT_EQ(tris[6].y, 0.0f);
    EXPECT_FLOAT_EQ(tris[8].x, 1.1f);
    EXPECT_FLOAT_EQ(tris[8].y, -3.0f);
    // Area of the two triangles = length along the major axis times the width.
    auto area = [&](std::size_t i) {
        const ShapeVertex &a = tris[i], &b = tris[i + 1], &c = tris[i + 2];
        return std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2.0;
    };
    EXPECT_NEAR(area(0) + area(3), 4.0 * 0.2, 1e-6); // float vertices: 1e-6 m^2
    EXPECT_NEAR(area(6) + area(9), 3.0 * 0.2, 1e-6);
}

} // namespace
