// A lesson in the app: which step shows, whether its question is answered, where it pauses, and
// the keys that walk through it (PageDown/PageUp, Right/Left, Home/End, a number then Enter, R).
// Entering a step puts the world in exactly the state the step states (lesson_runner's
// stepStartWorld), every time. Plain logic: no GL, no ImGui.
#pragma once

#include "input_map.h"
#include "lesson.h"

#include <cstdint>
#include <optional>
#include <string>

struct App;

struct LessonSession {
    std::optional<Lesson> lesson; // none: no lesson open (the app shows scenes)
    std::size_t current = 0;      // step index
    // Where the step stops by itself: the frame count of its pause point, one frame earlier
    // while a question waits for its answer. None: it does not pause.
    std::optional<std::uint64_t> stopFrame;
    std::uint64_t pauseFrame = 0; // the pause point's frame (the runner's)
    bool stopped = false;         // the stop was reached (playing on does not stop again)
    bool revealed = false;        // the question's answer shows
    std::string digits;           // typed step number, until Enter

    bool active() const { return lesson.has_value(); }
    const LessonStep* step() const {
        return lesson && current < lesson->steps.size() ? &lesson->steps[current] : nullptr;
    }
    bool asking() const {
        const LessonStep* s = step();
        return s && !s->question.empty() && !revealed;
    }
};

// The lessons directory compiled in (the source tree's lessons/).
std::string builtInLessonsDirectory();
// What lesson files may name in this app: the shipped scenes and the overlay table.
LessonContext appLessonContext(const App& app);

// Opens a lesson file at step `first` (0-based). On error (the file, or a step that does not
// exist) sets app.error, keeps the current lesson or scene, and returns false.
bool openLesson(App& app, const std::string& path, std::size_t first = 0);
// Closes the lesson; the current scene stays.
void closeLesson(App& app);
// Shows step `index` from its start (R restarts the step this way). False when out of range.
bool enterStep(App& app, std::size_t index);
// The lesson's keys (input_map.h): LessonNext, LessonPrevious, LessonFirst, LessonLast,
// LessonJump, and Reset, which restarts the step in a lesson. Returns true when it handled the
// action (false: not a lesson action, or no lesson open and the action is Reset).
bool applyLessonAction(App& app, Action action);
// PageDown / Right: answers the question when one waits, else the next step.
void lessonNext(App& app);
// PageUp / Left: the previous step.
void lessonPrevious(App& app);
// A digit typed (0-9), then Enter jumps to that step number (1-based); a bad number sets
// app.error and stays.
void lessonTypeDigit(App& app, int digit);
bool lessonJump(App& app);
// Runs the step to its pause point and reveals its answer: what the window shows once the class
// has seen the step (offscreen screenshots, --record-steps).
void lessonShowPausePoint(App& app);
// After each simulation frame: pauses at the step's stop frame.
void lessonAfterFrame(App& app);
// The caption bar's first line: "n / N · title".
std::string lessonHeading(const LessonSession& session);
// The caption bar's text under it: the caption, then the question or its answer.
std::string lessonCaption(const LessonSession& session);
