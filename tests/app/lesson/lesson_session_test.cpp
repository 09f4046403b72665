// The lesson in the app: entering a step gives exactly the state the headless runner checks, the
// keys walk through the steps and their questions, R restarts, a bad lesson keeps the current one.
#include "app.h"
#include "input_map.h"
#include "inspector_format.h"
#include "lesson_prompt.h"
#include "lesson_runner.h"
#include "lesson_session.h"
#include "spoken_text.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

const std::string kLecture3 = std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json";
const std::string kBadLessons = std::string(SANDBOX_TEST_DATA_DIR) + "/bad_lessons";

App lessonApp() {
    App app;
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    EXPECT_TRUE(openLesson(app, kLecture3)) << app.ui.messages.error;
    return app;
}

// Plays frame by frame as the window does, until the step pauses itself (or a bound).
void playUntilPaused(App& app) {
    for (int i = 0; i < 100000 && !app.sim.paused; ++i) stepSimulation(app);
}

} // namespace

TEST(LessonSession, EveryStepShowsWhatTheRunnerChecks) {
    App app = lessonApp();
    const Lesson& lesson = *app.lesson.lesson;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        ASSERT_TRUE(enterStep(app, i));
        EXPECT_EQ(stateHash(app.sim.world()), stateHash(stepStartWorld(lesson.steps[i])));
        EXPECT_EQ(app.sim.world().frame, 0u);
        lessonShowPausePoint(app);
        const StepRun run = runStepToPause(lesson.steps[i]);
        EXPECT_EQ(stateHash(app.sim.world()), stateHash(run.world)) << lesson.steps[i].title;
        EXPECT_TRUE(app.sim.paused);
        // One count of collisions: the badge's (the run's totals) is sandbox-cli lesson's, and
        // the rest rule's resting contacts are counted apart in both.
        EXPECT_EQ(app.sim.run.totals.collisions, run.progress.collisions) << lesson.steps[i].title;
        EXPECT_EQ(app.sim.run.totals.contacts, run.progress.contacts) << lesson.steps[i].title;
    }
}

// Predict, then observe (issue 24): every step opens paused at its setup (t = 0) with its
// question; the next press plays it, at its time scale, through the window's clock to its
// moment, where it pauses by itself and shows the answer (the runner's state, bit for bit).
TEST(LessonSession, EveryStepOpensAtItsSetupAndPlaysToItsMoment) {
    App app = lessonApp();
    const Lesson& lesson = *app.lesson.lesson;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        enterStep(app, i);
        EXPECT_EQ(app.sim.world().time, 0.0) << step.title;
        EXPECT_TRUE(app.sim.paused) << step.title;
        EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Setup) << step.title;
        if (!step.question.empty()) {
            const std::string caption = captionText(lessonCaption(app.lesson, app.sim));
            EXPECT_NE(caption.find("Predict: " + stepPrompt(step).question), std::string::npos)
                << step.title;
            EXPECT_NE(caption.find("\nA. " + stepPrompt(step).choices.at(0) + "\nB. "),
                      std::string::npos)
                << caption;
            EXPECT_EQ(caption.find("Answer: "), std::string::npos);
        }
        if (step.pause.kind == LessonPause::Kind::None) continue;
        const StepRun run = runStepToPause(step);
        const std::uint64_t frames = static_cast<std::uint64_t>(run.progress.frames);
        applyLessonAction(app, Action::LessonNext); // play
        EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Playing) << step.title;
        // The window's clock, 60 displayed frames a second, at the step's time scale.
        for (int k = 0; k < 100000 && !app.sim.paused; ++k) advanceSimulation(app, 1.0 / 60.0);
        EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment) << step.title;
        EXPECT_EQ(app.sim.world().frame, frames) << step.title;
        EXPECT_EQ(stateHash(app.sim.world()), stateHash(run.world)) << step.title;
        EXPECT_EQ(app.lesson.current, i); // still this step
        if (!step.question.empty()) {
            const std::string answer = stepAnswer(step, run, {}, nullptr).text;
            EXPECT_NE(captionText(lessonCaption(app.lesson, app.sim)).find("Answer: " + answer),
                      std::string::npos)
                << step.title << "\n"
                << captionText(lessonCaption(app.lesson, app.sim));
        }
        // Playing on does not stop again.
        app.sim.paused = false;
        advanceSimulation(app, 1.0 / 60.0);
        EXPECT_FALSE(app.sim.paused) << step.title;
    }
}

