// The classroom rules of the app as pure functions (tested without a window): what Esc does,
// when quitting must ask, the present mode's caption, the hints a first-time user sees, typed
// values checked against their slider's range, and the reference line of a resting stack.
#pragma once

#include "scene.h"

#include <optional>
#include <string>

// What Esc does, in this order: closes an open dialog (quit, save), then the Help window, then
// leaves present mode, then fullscreen; otherwise nothing (quitting is Ctrl+Q or the window's
// close button).
enum class EscapeEffect { CloseDialog, CloseHelp, LeavePresent, LeaveFullscreen, Nothing };
EscapeEffect escapeEffect(bool dialogOpen, bool helpOpen, bool presentMode, bool fullscreen);

// Quitting asks first when the user has edited the blocks, or the settings differ from the
// scene's, since the last load or save.
bool hasUnsavedEdits(bool blocksEdited, const WorldSettings& scene, const WorldSettings& now);

// The first sentence of a description (up to and including its first ". "), or all of it.
std::string firstSentence(const std::string& text);
// Present mode's one line: what the scene is, the method and the time, e.g.
// "Lecture example 1: A 1 kg block at 6 m/s hits a 2 kg block at rest, bounciness 1, no gravity.
//  ·  perfect  ·  t = 0.62 s". The description part is dropped when `withDescription` is false
// (the caller shortens it to fit the screen).
std::string presentCaption(const std::string& sceneName, const std::string& description,
                           Method method, double time, bool withDescription = true);

// The hint shown over a paused scene: at t = 0 "P to play" (and, the first time the app runs,
// the keys to start with); "" while it runs or once it has run.
std::string startHint(bool paused, double time, bool firstLaunch);

// A value typed into a slider (Ctrl+click) checked against the slider's range: clamped into
// [lo, hi], with a message naming what was typed and what was kept ("" when it was in range).
struct TypedValue {
    double value = 0.0;
    std::string message;
};
TypedValue checkTypedValue(const char* what, double typed, double lo, double hi, const char* unit);

// The height (m) the top of a resting stack must keep: when every dynamic block starts at rest
// under gravity pointing down, supported by the floor or by a block below it, the top of the
// highest one; std::nullopt otherwise (the scene is not a resting stack).
std::optional<double> restingStackTop(const Scene& scene);
