// Scene files, format v1 (SPEC.md, "Scene file format v1"): parsing with validation that names
// the place of every error. Saving and the conversion to and from World are in scene_save.cpp.
#include "scene.h"

#include "overlap_check.h"
#include "scene_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
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
constexpr int kMaxDepth = 64;  // the format itself needs 4 levels
constexpr double kMaxDt = 1.0; // s: longer frames are certainly a mistake
constexpr int kMaxSubsteps = 1000;
constexpr double kMaxMagnitude = 1e9; // m, m/s, m/s^2 (the messages say 1e9)
constexpr double kMaxMass = 1e15;     // kg (the message says 1e15)
constexpr double kMaxDrag = 1e6;      // kg/m^3 (the message says 1e6; water is 1e3)
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

// Walks the text once without recursion. Finds nesting deeper than kMaxDepth (nlohmann's DOM is
// built and destroyed recursively, so a 100,000-deep "[[[[" must never reach it) and duplicate
// keys in one object (nlohmann would silently keep the last). Strings are skipped with their
// escapes; anything malformed is left for the real parser to report.
std::optional<ScanProblem> prescan(const std::string& text, bool checkDuplicates) {
    std::vector<std::set<std::string_view>> keys; // one set per open object
    std::vector<char> open;                       // '{' or '['
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
            const std::string_view key = all.substr(start, i + 1 - start);
            if (!keys.back().insert(key).second)
                return ScanProblem{start, "duplicate key " + std::string(key)};
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
    std::string out;
    for (const char c : message) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02x", byte);
            out += hex;
        }
    }
    return out;
}

} // namespace

// ---- Values: typed access that names the JSON path on failure (scene_json.h) ----

namespace scene_json {

std::string indexPath(const std::string& path, std::size_t i) {
    return path + "[" + std::to_string(i) + "]";
}
std::string keyPath(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

void checkKeys(const json& object, const std::string& path,
               std::initializer_list<const char*> known) {
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

// An array of exactly `n` finite numbers.
std::vector<double> numbers(const json& value, const std::string& path, std::size_t n) {
    if (!value.is_array() || value.size() != n)
        throw ValueError{path, "must be an array of " + std::to_string(n) + " numbers"};
    std::vector<double> out;
    // Coordinates (m), speeds (m/s) and gravity (m/s^2) beyond 1e9 in size are mistakes, and
    // squaring them (energies) would overflow.
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(number(value[i], indexPath(path, i)));
        if (std::abs(out.back()) > kMaxMagnitude)
            throw ValueError{indexPath(path, i),
                             "must be between -1e9 and 1e9, not " + dumpValue(out.back())};
    }
    return out;
}

Vec2 vec2(const json& value, const std::string& path) {
    const std::vector<double> v = numbers(value, path, 2);
    return {v[0], v[1]};
}

} // namespace scene_json

namespace {

bool isColor(const std::string& s) {
    return s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), [](char c) {
               return std::isxdigit(static_cast<unsigned char>(c)) != 0;
           });
}