// The caption is composed once (lessonCaption): the page's text for a screen reader says what the
// bar says, line for line (the choices after the question, each a sentence), at the setup (the
// question and its choices) and at the moment (the answer or why there is none, no question).
TEST(LessonSession, ThePageReadsTheCaptionTheBarDraws) {
    App app = lessonApp();
    const Lesson& lesson = *app.lesson.lesson;
    auto flat = [](std::string text) { // the page's text is one line
        for (char& c : text)
            if (c == '\n') c = ' ';
        return text;
    };
    using Kind = LessonLine::Kind;
    int questions = 0, answers = 0;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const LessonStep& step = lesson.steps[i];
        ASSERT_TRUE(enterStep(app, i));
        for (int moment = 0; moment < 2; ++moment) {
            if (moment) lessonShowPausePoint(app);
            const LessonTexts texts = lessonTexts(app.lesson, app.sim);
            const std::vector<LessonLine> lines = lessonCaption(app.lesson, app.sim);
            const SpokenScreen spoken = spokenScreen(app);
            ASSERT_FALSE(lines.empty());
            EXPECT_EQ(lines[0].kind, Kind::Caption);
            std::string question, answer; // the bar's lines as the page says them
            std::size_t choices = 0;
            for (const LessonLine& line : lines) {
                if (line.kind == Kind::Question) question = flat(line.text);
                if (line.kind == Kind::Choice) question += " " + flat(line.text) + ".", ++choices;
                if (line.kind == Kind::Answer || line.kind == Kind::NoAnswer)
                    answer = flat(line.text);
            }
            EXPECT_EQ(spoken.caption, flat(texts.caption)) << step.title;
            EXPECT_EQ(spoken.question, question) << step.title;
            EXPECT_EQ(spoken.answer, answer) << step.title;
            if (texts.question.empty()) {
                EXPECT_EQ(spoken.question, "") << step.title;
            } else if (moment) {
                ++answers;
                EXPECT_EQ(spoken.question, "") << step.title;
                EXPECT_EQ(spoken.answer, texts.missed.empty() ? flat("Answer: " + texts.answer)
                                                              : flat("No answer: " + texts.missed))
                    << step.title;
            } else {
                ++questions;
                EXPECT_EQ(spoken.question.rfind(flat("Predict: " + texts.question), 0), 0u)
                    << step.title;
                EXPECT_EQ(choices, texts.choices.size()) << step.title;
                EXPECT_EQ(spoken.answer, "") << step.title;
            }
        }
    }
    EXPECT_GT(questions, 0); // the lecture asks
    EXPECT_EQ(answers, questions);
}

TEST(LessonSession, KeysWalkThroughTheSteps) {
    App app = lessonApp();
    const std::size_t n = app.lesson.lesson->steps.size();
    EXPECT_EQ(lessonHeading(app.lesson),
              "1 / " + std::to_string(n) + " \xc2\xb7 " + app.lesson.lesson->steps[0].title);
    // Which keys give these actions: KeyMap.EachKeyGivesItsAction (input_test.cpp).
    EXPECT_EQ(digitOfKey(keys::kKeypad0 + 3), 3);
    EXPECT_EQ(digitOfKey(keys::kEnter), -1);

    applyLessonAction(app, Action::LessonNext); // step 1 plays from its setup
    EXPECT_EQ(app.lesson.current, 0u);
    EXPECT_FALSE(app.sim.paused);
    applyLessonAction(app, Action::LessonNext); // its moment at once
    EXPECT_EQ(app.lesson.current, 0u);
    EXPECT_TRUE(app.sim.paused);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    applyLessonAction(app, Action::LessonNext); // step 2
    EXPECT_EQ(app.lesson.current, 1u);
    applyLessonAction(app, Action::LessonPrevious);
    EXPECT_EQ(app.lesson.current, 0u);
    applyLessonAction(app, Action::LessonPrevious); // stays at the first
    EXPECT_EQ(app.lesson.current, 0u);
    applyLessonAction(app, Action::LessonLast);
    EXPECT_EQ(app.lesson.current, n - 1);
    applyLessonAction(app, Action::LessonNext); // stays at the last
    EXPECT_EQ(app.lesson.current, n - 1);
    applyLessonAction(app, Action::LessonFirst);
    EXPECT_EQ(app.lesson.current, 0u);

    lessonTypeDigit(app.lesson, 1);
    lessonTypeDigit(app.lesson, 2);
    EXPECT_NE(captionText(lessonCaption(app.lesson, app.sim)).find("Go to step 12"),
              std::string::npos);
    applyLessonAction(app, Action::LessonJump);
    EXPECT_EQ(app.lesson.current, 11u);
    lessonTypeDigit(app.lesson, 9);
    lessonTypeDigit(app.lesson, 9);
    applyLessonAction(app, Action::LessonJump); // no step 99: an error, and the step stays
    EXPECT_EQ(app.lesson.current, 11u);
    EXPECT_NE(app.ui.messages.error.find("no step 99"), std::string::npos) << app.ui.messages.error;
}

