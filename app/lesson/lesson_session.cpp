#include "lesson_session.h"

#include "app_state.h"
#include "lesson_runner.h"
#include "options.h"

#ifndef SANDBOX_LESSONS_DIR
#define SANDBOX_LESSONS_DIR ""
#endif

namespace {

constexpr std::size_t kMaxDigits = 6;

// Runs the frames up to the pause point (a question's last frame) and pauses there.
void runToPausePoint(App& app) {
    LessonSession& s = app.lesson;
    s.stopped = true;
    while (s.stopFrame && app.world.frame < s.pauseFrame) stepSimulation(app);
    app.paused = true;
}

void reveal(App& app) {
    LessonSession& s = app.lesson;
    runToPausePoint(app);
    s.revealed = true;
    for (const std::string& name : s.step()->reveal) setOverlay(app.show, name, true);
}

} // namespace

std::string builtInLessonsDirectory() {
    return SANDBOX_LESSONS_DIR;
}

LessonContext appLessonContext(const App& app) {
    LessonContext c;
    c.scenesDir = app.scenesDir;
    c.overlayNames = overlayNames();
    return c;
}

bool openLesson(App& app, const std::string& path, std::size_t first) {
    LessonResult r = loadLessonFile(path, appLessonContext(app));
    if (!r.lesson) {
        app.error = r.error.text();
        return false;
    }
    std::string error;
    if (!stepIndex(*r.lesson, static_cast<long long>(first) + 1, &error)) {
        app.error = error;
        return false;
    }
    app.lesson = LessonSession{};
    app.lesson.lesson = std::move(*r.lesson);
    return enterStep(app, first);
}

void closeLesson(App& app) {
    app.lesson = LessonSession{};
    app.fitBounds.reset();
    setViewFrame(app, ViewFrame::World); // a step's frame ends with the lesson
}

bool enterStep(App& app, std::size_t index) {
    LessonSession& s = app.lesson;
    if (!s.lesson || index >= s.lesson->steps.size()) return false;
    const LessonStep& step = s.lesson->steps[index];
    s.current = index;
    s.revealed = false;
    s.stopped = false;
    s.digits.clear();
    setScene(app, step.scene, step.sceneSource);
    Overlays shown = ShowSet::noOverlays();
    for (const std::string& name : step.overlays) setOverlay(shown, name, true);
    app.show = shown;
    app.fitBounds = step.camera;
    app.autoFit = true;
    setViewFrame(app, step.frame);
    app.timeScale = step.timeScale;
    app.slowMotion = false;
    app.pauseOnCollision = false;
    app.selected = step.selected;
    app.thrust.on = step.thrust.has_value(); // the step states it, like its overlays
    if (step.thrust) app.thrust.force = *step.thrust;
    resetScene(app); // again, with the selection: the plots and the point of impact follow it
    const StepRun run = runStepToPause(step);
    s.pauseFrame = static_cast<std::uint64_t>(run.progress.frames);
    s.stopFrame.reset();
    if (step.pause.kind != LessonPause::Kind::None && run.reached) {
        s.stopFrame = s.asking() && s.pauseFrame > 0 ? s.pauseFrame - 1 : s.pauseFrame;
    }
    app.paused = s.stopFrame && *s.stopFrame == 0;
    s.stopped = app.paused;
    app.error.clear();
    app.note.clear();
    return true;
}

bool applyLessonAction(App& app, Action action) {
    LessonSession& s = app.lesson;
    switch (action) {
    case Action::Reset:
        return s.active() && enterStep(app, s.current);
    case Action::LessonNext:
        lessonNext(app);
        return true;
    case Action::LessonPrevious:
        lessonPrevious(app);
        return true;
    case Action::LessonFirst:
        if (s.active()) enterStep(app, 0);
        return true;
    case Action::LessonLast:
        if (s.active()) enterStep(app, s.lesson->steps.size() - 1);
        return true;
    case Action::LessonJump:
        lessonJump(app);
        return true;
    default:
        return false;
    }
}

void lessonNext(App& app) {
    LessonSession& s = app.lesson;
    if (!s.active()) return;
    if (s.asking()) {
        reveal(app);
        return;
    }
    if (s.current + 1 < s.lesson->steps.size()) enterStep(app, s.current + 1);
}

void lessonPrevious(App& app) {
    LessonSession& s = app.lesson;
    if (s.active() && s.current > 0) enterStep(app, s.current - 1);
}

void lessonTypeDigit(App& app, int digit) {
    LessonSession& s = app.lesson;
    if (!s.active() || digit < 0 || digit > 9 || s.digits.size() >= kMaxDigits) return;
    s.digits += static_cast<char>('0' + digit);
}

bool lessonJump(App& app) {
    LessonSession& s = app.lesson;
    if (!s.active() || s.digits.empty()) return false;
    const long long number = std::stoll(s.digits);
    s.digits.clear();
    std::string error;
    const auto index = stepIndex(*s.lesson, number, &error);
    if (!index) {
        app.error = error;
        return false;
    }
    return enterStep(app, *index);
}

void lessonShowPausePoint(App& app) {
    LessonSession& s = app.lesson;
    const LessonStep* step = s.step();
    if (!step) return;
    if (!step->question.empty() && !s.revealed) {
        reveal(app);
        return;
    }
    runToPausePoint(app);
}

void lessonAfterFrame(App& app) {
    LessonSession& s = app.lesson;
    if (!s.active() || s.stopped || !s.stopFrame) return;
    if (app.world.frame >= *s.stopFrame) {
        app.paused = true;
        s.stopped = true;
    }
}

std::string lessonHeading(const LessonSession& session) {
    const LessonStep* step = session.step();
    if (!step) return "";
    return std::to_string(session.current + 1) + " / " +
           std::to_string(session.lesson->steps.size()) + " \xc2\xb7 " + step->title;
}

std::string lessonCaption(const LessonSession& session) {
    const LessonStep* step = session.step();
    if (!step) return "";
    std::string text = step->caption;
    if (!step->question.empty()) {
        text += "\n" + (session.revealed ? "Answer: " + step->answer
                                         : "Question: " + step->question + "  (PageDown: answer)");
    }
    if (!session.digits.empty()) text += "\nGo to step " + session.digits + " (Enter)";
    return text;
}
