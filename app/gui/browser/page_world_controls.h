// The page's hidden form has a labelled control for every world key of the settings table
// (settings_table.h: the scene's rows), made from the table: a new world key gets its control
// without a word here. Pure logic (nlohmann::json for the page, the App's settings): the page
// (platform/web/index.html) builds its form from worldControlsJson() once and sends each change
// back through applyWorldControl(). page_controls.h carries both.
#pragma once

#include "input_limits.h"
#include "settings_table.h"

#include <nlohmann/json.hpp>

#include <string>

struct App;
struct WorldSettings;

// [{"key", "label", "kind", "value", ...}] for every row of the scene's settings in the panel's
// order (panelOrder, panel_rows.h): kind "number" or "whole" (with "min" and "max"), "pair"
// (value [x, y]: the page makes the controls KEY-x and KEY-y), "choice" (value a name of
// "names"), "set" (value the names set, of "names") or "flag" (value true or false). The label
// is what a screen reader says: "Bounciness C", "Time step dt in s", "Gravity g, x in m/s²".
nlohmann::json worldControlsJson(const WorldSettings& s);

// The control named `control` (a world key, or KEY-x / KEY-y of a pair) set to `value` (a number
// as typed, a name, names joined by commas or "none" for a set, "on" or "off"): false when no
// world key has that control. A value the panel would refuse is refused the same way: `error`
// says why (the panel's warning under its field), the setting is kept.
bool applyWorldControl(App& app, const std::string& control, const std::string& value,
                       std::string& error);

// A world key's value as the page's controls and URL parameters write it, read into `s`: a number,
// "X,Y" for a pair, a name, names joined by commas (or "none") for a set, "on" or "off"; all or
// nothing. Empty `expected` when it was taken (settings_table::readFlag's words otherwise).
settings_table::FlagProblem readWorldValue(const settings_table::WorldKey& row,
                                           const std::string& text, WorldSettings& s);

// A typed number checked as the panel checks it (classroom.h): taken into `out`, or refused with
// the panel's warning under `field` (also returned in `error`).
bool acceptTypedNumber(App& app, const char* field, const std::string& text, double current,
                       const limits::Range& range, double& out, std::string& error);
