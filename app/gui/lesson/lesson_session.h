// A lesson in the app: which step shows, whether its question is answered, where it pauses, and
// how it is walked through (next, previous, a step by number; the app's keys call these).
// It drives the simulation session and the view (never the other way round): entering a step
// puts the world in exactly the state the step states (lesson_runner's stepStartWorld), every
// time, shows the step's overlays, camera and frame; playing it watches every frame for the
// step's event in the world as the lecturer has made it (lesson_runner's LessonWatch, told by
// SimulationSession::stopWhen) and pauses after the watch. What the caption bar says is computed
// from that run (lesson_prompt.h). Plain logic: no GL, no ImGui.
#pragma once

#include "lesson.h"
#include "lesson_prompt.h"
#include "lesson_runner.h"
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
    // The step as written, run headless when it is entered: the time a changed run gives its
    // event (liveWithin) and the result shown beside a changed answer.
    std::optional<StepRun> written;
    // The live run, from the press that played it: the world it started from (what the question
    // and the choices read) and its event, watched frame by frame.
    std::optional<World> playedFrom;
    std::optional<LessonWatch> watch;
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
    // True when the step pauses by itself (it has an event).
    bool pauses() const {
        const LessonStep* s = step();
        return s && s->pause.kind != LessonPause::Kind::None;
    }
};

// What the caption bar says now, computed from the world (lesson_prompt.h): the slide's point, the
// question and its choices at the setup (the lecturer's changes included), the answer at the
// moment, or, when the event did not come, why not.
struct LessonTexts {
    std::string caption;
    std::string question;             // "" when the step asks nothing
    std::vector<std::string> choices; // "A. -2 m/s and 2 J", lettered
    std::string answer;               // at the moment, when the event came and the step asks
    std::string missed;               // at the moment, when it did not: why, in words
};
LessonTexts lessonTexts(const LessonSession& s, const SimulationSession& sim);
// The same unlettered, for the class poll: the question and choices of the world the step is
// asked of (lesson_prompt's StepPrompt) and, at the moment, the answer with the choices the live
// run proved (none before the moment).
StepPrompt lessonPrompt(const LessonSession& s, const SimulationSession& sim);
std::optional<StepAnswer> lessonAnswer(const LessonSession& s, const SimulationSession& sim);
// What the lecturer changed of the step as written, as the answer says it ("With C = 0.9, m2's
// mass 4 kg: ...", lesson_prompt's setupChanges); empty while the world played from is the
// step's setup as written.
std::vector<std::string> lessonChanges(const LessonSession& s, const SimulationSession& sim);

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
// The step's setup as a link carried it (the student's changes: link.h): the step stays, paused at
// its setup with its question, in the world of `carried` (R replays it; Shift+R the step as
// written).
void lessonTakeSetup(LessonSession& s, SimulationSession& sim, View& view, const Scene& carried);
// The world the step is asked of: the one played from, else the one on screen (at the setup).
const World& lessonSetupWorld(const LessonSession& s, const SimulationSession& sim);
// Runs the step to its event and the watch after it, and reveals its answer: what the window shows
// once the class has seen the step (offscreen screenshots, --record-steps).
void lessonShowPausePoint(LessonSession& s, SimulationSession& sim, View& view);
// True when the three methods run alongside: their overlay is shown, or the open step reveals
// it at its moment (it runs hidden while the question is asked, so no table gives the answer
// away, and shows the whole run with the answer).
bool lessonRunsSideBySide(const LessonSession& s, const View& view);
// Before the simulation runs frames (P, N, the panel's Play or Step, the page's controls: every
// way but the lesson's own play): at the step's setup the step is played from here, as the next
// press plays it, so that its question keeps reading the world it asks about (the one played
// from) and its moment still comes. False when the step pauses at once (its moment shown): then
// no frame is to run.
bool lessonBeforeFrames(LessonSession& s, SimulationSession& sim, View& view);
// After the frames of a displayed frame: when the step reached its moment while playing, shows
// the answer and the overlays that prove it (or, when its event did not come, says why).
void lessonAfterFrames(LessonSession& s, SimulationSession& sim, View& view);
// The caption bar's first line: "n / N · title".
std::string lessonHeading(const LessonSession& session);
// The key to press next, by phase ("PageDown: play" at the setup); "" at the moment. On a touch
// screen (`touch`), which has no keys, the button to tap instead: "Tap Play" at the setup (the
// bar's Play plays to the moment and stops there), "Tap Next" at the moment.
std::string lessonHint(const LessonSession& session, bool touch = false);
// A line of the caption bar under its heading, as shown.
struct LessonLine {
    enum class Kind : std::uint8_t { Caption, Question, Choice, Answer, NoAnswer, Hint, GoTo };
    Kind kind;
    std::string text; // "Predict: " and the question, "A. ..." a choice, "Answer: " and the answer
};
// The caption bar's lines under its heading, composed here once from lessonTexts: the bar draws
// them (each kind in its colour, the choices side by side where they fit), the browser page's
// text and live region read them (spoken_text.h), the tests check them. The step's caption; then
// "Predict: " and its question with its lettered choices (one line each) until the moment;
// "Answer: " and the answer the run gives once revealed, or "No answer: " and why the event did
// not come; the key to press next (lessonHint); a step number being typed. None without a step.
std::vector<LessonLine> lessonCaption(const LessonSession& session, const SimulationSession& sim);
// The lines' texts, one per line.
std::string captionText(const std::vector<LessonLine>& lines);
