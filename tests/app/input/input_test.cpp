// The key map and the mouse: what each key and drag does to the app (no GL).
#include "app.h"
#include "input_map.h"
#include "mouse_tool.h"
#include "options.h"
#include "placement.h"
#include "test_fixtures.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace {

// A key pressed, with or without Ctrl and Shift, and the action it must give (thrust off).
struct Press {
    int key;
    bool ctrl;
    bool shift;
    Action action;
};

// The lecture's keys, then the sandbox's, then the lesson's.
const Press kPresses[] = {
    {keys::kR, false, false, Action::Reset},
    {keys::kP, false, false, Action::TogglePause},
    {keys::kSpace, false, false, Action::ToggleSlowMotion},
    {keys::kD, false, false, Action::ToggleTrails},
    {keys::kC, false, false, Action::ClearTrails},
    {keys::kS, false, false, Action::CycleMethod},

    {keys::kN, false, false, Action::StepOnce},
    {keys::kF5, false, false, Action::TogglePresent},
    {keys::kTab, false, false, Action::KeyboardFocus},
    {keys::kF6, false, false, Action::NextWindow},
    {keys::kM, false, false, Action::ToggleSound},
    {keys::kA, false, false, Action::TogglePoll},
    {keys::kR, false, true, Action::ResetToFile},
    {keys::kP, false, true, Action::TogglePause}, // Shift does not matter
    {keys::kQ, true, false, Action::Quit},
    {keys::kF11, false, false, Action::ToggleFullscreen},
    {keys::kEqual, true, false, Action::UiScaleUp},
    {keys::kMinus, true, false, Action::UiScaleDown},
    {keys::kEscape, false, false, Action::Escape}, // never quits at once
    {keys::kDelete, false, false, Action::DeleteSelected},
    {keys::kS, true, false, Action::Save},
    {keys::kEqual, false, false, Action::None}, // Ctrl is needed
    {999, false, false, Action::None},

    {keys::kPageDown, false, false, Action::LessonNext},
    {keys::kRight, false, false, Action::LessonNext},
    {keys::kPageUp, false, false, Action::LessonPrevious},
    {keys::kLeft, false, false, Action::LessonPrevious},
    {keys::kHome, false, false, Action::LessonFirst},
    {keys::kEnd, false, false, Action::LessonLast},
    {keys::kEnter, false, false, Action::LessonJump},
    {keys::k0 + 7, false, false, Action::LessonDigit},
};

TEST(KeyMap, EachKeyGivesItsAction) {
    for (const Press& p : kPresses) {
        EXPECT_EQ(actionForKey(p.key, p.ctrl, p.shift), p.action)
            << "key " << p.key << (p.ctrl ? " with Ctrl" : "") << (p.shift ? " with Shift" : "");
    }
}

TEST(KeyMap, NoKeyIsBoundTwiceAndEveryBindingIsDescribed) {
    // The same key may have one binding with thrust off and another with it on (the arrows).
    std::set<std::pair<int, int>> seen;
    for (const KeyBinding& b : keyBindings()) {
        const int mods = int(b.ctrl) + 2 * int(b.shift);
        const int contexts = b.when == KeyWhen::Always ? 3 : b.when == KeyWhen::ThrustOff ? 1 : 2;
        for (int c = 1; c <= 2; ++c) {
            if (contexts & c) {
                EXPECT_TRUE(seen.insert({b.key, mods + 4 * c}).second) << b.keyName;
            }
        }
        EXPECT_NE(std::string(b.description), "");
        EXPECT_NE(std::string(actionName(b.action)), "none");
    }
}

// An app with a 20 x 12 world seen at 50 px/m in a 1000 x 600 viewport: world (x, y) is at
// screen (50x, 600 - 50y).
App makeApp() {
    const Scene scene =
        weightlessScene("test", {testBlock("A", {5, 5}, {2, 2}), testBlock("B", {12, 5}, {2, 2}),
                                 staticBlock("floor", {10, 0.5}, {20, 1})});
    App app;
    setScene(app, scene, "test.json");
    app.view.camera.setViewport({0, 0, 1000, 600});
    app.view.camera.setCentre({10, 6});
    app.view.camera.setPixelsPerMetre(50);
    app.view.autoFit = false;
    return app;
}

Vec2 screenOf(const App& app, Vec2 world) {
    return app.view.camera.worldToScreen(world);
}

