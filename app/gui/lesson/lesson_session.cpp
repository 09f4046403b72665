#include "lesson_session.h"

#include "lesson_runner.h"
#include "overlays.h"

#include <algorithm>

#ifndef SANDBOX_LESSONS_DIR
#define SANDBOX_LESSONS_DIR ""
#endif

namespace {

constexpr std::size_t kMaxDigits = 6;

// Runs the frames up to the pause point and pauses there.
void runToPausePoint(const LessonSession& s, SimulationSession& sim, const View& view) {
    sim.stopAtFrame.reset(); // reached here, not again by playing on
    while (s.stopFrame && sim.world().frame < *s.stopFrame) sim.step(lessonRunsSideBySide(s, view));
    sim.paused = true;
}

// The moment: the answer shows, with the overlays that prove it.
void reveal(LessonSession& s, View& view) {
    s.phase = LessonSession::Phase::Moment;
    if (s.step()->question.empty() || s.revealed) return;
    s.revealed = true;
    for (const std::string& name : s.step()->reveal) setOverlay(view.show, name, true);
}

// Paused at the setup (t = 0), the question asked; `run` says where the step's moment is.
void showSetup(LessonSession& s, SimulationSession& sim, View& view, const StepRun& run) {
    const LessonStep& step = *s.step();
    s.revealed = false;
    s.phase = LessonSession::Phase::Setup;
    s.stopFrame.reset();
    if (step.pause.kind != LessonPause::Kind::None && run.reached)
        s.stopFrame = static_cast<std::uint64_t>(run.progress.frames);
    sim.pauseAtSceneEnd = false; // the step stops where it says
    sim.paused = true;
    sim.stopAtFrame.reset();
    if (s.stopFrame && *s.stopFrame == 0) reveal(s, view); // a step whose moment is its setup
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
    setViewFrame(view, ViewFrame::World); // a step's frame ends with the lesson
}

bool enterStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages,
               std::size_t index) {
    if (!s.lesson || index >= s.lesson->steps.size()) return false;
    const LessonStep& step = s.lesson->steps[index];
    s.current = index;
    s.revealed = false;
    s.digits.clear();
    // The world the step states, seen as it says.
    sim.setScene(*step.scene, step.sceneSource);
    Overlays shown = ShowSet::noOverlays();
    for (const std::string& name : step.overlays) setOverlay(shown, name, true);
    view.show = shown;
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
    showSetup(s, sim, view, runStepToPause(step));
    messages.clear();
    return true;
}

void replayStep(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (!s.step()) return;
    sim.reset(); // the lecturer's method and settings stay, as R outside lessons
    followNewRun(view, sim.world());
    LessonStep asRun = *s.step(); // where the step now pauses, with those settings
    Scene withSettings = *asRun.scene;
    withSettings.settings = sim.world().settings;
    asRun.scene = std::make_shared<const Scene>(std::move(withSettings));
    showSetup(s, sim, view, runStepToPause(asRun));
    messages.clear();
}

void lessonNext(LessonSession& s, SimulationSession& sim, View& view, Messages& messages) {
    if (!s.active()) return;
    switch (s.phase) {
    case LessonSession::Phase::Setup: // play toward the moment
        s.phase = LessonSession::Phase::Playing;
        sim.stopAtFrame = s.stopFrame;
        sim.paused = false;
        return;
    case LessonSession::Phase::Playing: // the moment at once
        if (s.stopFrame) {
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
    reveal(s, view);
}

bool lessonRunsSideBySide(const LessonSession& s, const View& view) {
    if (view.show.sideBySide) return true;
    const LessonStep* step = s.step();
    return step &&
           std::find(step->reveal.begin(), step->reveal.end(), "sidebyside") != step->reveal.end();
}

void lessonAfterFrames(LessonSession& s, SimulationSession& sim, View& view) {
    if (s.phase != LessonSession::Phase::Playing || !s.stopFrame) return;
    if (sim.world().frame < *s.stopFrame) return;
    sim.stopAtFrame.reset();
    sim.paused = true;
    reveal(s, view);
}

std::string lessonHeading(const LessonSession& session) {
    const LessonStep* step = session.step();
    if (!step) return "";
    return std::to_string(session.current + 1) + " / " +
           std::to_string(session.lesson->steps.size()) + " \xc2\xb7 " + step->title;
}

std::string lessonHint(const LessonSession& session) {
    if (!session.step()) return "";
    switch (session.phase) {
    case LessonSession::Phase::Setup:
        return session.stopFrame ? "PageDown: play" : "";
    case LessonSession::Phase::Playing:
        return "PageDown: the moment at once";
    case LessonSession::Phase::Moment:
        return "";
    }
    return "";
}

std::vector<LessonLine> lessonCaption(const LessonSession& session) {
    const LessonStep* step = session.step();
    if (!step) return {};
    using Kind = LessonLine::Kind;
    std::vector<LessonLine> lines{{Kind::Caption, step->caption}};
    if (!step->question.empty()) {
        if (session.revealed)
            lines.push_back({Kind::Answer, "Answer: " + step->answer});
        else
            lines.push_back({Kind::Question, "Predict: " + step->question});
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
