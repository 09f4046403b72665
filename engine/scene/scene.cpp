// Scene files, format v1 (docs/scene-format.md): parsing with validation that names
// the place of every error. Saving and the conversion to and from World are in scene_save.cpp.
#include "scene.h"

#include "input_limits.h"
#include "overlap_check.h"
#include "printable.h"
#include "scene_json.h"
#include "settings_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <string_view>

using json = nlohmann::json;
using scene_json::dumpValue;
using scene_json::numberList;
using namespace scene_json; // the typed access below: number(), string(), vec2(), ...

namespace {

constexpr std::size_t kMaxFileBytes = 64u << 20; // 64 MiB
constexpr std::size_t kMaxBlocks = 200000;
constexpr int kMaxDepth = 64; // the format itself needs 4 levels
// m: overlaps up to this much count as touching, so stacks typed in decimals ("exactly
// touching" up to rounding) are accepted.
constexpr double kTouchTolerance = 1e-9;

// ---- Syntax: line and column, and a pre-scan for nesting depth and duplicate keys ----

struct TextPlace {
    std::size_t line = 1, column = 1;
};

TextPlace placeOf(const std::string& text, std::size_t index) {
    index = std::min(index, text.size());
    TextPlace place;
    for (std::size_t i = 0; i < index; ++i) {
        if (text[i] == '\n') {
            ++place.line;
            place.column = 1;
        } else {
            ++place.column;
        }
    }
    return place;
}

std::string placeName(const std::string& source, const std::string& text, std::size_t index) {
    const TextPlace p = placeOf(text, index);
    return source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
}

struct ScanProblem {
    std::size_t index = 0;
    std::string message;
};

// Appends code point c as UTF-8 (a lone surrogate, which the parser has refused by now, as the
// replacement character).
void appendUtf8(std::string& out, std::uint32_t c) {
    if (c >= 0xd800 && c <= 0xdfff) c = 0xfffd;
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xc0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3f));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xe0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (c & 0x3f));
    } else {
        out += static_cast<char>(0xf0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
        out += static_cast<char>(0x80 | (c & 0x3f));
    }
}

// The text of a JSON string that the parser has accepted (without its quotes), its escapes
// decoded: "m\u0061ss" and "mass" are the same key.
std::string decodedString(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    auto hex4 = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t k = at; k < at + 4 && k < raw.size(); ++k) {
            const char c = raw[k];
            v = v * 16 + static_cast<std::uint32_t>(std::isdigit(static_cast<unsigned char>(c))
                                                        ? c - '0'
                                                        : (std::tolower(c) - 'a' + 10));
        }
        return v;
    };
    for (std::size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] != '\\' || i + 1 >= raw.size()) {
            out += raw[i];
            continue;
        }
        const char e = raw[++i];
        if (e != 'u') {
            const char* const from = "bfnrt";
            const char* const to = "\b\f\n\r\t";
            const char* const at = std::strchr(from, e);
            out += at && *at ? to[at - from] : e; // \" \\ \/ stand for themselves
            continue;
        }
        std::uint32_t c = hex4(i + 1);
        i += 4;
        // A high surrogate followed by a low one: one code point beyond U+FFFF.
        if (c >= 0xd800 && c <= 0xdbff && i + 6 < raw.size() && raw[i + 1] == '\\' &&
            raw[i + 2] == 'u') {
            const std::uint32_t low = hex4(i + 3);
            if (low >= 0xdc00 && low <= 0xdfff) {
                c = 0x10000 + ((c - 0xd800) << 10) + (low - 0xdc00);
                i += 6;
            }
        }
        appendUtf8(out, c);
    }
    return out;
}

