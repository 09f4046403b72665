// Scene files, format v1: writing (round-trips exactly through parseScene), saving without
// losing data, and the conversion between a Scene and a World.
#include "scene.h"

#include "safe_file.h"
#include "scene_json.h"
#include "settings_table.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

using json = nlohmann::json;
using scene_json::dumpValue;
using scene_json::numberList;

namespace {

std::string field(const char* key, const std::string& valueText) {
    return "\"" + std::string(key) + "\": " + valueText;
}

// A block on one line, its keys in the table's order (settings_table.h), that of
// docs/scene-format.md.
std::string blockText(const BlockDef& b) {
    using settings_table::BlockKind;
    std::vector<std::string> fields;
    for (const settings_table::BlockKey& row : settings_table::blockKeys()) {
        switch (row.kind) {
        case BlockKind::Text:
        case BlockKind::Color:
            if (!(b.*row.text).empty()) fields.push_back(field(row.key, dumpValue(b.*row.text)));
            break;
        case BlockKind::Force:
            if (b.*row.pair == Vec2{}) break;
            [[fallthrough]];
        case BlockKind::Pair:
        case BlockKind::Size:
            fields.push_back(field(row.key, numberList({(b.*row.pair).x, (b.*row.pair).y})));
            break;
        case BlockKind::Own:
            if (b.*row.number >= 0.0) fields.push_back(field(row.key, dumpValue(b.*row.number)));
            break;
        case BlockKind::Mass: {
            const json mass = b.kind == BodyKind::Static      ? json("static")
                              : b.kind == BodyKind::Kinematic ? json("kinematic")
                                                              : json(b.mass);
            fields.push_back(field(row.key, dumpValue(mass)));
            break;
        }
        }
    }
    std::string out = "{";
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? ", " : "") + fields[i];
    return out + "}";
}

} // namespace

nlohmann::json blockJson(const BlockDef& block) {
    return json::parse(blockText(block));
}

nlohmann::json settingJson(const settings_table::WorldKey& row, const WorldSettings& s) {
    using settings_table::Kind;
    switch (row.kind) {
    case Kind::Number:
        return s.*row.number;
    case Kind::Whole:
        return s.*row.whole;
    case Kind::Pair:
        return json::array({(s.*row.pair).x, (s.*row.pair).y});
    case Kind::Choice:
        return row.names.name(row.getChoice(s));
    case Kind::Flag:
        return s.*row.flag;
    case Kind::NameSet: {
        json names = json::array();
        for (int i = 0; i < row.names.count; ++i)
            if ((s.*row.bits >> i) & 1u) names.push_back(row.names.name(i));
        return names;
    }
    }
    return nullptr;
}

bool BlockDef::operator==(const BlockDef& o) const {
    const auto keys = settings_table::blockKeys();
    return std::all_of(keys.begin(), keys.end(), [&](const settings_table::BlockKey& row) {
        return settings_table::same(row, *this, o);
    });
}

bool Scene::operator==(const Scene& o) const {
    // Compares what a scene file holds; engine-only settings (restSpeed, eventCap,
    // measureOverlap) are not part of format v1.
    return name == o.name && description == o.description && duration == o.duration &&
           bounds.min == o.bounds.min && bounds.max == o.bounds.max &&
           settings_table::sameSceneSettings(settings, o.settings) && blocks == o.blocks &&
           player == o.player;
}

std::string sceneToJson(const Scene& scene) {
    const WorldSettings& s = scene.settings;
    std::string out = "{\n";
    out += "  " + field("name", dumpValue(scene.name)) + ",\n";
    if (!scene.description.empty())
        out += "  " + field("description", dumpValue(scene.description)) + ",\n";
    if (scene.duration) out += "  " + field("duration", dumpValue(*scene.duration)) + ",\n";
    out += "  \"world\": {\n";
    const Bounds& b = scene.bounds;
    out += "    " + field("bounds", numberList({b.min.x, b.min.y, b.max.x, b.max.y}));
    for (const settings_table::WorldKey& row : settings_table::worldKeys()) {
        if (!row.inScene) continue;
        // A pair as [x, y] with a space, as the bounds; everything else as its JSON value.
        const std::string value = row.kind == settings_table::Kind::Pair
                                      ? numberList({(s.*row.pair).x, (s.*row.pair).y})
                                      : dumpValue(settingJson(row, s));
        out += ",\n    " + field(row.key, value);
    }
    out += "\n  },\n";
    out += "  \"blocks\": [";
    for (std::size_t i = 0; i < scene.blocks.size(); ++i)
        out += (i ? ",\n    " : "\n    ") + blockText(scene.blocks[i]);
    out += scene.blocks.empty() ? "]" : "\n  ]";
    if (const auto& p = scene.player) {
        const std::string& name = scene.blocks[static_cast<std::size_t>(p->block)].name;
        out += ",\n  \"player\": {" + field("block", dumpValue(name)) + ", " +
               field("force", dumpValue(p->force)) + ", " + field("jump", dumpValue(p->jump)) + "}";
    }
    return out + "\n}\n";
}

bool saveSceneFile(const Scene& scene, const std::string& path, std::string* error) {
    return writeFileSafely(path, sceneToJson(scene), error);
}

World makeWorld(const Scene& scene) {
    World world;
    world.settings = scene.settings;
    world.bounds = scene.bounds;
    world.blocks.reserve(scene.blocks.size());
    for (const BlockDef& def : scene.blocks) world.blocks.push_back(makeBlock(def));
    return world;
}

Block makeBlock(const BlockDef& def) {
    Block b;
    b.position = def.position;
    b.size = def.size;
    b.kind = def.kind;
    b.velocity = def.kind == BodyKind::Static ? Vec2{} : def.velocity;
    b.mass = def.kind == BodyKind::Dynamic ? def.mass : kInfiniteMass;
    b.force = def.kind == BodyKind::Dynamic ? def.force : Vec2{};
    b.friction = def.friction;
    return b;
}

BlockDef blockDefOf(const Block& b) {
    BlockDef def;
    def.position = b.position;
    def.size = b.size;
    def.velocity = b.velocity;
    def.kind = b.kind;
    def.friction = b.friction;
    if (b.kind == BodyKind::Dynamic) def.mass = b.mass, def.force = b.force;
    return def;
}

Scene sceneFromWorld(const World& world, const Scene& original) {
    Scene scene;
    scene.name = original.name;
    scene.description = original.description;
    scene.duration = original.duration; // not the world's: how long the scene is watched
    scene.bounds = world.bounds;
    scene.settings = world.settings;
    scene.blocks.reserve(world.blocks.size());
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        BlockDef def = blockDefOf(world.blocks[i]);
        if (i < original.blocks.size()) {
            def.name = original.blocks[i].name;
            def.color = original.blocks[i].color;
        }
        scene.blocks.push_back(def);
    }
    // The player while its block is still there, dynamic and named (a file names it).
    if (const auto& p = original.player; p && p->block < static_cast<int>(scene.blocks.size())) {
        const BlockDef& def = scene.blocks[static_cast<std::size_t>(p->block)];
        if (def.kind == BodyKind::Dynamic && !def.name.empty()) scene.player = p;
    }
    return scene;
}
