// The rows of the world's settings and of a block's fields, and what every reader does with a row
// by its kind. Reading and writing the JSON of a scene file is in scene.cpp and scene_save.cpp.
#include "settings_table.h"

#include "block_def.h"
#include "world_settings.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace settings_table {

namespace {

using limits::Range;

// A block's keys in the order of a scene file (the panel's words for the fields it edits are the
// app's: app/gui/view/panel_rows.h).
const BlockKey kBlock[] = {
    {"name", BlockKind::Text, &BlockDef::name, nullptr, Range{0, 0, ""}, false},
    {"position", BlockKind::Pair, nullptr, &BlockDef::position, limits::kCoordinate, true},
    {"size", BlockKind::Size, nullptr, &BlockDef::size, limits::kSize, true},
    {"velocity", BlockKind::Pair, nullptr, &BlockDef::velocity, limits::kSpeed, false},
    {"mass", BlockKind::Mass, nullptr, nullptr, limits::kMass, false},
    {"force", BlockKind::Force, nullptr, &BlockDef::force, limits::kForce, false},
    {"color", BlockKind::Color, &BlockDef::color, nullptr, Range{0, 0, ""}, false},
    {"friction", BlockKind::Own, nullptr, nullptr, limits::kFriction, false, &BlockDef::friction},
};

bool sameNumber(double a, double b) {
    return a == b || (a != a && b != b);
}

std::string logNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// "m/s^2" -> "m/s²", "kg/m^3" -> "kg/m³".
std::string prettyUnit(const char* unit) {
    std::string out = unit;
    for (const auto& [from, to] : {std::pair{"^2", "²"}, std::pair{"^3", "³"}}) {
        for (std::size_t at = out.find(from); at != std::string::npos; at = out.find(from))
            out.replace(at, std::strlen(from), to);
    }
    return out;
}

std::string withUnit(const std::string& text, const std::string& unit) {
    return unit.empty() ? text : text + " " + unit;
}

} // namespace

Rows<WorldKey> worldKeys() {
    return {std::begin(kWorldKeys), std::end(kWorldKeys)};
}

// The scene's rows sorted by `rank` (stable: equal ranks keep the table's order).
std::vector<const WorldKey*> sceneRowsBy(int (*rank)(const WorldKey&)) {
    std::vector<const WorldKey*> out;
    for (const WorldKey& row : kWorldKeys)
        if (row.inScene) out.push_back(&row);
    std::stable_sort(out.begin(), out.end(),
                     [rank](const WorldKey* a, const WorldKey* b) { return rank(*a) < rank(*b); });
    return out;
}

constexpr int kLast = 1000000; // the rank of a row without a place: after the placed ones

const std::vector<const WorldKey*>& cliOrder() {
    static const std::vector<const WorldKey*> rows =
        sceneRowsBy([](const WorldKey& k) { return k.cli.place > 0 ? k.cli.place : kLast; });
    return rows;
}

const WorldKey* findWorldKey(const std::string& key) {
    for (const WorldKey& row : kWorldKeys)
        if (row.inScene && key == row.key) return &row;
    return nullptr;
}

bool same(const WorldKey& row, const WorldSettings& a, const WorldSettings& b) {
    switch (row.kind) {
    case Kind::Number:
        return sameNumber(a.*row.number, b.*row.number);
    case Kind::Whole:
        return a.*row.whole == b.*row.whole;
    case Kind::Pair:
        return sameNumber((a.*row.pair).x, (b.*row.pair).x) &&
               sameNumber((a.*row.pair).y, (b.*row.pair).y);
    case Kind::Choice:
        return row.getChoice(a) == row.getChoice(b);
    case Kind::NameSet:
        return a.*row.bits == b.*row.bits;
    case Kind::Flag:
        return a.*row.flag == b.*row.flag;
    }
    return true;
}

bool sameSceneSettings(const WorldSettings& a, const WorldSettings& b) {
    return std::all_of(std::begin(kWorldKeys), std::end(kWorldKeys),
                       [&](const WorldKey& row) { return !row.inScene || same(row, a, b); });
}

bool sameAllSettings(const WorldSettings& a, const WorldSettings& b) {
    return std::all_of(std::begin(kWorldKeys), std::end(kWorldKeys),
                       [&](const WorldKey& row) { return same(row, a, b); });
}

void copy(const WorldKey& row, const WorldSettings& from, WorldSettings& to) {
    switch (row.kind) {
    case Kind::Number:
        to.*row.number = from.*row.number;
        break;
    case Kind::Whole:
        to.*row.whole = from.*row.whole;
        break;
    case Kind::Pair:
        to.*row.pair = from.*row.pair;
        break;
    case Kind::Choice:
        row.setChoice(to, row.getChoice(from));
        break;
    case Kind::NameSet:
        to.*row.bits = from.*row.bits;
        break;
    case Kind::Flag:
        to.*row.flag = from.*row.flag;
        break;
    }
}

std::string joinedNames(const Names& names, bool quoted, const char* extra) {
    std::vector<std::string> all;
    for (int i = 0; i < names.count; ++i) all.push_back(names.name(i));
    if (extra) all.push_back(extra);
    std::string out;
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (i > 0) out += i + 1 == all.size() ? " or " : ", ";
        out += quoted ? "\"" + all[i] + "\"" : all[i];
    }
    return out;
}

std::string setNames(const WorldKey& row, const WorldSettings& s, const char* separator) {
    std::string out;
    for (int i = 0; i < row.names.count; ++i) {
        if (!((s.*row.bits >> i) & 1u)) continue;
        out += (out.empty() ? "" : separator) + std::string(row.names.name(i));
    }
    return out;
}