// Walks the text once without recursion. Finds nesting deeper than kMaxDepth (nlohmann's DOM is
// built and destroyed recursively, so a 100,000-deep "[[[[" must never reach it) and duplicate
// keys in one object (nlohmann would silently keep the last), compared after decoding their
// escapes. Strings are skipped with their escapes; anything malformed is left for the real
// parser to report.
std::optional<ScanProblem> prescan(const std::string& text, bool checkDuplicates) {
    std::vector<std::set<std::string>> keys; // one set per open object: decoded keys
    std::vector<char> open;                  // '{' or '['
    const std::string_view all(text);
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '{' || c == '[') {
            if (open.size() >= static_cast<std::size_t>(kMaxDepth))
                return ScanProblem{i,
                                   "nesting deeper than " + std::to_string(kMaxDepth) + " levels"};
            open.push_back(c);
            keys.emplace_back();
        } else if (c == '}' || c == ']') {
            if (!open.empty()) {
                open.pop_back();
                keys.pop_back();
            }
        } else if (c == '"') {
            const std::size_t start = i;
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            if (!checkDuplicates || open.empty() || open.back() != '{') continue;
            std::size_t next = i + 1;
            while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next])))
                ++next;
            if (next >= text.size() || text[next] != ':') continue; // a value, not a key
            const std::string_view raw = all.substr(start + 1, i - start - 1);
            std::string key = decodedString(raw);
            if (keys.back().count(key)) {
                std::string message = "duplicate key \"" + printable(key) + "\"";
                if (key != raw) message += " (written \"" + printable(raw) + "\")";
                return ScanProblem{start, message};
            }
            keys.back().insert(std::move(key));
        }
    }
    return std::nullopt;
}

// nlohmann's messages start with "[json.exception...] parse error at line L, column C: " and may
// quote raw bytes of the input; those are shown as \xNN so junk never reaches a terminal.
std::string parserMessage(const std::string& what) {
    const std::size_t column = what.find("column ");
    const std::size_t colon = what.find(": ", column == std::string::npos ? 0 : column);
    const std::string message = colon == std::string::npos ? what : what.substr(colon + 2);
    return printable(message, 2 * kPrintableDefault);
}

} // namespace

// ---- Values: typed access that names the JSON path on failure (scene_json.h) ----

namespace scene_json {

std::string indexPath(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}
// The key is from the file: shown printable (an unknown key's name may be anything).
std::string keyPath(const std::string& path, const std::string& key) {
    const std::string shown = printable(key);
    return path.empty() ? shown : path + "." + shown;
}

void checkKeys(const json& object, const std::string& path,
               std::initializer_list<const char*> known) {
    checkKeys(object, path, std::vector<const char*>(known));
}

void checkKeys(const json& object, const std::string& path, const std::vector<const char*>& known) {
    for (const auto& item : object.items()) {
        const bool ok =
            std::any_of(known.begin(), known.end(), [&](const char* k) { return item.key() == k; });
        if (!ok) throw ValueError{keyPath(path, item.key()), "unknown key"};
    }
}

const json& requireObject(const json& value, const std::string& path) {
    if (!value.is_object()) throw ValueError{path, "must be an object"};
    return value;
}

double number(const json& value, const std::string& path) {
    if (!value.is_number()) throw ValueError{path, "must be a number"};
    const double x = value.get<double>();
    if (!std::isfinite(x)) throw ValueError{path, "must be a finite number"};
    return x;
}

std::string string(const json& value, const std::string& path) {
    if (!value.is_string()) throw ValueError{path, "must be a string"};
    return value.get<std::string>();
}

double number(const json& value, const std::string& path, const limits::Range& range) {
    const double x = number(value, path);
    if (std::string problem = limits::violation(range, x); !problem.empty())
        throw ValueError{path, problem};
    return x;
}

std::vector<double> numbers(const json& value, const std::string& path, std::size_t n,
                            const limits::Range& range) {
    if (!value.is_array() || value.size() != n)
        throw ValueError{path, "must be an array of " + std::to_string(n) + " numbers"};
    std::vector<double> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(number(value[i], indexPath(path, i), range));
    return out;
}

Vec2 vec2(const json& value, const std::string& path, const limits::Range& range) {
    const std::vector<double> v = numbers(value, path, 2, range);
    return {v[0], v[1]};
}

std::vector<double> numbers(const json& value, const std::string& path, std::size_t n) {
    return numbers(value, path, n, limits::kMagnitude);
}

Vec2 vec2(const json& value, const std::string& path) {
    return vec2(value, path, limits::kMagnitude);
}

} // namespace scene_json

namespace {

// A length (a block's side, the bounds' extent) at coordinates of magnitude up to `magnitude`.
void checkLength(double length, double magnitude, const std::string& path,
                 const limits::Range& range = limits::kSize) {
    if (std::string problem = limits::lengthViolation(length, magnitude, range); !problem.empty())
        throw ValueError{path, problem};
}

bool isColor(const std::string& s) {
    return s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), [](char c) {
               return std::isxdigit(static_cast<unsigned char>(c)) != 0;
           });
}