TEST(LessonSession, LeavingAndComingBackGivesTheSameState) {
    App app = lessonApp();
    enterStep(app, 3);
    const std::uint64_t start = stateHash(app.sim.world());
    const Overlays shown = app.view.show;
    applyLessonAction(app, Action::LessonNext); // play (step 4 asks)
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view); // the moment: the answer
    EXPECT_FALSE(app.lesson.asking());
    applyLessonAction(app, Action::LessonNext); // step 5
    EXPECT_EQ(app.lesson.current, 4u);
    applyLessonAction(app, Action::LessonPrevious);
    EXPECT_EQ(app.lesson.current, 3u);
    EXPECT_EQ(stateHash(app.sim.world()), start);
    EXPECT_EQ(app.sim.world().time, 0.0);
    EXPECT_EQ(app.view.show.poi, shown.poi);
    EXPECT_EQ(app.view.show.inspector, shown.inspector); // the reveal's overlays are off again
    EXPECT_TRUE(app.lesson.asking());
}

// R replays the step from its setup keeping what the lecturer changed, as R does outside lessons
// (issue 24: step 2's answer says "S stops it"; after S, R must not bring the step's method
// back); Shift+R restores the step as written.
TEST(LessonSession, RReplaysWithTheLecturersChangesShiftRAsWritten) {
    App app = lessonApp();
    enterStep(app, 1); // the bullet: move-and-correct tunnels
    const std::uint64_t start = stateHash(app.sim.world());
    const int selected = app.sim.selected;
    applyLessonAction(app, Action::LessonNext);
    for (int i = 0; i < 5; ++i) stepSimulation(app);
    app.sim.world().settings.method = Method::Perfect; // S
    applyLessonAction(app, Action::Reset);
    EXPECT_EQ(app.lesson.current, 1u);
    EXPECT_EQ(app.sim.world().time, 0.0);
    EXPECT_EQ(app.sim.world().settings.method, Method::Perfect); // kept
    EXPECT_EQ(app.sim.selected, selected);
    EXPECT_TRUE(app.sim.paused); // at the setup again
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Setup);
    // Played to its moment, the perfect method stops the bullet at the wall.
    applyLessonAction(app, Action::LessonNext);
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    const Block& bullet = app.sim.world().blocks[static_cast<std::size_t>(selected)];
    EXPECT_LT(bullet.position.x, 12.0);          // in front of the wall (at x = 12 m), not past it
    applyLessonAction(app, Action::ResetToFile); // Shift+R
    EXPECT_EQ(app.sim.world().settings.method, app.lesson.step()->scene->settings.method);
    EXPECT_EQ(stateHash(app.sim.world()), start);
    EXPECT_TRUE(app.sim.paused);
}

TEST(LessonSession, StepSettingsAreApplied) {
    App app = lessonApp();
    for (std::size_t i = 0; i < app.lesson.lesson->steps.size(); ++i) {
        enterStep(app, i);
        const LessonStep& step = *app.lesson.step();
        EXPECT_EQ(app.sim.selected, step.selected);
        EXPECT_EQ(app.sim.world().settings.method, step.scene->settings.method);
        EXPECT_EQ(app.sim.timeScale, step.timeScale);
        EXPECT_EQ(app.view.show.vectors, std::find(step.overlays.begin(), step.overlays.end(),
                                                   "vectors") != step.overlays.end());
        EXPECT_EQ(app.view.fitBounds.has_value(), step.camera.has_value());
    }
}

