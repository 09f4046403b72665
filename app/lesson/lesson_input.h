// A lesson step's "input" (docs/lesson-format.md): the player's keys scripted over time, so a
// demo plays itself the same way in the window, offscreen and in sandbox-cli lesson.
#pragma once

#include "player.h"
#include "scene.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

// Parses `value` (at JSON path `path`): an array of {"at": s, "hold": [keys], "for": s} and
// {"at": s, "press": key}, keys "left", "right", "up". The step's scene must have a "player".
// Throws scene_json::ValueError naming the path of what is wrong.
std::vector<ScriptedKeys> parseLessonInput(const nlohmann::json& value, const std::string& path,
                                           const Scene& scene);
