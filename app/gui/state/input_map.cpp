#include "input_map.h"

const std::vector<KeyBinding>& keyBindings() {
    static const std::vector<KeyBinding> bindings{
        {keys::kR, false, Action::Reset, "R", "Reset to the scene as loaded"},
        {keys::kP, false, Action::TogglePause, "P", "Pause / resume"},
        {keys::kSpace, false, Action::ToggleSlowMotion, "Space", "Slow motion (5 frames/s)"},
        {keys::kD, false, Action::ToggleTrails, "D", "Draw trajectories on / off"},
        {keys::kC, false, Action::ClearTrails, "C", "Clear trajectories"},
        {keys::kS, false, Action::CycleMethod, "S", "Cycle the simulation method"},
        {keys::kN, false, Action::StepOnce, "N", "Single step (pauses)"},
        {keys::kV, false, Action::ToggleVectors, "V", "Velocity arrows on / off"},
        {keys::kF, false, Action::FitView, "F", "Fit the world into the view"},
        {keys::kTab, false, Action::ToggleUi, "Tab", "Hide / show the panels"},
        {keys::kF11, false, Action::ToggleFullscreen, "F11", "Fullscreen"},
        {keys::kF1, false, Action::ToggleHelp, "F1", "This help"},
        {keys::kEqual, true, Action::UiScaleUp, "Ctrl+=", "Larger UI (projector)"},
        {keys::kKeypadAdd, true, Action::UiScaleUp, "Ctrl+Keypad +", "Larger UI"},
        {keys::kMinus, true, Action::UiScaleDown, "Ctrl+-", "Smaller UI"},
        {keys::kKeypadSubtract, true, Action::UiScaleDown, "Ctrl+Keypad -", "Smaller UI"},
        {keys::kS, true, Action::Save, "Ctrl+S", "Save the current state as a scene"},
        {keys::kDelete, false, Action::DeleteSelected, "Delete", "Remove the selected block"},
        {keys::kEscape, false, Action::Quit, "Esc", "Quit"},
    };
    return bindings;
}

Action actionForKey(int key, bool ctrl) {
    for (const KeyBinding& b : keyBindings()) {
        if (b.key == key && b.ctrl == ctrl) return b.action;
    }
    return Action::None;
}

const char* actionName(Action action) {
    switch (action) {
    case Action::None:
        return "none";
    case Action::Reset:
        return "reset";
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
    case Action::FitView:
        return "fit-view";
    case Action::ToggleUi:
        return "toggle-ui";
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
    case Action::Quit:
        return "quit";
    case Action::Save:
        return "save";
    }
    return "none";
}