void parseWorld(const json& world, Scene& scene) {
    requireObject(world, "world");
    checkKeys(world, "world",
              {"bounds", "gravity", "bounciness", "method", "dt", "substeps", "resolve",
               "integrator", "mistakes", "drag"});
    WorldSettings& s = scene.settings;
    if (world.contains("bounds")) {
        const std::vector<double> b = numbers(world["bounds"], "world.bounds", 4);
        if (!(b[0] < b[2] && b[1] < b[3]))
            throw ValueError{"world.bounds", "must be [xmin, ymin, xmax, ymax] with xmin < xmax "
                                             "and ymin < ymax"};
        scene.bounds.min = {b[0], b[1]};
        scene.bounds.max = {b[2], b[3]};
    }
    if (world.contains("gravity")) s.gravity = vec2(world["gravity"], "world.gravity");
    if (world.contains("bounciness")) {
        s.bounciness = number(world["bounciness"], "world.bounciness");
        if (s.bounciness < 0.0 || s.bounciness > 1.0)
            throw ValueError{"world.bounciness", "must be between 0 and 1"};
    }
    if (world.contains("method")) {
        const std::string name = string(world["method"], "world.method");
        if (!parseMethod(name.c_str(), s.method))
            throw ValueError{"world.method", "must be \"perfect\", \"move-and-correct\" or "
                                             "\"turn-based\", not \"" +
                                                 name + "\""};
    }
    if (world.contains("dt")) {
        s.dt = number(world["dt"], "world.dt");
        if (!(s.dt > 0.0 && s.dt <= kMaxDt))
            throw ValueError{"world.dt", "must be more than 0 and at most 1 second"};
    }
    if (world.contains("substeps")) {
        const double k = number(world["substeps"], "world.substeps");
        if (k != std::floor(k) || k < 1 || k > kMaxSubsteps)
            throw ValueError{"world.substeps",
                             "must be a whole number from 1 to " + std::to_string(kMaxSubsteps)};
        s.substeps = static_cast<int>(k);
    }
    if (world.contains("resolve")) {
        const std::string name = string(world["resolve"], "world.resolve");
        if (!parseResolve(name.c_str(), s.resolve))
            throw ValueError{"world.resolve",
                             "must be \"momentum\" or \"reflect\", not " + dumpValue(name)};
    }
    if (world.contains("integrator")) {
        const std::string name = string(world["integrator"], "world.integrator");
        if (!parseIntegrator(name.c_str(), s.integrator))
            throw ValueError{"world.integrator", "must be \"semi-implicit-euler\", "
                                                 "\"explicit-euler\" or \"exact\", not " +
                                                     dumpValue(name)};
    }
    if (world.contains("mistakes")) {
        const json& list = world["mistakes"];
        if (!list.is_array()) throw ValueError{"world.mistakes", "must be an array of names"};
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string path = indexPath("world.mistakes", i);
            const std::string name = string(list[i], path);
            Mistake m{};
            if (!parseMistake(name.c_str(), m))
                throw ValueError{path, "must be \"discrete\", \"move-back\", \"first-found\" or "
                                       "\"no-approach-test\", not " +
                                           dumpValue(name)};
            if (s.has(m)) throw ValueError{path, dumpValue(name) + " is listed twice"};
            s.set(m, true);
        }
    }
    if (world.contains("drag")) {
        s.drag = number(world["drag"], "world.drag");
        if (!(s.drag >= 0.0 && s.drag <= kMaxDrag))
            throw ValueError{"world.drag", "must be from 0 to 1e6 kg/m^3"};
    }
}

