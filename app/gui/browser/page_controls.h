// The browser page's own text and form controls, for a screen reader or a switch device: beside
// the canvas, the page keeps real DOM text in step with what the canvas shows (spoken_text.h)
// and native, labelled, visually hidden controls (scene, lesson next/previous, play/pause,
// step, reset, undo, redo, one for every world key of the settings table (page_world_controls.h),
// the selected block and its mass) that drive the same state as the panel. This is the logic both
// ways, with no browser: tested in tests/app; the page (platform/web/index.html) draws it,
// main_web.cpp carries it.
#pragma once

#include "input_map.h"

#include <cstddef>
#include <string>

struct App;
struct SpokenScreen;

// What the page shows, as JSON: {"screen": the SpokenScreen's texts, "controls": the controls'
// values and choices, "world" the world keys' controls}. The page rewrites its DOM only when this
// text changes.
std::string pageStateJson(const App& app);
// The same with the screen's texts as the caller already made them (spokenScreen(app)).
std::string pageStateJson(const App& app, const SpokenScreen& s);
// The page's "selected block" control lists the first kListedBlocks blocks and the selected one
// (200,000 options made again every quarter second would take the page's frames, for nobody).
inline constexpr std::size_t kListedBlocks = 100;

// One of the page's controls was set. `control` is the form control's name ("scene",
// "lesson-previous", "lesson-next", "play", "step", "reset", a world key's (page_world_controls.h:
// "method", "bounciness", "gravity-x", "friction", "mistakes", ...), "block", "mass"), `value` its
// value (a number as typed, a scene's path, a name, a block's index; "" for a button). A value the
// panel would refuse is refused the same way (its warning shows under the panel's field and is
// returned); a button's effect is an Action for the caller to apply (app_frame.h's applyAction), so
// it does exactly what the key does.
struct PageControlOutcome {
    Action action = Action::None;
    std::string error; // "" when taken
};
PageControlOutcome applyPageControl(App& app, const std::string& control, const std::string& value);
