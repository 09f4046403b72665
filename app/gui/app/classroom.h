// The classroom rules of the app as pure functions (tested without a window): what Esc does,
// when quitting must ask, the present mode's caption, the hints a first-time user sees, typed
// typed values checked against the input limits, and the reference line of a resting stack.
#pragma once

#include "input_limits.h"
#include "scene.h"

#include <optional>
#include <string>

// What Esc does, in this order: closes an open dialog (quit, save), then the Help window, then
// leaves present mode, then fullscreen; otherwise nothing (quitting is Ctrl+Q or the window's
// close button).
enum class EscapeEffect { CloseDialog, CloseHelp, LeavePresent, LeaveFullscreen, Nothing };
EscapeEffect escapeEffect(bool dialogOpen, bool helpOpen, bool presentMode, bool fullscreen);

// The first sentence of a description (up to and including its first ". "), or all of it.
std::string firstSentence(const std::string& text);
// Present mode's one line: what the scene is, the method and the time, e.g.
// "Lecture example 1: A 1 kg block at 6 m/s hits a 2 kg block at rest, bounciness 1, no gravity.
//  ·  perfect  ·  t = 0.62 s". The description part is dropped when `withDescription` is false
// (the caller shortens it to fit the screen).
// "perfect   ·   t = 0.62 s": the method and the time, as the captions write them.
std::string methodAndTime(Method method, double time);
std::string presentCaption(const std::string& sceneName, const std::string& description,
                           Method method, double time, bool withDescription = true);

// In a lesson there is one caption bar (app/gui/ui/lesson_bar.cpp), presenting or not:
// "n / N · title", then on the same line this, then the caption and the question or answer.
// In present mode the method and time (methodAndTime: the status badge that shows them is
// hidden there, and present mode's one-line caption gives way to the bar); otherwise the keys,
// without PageDown after a hint that names it already (`hinted`: "PageDown: play"), and on a
// touch screen (`touch`) nothing: the hint beside it names the button to tap.
std::string lessonBarStatus(bool presentMode, Method method, double time, bool touch = false,
                            bool hinted = false);

// The hint shown over a paused scene: at t = 0 "P to play" (and, the first time the app runs,
// the keys to start with); "" while it runs or once it has run.
std::string startHint(bool paused, double time, bool firstLaunch, bool touch);

// A number typed into a field of the controls panel (Ctrl+click on a slider, or a drag field),
// checked against its limit in engine/world/input_limits.h, the table that scene files and flags
// use: a good value is taken; any other leaves the field at `current` with a message naming the
// field, the limit and what was typed ("frame rate: must be from 1 to 1e6 Hz, not 2e6").
struct TypedValue {
    bool ok = true;
    double value = 0.0; // what the field takes: the typed value, or `current` when refused
    std::string message;
};
TypedValue checkTypedValue(const char* field, double typed, double current,
                           const limits::Range& range);
// The number a panel field shows for `value` under its printf `format` ("%.2f", "%.3g kg/m³",
// "%.0f Hz"), read back: a value set with a slider, a drag or Ctrl+click (a float: 0.44f is
// 0.4399999976158142) is kept as the panel showed it (0.44), so the scene saves and links what
// the user saw. A format without a floating-point conversion (%d) leaves `value` as it is.
double shownNumber(double value, const char* format);
// The panel's one warning about a typed value (shown under its field in the warning colour):
// set by a refused value, cleared by the next good value of the same field or by a new scene.
struct TypedWarning {
    std::string field;
    std::string message;
    // Notes the outcome of `field`'s check; returns check.ok.
    bool note(const char* field, const TypedValue& check);
    void clear() { field.clear(), message.clear(); }
};

// The height (m) the top of a resting stack must keep: when every dynamic block starts at rest
// under gravity pointing down, supported by the floor or by a block below it, and one at least
// stands on another dynamic block, the top of the highest one; std::nullopt otherwise (the scene
// is not a resting stack: the platformer's player, crate and coin at rest on the floor and a
// shelf are not).
std::optional<double> restingStackTop(const Scene& scene);
