#include "lesson_session.h"

#include "lesson_runner.h"
#include "overlays.h"
#include "save_naming.h"

#include <algorithm>

#ifndef SANDBOX_LESSONS_DIR
#define SANDBOX_LESSONS_DIR ""
#endif

namespace {

constexpr std::size_t kMaxDigits = 6;

std::vector<std::string> labelNames(const SimulationSession& sim) {
    std::vector<std::string> names;
    for (const BlockLabel& l : sim.labels) names.push_back(l.name);
    return names;
}

// True when `now` is not the step's setup as written: its blocks (where, how fast, how heavy,
// how big, how many) or its settings differ.
bool differsFromWritten(const World& now, const World& written) {
    if (now.blocks.size() != written.blocks.size() || stateHash(now) != stateHash(written) ||
        settingsDiffer(now.settings, written.settings))
        return true;
    for (std::size_t i = 0; i < now.blocks.size(); ++i)
        if (now.blocks[i].mass != written.blocks[i].mass ||
            now.blocks[i].size.x != written.blocks[i].size.x ||
            now.blocks[i].size.y != written.blocks[i].size.y)
            return true;
    return false;
}

// The moment: the answer shows, with the overlays that prove it (nothing is claimed when the
// event did not come).
void reveal(LessonSession& s, const SimulationSession& sim, View& view) {
    s.phase = LessonSession::Phase::Moment;
    const bool missed = s.watch && s.watch->state() == LessonWatch::State::Missed;
    // The moment frames its evidence (its "moment_camera": a fixed rectangle, where the run as
    // written puts it) when the event came in the world as written. Not when the lecturer has
    // taken the camera (panned or zoomed: autoFit off), nor after a change (a mass, C) that may
    // send the evidence elsewhere: the step's camera, which frames the whole demo, stays. The
    // setup frames the step's camera again.
    if (s.step()->momentCamera && view.autoFit && !missed && lessonChanges(s, sim).empty())
        view.fitBounds = s.step()->momentCamera;
    if (s.step()->question.empty() || s.revealed) return;
    if (missed) return;
    s.revealed = true;
    for (const std::string& name : s.step()->reveal) setOverlay(view.show, name, true);
}

// Paused at the setup (t = 0), the question asked; nothing watched yet.
void showSetup(LessonSession& s, SimulationSession& sim) {
    s.revealed = false;
    s.phase = LessonSession::Phase::Setup;
    s.watch.reset();
    s.playedFrom.reset();
    sim.pauseAtSceneEnd = false; // the step stops where it says
    sim.paused = true;
    sim.stopAtFrame.reset();
    sim.stopWhen = nullptr;
}

// The press that plays the step: from the world as it is now (the lecturer's changes included)
// its event is watched frame by frame (SimulationSession::stopWhen). False when the step pauses
// at once (a time of 0, an event about a block that is gone).
bool startPlaying(LessonSession& s, SimulationSession& sim) {
    const LessonStep& step = *s.step();
    s.phase = LessonSession::Phase::Playing;
    s.playedFrom = sim.world();
    if (step.pause.kind == LessonPause::Kind::None) {
        sim.paused = false;
        return true;
    }
    const double within = s.written ? liveWithin(step, *s.written) : 1.0;
    s.watch.emplace(step, liveBlockIndex(*step.scene, labelNames(sim)), within,
                    step.pause.watch * sim.timeScale);
    if (s.watch->atStart(sim.world())) return false;
    LessonWatch* watch = &*s.watch;
    sim.stopWhen = [watch](const World& w, const StepStats& stats,
                           const std::vector<CollisionRecord>& log) {
        return watch->afterFrame(w, stats, log);
    };
    sim.paused = false;
    return true;
}

// Runs the frames up to the moment (or to where the event is given up) and pauses there.
void runToPausePoint(LessonSession& s, SimulationSession& sim, const View& view) {
    if (s.phase == LessonSession::Phase::Setup && !startPlaying(s, sim)) return;
    if (!s.watch) return;
    const LessonStep& step = *s.step();
    const int limit =
        frameLimit(step, *s.playedFrom, s.watch->within(), step.pause.watch * sim.timeScale);
    while (!s.watch->paused()) {
        if (s.watch->progress().frames >= limit) {
            s.watch->giveUp(sim.world(), "");
            break;
        }
        sim.step(lessonRunsSideBySide(s, view));
    }
    sim.stopWhen = nullptr;
    sim.paused = true;
}

} // namespace

