// The one table of the world's settings (WorldSettings) and of a block's fields (BlockDef): for
// each its key in scene files, the member it sets, its kind, limits and unit, and the words people
// read (its name and symbol in the note of a scene saved with changed settings and the log,
// sandbox-cli's flag and help). Scene parsing and saving, equality, the timeline's comparison, the
// --verbose log, sandbox-cli run's flags and --json, and the controls panel all read the rows, so
// a new world key is a row here, the engine code that uses it, a test and the docs
// (docs/scene-format.md); on the panel, also a row of the app's panel table
// (app/gui/view/panel_rows.cpp: its section, label, slider and tooltip).
#pragma once

#include "settings_rows.h"

#include <string>
#include <vector>

namespace settings_table {

// The rows (world_settings.h), in the order of a scene file's "world" (the order they are read
// and saved).
Rows<WorldKey> worldKeys();
// The scene's rows in sandbox-cli's order (its help and run --json): the placed ones (cliPlace
// 1, 2, ...), then the others in table order.
const std::vector<const WorldKey*>& cliOrder();
// The row with this scene key, or null.
const WorldKey* findWorldKey(const std::string& key);

// ---- Reading and comparing a row's value ----

// Equal values (doubles compared by value, a NaN equal to a NaN: the timeline's "same bits").
bool same(const WorldKey& row, const WorldSettings& a, const WorldSettings& b);
// Every row that a scene file holds (the engine-only rows skipped) is the same.
bool sameSceneSettings(const WorldSettings& a, const WorldSettings& b);
// Every row the same, engine-only ones included.
bool sameAllSettings(const WorldSettings& a, const WorldSettings& b);
// Copies the row's value from `from` into `to`.
void copy(const WorldKey& row, const WorldSettings& from, WorldSettings& to);

// The names of a Choice or NameSet joined for a sentence: quoted ("\"a\", \"b\" or \"c\"") or
// bare ("a, b or c"), with `extra` (e.g. "none") as the last one when given.
std::string joinedNames(const Names& names, bool quoted, const char* extra = nullptr);
// The names set in a NameSet, joined with `separator`; "" when none.
std::string setNames(const WorldKey& row, const WorldSettings& s, const char* separator);

// The unit of the value as people read it ("m/s²", "kg/m³", "Hz" for a rate), "" for none.
std::string shownUnit(const WorldKey& row);
// The value as people read it, numbers written by `format`, with its unit: "(0, -9.81) m/s²",
// "30 Hz", "turn-based", "discrete and move-back"; "" for an empty NameSet.
std::string shownValue(const WorldKey& row, const WorldSettings& s, std::string (*format)(double));
// The value for the --verbose log: "%.6g" numbers, "x,y" pairs, names ("none" for an empty set).
std::string logValue(const WorldKey& row, const WorldSettings& s);
// True when the value is "nothing" (a zero pair, an empty set): the note says "no gravity".
bool isNone(const WorldKey& row, const WorldSettings& s);

// ---- sandbox-cli run's flags ----

// The flag's help: the row's words, then its range and "(default: the scene's)" as the kind has.
std::string flagHelp(const WorldKey& row);
// A flag's refusal: the text refused (a pair's component alone) and what it must be.
struct FlagProblem {
    std::string text;
    std::string expected;
};
// Reads a flag's text into `s`: a number within the range, "X,Y", a name; for a NameSet a name
// added to the set or "none" (clears it). Empty `expected` when it was taken.
FlagProblem readFlag(const WorldKey& row, const std::string& text, WorldSettings& s);

// ---- Block fields ----

// The rows, in the order of a block's keys in a scene file.
Rows<BlockKey> blockKeys();
// The row with this key; the key must be one of the table's (a typo is a programming error).
const BlockKey& blockKey(const char* key);
// Equal as a scene file holds them (a static or kinematic block's mass is not in the file).
bool same(const BlockKey& row, const BlockDef& a, const BlockDef& b);

} // namespace settings_table
