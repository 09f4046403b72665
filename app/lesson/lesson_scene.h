// A lesson step's scene (docs/lesson-format.md, "scene" and "overrides"): a shipped or lesson
// file or an inline scene, read by the scene loader; its overrides of world settings are edits,
// applied as any edit is (applyEdit: the settings table's limits), and its "bounds" are merged
// into the scene's "world" object and read by the same loader, so a lesson accepts exactly the
// values a scene file does. Each error throws scene_json::ValueError naming its JSON path. Used
// by lesson.cpp only.
#pragma once

#include "lesson_step.h"
#include "scene.h"
#include "scene_json.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <memory>
#include <string>

namespace lesson_scene {

// Scenes already loaded in this lesson, by file (and overrides): a scene named by many steps is
// read and parsed once and its blocks held once. `blocks` counts the blocks of all of them.
struct SceneCache {
    struct Entry {
        std::shared_ptr<const Scene> scene;
        nlohmann::json root; // the file's JSON, to merge overrides into
    };
    std::map<std::string, Entry> files;
    std::map<std::string, std::shared_ptr<const Scene>> withOverrides;
    std::size_t blocks = 0;
    std::size_t maxBlocks = kMaxLessonBlocks;

    std::shared_ptr<const Scene> keep(Scene scene, const std::string& scenePath) {
        blocks += scene.blocks.size();
        if (blocks > maxBlocks)
            throw scene_json::ValueError{
                scenePath, "the lesson's scenes hold more than " + std::to_string(maxBlocks) +
                               " blocks in all (a scene that several steps name "
                               "counts once)"};
        return std::make_shared<const Scene>(std::move(scene));
    }
};

// Loads the step's scene with its overrides applied; sets step.sceneSource and step.timeScale.
void loadStepScene(const nlohmann::json& step, const std::string& path,
                   const LessonContext& context, SceneCache& cache, LessonStep& out);

} // namespace lesson_scene
