// Lesson files (docs/lesson-format.md): an ordered list of steps, each a scene with overrides,
// overlays, a pause point, an optional question and what the engine must reach there. Parsed and
// validated like scene files (errors name the file, line:column or a JSON path such as
// `steps[3].overlays[0]`). No GL, no ImGui: the app, sandbox-cli and the tests share it.
#pragma once

#include "lesson_step.h"

#include <optional>
#include <string>
#include <vector>

struct Lesson {
    std::string path; // the file it was loaded from ("" when parsed from text)
    std::string name;
    std::string description;
    std::vector<LessonStep> steps;
};

struct LessonResult {
    std::optional<Lesson> lesson;
    SceneError error; // meaningful only when !lesson
};

// Parses and validates lesson text; `sourceName` is used in error places.
LessonResult parseLesson(const std::string& text, const std::string& sourceName,
                         const LessonContext& context);
// Loads a lesson file; its directory becomes context.baseDir when that is empty.
LessonResult loadLessonFile(const std::string& path, LessonContext context);
// The index of step `number` (1-based, as the app and --step count); none, with a message, when
// the lesson has no such step.
std::optional<std::size_t> stepIndex(const Lesson& lesson, long long number, std::string* error);
// Frames a pause point needs: a time pause, up to the frame that ends at T; an event, the search
// (its `within`, else 120 s of simulated time) and the watch after it.
double pauseFrames(const LessonStep& step);
// Frames the runner tries before it gives up on a pause point: a time pause's frames (with a
// margin for rounding) or the collision search, within the step's budget of kMaxStepBlockSteps
// block-steps (blocks x frames x substeps). The lesson loader refuses a time pause beyond it.
int maxStepFrames(const LessonStep& step);
// True when `text` is a JSON object with a "steps" key (a lesson, not a scene). False for
// anything that does not parse.
bool isLessonText(const std::string& text);
bool isLessonFile(const std::string& path);
