// Scene files, format v1: writing (round-trips exactly through parseScene), saving without
// losing data, and the conversion between a Scene and a World.
#include "scene.h"

#include "scene_json.h"

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

// A block on one line, keys in the order of docs/scene-format.md.
std::string blockText(const BlockDef& b) {
    std::vector<std::string> fields;
    if (!b.name.empty()) fields.push_back(field("name", dumpValue(b.name)));
    fields.push_back(field("position", numberList({b.position.x, b.position.y})));
    fields.push_back(field("size", numberList({b.size.x, b.size.y})));
    fields.push_back(field("velocity", numberList({b.velocity.x, b.velocity.y})));
    const json mass = b.kind == BodyKind::Static      ? json("static")
                      : b.kind == BodyKind::Kinematic ? json("kinematic")
                                                      : json(b.mass);
    fields.push_back(field("mass", dumpValue(mass)));
    if (b.force != Vec2{}) fields.push_back(field("force", numberList({b.force.x, b.force.y})));
    if (!b.color.empty()) fields.push_back(field("color", dumpValue(b.color)));
    std::string out = "{";
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? ", " : "") + fields[i];
    return out + "}";
}

} // namespace

bool BlockDef::operator==(const BlockDef& o) const {
    // A static or kinematic block's mass is not part of the file ("static"/"kinematic").
    const bool sameMass = kind != BodyKind::Dynamic || mass == o.mass;
    return name == o.name && position == o.position && size == o.size && velocity == o.velocity &&
           kind == o.kind && sameMass && force == o.force && color == o.color;
}

bool Scene::operator==(const Scene& o) const {
    // Compares what a scene file holds; engine-only settings (restSpeed, eventCap,
    // measureOverlap) are not part of format v1.
    const WorldSettings& a = settings;
    const WorldSettings& b = o.settings;
    return name == o.name && description == o.description && duration == o.duration &&
           bounds.min == o.bounds.min && bounds.max == o.bounds.max && a.gravity == b.gravity &&
           a.bounciness == b.bounciness && a.dt == b.dt && a.substeps == b.substeps &&
           a.method == b.method && a.resolve == b.resolve && a.integrator == b.integrator &&
           a.mistakes == b.mistakes && a.drag == b.drag && blocks == o.blocks;
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
    out += "    " + field("bounds", numberList({b.min.x, b.min.y, b.max.x, b.max.y})) + ",\n";
    out += "    " + field("gravity", numberList({s.gravity.x, s.gravity.y})) + ",\n";
    out += "    " + field("bounciness", dumpValue(s.bounciness)) + ",\n";
    out += "    " + field("method", dumpValue(methodName(s.method))) + ",\n";
    out += "    " + field("dt", dumpValue(s.dt)) + ",\n";
    out += "    " + field("substeps", dumpValue(s.substeps)) + ",\n";
    out += "    " + field("resolve", dumpValue(resolveName(s.resolve))) + ",\n";
    out += "    " + field("integrator", dumpValue(integratorName(s.integrator))) + ",\n";
    json mistakes = json::array();
    for (int m = 0; m < static_cast<int>(Mistake::Count); ++m)
        if (s.has(static_cast<Mistake>(m)))
            mistakes.push_back(mistakeName(static_cast<Mistake>(m)));
    out += "    " + field("mistakes", dumpValue(mistakes)) + ",\n";
    out += "    " + field("drag", dumpValue(s.drag)) + "\n";
    out += "  },\n";
    out += "  \"blocks\": [";
    for (std::size_t i = 0; i < scene.blocks.size(); ++i)
        out += (i ? ",\n    " : "\n    ") + blockText(scene.blocks[i]);
    out += scene.blocks.empty() ? "]\n" : "\n  ]\n";
    return out + "}\n";
}

bool saveSceneFile(const Scene& scene, const std::string& path, std::string* error) {
    auto fail = [&](const std::string& message) {
        if (error) *error = path + ": " + message;
        return false;
    };
    const std::string text = sceneToJson(scene);
    const std::string temp = path + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return fail("cannot write " + temp);
        out << text;
        out.flush();
        if (!out) {
            out.close();
            std::remove(temp.c_str());
            return fail("cannot write " + temp);
        }
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        std::remove(temp.c_str());
        return fail("cannot replace the file");
    }
    return true;
}

World makeWorld(const Scene& scene) {
    World world;
    world.settings = scene.settings;
    world.bounds = scene.bounds;
    world.blocks.reserve(scene.blocks.size());
    for (const BlockDef& def : scene.blocks) {
        Block b;
        b.position = def.position;
        b.size = def.size;
        b.kind = def.kind;
        b.velocity = def.kind == BodyKind::Static ? Vec2{} : def.velocity;
        b.mass = def.kind == BodyKind::Dynamic ? def.mass : kInfiniteMass;
        b.force = def.kind == BodyKind::Dynamic ? def.force : Vec2{};
        world.blocks.push_back(b);
    }
    return world;
}

Scene sceneFromWorld(const World& world, const Scene& original) {
    Scene scene;
    scene.name = original.name;
    scene.description = original.description;
    scene.bounds = world.bounds;
    scene.settings = world.settings;
    scene.blocks.reserve(world.blocks.size());
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        const Block& b = world.blocks[i];
        BlockDef def;
        if (i < original.blocks.size()) {
            def.name = original.blocks[i].name;
            def.color = original.blocks[i].color;
        }
        def.position = b.position;
        def.size = b.size;
        def.velocity = b.velocity;
        def.kind = b.kind;
        if (b.kind == BodyKind::Dynamic) def.mass = b.mass, def.force = b.force;
        scene.blocks.push_back(def);
    }
    return scene;
}
