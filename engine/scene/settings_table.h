// The one table of the world's settings (WorldSettings) and of a block's fields (BlockDef): for
// each its key in scene files, the member it sets, its kind, limits and unit, and the words people
// read (the panel's label and tooltip, the note of a scene saved with changed settings, the log).
// Scene parsing and saving, equality, the timeline's comparison, the --verbose log, sandbox-cli
// run's flags and --json, and the controls panel all read the rows, so a new world key is a row
// here, the engine code that uses it, a test and the docs (docs/scene-format.md).
#pragma once

#include "input_limits.h"
#include "vec2.h"

#include <cstdint>
#include <string>
#include <vector>

struct BlockDef;
struct WorldSettings;

namespace settings_table {

enum class Kind : std::uint8_t {
    Number,  // a double within `range`
    Whole,   // an int within `range` (a whole number)
    Pair,    // a Vec2 ([x, y] in files, "X,Y" on the command line), each within `range`
    Choice,  // one name of a list: an enum such as Method
    NameSet, // any set of names of a list, written as an array of names: a bit set
    Flag,    // true or false
};

// Where the controls panel shows a setting; None: not on the panel.
enum class Section : std::uint8_t { None, Simulation, Physics };

// The names of a Choice or a NameSet, from the engine's own name functions (methodName, ...).
struct Names {
    int count = 0;
    const char* (*name)(int) = nullptr;
    const char* (*note)(int) = nullptr; // a line about each name (the mistakes' slides), or null
};

// The member a row reads and writes, by its kind (the others null).
struct Member {
    Kind kind = Kind::Number;
    double WorldSettings::*number = nullptr;          // Number
    int WorldSettings::*whole = nullptr;              // Whole
    Vec2 WorldSettings::*pair = nullptr;              // Pair
    bool WorldSettings::*flag = nullptr;              // Flag
    std::uint8_t WorldSettings::*bits = nullptr;      // NameSet: bit (1 << i) set for name i
    int (*getChoice)(const WorldSettings&) = nullptr; // Choice
    void (*setChoice)(WorldSettings&, int) = nullptr; // Choice
    Names names;                                      // Choice, NameSet

    constexpr Member(double WorldSettings::*m) : number(m) {}
    constexpr Member(int WorldSettings::*m) : kind(Kind::Whole), whole(m) {}
    constexpr Member(Vec2 WorldSettings::*m) : kind(Kind::Pair), pair(m) {}
    constexpr Member(bool WorldSettings::*m) : kind(Kind::Flag), flag(m) {}
    constexpr Member(std::uint8_t WorldSettings::*m, Names n)
        : kind(Kind::NameSet), bits(m), names(n) {}
    constexpr Member(int (*get)(const WorldSettings&), void (*set)(WorldSettings&, int), Names n)
        : kind(Kind::Choice), getChoice(get), setChoice(set), names(n) {}
};

// How people read a setting: its name in sentences ("gravity", "frame rate": the note, the
// panel), its symbol ("C", "g"), the panel's tooltip; a rate is shown as 1/value (dt as a frame
// rate, within `rateRange`, whose unit is shown).
struct Shown {
    const char* name = "";
    const char* symbol = "";
    const char* tooltip = "";
    bool asRate = false;
    limits::Range rateRange{0.0, 0.0, ""};
};

// sandbox-cli run: the flag ("" for none), its value's name in the help, the help's words; its
// place among the flags and in --json (1 first; 0: after the placed ones, in table order).
struct Cli {
    const char* flag = "";
    const char* value = "";
    const char* help = "";
    int place = 0;
};

// The controls panel: section, place in it (1 first), label, the slider's range and format; a
// Pair's preset button (its label and tooltip) sets the default value.
struct Panel {
    Section section = Section::None;
    int place = 0;
    const char* label = "";
    float min = 0.0f, max = 0.0f;
    const char* format = "";
    bool logarithmic = false;
    const char* presetLabel = "";
    const char* presetTooltip = "";
};

// One row: a world setting.
struct WorldKey : Member {
    const char* key = ""; // in a scene's "world", sandbox-cli run --json and the --verbose log
    limits::Range range{0.0, 0.0, ""}; // Number, Whole, Pair
    Shown shown;
    Cli cli;
    Panel panel;
    bool inScene = true; // false: an engine-only setting (no scene key, no panel, no flag)
};

// A table's rows, for a range-for.
template <typename Row> struct Rows {
    const Row* first;
    const Row* last;
    const Row* begin() const { return first; }
    const Row* end() const { return last; }
};

// The rows (world_settings.h), in the order of a scene file's "world" (the order they are read
// and saved).
Rows<WorldKey> worldKeys();
// The scene's rows in the panel's order (Simulation, then Physics, then any row not on the
// panel, in table order): the panel draws them and the --verbose log describes changes so.
const std::vector<const WorldKey*>& shownOrder();
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

enum class BlockKind : std::uint8_t {
    Text,  // a string (the name); written only when not empty
    Color, // "#rrggbb"; written only when not empty
    Pair,  // [x, y], each within `range`
    Size,  // a number (a square) or [w, h], each within `range` and long enough for its place
    Mass,  // a number within `range`, "static" or "kinematic" (the block's kind)
    Force, // [fx, fy] within `range` on a dynamic block only, |F|/m within the gravity limit;
           // written only when not zero
};

struct BlockKey {
    const char* key;
    BlockKind kind;
    std::string BlockDef::*text; // Text, Color
    Vec2 BlockDef::*pair;        // Pair, Size, Force
    limits::Range range;         // Pair, Size, Mass, Force
    bool required;
    const char* label;        // the panel's field ("" when the panel has none)
    const char* sliderFormat; // the panel's number format, unit included
    const char* tooltip;
};

// The rows, in the order of a block's keys in a scene file.
Rows<BlockKey> blockKeys();
// The row with this key; the key must be one of the table's (a typo is a programming error).
const BlockKey& blockKey(const char* key);
// Equal as a scene file holds them (a static or kinematic block's mass is not in the file).
bool same(const BlockKey& row, const BlockDef& a, const BlockDef& b);

} // namespace settings_table