// The platformer's moment frames its evidence (its "moment_camera": the shelf, the player, the
// coin on the floor); R frames the step's camera again; a lecturer who panned keeps their view.
TEST(LessonSession, TheMomentCameraFramesTheMomentAndRFramesTheSetup) {
    App app = lessonApp();
    std::size_t platformer = 0;
    while (platformer < app.lesson.lesson->steps.size() &&
           !app.lesson.lesson->steps[platformer].momentCamera)
        ++platformer;
    ASSERT_LT(platformer, app.lesson.lesson->steps.size()) << "no step has a moment_camera";
    enterStep(app, platformer);
    const LessonStep& step = *app.lesson.step();
    ASSERT_TRUE(app.view.fitBounds && step.camera);
    EXPECT_EQ(app.view.fitBounds->min.x, step.camera->min.x);
    applyLessonAction(app, Action::LessonNext); // play
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    ASSERT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    ASSERT_TRUE(app.view.fitBounds);
    EXPECT_EQ(app.view.fitBounds->min.x, step.momentCamera->min.x);
    EXPECT_EQ(app.view.fitBounds->max.y, step.momentCamera->max.y);
    applyLessonAction(app, Action::Reset); // R: the setup, framed as it was
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Setup);
    ASSERT_TRUE(app.view.fitBounds);
    EXPECT_EQ(app.view.fitBounds->min.x, step.camera->min.x);
    app.view.autoFit = false; // the lecturer pans: the moment keeps their view
    applyLessonAction(app, Action::LessonNext);
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    EXPECT_EQ(app.view.fitBounds->min.x, step.camera->min.x);
    EXPECT_FALSE(app.view.autoFit);
    // A lecturer's change at the setup (another C) may send the evidence elsewhere: the moment
    // keeps the step's camera, which frames the whole demo.
    enterStep(app, platformer);
    ASSERT_TRUE(app.view.autoFit);
    double& c = app.sim.world().settings.bounciness;
    c = c == 0.5 ? 0.25 : 0.5;
    applyLessonAction(app, Action::LessonNext);
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    EXPECT_FALSE(lessonChanges(app.lesson, app.sim).empty());
    ASSERT_TRUE(app.view.fitBounds);
    EXPECT_EQ(app.view.fitBounds->min.x, step.camera->min.x);
    EXPECT_EQ(app.view.fitBounds->max.y, step.camera->max.y);
}

TEST(LessonSession, AMalformedLessonKeepsTheCurrentOne) {
    App app = lessonApp();
    enterStep(app, 4);
    const std::uint64_t hash = stateHash(app.sim.world());
    for (const char* bad : {"unknown_overlay.json", "scene_fails.json", "bad_expectation.json",
                            "syntax.json", "no_such_lesson.json"}) {
        EXPECT_FALSE(openLesson(app, kBadLessons + "/" + bad));
        EXPECT_NE(app.ui.messages.error.find(bad), std::string::npos) << app.ui.messages.error;
        ASSERT_TRUE(app.lesson.active());
        EXPECT_EQ(app.lesson.lesson->path, kLecture3);
        EXPECT_EQ(app.lesson.current, 4u);
        EXPECT_EQ(stateHash(app.sim.world()), hash);
    }
    EXPECT_FALSE(openLesson(app, kLecture3, 99)); // a bad step index
    EXPECT_NE(app.ui.messages.error.find("no step 100"), std::string::npos)
        << app.ui.messages.error;
    EXPECT_EQ(app.lesson.current, 4u);
}

// A step's overrides are the step (lecture3 step 18: move-and-correct at 30 frames per
// second): Ctrl+Z has nothing of them to undo, R and Shift+R keep them; a change the lecturer
// makes on top is undone back to them.
TEST(LessonSession, AStepsOverridesAreItsSetupNotAnUndoableEdit) {
    App app = lessonApp();
    ASSERT_TRUE(enterStep(app, 17));
    const auto asWritten = [&] {
        EXPECT_EQ(app.sim.world().settings.method, Method::MoveAndCorrect);
        EXPECT_EQ(app.sim.world().settings.dt, 1.0 / 30.0);
    };
    asWritten();
    EXPECT_FALSE(app.sim.undo());
    EXPECT_EQ(app.sim.notice, "Nothing to undo");
    asWritten();
    EXPECT_TRUE(app.sim.apply(Edit::setWorld("method", "perfect")).empty());
    EXPECT_TRUE(app.sim.undo());
    asWritten();
    EXPECT_FALSE(app.sim.undo());
    app.sim.resetToFile();
    asWritten();
    app.sim.reset();
    asWritten();
    EXPECT_FALSE(app.sim.edits.canUndo()); // R kept them: nothing differs from the step's setup
}