std::string builtInLessonsDirectory() {
    return SANDBOX_LESSONS_DIR;
}

LessonContext appLessonContext(const std::string& scenesDir) {
    LessonContext c;
    c.scenesDir = scenesDir;
    c.overlayNames = overlayNames();
    return c;
}

bool openLesson(LessonSession& s, SimulationSession& sim, View& view, Messages& messages,
                const std::string& path, const std::string& scenesDir, std::size_t first) {
    LessonResult r = loadLessonFile(path, appLessonContext(scenesDir));
    if (!r.lesson) {
        messages.error = r.error.text();
        return false;
    }
    std::string error;
    if (!stepIndex(*r.lesson, static_cast<long long>(first) + 1, &error)) {
        messages.error = error;
        return false;
    }
    s = LessonSession{};
    s.lesson = std::move(*r.lesson);
    return enterStep(s, sim, view, messages, first);
}

void closeLesson(LessonSession& s, SimulationSession& sim, View& view) {
    s = LessonSession{};
    sim.stopAtFrame.reset();
    sim.script.clear();
    sim.pauseAtSceneEnd = true; // the scene's own end again
    view.fitBounds.reset();
    view.reserved = ShowSet::noOverlays();
    setViewFrame(view, ViewFrame::World); // a step's frame ends with the lesson
}

bool enterStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages,
               std::size_t index) {
    if (!s.lesson || index >= s.lesson->steps.size()) return false;
    const LessonStep& step = s.lesson->steps[index];
    s.current = index;
    s.revealed = false;
    s.digits.clear();
    // The world the step states, seen as it says; its edits play at their frames (reset below
    // plays those of frame 0, and R plays them again).
    // Its overrides are in its scene (not to be undone), printed as its setup.
    sim.setScene(*step.scene, step.sceneSource, step.overrides);
    sim.editLog = LogPlayer(step.edits);
    Overlays shown = ShowSet::noOverlays();
    for (const std::string& name : step.overlays) setOverlay(shown, name, true);
    view.show = shown;
    // The windows its moment opens keep their room from the setup on: the scene keeps one size
    // while the step is asked, played and answered (issue 39).
    view.reserved = ShowSet::noOverlays();
    for (const std::string& name : step.reveal) setOverlay(view.reserved, name, true);
    view.fitBounds = step.camera;
    view.autoFit = true;
    setViewFrame(view, step.frame);
    sim.timeScale = step.timeScale;
    sim.slowMotion = false;
    sim.pauseOnCollision = false;
    sim.selected = step.selected;
    sim.thrust.on = step.thrust.has_value(); // the step states it, like its overlays
    if (step.thrust) sim.thrust.force = *step.thrust;
    sim.script = step.input; // the step plays its player's keys itself
    sim.reset(); // again, with the selection: the plots and the point of impact follow it
    followNewRun(view, sim.world());
    s.written =
        runStepToPause(step); // as written: for a changed run's time and the answer beside it
    showSetup(s, sim);
    if (pausesAtItsSetup(step)) lessonShowPausePoint(s, sim, view);
    messages.clear();
    return true;
}

void lessonTakeSetup(LessonSession& s, SimulationSession& sim, View& view, const Scene& carried) {
    const LessonStep* step = s.step();
    if (!step) return;
    const int selected = sim.selected;
    std::vector<ScriptedKeys> script = sim.script;
    sim.setScene(carried, step->sceneSource);
    sim.selected = selected;
    sim.script = std::move(script);
    sim.reset(); // with the selection, as entering the step
    followNewRun(view, sim.world());
    view.fitBounds = step->camera;
    showSetup(s, sim);
}