// A button's or checkbox's label shows the key of its action from the key table, and leaves it
// out on a touch screen; ImGui's id (after "###") is the same either way.
TEST(KeyMap, LabelsShowTheTablesKeyExceptOnTouchScreens) {
    EXPECT_EQ(keyedLabel("Play", Action::TogglePause, false), "Play (P)###Play");
    EXPECT_EQ(keyedLabel("Play", Action::TogglePause, true), "Play###Play");
    EXPECT_EQ(keyedLabel("Slow motion", Action::ToggleSlowMotion, false),
              "Slow motion (Space)###Slow motion");
    EXPECT_EQ(keyedLabel("Slow motion", Action::ToggleSlowMotion, true),
              "Slow motion###Slow motion");
    EXPECT_EQ(keyedLabel("Save as...", Action::Save, false), "Save as... (Ctrl+S)###Save as...");
    EXPECT_EQ(keyedLabel("Cancel", Action::Escape, false), "Cancel (Esc)###Cancel");
    EXPECT_EQ(keyedLabel("Present", Action::TogglePresent, true), "Present###Present");
    // Rows of tables (the settings' method, the overlays) find their action by name.
    EXPECT_EQ(keyedLabel("method", actionOfControl("method"), false), "method (S)###method");
    EXPECT_EQ(keyedLabel("method", actionOfControl("method"), true), "method###method");
    EXPECT_EQ(actionOfControl("trails"), Action::ToggleTrails);
    EXPECT_EQ(keyedLabel("arrows", actionOfControl("vectors"), false), "arrows (V)###arrows");
    EXPECT_EQ(actionOfControl("plots"), Action::None); // no key toggles the plots
    EXPECT_EQ(keyedLabel("plots", Action::None, false), "plots###plots");
    // The key is the table's: its first binding of the action.
    for (const KeyBinding& b : keyBindings()) {
        if (b.action == Action::Navigate) continue;
        const std::string key = keyNameOf(b.action);
        EXPECT_FALSE(key.empty()) << actionName(b.action);
        EXPECT_EQ(keyedLabel("x", b.action, false), "x (" + key + ")###x");
    }
}

// Where a key goes (issue 38): the table's while the scene has the keyboard, whatever ImGui's focus
// was; while a window has it, ImGui's navigation takes the keys that move its ring, and Space and
// Enter only while the ring shows; the lesson's other keys stay the table's.
TEST(KeyRouting, TheLecturesKeysAreTheTablesUnlessAWindowWasGivenTheKeyboard) {
    const auto route = [](int key, bool navigation, bool ring, bool ctrl = false) {
        return routeKey(key, ctrl, actionForKey(key, ctrl), false, navigation, ring);
    };
    for (const int key : {keys::kRight, keys::kLeft, keys::kSpace, keys::kEnter, keys::kTab,
                          keys::kPageDown, keys::kP, keys::k0 + 1})
        EXPECT_EQ(route(key, false, false), KeyRoute::Table) << keyName(key, false, false);
    for (const int key :
         {keys::kRight, keys::kLeft, keys::kUp, keys::kDown, keys::kTab, keys::kHome, keys::kEnd})
        EXPECT_EQ(route(key, true, false), KeyRoute::Navigation) << keyName(key, false, false);
    EXPECT_EQ(route(keys::kSpace, true, false), KeyRoute::Table); // no ring: nothing to press
    EXPECT_EQ(route(keys::kSpace, true, true), KeyRoute::Navigation);
    EXPECT_EQ(route(keys::kEnter, true, true), KeyRoute::Navigation);
    for (const int key : {keys::kPageDown, keys::kPageUp, keys::kP, keys::kR, keys::kS, keys::kF5,
                          keys::kEscape, keys::k0 + 3})
        EXPECT_EQ(route(key, true, true), KeyRoute::Table) << keyName(key, false, false);
    EXPECT_EQ(route(keys::kRight, true, true, true), KeyRoute::Table); // Ctrl+Right
    // Typing into a field: the keys that type or edit are the field's, the ones that cannot
    // type are the table's.
    const auto typed = [](int key, bool ctrl = false) {
        return routeKey(key, ctrl, actionForKey(key, ctrl), true, false, false);
    };
    for (const int key : {keys::k0 + 1, keys::kKeypad0 + 3, keys::kR, keys::kS, keys::kP,
                          keys::kSpace, keys::kEnter, keys::kRight, keys::kLeft, keys::kHome,
                          keys::kEnd, keys::kDelete, keys::kTab, keys::kMinus})
        EXPECT_EQ(typed(key), KeyRoute::Typing) << keyName(key, false, false);
    for (const int key : {keys::kEscape, keys::kPageDown, keys::kPageUp, keys::kF1, keys::kF5,
                          keys::kF6, keys::kF11})
        EXPECT_EQ(typed(key), KeyRoute::Table) << keyName(key, false, false);
    EXPECT_EQ(typed(keys::kQ, true), KeyRoute::Table);  // Ctrl+Q quits
    EXPECT_EQ(typed(keys::kS, true), KeyRoute::Typing); // Ctrl+S: the field's
    EXPECT_EQ(routeKey(keys::kEscape, false, Action::Escape, true, true, true), KeyRoute::Table);
}