BlockDef parseBlock(const json& value, const std::string& path) {
    requireObject(value, path);
    checkKeys(value, path, {"name", "position", "size", "velocity", "mass", "color", "force"});
    BlockDef b;
    if (value.contains("name")) b.name = string(value["name"], keyPath(path, "name"));
    if (!value.contains("position")) throw ValueError{path, "missing \"position\""};
    b.position = vec2(value["position"], keyPath(path, "position"));
    if (!value.contains("size")) throw ValueError{path, "missing \"size\""};
    const json& size = value["size"];
    const std::string sizePath = keyPath(path, "size");
    if (size.is_number()) {
        const double side = number(size, sizePath);
        b.size = {side, side};
    } else if (size.is_array()) {
        b.size = vec2(size, sizePath);
    } else {
        throw ValueError{sizePath, "must be a number (a square) or [width, height]"};
    }
    if (!(b.size.x > 0.0 && b.size.y > 0.0)) throw ValueError{sizePath, "must be positive"};
    if (b.size.x > kMaxMagnitude || b.size.y > kMaxMagnitude)
        throw ValueError{sizePath, "must be at most 1e9 m"};
    if (value.contains("velocity")) b.velocity = vec2(value["velocity"], keyPath(path, "velocity"));
    // Without "mass" a block is dynamic with 1 kg (BlockDef's default).
    if (value.contains("mass")) {
        const json& mass = value["mass"];
        const std::string massPath = keyPath(path, "mass");
        if (mass == "static") {
            b.kind = BodyKind::Static;
        } else if (mass == "kinematic") {
            b.kind = BodyKind::Kinematic;
        } else if (mass.is_number()) {
            b.mass = number(mass, massPath);
            if (!(b.mass > 0.0 && b.mass <= kMaxMass))
                throw ValueError{massPath, "must be more than 0 and at most 1e15 kg"};
        } else {
            throw ValueError{massPath, "must be a positive number, \"static\" or \"kinematic\""};
        }
    }
    if (value.contains("force")) {
        const std::string forcePath = keyPath(path, "force");
        b.force = vec2(value["force"], forcePath);
        if (b.kind != BodyKind::Dynamic && b.force != Vec2{})
            throw ValueError{forcePath, "only a dynamic block (one with a mass) feels a force"};
        // Its acceleration, like gravity, at most 1e9 m/s^2 (F/m of a light block can be huge).
        if (length(b.force) / b.mass > kMaxMagnitude)
            throw ValueError{forcePath, "force / mass must be at most 1e9 m/s^2"};
    }
    if (value.contains("color")) {
        b.color = string(value["color"], keyPath(path, "color"));
        if (!isColor(b.color)) throw ValueError{keyPath(path, "color"), "must look like #rrggbb"};
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
    return blocks[i].name.empty() ? label : label + " (\"" + blocks[i].name + "\")";
}

// How a message starts for block i: its name if it has one (the path is already in `where`).
std::string blockSubject(const std::vector<BlockDef>& blocks, std::size_t i) {
    return blocks[i].name.empty() ? "the block" : "\"" + blocks[i].name + "\"";
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
    checkKeys(root, "", {"name", "description", "world", "blocks"});
    Scene scene;
    if (!root.contains("name")) throw ValueError{"(top level)", "missing \"name\""};
    scene.name = string(root["name"], "name");
    if (root.contains("description"))
        scene.description = string(root["description"], "description");
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

SceneResult failure(std::string where, std::string message) {
    SceneResult r;
    r.error = {std::move(where), std::move(message)};
    return r;
}

} // namespace

std::optional<SceneError> parseJsonText(const std::string& text, const std::string& sourceName,
                                        json& root) {
    if (text.size() > kMaxFileBytes) return SceneError{sourceName, "larger than 64 MiB"};
    if (std::all_of(text.begin(), text.end(),
                    [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }))
        return SceneError{placeName(sourceName, text, text.size()), "the file is empty"};
    if (auto problem = prescan(text, false)) // depth first: the parser must never see it
        return SceneError{placeName(sourceName, text, problem->index), problem->message};
    try {
        root = json::parse(text);
    } catch (const json::parse_error& e) {
        const std::size_t index = e.byte > 0 ? e.byte - 1 : 0;
        return SceneError{placeName(sourceName, text, index), parserMessage(e.what())};
    } catch (const json::exception& e) {
        // Number overflow (1e400) has no position in nlohmann; find the number in the text.
        std::string message = e.what();
        const std::size_t quote = message.find('\'');
        std::size_t index = std::string::npos;
        if (quote != std::string::npos && message.back() == '\'')
            index = text.find(message.substr(quote + 1, message.size() - quote - 2));
        message =
            message.substr(message.find("] ") == std::string::npos ? 0 : message.find("] ") + 2);
        if (index == std::string::npos) return SceneError{sourceName, message};
        return SceneError{placeName(sourceName, text, index), message};
    }
    // The parser stops at a NUL byte as at the end of the text: junk after it would pass unseen.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
        return SceneError{placeName(sourceName, text, nul), "a NUL byte: this is not a text file"};
    if (auto problem = prescan(text, true))
        return SceneError{placeName(sourceName, text, problem->index), problem->message};
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

std::optional<SceneError> readJsonFile(const std::string& path, std::string& text) {
    // Only regular files: a directory cannot be read and a FIFO could block forever.
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return SceneError{path, "no such file"};
    if (!std::filesystem::is_regular_file(path, ec)) return SceneError{path, "not a regular file"};
    std::ifstream in(path, std::ios::binary);
    if (!in) return SceneError{path, "cannot open the file"};
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size < 0) return SceneError{path, "cannot read the file"};
    if (static_cast<std::uint64_t>(size) > kMaxFileBytes)
        return SceneError{path, "larger than 64 MiB"};
    in.seekg(0, std::ios::beg);
    text.assign(static_cast<std::size_t>(size), '\0');
    if (size > 0 && !in.read(&text[0], size)) return SceneError{path, "cannot read the file"};
    return std::nullopt;
}

SceneResult loadSceneFile(const std::string& path) {
    std::string text;
    if (auto error = readJsonFile(path, text)) return failure(error->where, error->message);
    return parseScene(text, path);
}