const World& lessonSetupWorld(const LessonSession& s, const SimulationSession& sim) {
    return s.playedFrom ? *s.playedFrom : sim.world();
}

void replayStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (!s.step()) return;
    sim.reset();                  // the lecturer's method and settings stay, as R outside lessons
    sim.script = s.step()->input; // its player's keys played again (the arrows may have taken it)
    followNewRun(view, sim.world());
    view.fitBounds = s.step()->camera; // the setup's framing, should the moment have changed it
    showSetup(s, sim); // played again, it watches for its event in the world as it now is
    if (pausesAtItsSetup(*s.step())) lessonShowPausePoint(s, sim, view);
    messages.clear();
}

void lessonNext(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (!s.active()) return;
    switch (s.phase) {
    case LessonSession::Phase::Setup: // play toward the moment
        if (!startPlaying(s, sim)) lessonShowPausePoint(s, sim, view);
        return;
    case LessonSession::Phase::Playing: // the moment at once
        if (s.pauses()) {
            lessonShowPausePoint(s, sim, view);
            return;
        }
        break; // no moment: the next step
    case LessonSession::Phase::Moment:
        break;
    }
    if (s.current + 1 < s.lesson->steps.size()) enterStep(s, sim, view, messages, s.current + 1);
}

bool lessonJump(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (!s.active() || s.digits.empty()) return false;
    const long long number = std::stoll(s.digits);
    s.digits.clear();
    std::string error;
    const auto index = stepIndex(*s.lesson, number, &error);
    if (!index) {
        messages.error = error;
        return false;
    }
    return enterStep(s, sim, view, messages, *index);
}

void lessonPrevious(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (s.active() && s.current > 0) enterStep(s, sim, view, messages, s.current - 1);
}

void lessonTypeDigit(LessonSession& s, int digit) {
    if (!s.active() || digit < 0 || digit > 9 || s.digits.size() >= kMaxDigits) return;
    s.digits += static_cast<char>('0' + digit);
}

void lessonShowPausePoint(LessonSession& s, SimulationSession& sim, View& view) {
    if (!s.step()) return;
    runToPausePoint(s, sim, view);
    reveal(s, sim, view);
}

bool lessonRunsSideBySide(const LessonSession& s, const View& view) {
    if (view.show.sideBySide) return true;
    const LessonStep* step = s.step();
    return step &&
           std::find(step->reveal.begin(), step->reveal.end(), "sidebyside") != step->reveal.end();
}

bool lessonBeforeFrames(LessonSession& s, SimulationSession& sim, View& view) {
    if (!s.active() || s.phase != LessonSession::Phase::Setup) return true;
    const bool paused = sim.paused;
    if (!startPlaying(s, sim)) { // its event is there at once: the moment, as the next press
        lessonShowPausePoint(s, sim, view);
        return false;
    }
    sim.paused = paused; // N: one frame, and paused still
    return true;
}

void lessonAfterFrames(LessonSession& s, SimulationSession& sim, View& view) {
    if (s.phase != LessonSession::Phase::Playing || !s.watch || !s.watch->paused()) return;
    sim.stopWhen = nullptr;
    sim.paused = true;
    reveal(s, sim, view);
}

std::string lessonHeading(const LessonSession& session) {
    const LessonStep* step = session.step();
    if (!step) return "";
    return std::to_string(session.current + 1) + " / " +
           std::to_string(session.lesson->steps.size()) + " \xc2\xb7 " + step->title;
}