TEST(KeyRouting, TheLogNamesEachKey) {
    EXPECT_EQ(keyName(keys::kR, false, true), "Shift+R");
    EXPECT_EQ(keyName(keys::kS, true, false), "Ctrl+S");
    EXPECT_EQ(keyName(keys::kRight, false, false), "Right");
    EXPECT_EQ(keyName(keys::k0 + 1, false, false), "1");
    EXPECT_EQ(keyName(keys::kKeypad0 + 3, false, false), "Keypad 3");
    EXPECT_EQ(keyName(keys::kF5, false, false), "F5");
    EXPECT_EQ(keyName(keys::kSpace, false, false), "Space");
    EXPECT_EQ(keyName(keys::kLeftControl, false, false), ""); // a modifier alone
}

// `sandbox --help` names its keys from the key table: present mode is F5's (it said Tab).
TEST(KeyMap, TheHelpNamesTheTablesKeys) {
    const char* help[] = {"sandbox", "--help"};
    testing::internal::CaptureStdout();
    EXPECT_EQ(parseOptions(2, help).exitCode, 0);
    const std::string text = testing::internal::GetCapturedStdout();
    EXPECT_NE(text.find("(" + keyNameOf(Action::TogglePresent) + " toggles)"), std::string::npos)
        << text;
    EXPECT_EQ(keyNameOf(Action::TogglePresent), "F5");
    EXPECT_EQ(text.find("Tab toggles"), std::string::npos) << text;
    EXPECT_NE(text.find("; " + keyNameOf(Action::ToggleFrame) + " toggles)"), std::string::npos);
}

TEST(Mouse, ClickSelectsAndClickOnEmptySpaceDeselects) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {12.5, 5.5}), false);
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {12.5, 5.5}));
    EXPECT_EQ(app.sim.selected, 1);
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8, 9}), false);
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8, 9}));
    EXPECT_EQ(app.sim.selected, -1);
}

TEST(Mouse, DragMovesTheBlockAndHoldsTheSimulation) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {5.5, 5.5}), false);
    EXPECT_TRUE(app.mouse.holdsSimulation());
    mouseMove(app.mouse, app.sim, app.view, screenOf(app, {8.5, 8.5}));
    // The grab point stays under the cursor.
    EXPECT_TRUE(approxEqual(app.sim.world().blocks[0].position, Vec2{8, 8}, 1e-9));
    const double t = app.sim.world().time;
    EXPECT_EQ(advanceSimulation(app, 0.5), 0);
    EXPECT_EQ(app.sim.world().time, t);
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8.5, 8.5}));
    EXPECT_FALSE(app.mouse.holdsSimulation());
    EXPECT_TRUE(approxEqual(app.sim.world().blocks[0].position, Vec2{8, 8}, 1e-9));
}

TEST(Mouse, ADropOntoAnotherBlockLandsBesideItNeverOnTop) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {5, 5}), false);
    mouseMove(app.mouse, app.sim, app.view, screenOf(app, {11.6, 5.2}));
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {11.6, 5.2}));
    const Block& a = app.sim.world().blocks[0];
    EXPECT_FALSE(overlapsAnyBlock(app.sim.world(), 0, a.position, a.size));
    EXPECT_NEAR(a.position.x, 10.0, 1e-5); // left of B, touching
}

TEST(Mouse, RightDragFlingsWithTheDragVector) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Right, screenOf(app, {12, 5}), false);
    mouseMove(app.mouse, app.sim, app.view, screenOf(app, {14, 6}));
    EXPECT_TRUE(approxEqual(app.mouse.flingVelocity(), Vec2{2 * kFlingGain, kFlingGain}, 1e-9));
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Right, screenOf(app, {14, 6}));
    EXPECT_TRUE(approxEqual(app.sim.world().blocks[1].velocity, Vec2{4, 2}, 1e-9));
    EXPECT_EQ(app.sim.world().blocks[1].position, (Vec2{12, 5})); // flinging does not move it
}

TEST(Mouse, StaticBlocksCannotBeFlung) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Right, screenOf(app, {3, 0.5}), false);
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Right, screenOf(app, {6, 3}));
    EXPECT_EQ(app.sim.world().blocks[2].velocity, Vec2{});
}

