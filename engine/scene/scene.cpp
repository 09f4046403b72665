// Scene files, format v1 (docs/scene-format.md): parsing with validation that names the place of
// every error. JSON text, files and typed values are scene_json.cpp's; saving and the conversion
// to and from World are in scene_save.cpp.
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

using json = nlohmann::json;
using scene_json::dumpValue;
using scene_json::numberList;
using namespace scene_json; // the typed access below: number(), string(), vec2(), ...

namespace {

constexpr std::size_t kMaxBlocks = 200000;
// m: overlaps up to this much count as touching, so stacks typed in decimals ("exactly
// touching" up to rounding) are accepted.
constexpr double kTouchTolerance = 1e-9;

// A length (a block's side, the bounds' extent) at coordinates of magnitude up to `magnitude`.
void checkLength(double length, double magnitude, const std::string& path,
                 const limits::Range& range = limits::kSize) {
    if (std::string problem = limits::lengthViolation(length, magnitude, range); !problem.empty())
        throw ValueError{path, problem};
}

// A string of at most `maxChars` characters (names, the description).
std::string text(const json& value, const std::string& path, std::size_t maxChars) {
    std::string s = string(value, path);
    if (std::string problem = limits::textLengthViolation(s, maxChars); !problem.empty())
        throw ValueError{path, problem};
    return s;
}

bool isColor(const std::string& s) {
    return s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), [](char c) {
               return std::isxdigit(static_cast<unsigned char>(c)) != 0;
           });
}

} // namespace

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

namespace {

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
        b.*row.text = text(value, path, limits::kMaxNameChars);
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
    case BlockKind::Own:
        b.*row.number = number(value, path, row.range);
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

} // namespace

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

namespace {

// ---- Placement: bounds and overlaps ----

// A block's extent on one axis, shrunk by the touch tolerance so that touching is not overlap.
struct Span {
    double lo, hi;
};
Span span(Vec2 position, Vec2 size, int axis) {
    const double half = size[axis] * 0.5;
    const double shrink = std::min(0.5 * kTouchTolerance, 0.25 * size[axis]);
    return {position[axis] - half + shrink, position[axis] + half - shrink};
}
Span span(const BlockDef& b, int axis) {
    return span(b.position, b.size, axis);
}

bool outside(const Bounds& b, Span x, Span y) {
    return x.lo < b.min.x || x.hi > b.max.x || y.lo < b.min.y || y.hi > b.max.y;
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
        if (outside(b, span(scene.blocks[i], 0), span(scene.blocks[i], 1)))
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

// "player": {"block": NAME, "force": N, "jump": m/s}: a dynamic block, named, that the keys
// control (player.h).
PlayerDef parsePlayer(const json& value, const std::vector<BlockDef>& blocks) {
    requireObject(value, "player");
    checkKeys(value, "player", {"block", "force", "jump"});
    for (const char* key : {"block", "force", "jump"})
        if (!value.contains(key))
            throw ValueError{"player", std::string("missing \"") + key + "\""};
    PlayerDef player;
    const std::string name = string(value["block"], "player.block");
    for (std::size_t i = 0; i < blocks.size() && player.block < 0; ++i)
        if (blocks[i].name == name) player.block = static_cast<int>(i);
    if (player.block < 0)
        throw ValueError{"player.block", "no block is named \"" + printable(name) + "\""};
    if (blocks[static_cast<std::size_t>(player.block)].kind != BodyKind::Dynamic)
        throw ValueError{"player.block",
                         "\"" + printable(name) + "\" has no mass: the player is a dynamic block"};
    player.force = number(value["force"], "player.force", limits::kPlayerForce);
    player.jump = number(value["jump"], "player.jump", limits::kJumpSpeed);
    return player;
}

Scene parseValue(const json& root) {
    requireObject(root, "(top level)");
    checkKeys(root, "", kSceneKeys);
    Scene scene;
    if (!root.contains("name")) throw ValueError{"(top level)", "missing \"name\""};
    scene.name = text(root["name"], "name", limits::kMaxNameChars);
    if (root.contains("description"))
        scene.description = text(root["description"], "description", limits::kMaxDescriptionChars);
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
    if (root.contains("player")) scene.player = parsePlayer(root["player"], scene.blocks);
    return scene;
}

SceneResult failure(const std::string& where, const std::string& message) {
    SceneResult r;
    r.error = sceneError(where, message);
    return r;
}

} // namespace

std::string placementProblem(const World& world, std::size_t index) {
    const Block& block = world.blocks[index];
    const Span x = span(block.position, block.size, 0), y = span(block.position, block.size, 1);
    if (outside(world.bounds, x, y))
        return "sticks out of the world bounds " +
               numberList({world.bounds.min.x, world.bounds.min.y, world.bounds.max.x,
                           world.bounds.max.y});
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& other = world.blocks[i];
        if (i == index || (block.kind == BodyKind::Static && other.kind == BodyKind::Static))
            continue;
        const Span ox = span(other.position, other.size, 0);
        const Span oy = span(other.position, other.size, 1);
        if (x.lo < ox.hi && ox.lo < x.hi && y.lo < oy.hi && oy.lo < y.hi)
            return "overlaps " + indexPath("blocks", i);
    }
    return "";
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

SceneResult loadSceneFile(const std::string& path) {
    std::string text;
    if (auto error = readJsonFile(path, text)) return failure(error->where, error->message);
    return parseScene(text, path);
}