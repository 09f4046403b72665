// What a lesson step waits for and asks, read from its JSON (docs/lesson-format.md): the event
// of "pause_at", the named "values", the templates of its texts and its "choices". Each throws
// scene_json::ValueError naming the JSON path of what is wrong. Used by lesson.cpp only.
#pragma once

#include "lesson_step.h"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace lesson_questions {

// "pause_at": the event, its watch and its time.
LessonPause parsePause(const nlohmann::json& value, const std::string& path, const Scene& scene);
// A text of the step as a template (lesson_text.h): at most `maxLines` lines, each at most
// kMaxTemplateLineChars as written and kMaxLineChars of its own text (outside {...}).
LessonText templateText(const nlohmann::json& value, const std::string& path, std::size_t maxLines,
                        const Scene& scene, const std::vector<std::string>& valueNames);
// "values" into step.valueNames and step.values (no value reads itself through others).
void parseValues(const nlohmann::json& value, const std::string& path, const Scene& scene,
                 LessonStep& step);
// "choices" into step.choices and step.correct: 2 to 4, exactly one correct.
void parseChoices(const nlohmann::json& value, const std::string& path, const Scene& scene,
                  LessonStep& step);

} // namespace lesson_questions
