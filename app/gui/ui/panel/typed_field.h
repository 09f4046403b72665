// The controls panel's fields that take a typed value (Ctrl+click on a slider, a drag field):
// the value is checked against its limit (checkTypedValue, engine/input_limits.h), taken when it
// is good, otherwise the field keeps its value and the panel warns under it until a good one comes.
#pragma once

#include "app.h"

// The hovered item's tooltip (nothing for "").
void tooltip(const char* text);
// A value set in `field` (typed, dragged or slid), read as the field shows it under its printf
// `format` (shownNumber: 0.44f is taken as 0.44): true and `out` set when it is within `range`.
bool acceptTyped(App& app, const char* field, double typed, const char* format, double current,
                 const limits::Range& range, double& out);
// The same for a pair (x, y) from a 2-component field: each component that changed is read as
// shown and checked, and both are taken or neither. The one that did not change keeps its value.
bool acceptTyped2(App& app, const char* field, const float typed[2], const char* format,
                  Vec2 current, const limits::Range& range, Vec2& out);
// A block's force and mass together: F/m within what a scene file may hold (else the saved file
// would not load back); false and a warning under `field` when not.
bool acceptAcceleration(App& app, const char* field, Vec2 force, double mass);
// The warning about `field`'s last typed value, under the field, in the warning colour.
void typedWarning(const App& app, const char* field);