std::string lessonHint(const LessonSession& session, bool touch) {
    if (!session.step()) return "";
    if (touch) {
        const bool last = session.current + 1 >= session.lesson->steps.size();
        switch (session.phase) {
        case LessonSession::Phase::Setup: // short: it sits beside the heading on a phone
            return session.pauses() ? "Tap Play" : "";
        case LessonSession::Phase::Playing:
            return "";
        case LessonSession::Phase::Moment:
            return last ? "" : "Tap Next";
        }
        return "";
    }
    switch (session.phase) {
    case LessonSession::Phase::Setup:
        return session.pauses() ? "PageDown: play" : "";
    case LessonSession::Phase::Playing:
        return "PageDown: the moment at once";
    case LessonSession::Phase::Moment:
        return "";
    }
    return "";
}

std::vector<std::string> lessonChanges(const LessonSession& s, const SimulationSession& sim) {
    const LessonStep* step = s.step();
    if (!step || !s.written) return {};
    const World& setup = s.playedFrom ? *s.playedFrom : sim.world();
    if (setup.time != 0.0 || !differsFromWritten(setup, s.written->setup)) return {};
    const std::vector<std::string> said =
        setupChanges(*step, setup, liveBlockIndex(*step->scene, labelNames(sim)), s.written->setup);
    // A change no line names (a block's colour, say) still makes the world not the one written.
    return said.empty() ? std::vector<std::string>{"your changes"} : said;
}

StepPrompt lessonPrompt(const LessonSession& s, const SimulationSession& sim) {
    const LessonStep* step = s.step();
    if (!step) return {};
    // The question reads the world it is asked of: the one on screen at the setup (the lecturer's
    // changes show at once), the one the step was played from after that.
    const World& setup = s.playedFrom ? *s.playedFrom : sim.world();
    const std::vector<int> blocks = liveBlockIndex(*step->scene, labelNames(sim));
    return stepPrompt(*step, setup, blocks, lessonChanges(s, sim).empty());
}

std::optional<StepAnswer> lessonAnswer(const LessonSession& s, const SimulationSession& sim) {
    const LessonStep* step = s.step();
    if (!step || s.phase != LessonSession::Phase::Moment || !s.watch) return std::nullopt;
    const World& setup = s.playedFrom ? *s.playedFrom : sim.world();
    const StepRun run = watchedRun(*s.watch, setup, sim.world());
    return stepAnswer(*step, run, lessonChanges(s, sim), s.written ? &*s.written : nullptr);
}

LessonTexts lessonTexts(const LessonSession& s, const SimulationSession& sim) {
    LessonTexts t;
    if (!s.step()) return t;
    const StepPrompt prompt = lessonPrompt(s, sim);
    t.caption = prompt.caption;
    t.question = prompt.question;
    for (std::size_t i = 0; i < prompt.choices.size(); ++i)
        t.choices.push_back(choiceLetter(i) + ". " + prompt.choices[i]);
    const std::optional<StepAnswer> answer = lessonAnswer(s, sim);
    if (!answer) return t;
    t.missed = answer->missed;
    if (s.revealed) t.answer = answer->text;
    return t;
}

std::vector<LessonLine> lessonCaption(const LessonSession& session, const SimulationSession& sim) {
    if (!session.step()) return {};
    using Kind = LessonLine::Kind;
    const LessonTexts t = lessonTexts(session, sim);
    std::vector<LessonLine> lines{{Kind::Caption, t.caption}};
    if (!t.missed.empty()) {
        lines.push_back({Kind::NoAnswer, "No answer: " + t.missed});
    } else if (session.revealed) {
        if (!t.answer.empty()) lines.push_back({Kind::Answer, "Answer: " + t.answer});
    } else if (!t.question.empty()) {
        lines.push_back({Kind::Question, "Predict: " + t.question});
        for (const std::string& c : t.choices) lines.push_back({Kind::Choice, c});
    }
    const std::string hint = lessonHint(session);
    if (!hint.empty()) lines.push_back({Kind::Hint, hint});
    if (!session.digits.empty())
        lines.push_back({Kind::GoTo, "Go to step " + session.digits + " (Enter)"});
    return lines;
}

std::string captionText(const std::vector<LessonLine>& lines) {
    std::string text;
    for (const LessonLine& line : lines) text += (text.empty() ? "" : "\n") + line.text;
    return text;
}
