// A lesson in the app: which step shows, whether its question is answered, where it pauses, and
// how it is walked through (next, previous, a step by number; the app's keys call these).
// It drives the simulation session and the view (never the other way round): entering a step
// puts the world in exactly the state the step states (lesson_runner's stepStartWorld), every
// time, shows the step's overlays, camera and frame, and tells the session where to stop
// (SimulationSession::stopAtFrame). Plain logic: no GL, no ImGui.
#pragma once

#include "lesson.h"
#include "messages.h"
#include "simulation_session.h"
#include "view.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

struct LessonSession {
    // Predict, then observe: a step opens paused at its setup (t = 0) with its question; the
    // next press plays it to its moment, which pauses and shows the answer; the next goes on.
    enum class Phase {
        Setup,   // paused at t = 0, the question asked
        Playing, // running toward the moment (the question still shown)
        Moment,  // paused at the pause point (or running free: no pause point), answer shown
    };
    std::optional<Lesson> lesson; // none: no lesson open (the app shows scenes)
    std::size_t current = 0;      // step index
    Phase phase = Phase::Setup;
    // The frame count of the step's pause point (the runner's, for the step as it now runs:
    // after R, with the lecturer's method and settings). None: it does not pause.
    std::optional<std::uint64_t> stopFrame;
    bool revealed = false; // the question's answer shows (at the moment)
    std::string digits;    // typed step number, until Enter

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
// What lesson files may name in this app: the shipped scenes (in `scenesDir`) and the overlay
// table.
LessonContext appLessonContext(const std::string& scenesDir);

// The functions below drive `sim` and `view` and report in `messages`.
// Opens a lesson file at step `first` (0-based). On error (the file, or a step that does not
// exist) sets messages.error, keeps the current lesson or scene, and returns false.
bool openLesson(LessonSession& s, SimulationSession& sim, View& view, Messages& messages,
                const std::string& path, const std::string& scenesDir, std::size_t first = 0);
// Closes the lesson; the current scene stays (its own stops, the world's frame and camera).
void closeLesson(LessonSession& s, SimulationSession& sim, View& view);
// Shows step `index` as written, paused at its setup (t = 0) with its question (Shift+R restores
// the step this way). False when out of range.
bool enterStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages,
               std::size_t index);
// R: the step again from its setup, keeping what the lecturer changed (method, C, g, frame rate,
// substeps, time scale, overlays), as R does outside lessons; it stops at its pause point as the
// step now runs.
void replayStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages);
// The next press: at the setup it plays the step toward its moment; while it plays it goes to
// the moment at once; at the moment, the next step (none after the last).
void lessonNext(LessonSession& s, SimulationSession& sim, View& view, Messages& messages);
// The previous step (none before the first).
void lessonPrevious(LessonSession& s, SimulationSession& sim, View& view, Messages& messages);
// A digit typed (0-9), then lessonJump goes to that step number (1-based); a bad number sets
// messages.error and stays (false).
void lessonTypeDigit(LessonSession& s, int digit);
bool lessonJump(LessonSession& s, SimulationSession& sim, View& view, Messages& messages);
// Runs the step to its pause point and reveals its answer: what the window shows once the class
// has seen the step (offscreen screenshots, --record-steps).
void lessonShowPausePoint(LessonSession& s, SimulationSession& sim, View& view);
// True when the three methods run alongside: their overlay is shown, or the open step reveals
// it at its moment (it runs hidden while the question is asked, so no table gives the answer
// away, and shows the whole run with the answer).
bool lessonRunsSideBySide(const LessonSession& s, const View& view);
// After the frames of a displayed frame: when the step reached its moment while playing, shows
// the answer and the overlays that prove it.
void lessonAfterFrames(LessonSession& s, SimulationSession& sim, View& view);
// The caption bar's first line: "n / N · title".
std::string lessonHeading(const LessonSession& session);
// The key to press next, by phase ("PageDown: play" at the setup); "" at the moment.
std::string lessonHint(const LessonSession& session);
// A line of the caption bar under its heading, as shown.
struct LessonLine {
    enum class Kind : std::uint8_t { Caption, Question, Answer, Hint, GoTo };
    Kind kind;
    std::string text; // "Predict: " and the question, "Answer: " and the answer, ...
};
// The caption bar's lines under its heading, composed here once: the bar draws them (each kind
// in its colour), the browser page's text reads them (spoken_text.h), the tests check them. The
// step's caption; then "Predict: " and its question until the answer is revealed, "Answer: " and
// the answer after; the key to press next (lessonHint); a step number being typed. None without
// a step.
std::vector<LessonLine> lessonCaption(const LessonSession& session);
// The lines' texts, one per line.
std::string captionText(const std::vector<LessonLine>& lines);