std::string shownUnit(const WorldKey& row) {
    return prettyUnit(row.shown.asRate ? row.shown.rateRange.unit : row.range.unit);
}

bool isNone(const WorldKey& row, const WorldSettings& s) {
    if (row.kind == Kind::Pair) return s.*row.pair == Vec2{};
    if (row.kind == Kind::NameSet) return s.*row.bits == 0;
    return false;
}

std::string shownValue(const WorldKey& row, const WorldSettings& s, std::string (*format)(double)) {
    switch (row.kind) {
    case Kind::Number: {
        const double v = s.*row.number;
        return withUnit(format(row.shown.asRate ? 1.0 / v : v), shownUnit(row));
    }
    case Kind::Whole:
        return withUnit(std::to_string(s.*row.whole), shownUnit(row));
    case Kind::Pair: {
        const Vec2 v = s.*row.pair;
        return withUnit("(" + format(v.x) + ", " + format(v.y) + ")", shownUnit(row));
    }
    case Kind::Choice:
        return row.names.name(row.getChoice(s));
    case Kind::NameSet:
        return setNames(row, s, " and ");
    case Kind::Flag:
        return s.*row.flag ? "on" : "off";
    }
    return "";
}

std::string logValue(const WorldKey& row, const WorldSettings& s) {
    switch (row.kind) {
    case Kind::Number:
        return logNumber(s.*row.number);
    case Kind::Whole:
        return std::to_string(s.*row.whole);
    case Kind::Pair:
        return logNumber((s.*row.pair).x) + "," + logNumber((s.*row.pair).y);
    case Kind::Choice:
        return row.names.name(row.getChoice(s));
    case Kind::NameSet:
        return isNone(row, s) ? "none" : setNames(row, s, ",");
    case Kind::Flag:
        return s.*row.flag ? "on" : "off";
    }
    return "";
}

std::string flagHelp(const WorldKey& row) {
    const std::string scene = " (default: the scene's)";
    switch (row.kind) {
    case Kind::Number:
    case Kind::Whole:
        return std::string(row.cli.help) + ", " + limits::describe(row.range) + scene;
    case Kind::Pair: {
        const Vec2 example = defaultWorldSettings().*row.pair;
        return std::string(row.cli.help) + ", e.g. " + limits::formatNumber(example.x) + "," +
               limits::formatNumber(example.y) + ", each " + limits::describe(row.range) + scene;
    }
    case Kind::Choice:
        return row.cli.help + scene;
    case Kind::NameSet:
    case Kind::Flag:
        return row.cli.help;
    }
    return row.cli.help;
}

FlagProblem readFlag(const WorldKey& row, const std::string& text, WorldSettings& s) {
    switch (row.kind) {
    case Kind::Number: {
        double v = 0.0;
        std::string problem = limits::textViolation(text, row.range, v);
        if (!problem.empty()) return {text, problem};
        s.*row.number = v;
        return {};
    }
    case Kind::Whole: {
        double v = 0.0;
        std::string problem = limits::textViolation(text, row.range, v);
        if (!problem.empty()) return {text, problem};
        s.*row.whole = static_cast<int>(v);
        return {};
    }
    case Kind::Pair: {
        const std::size_t comma = text.find(',');
        if (comma == std::string::npos) {
            const Vec2 example = defaultWorldSettings().*row.pair;
            return {text, "must be " + std::string(row.cli.value) + " in " + row.range.unit +
                              ", e.g. " + limits::formatNumber(example.x) + "," +
                              limits::formatNumber(example.y)};
        }
        Vec2 v;
        for (int axis = 0; axis < 2; ++axis) {
            const std::string part = axis ? text.substr(comma + 1) : text.substr(0, comma);
            std::string problem = limits::textViolation(part, row.range, axis ? v.y : v.x);
            if (!problem.empty()) return {part, problem};
        }
        s.*row.pair = v;
        return {};
    }
    case Kind::Choice:
        for (int i = 0; i < row.names.count; ++i) {
            if (text != row.names.name(i)) continue;
            row.setChoice(s, i);
            return {};
        }
        return {text, "must be " + joinedNames(row.names, false)};
    case Kind::NameSet:
        if (text == "none") {
            s.*row.bits = 0;
            return {};
        }
        for (int i = 0; i < row.names.count; ++i) {
            if (text != row.names.name(i)) continue;
            s.*row.bits = static_cast<std::uint8_t>(s.*row.bits | (1u << i));
            return {};
        }
        return {text, "must be " + joinedNames(row.names, false, "none")};
    case Kind::Flag:
        if (text != "on" && text != "off") return {text, "must be on or off"};
        s.*row.flag = text == "on";
        return {};
    }
    return {};
}

Rows<BlockKey> blockKeys() {
    return {std::begin(kBlock), std::end(kBlock)};
}

const BlockKey& blockKey(const char* key) {
    for (const BlockKey& row : kBlock)
        if (std::strcmp(row.key, key) == 0) return row;
    std::fprintf(stderr, "settings_table::blockKey: no block key \"%s\"\n", key);
    std::abort();
}

bool same(const BlockKey& row, const BlockDef& a, const BlockDef& b) {
    switch (row.kind) {
    case BlockKind::Text:
    case BlockKind::Color:
        return a.*row.text == b.*row.text;
    case BlockKind::Pair:
    case BlockKind::Size:
    case BlockKind::Force:
        return a.*row.pair == b.*row.pair;
    case BlockKind::Own:
        return a.*row.number == b.*row.number;
    case BlockKind::Mass:
        // A static or kinematic block's mass is not part of the file ("static"/"kinematic").
        return a.kind == b.kind && (a.kind != BodyKind::Dynamic || a.mass == b.mass);
    }
    return true;
}

} // namespace settings_table