// A world setting's value (settings_table.h), by its kind; errors name `path`.
void readSetting(const settings_table::WorldKey& row, const json& value, const std::string& path,
                 WorldSettings& s) {
    using settings_table::Kind;
    switch (row.kind) {
    case Kind::Number:
        s.*row.number = number(value, path, row.range);
        return;
    case Kind::Whole:
        s.*row.whole = static_cast<int>(number(value, path, row.range));
        return;
    case Kind::Pair:
        s.*row.pair = vec2(value, path, row.range);
        return;
    case Kind::Flag:
        if (!value.is_boolean()) throw ValueError{path, "must be true or false"};
        s.*row.flag = value.get<bool>();
        return;
    case Kind::Choice: {
        const std::string name = string(value, path);
        for (int i = 0; i < row.names.count; ++i) {
            if (name != row.names.name(i)) continue;
            row.setChoice(s, i);
            return;
        }
        throw ValueError{path, "must be " + settings_table::joinedNames(row.names, true) +
                                   ", not \"" + printable(name) + "\""};
    }
    case Kind::NameSet: {
        if (!value.is_array()) throw ValueError{path, "must be an array of names"};
        std::uint8_t& bits = s.*row.bits;
        for (std::size_t k = 0; k < value.size(); ++k) {
            const std::string at = indexPath(path, k);
            const std::string name = string(value[k], at);
            int found = -1;
            for (int i = 0; i < row.names.count && found < 0; ++i)
                if (name == row.names.name(i)) found = i;
            if (found < 0)
                throw ValueError{at, "must be " + settings_table::joinedNames(row.names, true) +
                                         ", not " + dumpValue(name)};
            const auto bit = static_cast<std::uint8_t>(1u << found);
            if (bits & bit) throw ValueError{at, dumpValue(name) + " is listed twice"};
            bits = static_cast<std::uint8_t>(bits | bit);
        }
        return;
    }
    }
}

void parseWorld(const json& world, Scene& scene) {
    requireObject(world, "world");
    std::vector<const char*> known{"bounds"};
    for (const settings_table::WorldKey& row : settings_table::worldKeys())
        if (row.inScene) known.push_back(row.key);
    checkKeys(world, "world", known);
    if (world.contains("bounds")) {
        const std::vector<double> b =
            numbers(world["bounds"], "world.bounds", 4, limits::kCoordinate);
        if (!(b[0] < b[2] && b[1] < b[3]))
            throw ValueError{"world.bounds", "must be [xmin, ymin, xmax, ymax] with xmin < xmax "
                                             "and ymin < ymax"};
        for (int axis = 0; axis < 2; ++axis)
            checkLength(b[axis + 2] - b[axis], std::max(std::abs(b[axis]), std::abs(b[axis + 2])),
                        "world.bounds (" + std::string(axis ? "height" : "width") + ")",
                        limits::kExtent);
        scene.bounds.min = {b[0], b[1]};
        scene.bounds.max = {b[2], b[3]};
    }
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (row.inScene && world.contains(row.key))
            readSetting(row, world[row.key], keyPath("world", row.key), scene.settings);
    }
}

// A block's field (settings_table.h), by its kind; `b` holds the fields read before it (a size
// is checked against the position, a force against the mass).
void readBlockField(const settings_table::BlockKey& row, const json& value, const std::string& path,
                    BlockDef& b) {
    using settings_table::BlockKind;
    switch (row.kind) {
    case BlockKind::Text:
        b.*row.text = string(value, path);
        return;
    case BlockKind::Color:
        b.*row.text = string(value, path);
        if (!isColor(b.*row.text)) throw ValueError{path, "must look like #rrggbb"};
        return;
    case BlockKind::Pair:
        b.*row.pair = vec2(value, path, row.range);
        return;
    case BlockKind::Size:
        if (value.is_number()) {
            const double side = number(value, path);
            b.*row.pair = {side, side};
            checkLength(side, std::max(std::abs(b.position.x), std::abs(b.position.y)), path,
                        row.range);
        } else if (value.is_array()) {
            b.*row.pair = vec2(value, path, row.range);
            for (int axis = 0; axis < 2; ++axis)
                checkLength((b.*row.pair)[axis], std::abs(b.position[axis]), indexPath(path, axis),
                            row.range);
        } else {
            throw ValueError{path, "must be a number (a square) or [width, height]"};
        }
        return;
    case BlockKind::Mass:
        // Without "mass" a block is dynamic with 1 kg (BlockDef's default).
        if (value == "static") {
            b.kind = BodyKind::Static;
        } else if (value == "kinematic") {
            b.kind = BodyKind::Kinematic;
        } else if (value.is_number()) {
            b.mass = number(value, path, row.range);
        } else {
            throw ValueError{path, "must be a positive number, \"static\" or \"kinematic\""};
        }
        return;
    case BlockKind::Force:
        b.*row.pair = vec2(value, path, row.range);
        if (b.kind != BodyKind::Dynamic && b.*row.pair != Vec2{})
            throw ValueError{path, "only a dynamic block (one with a mass) feels a force"};
        // Its acceleration, like gravity, at most 1e9 m/s^2 (F/m of a light block can be huge).
        if (std::string problem = limits::accelerationViolation(length(b.*row.pair), b.mass);
            !problem.empty())
            throw ValueError{path, problem};
        return;
    }
}

