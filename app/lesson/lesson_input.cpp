#include "lesson_input.h"

#include "input_limits.h"
#include "scene_json.h"

#include <nlohmann/json.hpp>

using json = nlohmann::json;
using namespace scene_json;

namespace {

constexpr std::size_t kMaxInputs = 1000; // per step
constexpr double kMaxInputTime = 600.0;  // s, as a step's pause time

// One key's name ("left", "right", "up") into `keys`.
void addKey(const json& value, const std::string& path, PlayerKeys& keys) {
    const std::string name = string(value, path);
    if (name == "left")
        keys.left = true;
    else if (name == "right")
        keys.right = true;
    else if (name == "up")
        keys.up = true;
    else
        throw ValueError{path, "unknown key " + dumpValue(json(name)) +
                                   " (expected \"left\", \"right\" or \"up\")"};
}

ScriptedKeys parseOne(const json& value, const std::string& path) {
    requireObject(value, path);
    checkKeys(value, path, {"at", "hold", "for", "press"});
    if (!value.contains("at")) throw ValueError{path, "missing \"at\""};
    const limits::Range when{0.0, kMaxInputTime, "s"};
    ScriptedKeys s;
    s.at = number(value["at"], keyPath(path, "at"), when);
    const bool hold = value.contains("hold"), press = value.contains("press");
    if (hold == press) throw ValueError{path, "needs one of \"hold\" and \"press\""};
    if (press) {
        if (value.contains("for"))
            throw ValueError{keyPath(path, "for"), "a press lasts one frame: no \"for\""};
        addKey(value["press"], keyPath(path, "press"), s.keys);
        return s;
    }
    const std::string holdPath = keyPath(path, "hold");
    const json& keys = value["hold"];
    if (!keys.is_array() || keys.empty() || keys.size() > 3)
        throw ValueError{holdPath, "must be an array of 1 to 3 keys"};
    for (std::size_t i = 0; i < keys.size(); ++i) addKey(keys[i], indexPath(holdPath, i), s.keys);
    if (!value.contains("for")) throw ValueError{path, "a \"hold\" needs \"for\" (s)"};
    s.duration =
        number(value["for"], keyPath(path, "for"), limits::Range{1e-6, kMaxInputTime, "s"});
    return s;
}

} // namespace

std::vector<ScriptedKeys> parseLessonInput(const json& value, const std::string& path,
                                           const Scene& scene) {
    if (!scene.player)
        throw ValueError{path, "needs a scene with a \"player\" (the block the keys control)"};
    if (!value.is_array()) throw ValueError{path, "must be an array"};
    if (value.size() > kMaxInputs)
        throw ValueError{path, "more than " + std::to_string(kMaxInputs) + " inputs"};
    std::vector<ScriptedKeys> script;
    for (std::size_t i = 0; i < value.size(); ++i)
        script.push_back(parseOne(value[i], indexPath(path, i)));
    return script;
}
