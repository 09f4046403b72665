// What a lesson file may say, checked before it is used (docs/lesson-format.md): the limits of its
// sizes, its text fields, the blocks and overlays it names, and the scene files its steps name.
// Each throws scene_json::ValueError naming the JSON path of what is wrong. Used by lesson.cpp
// only.
#pragma once

#include "scene.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace lesson_guards {

// The limits of a lesson file.
constexpr std::size_t kMaxSteps = 1000;
constexpr std::size_t kMaxExpects = 100; // per step
constexpr std::size_t kMaxValues = 20;   // named values per step
constexpr std::size_t kMaxCaptionLines = 3;
constexpr std::size_t kMaxLineChars = 200; // a caption line, a title, a question or an answer
// A line of a template (a caption, question, choice or answer with {...} in it), as written: the
// expressions take room the text they print does not (ctest holds the shipped lessons' texts as
// shown to kMaxLineChars).
constexpr std::size_t kMaxTemplateLineChars = 400;
constexpr double kMaxPauseTime = 600.0; // s
constexpr int kMaxPauseCollision = 1000000;
constexpr double kMaxFrameRate = 10000.0;         // Hz (dt at least 1e-4 s)
constexpr double kCollisionSearchSeconds = 120.0; // s of simulated time to find a collision

// A name echoed in a message, quoted, escaped and cut (printable.h): no raw control bytes reach a
// terminal, and a 10 MB name is not a 10 MB message.
std::string quoted(const std::string& s);
// A text field: a non-empty string of printable characters (newlines only where allowed), each
// line at most kMaxLineChars.
std::string text(const nlohmann::json& value, const std::string& path, std::size_t maxLines,
                 std::size_t maxLineChars = kMaxLineChars);
// The index of the scene's block named `name`, -1 when none is.
int blockIndex(const Scene& scene, const std::string& name);
// The index of the block `value` names; throws when the step's scene has none of that name.
int requireBlock(const Scene& scene, const nlohmann::json& value, const std::string& path);
// An array of overlay names, each one of `known` (the overlay table's names; empty: not checked),
// repeats dropped.
std::vector<std::string> overlayList(const nlohmann::json& value, const std::string& path,
                                     const std::vector<std::string>& known);
// Where a step's scene path is looked for (LessonContext's fields of the same names).
struct SceneFolders {
    std::string scenesDir;  // shipped scenes, for "scene": "bullet_wall"
    std::string baseDir;    // scene paths are relative to it ("" = cwd)
    std::string lessonFile; // the lesson's own file: no step may name it
};
// The file a step's "scene" string names: a path relative to the lesson's folder that stays
// inside it (after "..", "." and links), a regular file and not the lesson itself; else a shipped
// scene's name (no "/"). "" when there is none; a path that exists but may not be used throws.
std::string findSceneFile(const std::string& name, const SceneFolders& context,
                          const std::string& scenePath);

} // namespace lesson_guards
