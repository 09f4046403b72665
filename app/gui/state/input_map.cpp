#include "input_map.h"

const std::vector<KeyBinding>& keyBindings() {
    static const std::vector<KeyBinding> bindings{
        {keys::kR, false, Action::Reset, "R",
         "Reset blocks and time (keeps method, C, g, frame rate, substeps; in a lesson: restart "
         "the step)"},
        {keys::kR, false, Action::ResetToFile, "Shift+R", "Reset to file: everything as loaded",
         true, true},
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
        {keys::kTab, false, Action::TogglePresent, "Tab",
         "Present mode: only the scene and a caption (again: all back)"},
        {keys::kF11, false, Action::ToggleFullscreen, "F11", "Fullscreen"},
        {keys::kF1, false, Action::ToggleHelp, "F1", "This help"},
        {keys::kEqual, true, Action::UiScaleUp, "Ctrl+=", "Larger UI (projector)"},
        {keys::kKeypadAdd, true, Action::UiScaleUp, "Ctrl+Keypad +", "Larger UI"},
        {keys::kMinus, true, Action::UiScaleDown, "Ctrl+-", "Smaller UI"},
        {keys::kKeypadSubtract, true, Action::UiScaleDown, "Ctrl+Keypad -", "Smaller UI"},
        {keys::kS, true, Action::Save, "Ctrl+S", "Save the current state as a scene"},
        {keys::kDelete, false, Action::DeleteSelected, "Delete", "Remove the selected block"},
        {keys::kEscape, false, Action::Escape, "Esc",
         "Close Help or a dialog; leave present mode or fullscreen"},
        {keys::kQ, true, Action::Quit, "Ctrl+Q", "Quit (asks when there are unsaved edits)"},
        {keys::kPageDown, false, Action::LessonNext, "PageDown",
         "Lesson: answer, then the next step"},
        {keys::kRight, false, Action::LessonNext, "Right", "Lesson: answer, then the next step"},
        {keys::kPageUp, false, Action::LessonPrevious, "PageUp", "Lesson: the previous step"},
        {keys::kLeft, false, Action::LessonPrevious, "Left", "Lesson: the previous step"},
        {keys::kHome, false, Action::LessonFirst, "Home", "Lesson: the first step"},
        {keys::kEnd, false, Action::LessonLast, "End", "Lesson: the last step"},
        {keys::kEnter, false, Action::LessonJump, "0-9, Enter", "Lesson: go to step number ..."},
        {keys::kKeypadEnter, false, Action::LessonJump, "Keypad Enter",
         "Lesson: go to step number ...", false},
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
    return bindings;
}

int digitOfKey(int key) {
    if (key >= keys::k0 && key <= keys::k0 + 9) return key - keys::k0;
    if (key >= keys::kKeypad0 && key <= keys::kKeypad0 + 9) return key - keys::kKeypad0;
    return -1;
}

Action actionForKey(int key, bool ctrl, bool shift) {
    for (const KeyBinding& b : keyBindings()) {
        if (b.key == key && b.ctrl == ctrl && b.shift == shift) return b.action;
    }
    if (shift) return actionForKey(key, ctrl, false);
    return Action::None;
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
    case Action::TogglePresent:
        return "present";
    case Action::ToggleFullscreen:
        return "fullscreen";
    case Action::ToggleHelp:
        return "help";
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
    }
    return "none";
}
