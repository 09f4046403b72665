// What a link to the browser build asks for, so a lecturer can post one:
//   index.html?scene=newtons_cradle&method=turn-based&show=plots,inspector
//   index.html?lesson=lecture3&step=5
// scene: a shipped scene's name; method: perfect, move-and-correct or turn-based; show: a --show
// list; frame: world or com (the centre-of-mass frame, view_frame.h); lesson: a shipped lesson's
// name, step: its step (1-based, needs lesson). Pure logic (no
// browser): the web main reads location.search and hands it here.
#pragma once

#include "options.h"
#include "world.h"

#include <optional>
#include <string>
#include <vector>

struct App;

struct UrlParams {
    std::string scene; // a shipped scene's name, "" when not given
    bool methodGiven = false;
    Method method = Method::Perfect;
    bool showGiven = false;
    ShowSet show;
    std::optional<ViewFrame> frame; // none when not given
    std::string lesson;             // a shipped lesson's name, "" when not given
    int step = 0;                   // 1-based; 0 when not given
    // One message per bad parameter, naming it ("URL parameter method: unknown 'x' ...").
    std::vector<std::string> errors;
};

// Parses a query string, with or without its leading '?' (percent-encoding and '+' decoded).
// Unknown parameters, bad values and repeated parameters are errors; the good ones still count.
UrlParams parseUrlParams(const std::string& query);

// Applies the parameters to a set-up app: opens the lesson at its step or the scene (a bad one
// keeps the current scene), then the method and the overlays. Every error goes to
// app.ui.messages.error, one per line.
void applyUrlParams(App& app, const UrlParams& params);