BlockDef parseBlock(const json& value, const std::string& path) {
    requireObject(value, path);
    std::vector<const char*> known;
    for (const settings_table::BlockKey& row : settings_table::blockKeys())
        known.push_back(row.key);
    checkKeys(value, path, known);
    BlockDef b;
    for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
        if (value.contains(row.key))
            readBlockField(row, value[row.key], keyPath(path, row.key), b);
        else if (row.required)
            throw ValueError{path, "missing \"" + std::string(row.key) + "\""};
    }
    return b;
}

// ---- Placement: bounds and overlaps ----

// A block's extent on one axis, shrunk by the touch tolerance so that touching is not overlap.
struct Span {
    double lo, hi;
};
Span span(const BlockDef& b, int axis) {
    const double half = b.size[axis] * 0.5;
    const double shrink = std::min(0.5 * kTouchTolerance, 0.25 * b.size[axis]);
    return {b.position[axis] - half + shrink, b.position[axis] + half - shrink};
}

std::string blockLabel(const std::vector<BlockDef>& blocks, std::size_t i) {
    const std::string label = indexPath("blocks", i);
    return blocks[i].name.empty() ? label : label + " (\"" + printable(blocks[i].name) + "\")";
}

// How a message starts for block i: its name if it has one (the path is already in `where`).
std::string blockSubject(const std::vector<BlockDef>& blocks, std::size_t i) {
    return blocks[i].name.empty() ? "the block" : "\"" + printable(blocks[i].name) + "\"";
}

void checkInBounds(const Scene& scene) {
    const Bounds& b = scene.bounds;
    for (std::size_t i = 0; i < scene.blocks.size(); ++i) {
        const Span x = span(scene.blocks[i], 0), y = span(scene.blocks[i], 1);
        if (x.lo < b.min.x || x.hi > b.max.x || y.lo < b.min.y || y.hi > b.max.y)
            throw ValueError{indexPath("blocks", i),
                             blockSubject(scene.blocks, i) + " sticks out of the world bounds " +
                                 numberList({b.min.x, b.min.y, b.max.x, b.max.y})};
    }
}

// Positive-area overlaps between blocks; static blocks may overlap each other.
void checkOverlaps(const std::vector<BlockDef>& blocks) {
    std::vector<overlap_check::Box> boxes;
    boxes.reserve(blocks.size());
    for (const BlockDef& b : blocks) {
        const Span x = span(b, 0), y = span(b, 1);
        boxes.push_back({x.lo, y.lo, x.hi, y.hi, b.kind == BodyKind::Static});
    }
    if (const auto pair = overlap_check::findOverlap(boxes)) {
        const std::size_t later = std::max(pair->first, pair->second);
        const std::size_t earlier = std::min(pair->first, pair->second);
        throw ValueError{indexPath("blocks", later),
                         blockSubject(blocks, later) + " overlaps " + blockLabel(blocks, earlier)};
    }
}

