#include "input_map.h"

#include <cmath>

const std::vector<KeyBinding>& keyBindings() {
    static const std::vector<KeyBinding> bindings{
        {keys::kR, false, Action::Reset, "R",
         "Reset blocks and time (keeps method, C, g, frame rate, substeps; in a lesson: the step "
         "again from its setup, keeping those)"},
        {keys::kR, false, Action::ResetToFile, "Shift+R",
         "Reset to file: everything as loaded (in a lesson: the step as written)", true, true},
        {keys::kP, false, Action::TogglePause, "P", "Pause / resume"},
        {keys::kSpace, false, Action::ToggleSlowMotion, "Space", "Slow motion (5 frames/s)"},
        {keys::kD, false, Action::ToggleTrails, "D", "Draw trajectories on / off"},
        {keys::kC, false, Action::ClearTrails, "C", "Clear trajectories"},
        {keys::kS, false, Action::CycleMethod, "S", "Cycle the simulation method"},
        {keys::kN, false, Action::StepOnce, "N", "Single step (pauses)"},
        {keys::kV, false, Action::ToggleVectors, "V", "Velocity arrows on / off"},
        {keys::kU, false, Action::ToggleFrame, "U",
         "Centre-of-mass frame: the view moves with u, arrows show w = v - u (again: the world's)"},
        {keys::kF, false, Action::FitView, "F", "Fit the world into the view"},
        {keys::kM, false, Action::ToggleSound, "M",
         "Sound on / off: a knock at each collision (louder for a harder hit, higher for a "
         "smaller block, lower on a wall); off by default outside lessons, remembered"},
        {keys::kF5, false, Action::TogglePresent, "F5",
         "Present mode: only the scene and a caption (again: all back)"},
        {keys::kTab, false, Action::KeyboardFocus, "Tab",
         "Keyboard: the focus ring on the panel's first control; then Tab and Shift+Tab go "
         "from field to field (type a value, Enter), the arrows from control to control"},
        {-1, false, Action::Navigate, "Arrows, Space, Enter, Esc",
         "Keyboard, with the focus ring shown: the arrows move to a control; Space presses a "
         "button, ticks a box, opens a section or a list; Enter types into a slider; Esc leaves "
         "the controls (the arrows, Space and Enter act on the scene and the lesson again)"},
        {keys::kF6, false, Action::NextWindow, "F6",
         "Keyboard: the focus ring on the next window (the panel, each overlay window, Help)"},
        {keys::kF11, false, Action::ToggleFullscreen, "F11", "Fullscreen"},
        {keys::kF1, false, Action::ToggleHelp, "F1", "This help"},
        {keys::kA, false, Action::TogglePoll, "A",
         "Ask the class: the poll on / off (a lesson's questions on the students' phones)"},
        {keys::kEqual, true, Action::UiScaleUp, "Ctrl+=", "Larger UI (projector)", true, false,
         KeyWhen::Always, "The browser's zoom: a larger UI (projector)"},
        {keys::kKeypadAdd, true, Action::UiScaleUp, "Ctrl+Keypad +", "Larger UI", true, false,
         KeyWhen::Always, "The browser's zoom: a larger UI"},
        {keys::kMinus, true, Action::UiScaleDown, "Ctrl+-", "Smaller UI", true, false,
         KeyWhen::Always, "The browser's zoom: a smaller UI"},
        {keys::kKeypadSubtract, true, Action::UiScaleDown, "Ctrl+Keypad -", "Smaller UI", true,
         false, KeyWhen::Always, "The browser's zoom: a smaller UI"},
        {keys::kS, true, Action::Save, "Ctrl+S",
         "Save the current state as a scene (the browser downloads it)"},
        {keys::kDelete, false, Action::DeleteSelected, "Delete", "Remove the selected block"},
        {keys::kEscape, false, Action::Escape, "Esc",
         "Close Help or a dialog; leave present mode or fullscreen"},
        {keys::kQ, true, Action::Quit, "Ctrl+Q", "Quit (asks when there are unsaved edits)", true,
         false, KeyWhen::Always, ""}, // a tab is closed by the browser (which asks, on edits)
        {keys::kPageDown, false, Action::LessonNext, "PageDown",
         "Lesson: answer, then the next step"},
        {keys::kRight, false, Action::LessonNext, "Right",
         "Lesson: answer, then the next step (thrust off)", true, false, KeyWhen::ThrustOff},
        {keys::kPageUp, false, Action::LessonPrevious, "PageUp", "Lesson: the previous step"},
        {keys::kLeft, false, Action::LessonPrevious, "Left",
         "Lesson: the previous step (thrust off)", true, false, KeyWhen::ThrustOff},
        {keys::kHome, false, Action::LessonFirst, "Home", "Lesson: the first step"},
        {keys::kEnd, false, Action::LessonLast, "End", "Lesson: the last step"},
        {keys::kEnter, false, Action::LessonJump, "0-9, Enter", "Lesson: go to step number ..."},
        {keys::kKeypadEnter, false, Action::LessonJump, "Keypad Enter",
         "Lesson: go to step number ...", false},
        {keys::kRight, false, Action::ThrustRight, "Arrow keys",
         "Thrust on (Physics section): push the selected block while held; the arrows then do "
         "not step a lesson (PageDown / PageUp do)",
         true, false, KeyWhen::ThrustOn},
        {keys::kLeft, false, Action::ThrustLeft, "Left", "Thrust: push left", false, false,
         KeyWhen::ThrustOn},
        {keys::kUp, false, Action::ThrustUp, "Up", "Thrust: push up", false, false,
         KeyWhen::ThrustOn},
        {keys::kDown, false, Action::ThrustDown, "Down", "Thrust: push down", false, false,
         KeyWhen::ThrustOn},
    };
    static const std::vector<KeyBinding> withDigits = [] {
        std::vector<KeyBinding> all = bindings;
        for (int d = 0; d <= 9; ++d) {
            all.push_back({keys::k0 + d, false, Action::LessonDigit, "0-9",
                           "Lesson: a digit of a step number", false});
            all.push_back({keys::kKeypad0 + d, false, Action::LessonDigit, "Keypad 0-9",
                           "Lesson: a digit of a step number", false});
        }
        return all;
    }();
    return withDigits;
}

