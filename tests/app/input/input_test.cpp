// The key map and the mouse: what each key and drag does to the app (no GL).
#include "app.h"
#include "input_map.h"
#include "mouse_tool.h"
#include "placement.h"
#include "test_fixtures.h"

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

} // namespace