Scene parseValue(const json& root) {
    requireObject(root, "(top level)");
    checkKeys(root, "", {"name", "description", "duration", "world", "blocks"});
    Scene scene;
    if (!root.contains("name")) throw ValueError{"(top level)", "missing \"name\""};
    scene.name = string(root["name"], "name");
    if (root.contains("description"))
        scene.description = string(root["description"], "description");
    if (root.contains("duration"))
        scene.duration = number(root["duration"], "duration", limits::kDuration);
    if (root.contains("world")) parseWorld(root["world"], scene);
    if (!root.contains("blocks")) throw ValueError{"(top level)", "missing \"blocks\""};
    const json& blocks = root["blocks"];
    if (!blocks.is_array()) throw ValueError{"blocks", "must be an array"};
    if (blocks.size() > kMaxBlocks)
        throw ValueError{"blocks", "more than " + std::to_string(kMaxBlocks) + " blocks"};
    scene.blocks.reserve(blocks.size());
    for (std::size_t i = 0; i < blocks.size(); ++i)
        scene.blocks.push_back(parseBlock(blocks[i], indexPath("blocks", i)));
    checkInBounds(scene);
    checkOverlaps(scene.blocks);
    return scene;
}

// Every error leaves through here: its place (with the file's name) and message printable and
// bounded, whatever the file's name and contents (a key, a name or a number can be megabytes).
SceneError placed(const std::string& where, const std::string& message) {
    return {printable(where, kPrintablePath), printable(message, 4 * kPrintableDefault)};
}

SceneResult failure(const std::string& where, const std::string& message) {
    SceneResult r;
    r.error = placed(where, message);
    return r;
}

} // namespace

std::optional<SceneError> parseJsonText(const std::string& text, const std::string& sourceName,
                                        json& root) {
    if (text.size() > kMaxFileBytes) return placed(sourceName, "larger than 64 MiB");
    if (std::all_of(text.begin(), text.end(),
                    [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }))
        return placed(placeName(sourceName, text, text.size()), "the file is empty");
    if (auto problem = prescan(text, false)) // depth first: the parser must never see it
        return placed(placeName(sourceName, text, problem->index), problem->message);
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        const std::size_t index = e.byte > 0 ? e.byte - 1 : 0;
        return placed(placeName(sourceName, text, index), parserMessage(e.what()));
    } catch (const json::exception& e) {
        // Number overflow (1e400) has no position in nlohmann; find the number in the text.
        std::string message = e.what();
        const std::size_t quote = message.find('\'');
        std::size_t index = std::string::npos;
        if (quote != std::string::npos && message.back() == '\'')
            index = text.find(message.substr(quote + 1, message.size() - quote - 2));
        message =
            message.substr(message.find("] ") == std::string::npos ? 0 : message.find("] ") + 2);
        if (index == std::string::npos) return placed(sourceName, message);
        return placed(placeName(sourceName, text, index), message);
    }
    // The parser stops at a NUL byte as at the end of the text: junk after it would pass unseen.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
        return placed(placeName(sourceName, text, nul), "a NUL byte: this is not a text file");
    if (auto problem = prescan(text, true))
        return placed(placeName(sourceName, text, problem->index), problem->message);
    return std::nullopt;
}

SceneResult parseScene(const std::string& text, const std::string& sourceName) {
    json root;
    if (auto error = parseJsonText(text, sourceName, root))
        return failure(error->where, error->message);
    try {
        SceneResult r;
        r.scene = parseValue(root);
        return r;
    } catch (const ValueError& e) {
        return failure(sourceName + ": " + e.path, e.message);
    }
}

std::optional<SceneError> regularFileError(const std::string& path) {
    // Only regular files: a directory cannot be read and a FIFO could block forever. A path that
    // cannot be followed says why (a symlink loop, a directory without permission).
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(path, ec);
    if (status.type() == std::filesystem::file_type::not_found) return placed(path, "no such file");
    if (ec) return placed(path, "cannot open the file: " + ec.message());
    if (!std::filesystem::is_regular_file(status)) return placed(path, "not a regular file");
    return std::nullopt;
}

std::optional<SceneError> readJsonFile(const std::string& path, std::string& text) {
    if (auto error = regularFileError(path)) return error;
    std::ifstream in(path, std::ios::binary);
    if (!in) return placed(path, "cannot open the file");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) return placed(path, "cannot read the file");
    if (static_cast<std::uint64_t>(size) > kMaxFileBytes) return placed(path, "larger than 64 MiB");
    in.seekg(0, std::ios::beg);
    text.assign(static_cast<std::size_t>(size), '\0');
    if (size > 0 && !in.read(&text[0], size)) return placed(path, "cannot read the file");
    return std::nullopt;
}

SceneResult loadSceneFile(const std::string& path) {
    std::string text;
    if (auto error = readJsonFile(path, text)) return failure(error->where, error->message);
    return parseScene(text, path);
}