TEST(LessonSession, LoadingASceneLeavesTheLesson) {
    App app = lessonApp();
    ASSERT_TRUE(loadScene(app, std::string(SANDBOX_SCENES_DIR) + "/single_bounce.json"));
    EXPECT_FALSE(app.lesson.active());
    EXPECT_FALSE(app.view.fitBounds.has_value());
    applyLessonAction(app, Action::LessonNext); // nothing happens without a lesson
    EXPECT_EQ(app.sim.scene.name, "Single bounce");
}

// Issue 18: in present mode a lesson keeps one caption bar ("n / N · title", the caption, and
// the method and t beside the heading, since the status badge is hidden), the scene below it,
// and no window.
TEST(LessonSession, PresentModeKeepsTheOneCaptionBar) {
    App app = lessonApp();
    app.view.captionHeight = 120.0; // what the bar measured last frame
    app.view.show.plots = true;
    setPresentMode(app.view, true);
    const Layout layout = computeAppLayout(app.view, app.lesson.active(), 1920, 1080);
    EXPECT_TRUE(layout.windows.empty());
    EXPECT_EQ(layout.panel.width, 0.0);
    EXPECT_GE(layout.scene.y, 120.0); // the world is fitted below the bar
    EXPECT_EQ(lessonBarStatus(true, Method::Perfect, 0.625), "perfect   ·   t = 0.62 s");
    EXPECT_EQ(lessonBarStatus(false, Method::Perfect, 0.625),
              "PageDown next, PageUp back, R restart");
    // After "PageDown: play" the keys do not name PageDown again.
    EXPECT_EQ(lessonBarStatus(false, Method::Perfect, 0.0, false, true), "PageUp back, R restart");
    EXPECT_EQ(lessonBarStatus(false, Method::Perfect, 0.0, true),
              ""); // touch: the hint names the tap
    EXPECT_EQ(lessonHeading(app.lesson).rfind("1 / ", 0), 0u) << lessonHeading(app.lesson);
}

// Issue 18: step 24 ("collisions that are not really collisions") waits for the collision the
// relative-velocity test refuses, and the inspector says so as the Tips slide does; the watch
// after it shows the real collision it causes in the next frame.
TEST(LessonSession, TheNotACollisionStepShowsTheRelativeVelocityTest) {
    App app = lessonApp();
    ASSERT_TRUE(enterStep(app, 23)) << app.ui.messages.error;
    ASSERT_EQ(app.lesson.step()->title, "Tips: BAD, a collision that is not a collision");
    lessonShowPausePoint(app);
    ASSERT_EQ(app.sim.telemetry.recent.size(), 2u);
    EXPECT_FALSE(collisionFormula(app.sim.telemetry.recent.back(), "red", "blue").separating);
    const CollisionRecord& r = app.sim.telemetry.recent.front();
    EXPECT_TRUE(r.firstBelow); // red is behind (left of) blue
    const CollisionFormula f =
        collisionFormula(r, app.sim.blockDisplayName(r.block), app.sim.blockDisplayName(r.other));
    EXPECT_TRUE(f.separating);
    EXPECT_EQ(f.relative.rfind("rel. vel. along x = v1 - v2 = 3 - 4 = -1 < 0: separating", 0), 0u)
        << f.relative;
}

// ---- What the lecturer changes mid-demo stays true (issue 38) ----

