// The row types of the one settings table (settings_table.h): what a row of the world's settings
// (WorldKey) and of a block's fields (BlockKey) holds. Header-only and below both WorldSettings
// (world_settings.h, whose rows they type) and the scene (scene.h): it includes neither.
#pragma once

#include "input_limits.h"
#include "vec2.h"

#include <cstdint>
#include <string>

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

// ---- Block fields ----

enum class BlockKind : std::uint8_t {
    Text,  // a string (the name); written only when not empty
    Color, // "#rrggbb"; written only when not empty
    Pair,  // [x, y], each within `range`
    Size,  // a number (a square) or [w, h], each within `range` and long enough for its place
    Mass,  // a number within `range`, "static" or "kinematic" (the block's kind)
    Force, // [fx, fy] within `range` on a dynamic block only, |F|/m within the gravity limit;
           // written only when not zero
    Own,   // a number within `range` that overrides a world setting for this block; absent
           // (< 0 in BlockDef) means the world's, and is not written
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
    double BlockDef::*number = nullptr; // Own
};

} // namespace settings_table
