#include "lesson_scene.h"

#include "edit.h"
#include "input_limits.h"
#include "lesson_guards.h"
#include "printable.h"
#include "settings_table.h"

#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;
using json = nlohmann::json;
using namespace scene_json;
using namespace lesson_guards;

namespace lesson_scene {

namespace {

// Parsed-from-memory scenes are named this; their error places are rewritten to the lesson's.
const char* const kInline = "\x01";

// A scene error from the loader, placed in the lesson: inline scenes get the step's JSON path,
// files keep their own place after the step's.
ValueError sceneError(const SceneError& e, const std::string& scenePath) {
    // The loader's places are printable (printable.h): the marker arrives as "\x01".
    const std::string inlineName = printable(kInline);
    const std::string inlinePrefix = inlineName + ": ";
    if (e.where.rfind(inlinePrefix, 0) == 0)
        return ValueError{scenePath + "." + e.where.substr(inlinePrefix.size()), e.message};
    if (e.where == inlineName) return ValueError{scenePath, e.message};
    return ValueError{scenePath, e.text()};
}

// The keys of "overrides" that are not world keys of the settings table.
constexpr const char* kStepOverrideKeys[] = {"frame_rate", "time_scale", "bounds"};

std::string overrideKeyList() {
    std::string list;
    for (const settings_table::WorldKey& row : settings_table::worldKeys())
        if (row.inScene) list += std::string(list.empty() ? "" : ", ") + row.key;
    for (const char* key : kStepOverrideKeys) list += std::string(", ") + key;
    return list;
}

// Reads a step's "overrides": its world settings become edits (out.overrides, "frame_rate" the
// edit of dt), "time_scale" the step's; returns "bounds" when it is given (the scene's shape,
// which no edit changes), else null. Only the form is checked here; the values where they apply.
const json* readOverrides(const json& overrides, const std::string& overridesPath,
                          LessonStep& out) {
    const json* bounds = nullptr;
    for (const auto& item : overrides.items()) {
        const std::string key = item.key();
        const std::string keyAt = keyPath(overridesPath, key);
        if (key == "time_scale") {
            out.timeScale = number(item.value(), keyAt);
            if (const std::string bad = limits::violation(limits::kTimeScale, out.timeScale);
                !bad.empty())
                throw ValueError{keyAt, bad};
        } else if (key == "frame_rate") {
            if (overrides.contains("dt")) throw ValueError{keyAt, "give \"dt\" or \"frame_rate\""};
            const double rate = number(item.value(), keyAt);
            if (!(rate >= 1.0 && rate <= kMaxFrameRate))
                throw ValueError{keyAt, "must be from 1 to 10000 frames per second"};
            out.overrides.push_back(Edit::setWorld("dt", 1.0 / rate));
        } else if (key == "bounds") {
            bounds = &item.value();
        } else {
            const settings_table::WorldKey* row = settings_table::findWorldKey(key);
            if (!row || !row->inScene)
                throw ValueError{keyAt, "unknown key " + quoted(key) + " (expected " +
                                            overrideKeyList() + ")"};
            out.overrides.push_back(Edit::setWorld(key, item.value()));
        }
    }
    return bounds;
}

// `settings` with the step's override edits applied as any edit is (applyEdit: the settings
// table's limits and messages); a refused one is an error at its override.
WorldSettings settingsAfter(const WorldSettings& settings, const std::vector<Edit>& edits,
                            const std::string& overridesPath) {
    World world; // world settings only: an edit of a world key reads no block
    world.settings = settings;
    std::vector<BlockLabel> labels;
    for (const Edit& edit : edits) {
        const ApplyResult r = applyEdit({world, labels}, edit);
        if (!r.applied) {
            // "dt" is the edit a "frame_rate" made (its range was checked where it was read).
            throw ValueError{keyPath(overridesPath, edit.key), r.error.message};
        }
    }
    return world.settings;
}

// The scene of `root` (a scene file's JSON) with its world's "bounds" replaced, read by the
// scene loader (its blocks must fit in them); errors placed at the override.
Scene sceneWithBounds(const json& root, const json& bounds, const std::string& overridesPath) {
    json merged = root;
    json world = merged.contains("world") ? merged["world"] : json::object();
    world["bounds"] = bounds;
    merged["world"] = world;
    SceneResult scene = parseScene(merged.dump(), kInline);
    if (scene.scene) return std::move(*scene.scene);
    // "world.bounds" -> "steps[2].overrides.bounds"; anything else the bounds broke (a block now
    // outside them) is placed at the overrides with the scene's path.
    const ValueError e = sceneError(scene.error, "");
    const std::string where = e.path.empty() ? "" : e.path.substr(1);
    const std::string prefix = "world.bounds";
    if (where.rfind(prefix, 0) == 0)
        throw ValueError{keyPath(overridesPath, "bounds") + where.substr(prefix.size()), e.message};
    throw ValueError{overridesPath,
                     "with these overrides the scene fails: " + where + ": " + e.message};
}

} // namespace

void loadStepScene(const json& step, const std::string& path, const LessonContext& context,
                   SceneCache& cache, LessonStep& out) {
    const std::string scenePath = keyPath(path, "scene");
    if (!step.contains("scene")) throw ValueError{path, "missing \"scene\""};
    const json& scene = step["scene"];
    json inlineRoot;
    const json* root = &inlineRoot;
    if (scene.is_string()) {
        const std::string name = scene.get<std::string>();
        const std::string file = findSceneFile(
            name, SceneFolders{context.scenesDir, context.baseDir, context.lessonFile}, scenePath);
        if (file.empty())
            throw ValueError{scenePath, "no scene " + quoted(name) +
                                            " (neither a file in the lesson's folder nor a "
                                            "shipped scene in " +
                                            (context.scenesDir.empty()
                                                 ? "(none)"
                                                 : printable(context.scenesDir, kPrintablePath)) +
                                            ")"};
        auto cached = cache.files.find(file);
        if (cached == cache.files.end()) {
            std::string fileText;
            if (auto e = readJsonFile(file, fileText)) throw ValueError{scenePath, e->text()};
            // Its own errors at its own places.
            SceneResult plain = parseScene(fileText, file);
            if (!plain.scene) throw ValueError{scenePath, plain.error.text()};
            SceneCache::Entry entry;
            parseJsonText(fileText, file, entry.root);
            entry.scene = cache.keep(std::move(*plain.scene), scenePath);
            cached = cache.files.emplace(file, std::move(entry)).first;
        }
        out.sceneSource = file;
        out.scene = cached->second.scene;
        root = &cached->second.root;
    } else if (scene.is_object()) {
        inlineRoot = scene;
        SceneResult plain = parseScene(inlineRoot.dump(), kInline);
        if (!plain.scene) throw sceneError(plain.error, scenePath);
        out.scene = cache.keep(std::move(*plain.scene), scenePath);
    } else {
        throw ValueError{scenePath, "must be a shipped scene's name, a path, or a scene object"};
    }
    if (!step.contains("overrides")) return;

    const std::string overridesPath = keyPath(path, "overrides");
    const json& overrides = requireObject(step["overrides"], overridesPath);
    const json* bounds = readOverrides(overrides, overridesPath, out);
    // The same file with the same overrides: the scene already made for an earlier step.
    const std::string sharedKey =
        out.sceneSource.empty() ? "" : out.sceneSource + "\n" + overrides.dump();
    if (auto it = cache.withOverrides.find(sharedKey);
        !sharedKey.empty() && it != cache.withOverrides.end()) {
        out.scene = it->second;
        return;
    }
    Scene setup = bounds ? sceneWithBounds(*root, *bounds, overridesPath) : *out.scene;
    setup.settings = settingsAfter(setup.settings, out.overrides, overridesPath);
    out.scene = cache.keep(std::move(setup), scenePath);
    if (!sharedKey.empty()) cache.withOverrides.emplace(sharedKey, out.scene);
}

} // namespace lesson_scene