TEST(Mouse, DoubleClickOnEmptySpaceAddsABlockThatOverlapsNothing) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8, 9}), true);
    ASSERT_EQ(app.sim.world().blocks.size(), 4u);
    EXPECT_EQ(app.sim.selected, 3);
    EXPECT_EQ(app.sim.labels.size(), 4u);
    // Next to a block: placed beside it.
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8.3, 8.2}), true);
    ASSERT_EQ(app.sim.world().blocks.size(), 5u);
    const Block& b = app.sim.world().blocks[4];
    EXPECT_FALSE(overlapsAnyBlock(app.sim.world(), 4, b.position, b.size));
}

TEST(Mouse, DoubleClickOnABlockOnlySelectsIt) {
    App app = makeApp();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {5, 5}), true);
    EXPECT_EQ(app.sim.world().blocks.size(), 3u);
    EXPECT_EQ(app.sim.selected, 0);
}

TEST(Mouse, WheelZoomsAboutTheCursorAndMiddleDragPans) {
    App app = makeApp();
    const Vec2 cursor = screenOf(app, {4, 3});
    mouseWheel(app.view, cursor, 2.0);
    EXPECT_GT(app.view.camera.pixelsPerMetre(), 50.0);
    EXPECT_TRUE(approxEqual(app.view.camera.screenToWorld(cursor), Vec2{4, 3}, 1e-9));
    const Vec2 centre = app.view.camera.centre();
    mousePress(app.mouse, app.sim, app.view, MouseButton::Middle, {500, 300}, false);
    mouseMove(app.mouse, app.sim, app.view, {600, 300});
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Middle, {600, 300});
    EXPECT_LT(app.view.camera.centre().x, centre.x);
    EXPECT_FALSE(app.view.autoFit);
}

TEST(Mouse, DeleteRemovesTheSelectedBlockAndItsLabel) {
    App app = makeApp();
    app.sim.selected = 0;
    deleteSelected(app);
    ASSERT_EQ(app.sim.world().blocks.size(), 2u);
    EXPECT_EQ(app.sim.labels[0].name, "B");
    EXPECT_EQ(app.sim.selected, -1);
    deleteSelected(app); // nothing selected: nothing happens
    EXPECT_EQ(app.sim.world().blocks.size(), 2u);
}

// Undo and redo through the session (Ctrl+Z, Ctrl+Y): what was undone is said with the panel's
// digits; a drag of the mouse is one edit; R keeps the settings as edits that undo can take back.
TEST(Undo, SaysWhatItUndidAndADragIsOneEdit) {
    App app = makeApp();
    EXPECT_FALSE(app.sim.undo());
    EXPECT_EQ(app.sim.notice, "Nothing to undo");
    app.sim.beginGesture();
    for (double c : {0.95, 0.9}) app.sim.apply(Edit::setWorld("bounciness", c), true);
    ASSERT_TRUE(app.sim.undo());
    EXPECT_EQ(app.sim.notice, "undo: bounciness 0.90 -> 1.00");
    EXPECT_EQ(app.sim.world().settings.bounciness, 1.0);
    ASSERT_TRUE(app.sim.redo());
    EXPECT_EQ(app.sim.notice, "redo: bounciness 1.00 -> 0.90");
    // A block dragged over several moves: one undo puts it back exactly.
    const Vec2 start = app.sim.world().blocks[0].position;
    mousePress(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, start), false);
    for (double x : {6.0, 7.0, 8.5}) mouseMove(app.mouse, app.sim, app.view, screenOf(app, {x, 7}));
    mouseRelease(app.mouse, app.sim, app.view, MouseButton::Left, screenOf(app, {8.5, 7}));
    ASSERT_NE(app.sim.world().blocks[0].position, start);
    undoOrRedo(app, true);
    EXPECT_EQ(app.sim.world().blocks[0].position, start);
    EXPECT_EQ(app.sim.notice, "undo: A position: (8.50, 7.00) m -> (5.00, 5.00) m");
    // R keeps C = 0.9 as an edit at frame 0: undone, C is the scene's again.
    for (int i = 0; i < 5; ++i) stepSimulation(app);
    resetScene(app);
    EXPECT_EQ(app.sim.world().settings.bounciness, 0.9);
    ASSERT_EQ(app.sim.editsSinceLoad().size(), 1u);
    EXPECT_EQ(logText(app.sim.editsSinceLoad()),
              "{\"frame\": 0, \"set\": \"bounciness\", \"value\": 0.9}\n");
    ASSERT_TRUE(app.sim.undo());
    EXPECT_EQ(app.sim.world().settings.bounciness, 1.0);
    EXPECT_TRUE(app.sim.edits.canRedo());
    // Shift+R and a load forget it all.
    resetToFile(app);
    EXPECT_FALSE(app.sim.edits.canRedo());
    EXPECT_TRUE(app.sim.editsSinceLoad().empty());
}

} // namespace
