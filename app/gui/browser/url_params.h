// What a link to the browser build asks for, so a lecturer can post one:
//   index.html?scene=newtons_cradle&method=turn-based&show=plots,inspector
//   index.html?lesson=lecture3&step=5
// The parameters are the table kUrlParams (the README lists the same). Parameters that trackers
// add to links (utm_*, fbclid, gclid, ...: isTrackerParam) are ignored without a word; other
// unknown ones are listed once, briefly. Pure logic (no browser): the web main reads
// location.search and hands it here.
#pragma once

#include "options.h"
#include "settings_table.h"
#include "world.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

struct App;

// The parameters a link may carry, in the order the address bar writes them; and every world key
// of the settings table (panelOrder, panel_rows.h: method, bounciness, gravity=X,Y, dt,
// substeps, resolve, integrator, mistakes=a,b or none, drag, friction), each set after the scene
// opens, as the page's controls take it (page_world_controls.h: readWorldValue).
struct UrlParamInfo {
    const char* name;
    const char* meaning; // for the README and the message about unknown parameters
};
inline constexpr UrlParamInfo kUrlParams[] = {
    {"scene", "a shipped scene's name (app/scenes/NAME.json)"},
    {"lesson", "a shipped lesson's name (lessons/NAME.json)"},
    {"step", "the lesson's step, 1-based (needs lesson)"},
    {"show", "the overlays shown: a --show list (empty: none)"},
    {"frame", "world or com (the centre-of-mass frame)"},
};

// Parameters that link trackers add (utm_source, fbclid, gclid, ...): not the sandbox's business.
bool isTrackerParam(std::string_view name);

struct UrlParams {
    std::string scene; // a shipped scene's name, "" when not given
    // The world keys given (in the query's order) and their values (read onto the defaults).
    std::vector<const settings_table::WorldKey*> worldGiven;
    WorldSettings world = defaultWorldSettings();
    bool showGiven = false;
    ShowSet show;
    std::optional<ViewFrame> frame; // none when not given
    std::string lesson;             // a shipped lesson's name, "" when not given
    // The lesson's step, 1-based, as given (stepText); 0 when not given, -1 when it is no step
    // number (0, not a whole number, or one too long to be any lesson's): applyUrlParams checks
    // it against the lesson.
    int step = 0;
    std::string stepText;
    // The scene a link carries in its fragment (#scene=..., link.h): the page decodes it into
    // this file before the app starts; "" when there is none. Not parsed from the query.
    std::string linkScene;
    // One message per bad parameter, naming it ("URL parameter method: 'x' must be ..."), at most
    // kMaxUrlErrors of them (then one line counting the rest); unknown parameters share one line
    // at the end.
    std::vector<std::string> errors;
};
inline constexpr std::size_t kMaxUrlErrors = 5;

// Parses a query string, with or without its leading '?' (percent-encoding and '+' decoded).
// Bad values and repeated parameters are errors; the good ones still count.
UrlParams parseUrlParams(const std::string& query);

// Applies the parameters to a set-up app: opens the lesson at its step, the link's scene or the
// shipped scene (a bad one keeps the current scene), then the world keys given and the overlays.
// Every error goes to app.ui.messages.error, one per line. The one rule for a value out of its
// range or not understood: it is not applied, its message names the parameter, what was given and
// what it may be, and the rest of the link opens (a lesson whose step is out of range opens at its
// first step).
void applyUrlParams(App& app, const UrlParams& params);