namespace {

// Enters step `number` (1-based), lets `change` edit the world at its setup as the panel would,
// plays it to its moment as the window does and returns the caption bar's text there.
template <typename Change> std::string changedMoment(App& app, std::size_t number, Change change) {
    EXPECT_TRUE(enterStep(app, number - 1));
    change(app.sim.world());
    applyLessonAction(app, Action::LessonNext);
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment) << "step " << number;
    return captionText(lessonCaption(app.lesson, app.sim));
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

// C changed at the setup: the question asks with it, the answer says so and gives its numbers
// (issue 38: "-2 m/s, 2 J" with C = 0.9 in effect), beside the result as written.
TEST(LessonMidDemo, BouncinessChangedAtTheSetup) {
    App app = lessonApp();
    ASSERT_TRUE(enterStep(app, 2));
    app.sim.world().settings.bounciness = 0.9;
    EXPECT_TRUE(
        has(captionText(lessonCaption(app.lesson, app.sim)), "with C = 0.9. Its velocity after"))
        << captionText(lessonCaption(app.lesson, app.sim));
    const std::string text = changedMoment(app, 3, [](World& w) { w.settings.bounciness = 0.9; });
    EXPECT_TRUE(has(text, "Answer: With C = 0.9: A. v' = -C·v = -0.9·4 = -3.6 m/s")) << text;
    EXPECT_TRUE(has(text, "As written: A, -2 m/s and 2 J.")) << text;
    EXPECT_NEAR(app.sim.world().blocks[0].velocity.x, -3.6, 1e-12);
}

// A mass changed: the answer names it and prints the inspector's numbers (issue 38: the answer
// said -2 and 4, the inspector -3.6 and 2.4).
TEST(LessonMidDemo, MassChangedAtTheSetup) {
    App app = lessonApp();
    const std::string text = changedMoment(app, 13, [](World& w) { w.blocks[1].mass = 4.0; });
    EXPECT_TRUE(has(text, "Answer: With m2's mass 4 kg: A. v1' = 1.2 - 1·(6 - 1.2) = -3.6 m/s"))
        << text;
    EXPECT_NE(app.lesson.step()->scene->blocks[1].name.find("m2"), std::string::npos);
}

// The frame rate changed: the pause follows the event in the lecturer's world (issue 38: paused at
// t = 0.08 s with 0 collisions), and the answer says what changed.
TEST(LessonMidDemo, FrameRateChangedAtTheSetup) {
    App app = lessonApp();
    const std::string text = changedMoment(app, 4, [](World& w) { w.settings.dt = 1.0 / 60.0; });
    EXPECT_TRUE(has(text, "Answer: With frame rate 60 Hz: A.")) << text;
    EXPECT_TRUE(has(text, "touches the step at x = 8.75 m")) << text;
    ASSERT_TRUE(app.lesson.watch && app.lesson.watch->hit());
    EXPECT_NEAR(app.lesson.watch->hit()->time, 5.75 / 14.0, 1e-12);
}

// The method changed with S: the bullet bounces and the answer says where, not "past the wall".
TEST(LessonMidDemo, MethodChangedAtTheSetup) {
    App app = lessonApp();
    const std::string text =
        changedMoment(app, 2, [](World& w) { w.settings.method = Method::Perfect; });
    EXPECT_TRUE(has(text, "Answer: With method perfect: B. At x = ")) << text;
    EXPECT_FALSE(has(text, "16 m")) << text;
}

// A block moved off the line: the event does not come, the bar says why and claims no answer.
TEST(LessonMidDemo, ABlockMovedOffTheLineSaysWhyAndClaimsNothing) {
    App app = lessonApp();
    const std::string text = changedMoment(app, 13, [](World& w) { w.blocks[1].position.y += 3; });
    EXPECT_TRUE(has(text, "No answer: ")) << text;
    EXPECT_FALSE(has(text, "Answer: ")) << text;
}

// Every change is said by its name, in the order of the settings table, then the blocks.
TEST(LessonMidDemo, TheChangesAreSaidByName) {
    App app = lessonApp();
    ASSERT_TRUE(enterStep(app, 12));
    World& w = app.sim.world();
    w.settings.bounciness = 0.5;
    w.blocks[0].velocity.x = 3.0;
    w.blocks[1].position.x += 1.0;
    const std::vector<std::string> changes = lessonChanges(app.lesson, app.sim);
    const std::string m2 = app.lesson.step()->scene->blocks[1].name;
    const std::string m1 = app.lesson.step()->scene->blocks[0].name;
    ASSERT_EQ(changes.size(), 3u);
    EXPECT_EQ(changes[0], "C = 0.5");
    EXPECT_EQ(changes[1], m1 + "'s velocity (3, 0) m/s");
    EXPECT_EQ(changes[2].rfind(m2 + " moved to (", 0), 0u) << changes[2];
    applyLessonAction(app, Action::ResetToFile); // Shift+R: as written, nothing to say
    EXPECT_TRUE(lessonChanges(app.lesson, app.sim).empty());
}

// The class poll asks the question of the world on screen and marks the choice the live run
// proved: step 3 with C = 0.9 asks with 0.9; step 2 with the perfect method proves B (the bullet
// bounces back), not A as written (it tunnels).
TEST(LessonMidDemo, ThePollAsksTheLiveQuestionAndMarksTheLiveRunsChoice) {
    if (!pollAvailable()) GTEST_SKIP() << kPollUnavailable;
    App app = lessonApp();
    ASSERT_TRUE(enterStep(app, 2));
    app.sim.world().settings.bounciness = 0.9;
    ASSERT_TRUE(startPoll(app.poll, app.lesson, app.sim, "127.0.0.1")) << app.poll.error;
    PollScreen screen = pollScreen(app.poll, app.lesson);
    ASSERT_TRUE(screen.asking && screen.open);
    EXPECT_EQ(screen.step, 3);
    EXPECT_TRUE(has(screen.question, "with C = 0.9.")) << screen.question;
    ASSERT_EQ(screen.choices.size(), 4u);
    EXPECT_EQ(screen.choices[0], "-3.6 m/s and 6.48 J");

    ASSERT_TRUE(enterStep(app, 1));
    app.sim.world().settings.method = Method::Perfect;
    followLesson(app.poll, app.lesson, app.sim);
    screen = pollScreen(app.poll, app.lesson);
    ASSERT_TRUE(screen.asking && screen.open);
    EXPECT_EQ(screen.step, 2);
    EXPECT_EQ(screen.proved, -1);               // not known before the run
    applyLessonAction(app, Action::LessonNext); // plays: the vote closes
    followLesson(app.poll, app.lesson, app.sim);
    EXPECT_FALSE(pollScreen(app.poll, app.lesson).open);
    playUntilPaused(app);
    lessonAfterFrames(app.lesson, app.sim, app.view);
    followLesson(app.poll, app.lesson, app.sim);
    screen = pollScreen(app.poll, app.lesson);
    EXPECT_TRUE(screen.histogram);
    EXPECT_EQ(app.lesson.step()->correct, 0);
    EXPECT_EQ(screen.proved, 1);
    stopPoll(app.poll);
}

// The lecture's P (or N, or the panel's Play and Step) at a step's setup, instead of the lesson's
// PageDown: the step is played from there all the same. Before, the step stayed at its setup
// while the world ran, and its question read the running world as if it were the setup: after
// step 10's collision "Solution 1: v1' = 4, v2' = -2", false (seen walking the lesson), and no
// moment came. Now the question stays the setup's, word for word, and the step pauses at its
// moment in the runner's state, bit for bit, as PageDown plays it.
TEST(LessonSession, PAtTheSetupPlaysTheStepAndItsQuestionStaysTrue) {
    App app = lessonApp();
    const Lesson& lesson = *app.lesson.lesson;
    std::size_t momentum = lesson.steps.size();
    for (std::size_t i = 0; i < lesson.steps.size(); ++i)
        if (lesson.steps[i].title == "Momentum: total momentum zero") momentum = i;
    ASSERT_LT(momentum, lesson.steps.size());
    const LessonStep& step = lesson.steps[momentum];
    const StepRun run = runStepToPause(step);

    ASSERT_TRUE(enterStep(app, momentum));
    const std::string question = lessonTexts(app.lesson, app.sim).question;
    ASSERT_NE(question.find("Solution 1: v1' = -4, v2' = 2."), std::string::npos) << question;
    app.sim.paused = false; // P (applyAction's TogglePause)
    for (int k = 0; k < 100000 && !app.sim.paused; ++k) {
        advanceSimulation(app, 1.0 / 60.0);
        ASSERT_EQ(lessonTexts(app.lesson, app.sim).question, question)
            << "t = " << app.sim.world().time;
    }
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Moment);
    EXPECT_EQ(stateHash(app.sim.world()), stateHash(run.world));
    EXPECT_EQ(lessonTexts(app.lesson, app.sim).question, question);
    EXPECT_NE(lessonTexts(app.lesson, app.sim).answer.find("v1' = -4 m/s and v2' = 2 m/s"),
              std::string::npos)
        << lessonTexts(app.lesson, app.sim).answer;

    // N at the setup: one frame, the step playing, still paused, the question the setup's.
    ASSERT_TRUE(enterStep(app, momentum));
    app.sim.paused = true; // applyAction's StepOnce
    stepSimulation(app);
    EXPECT_EQ(app.sim.world().frame, 1u);
    EXPECT_TRUE(app.sim.paused);
    EXPECT_EQ(app.lesson.phase, LessonSession::Phase::Playing);
    EXPECT_EQ(lessonTexts(app.lesson, app.sim).question, question);
}
