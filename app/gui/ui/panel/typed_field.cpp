// The controls panel's fields that take a typed value: checked against their limits
// (typed_field.h).
#include "typed_field.h"

#include "ui_style.h"

#include <imgui.h>

#include <string>

void tooltip(const char* text) {
    if (*text && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

// A value set in `field` (Ctrl+click on a slider, a slide or a drag), read as the field shows it
// (shownNumber) and checked against its limit (checkTypedValue, engine/input_limits.h): true and
// `out` set when it is good; otherwise the field keeps `current` and the panel warns under it
// until a good value comes.
bool acceptTyped(App& app, const char* field, double typed, const char* format, double current,
                 const limits::Range& range, double& out) {
    const TypedValue check = checkTypedValue(field, shownNumber(typed, format), current, range);
    out = check.value;
    return app.ui.typedWarning.note(field, check);
}

// The same for a pair (x, y) from a 2-component field: each component that changed is checked,
// and both are taken or neither. The one that did not change keeps its double value.
bool acceptTyped2(App& app, const char* field, const float typed[2], const char* format,
                  Vec2 current, const limits::Range& range, Vec2& out) {
    const double now[2] = {current.x, current.y};
    double wanted[2] = {current.x, current.y};
    TypedValue check;
    for (int k = 0; k < 2 && check.ok; ++k) {
        if (typed[k] == static_cast<float>(now[k])) continue;
        check = checkTypedValue(field, shownNumber(typed[k], format), now[k], range);
        wanted[k] = check.value;
    }
    if (check.ok) out = Vec2{wanted[0], wanted[1]};
    return app.ui.typedWarning.note(field, check);
}

// A block's force and mass together: F/m within what a scene file may hold (else the saved file
// would not load back); false and a warning under `field` when not.
bool acceptAcceleration(App& app, const char* field, Vec2 force, double mass) {
    const std::string problem = limits::accelerationViolation(length(force), mass);
    if (problem.empty()) return true;
    return app.ui.typedWarning.note(field,
                                    TypedValue{false, 0.0, std::string(field) + ": " + problem});
}

// The warning about `field`'s last typed value, under the field, in the warning colour.
void typedWarning(const App& app, const char* field) {
    const TypedWarning& w = app.ui.typedWarning;
    if (w.message.empty() || w.field != field) return;
    ImGui::PushStyleColor(ImGuiCol_Text, uiWarningColor());
    textWrappedAtSpaces(w.message);
    ImGui::PopStyleColor();
}