bool navigationKey(int key) {
    static const int kNavigationKeys[] = {keys::kLeft,        keys::kRight, keys::kUp,
                                          keys::kDown,        keys::kSpace, keys::kEnter,
                                          keys::kKeypadEnter, keys::kTab,   keys::kEscape};
    for (int k : kNavigationKeys)
        if (k == key) return true;
    return false;
}

int digitOfKey(int key) {
    if (key >= keys::k0 && key <= keys::k0 + 9) return key - keys::k0;
    if (key >= keys::kKeypad0 && key <= keys::kKeypad0 + 9) return key - keys::kKeypad0;
    return -1;
}

Action actionForKey(int key, bool ctrl, bool shift, bool thrust, bool browser) {
    for (const KeyBinding& b : keyBindings()) {
        if (b.when == (thrust ? KeyWhen::ThrustOff : KeyWhen::ThrustOn)) continue;
        if (b.key != key || b.ctrl != ctrl || b.shift != shift) continue;
        return browser && b.inBrowser ? Action::None : b.action; // the browser keeps it
    }
    if (shift) return actionForKey(key, ctrl, false, thrust, browser);
    return Action::None;
}

Vec2 thrustDirectionOf(Action action) {
    switch (action) {
    case Action::ThrustLeft:
        return {-1.0, 0.0};
    case Action::ThrustRight:
        return {1.0, 0.0};
    case Action::ThrustDown:
        return {0.0, -1.0};
    case Action::ThrustUp:
        return {0.0, 1.0};
    default:
        return {};
    }
}

Vec2 heldThrustDirection(const std::function<bool(int key)>& isDown) {
    Vec2 sum;
    for (const KeyBinding& b : keyBindings()) {
        if (b.when == KeyWhen::ThrustOn && isDown(b.key)) sum = sum + thrustDirectionOf(b.action);
    }
    const double n = std::hypot(sum.x, sum.y);
    return n > 0.0 ? sum * (1.0 / n) : Vec2{};
}

const char* actionName(Action action) {
    switch (action) {
    case Action::None:
        return "none";
    case Action::Reset:
        return "reset";
    case Action::ResetToFile:
        return "reset-to-file";
    case Action::TogglePause:
        return "pause";
    case Action::ToggleSlowMotion:
        return "slow-motion";
    case Action::ToggleTrails:
        return "trails";
    case Action::ClearTrails:
        return "clear-trails";
    case Action::CycleMethod:
        return "cycle-method";
    case Action::StepOnce:
        return "step";
    case Action::ToggleVectors:
        return "vectors";
    case Action::ToggleFrame:
        return "frame";
    case Action::FitView:
        return "fit-view";
    case Action::ToggleSound:
        return "sound";
    case Action::TogglePresent:
        return "present";
    case Action::KeyboardFocus:
        return "keyboard-focus";
    case Action::NextWindow:
        return "next-window";
    case Action::Navigate:
        return "navigate";
    case Action::ToggleFullscreen:
        return "fullscreen";
    case Action::ToggleHelp:
        return "help";
    case Action::TogglePoll:
        return "poll";
    case Action::UiScaleUp:
        return "ui-scale-up";
    case Action::UiScaleDown:
        return "ui-scale-down";
    case Action::DeleteSelected:
        return "delete";
    case Action::Escape:
        return "escape";
    case Action::Quit:
        return "quit";
    case Action::Save:
        return "save";
    case Action::LessonNext:
        return "lesson-next";
    case Action::LessonPrevious:
        return "lesson-previous";
    case Action::LessonFirst:
        return "lesson-first";
    case Action::LessonLast:
        return "lesson-last";
    case Action::LessonDigit:
        return "lesson-digit";
    case Action::LessonJump:
        return "lesson-jump";
    case Action::ThrustLeft:
        return "thrust-left";
    case Action::ThrustRight:
        return "thrust-right";
    case Action::ThrustDown:
        return "thrust-down";
    case Action::ThrustUp:
        return "thrust-up";
    }
    return "none";
}

std::string keyNameOf(Action action) {
    if (action == Action::None) return "";
    for (const KeyBinding& b : keyBindings())
        if (b.action == action) return b.keyName;
    return "";
}

std::string keyedLabel(const std::string& text, Action action, bool touch) {
    const std::string key = touch ? std::string() : keyNameOf(action);
    return (key.empty() ? text : text + " (" + key + ")") + "###" + text;
}

Action actionOfControl(const std::string& name) {
    if (name == "method") return Action::CycleMethod; // actionName: "cycle-method"
    for (int a = static_cast<int>(Action::None) + 1; a <= static_cast<int>(Action::ThrustUp); ++a)
        if (name == actionName(static_cast<Action>(a))) return static_cast<Action>(a);
    return Action::None;
}
