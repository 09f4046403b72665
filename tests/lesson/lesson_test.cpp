// Lesson files: every expectation of every shipped lesson holds through the engine (so a lesson
// cannot silently go wrong when the engine changes), steps are entered exactly, and malformed
// lessons fail with their place.
#include "lesson.h"
#include "lesson_runner.h"
#include "lesson_test_context.h"
#include "vocabulary.h"

#include "says.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

LessonContext context() {
    return shippedLessonContext();
}

std::vector<std::string> shippedLessons() {
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(SANDBOX_LESSONS_DIR))
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

struct StepCase {
    std::string file;
    std::size_t step;
};

void PrintTo(const StepCase& c, std::ostream* out) {
    *out << fs::path(c.file).filename().string() << " step " << c.step + 1;
}

std::vector<StepCase> shippedSteps() {
    std::vector<StepCase> cases;
    for (const std::string& file : shippedLessons()) {
        const LessonResult r = loadLessonFile(file, context());
        const std::size_t n = r.lesson ? r.lesson->steps.size() : 1; // a broken file: one case
        for (std::size_t i = 0; i < n; ++i) cases.push_back({file, i});
    }
    return cases;
}

std::string caseName(const testing::TestParamInfo<StepCase>& info) {
    std::string name =
        fs::path(info.param.file).stem().string() + "_step" + std::to_string(info.param.step + 1);
    std::replace_if(
        name.begin(), name.end(),
        [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return name;
}

std::string errorOf(const std::string& file) {
    const LessonResult r =
        loadLessonFile(std::string(SANDBOX_TEST_DATA_DIR) + "/" + file, context());
    EXPECT_FALSE(r.lesson) << file << " should not load";
    return r.error.text();
}

// The error of loading the bad lesson `file` says `part` (somewhere in it).
::testing::AssertionResult errorSays(const std::string& file, const std::string& part) {
    return says(errorOf(file), part);
}

LessonStep onlyStep(const std::string& text) {
    const LessonResult r = parseLesson(text, "test.json", context());
    EXPECT_TRUE(r.lesson) << r.error.text();
    return r.lesson ? r.lesson->steps.at(0) : LessonStep{};
}

// Two blocks of the lecture's second worked example (m1 = 1 kg at 6 m/s, m2 = 2 kg at rest).
const char* const kExample = R"({"name": "x", "world": {"gravity": [0, 0]}, "blocks": [
    {"name": "m1", "position": [4, 6], "size": 1, "velocity": [6, 0], "mass": 1},
    {"name": "m2", "position": [8.75, 6], "size": 1, "mass": 2}]})";

std::string lessonWith(const std::string& stepFields) {
    return std::string(R"({"name": "t", "steps": [{"title": "s", "caption": "c", "scene": )") +
           kExample + (stepFields.empty() ? "" : ", " + stepFields) + "}]}";
}

} // namespace

class ShippedLessonStep : public testing::TestWithParam<StepCase> {};

// The expectations of the step, checked at its pause point through the engine.
TEST_P(ShippedLessonStep, ReachesWhatItExpects) {
    const LessonResult r = loadLessonFile(GetParam().file, context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const LessonStep& step = r.lesson->steps.at(GetParam().step);
    const StepRun run = runStepToPause(step);
    EXPECT_TRUE(run.reached) << step.title;
    for (const std::string& failure : checkStep(step, run)) ADD_FAILURE() << failure;
}

// Motion worth watching (issue 24): from its setup (t = 0) to its moment every step shows the
// class 1.5 to 12 s of motion at its time scale (a step without a pause point is not timed).
// The bounds are the issue's; the time is the engine's sum of frame steps, so 1e-9 s of slack
// for its rounding (90 frames of 1/60 s end at 1.4999999999999996 s).
TEST_P(ShippedLessonStep, ShowsOneAndAHalfToTwelveSecondsOfMotion) {
    const LessonResult r = loadLessonFile(GetParam().file, context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const LessonStep& step = r.lesson->steps.at(GetParam().step);
    if (step.pause.kind == LessonPause::Kind::None) GTEST_SKIP() << "no pause point";
    const StepRun run = runStepToPause(step);
    const double seconds = run.world.time / step.timeScale;
    EXPECT_GE(seconds, 1.5 - 1e-9)
        << step.title << ": " << run.world.time << " s at time scale " << step.timeScale;
    EXPECT_LE(seconds, 12.0 + 1e-9)
        << step.title << ": " << run.world.time << " s at time scale " << step.timeScale;
}

// Every question true of the setup on screen (issue 24): a step that asks states what its
// question says of the setup in `given`, checked at t = 0 (checkSetup: exact numbers within each
// statement's tolerance, 1e-9 unless it says), and every block it names there lies inside the
// step's camera (or the world, without one), so the class can read those numbers off the screen.
TEST_P(ShippedLessonStep, ItsQuestionIsTrueOfTheSetupOnScreen) {
    const LessonResult r = loadLessonFile(GetParam().file, context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const LessonStep& step = r.lesson->steps.at(GetParam().step);
    if (step.question.empty()) GTEST_SKIP() << "no question";
    EXPECT_FALSE(step.given.empty()) << step.title << ": what does its question say of the setup?";
    for (const std::string& failure : checkSetup(step)) ADD_FAILURE() << failure;
    const World setup = stepStartWorld(step);
    const Bounds frame = step.camera.value_or(setup.bounds);
    for (const LessonExpect& e : step.given) {
        if (e.block < 0) continue;
        const Block& b = setup.blocks.at(static_cast<std::size_t>(e.block));
        const Vec2 lo = b.position - b.halfSize(), hi = b.position + b.halfSize();
        if (b.isDynamic()) { // a wall may run on past the frame; what moves is seen whole
            EXPECT_TRUE(lo.x >= frame.min.x && lo.y >= frame.min.y && hi.x <= frame.max.x &&
                        hi.y <= frame.max.y)
                << step.title << ": " << e.blockName << " is not all inside the camera";
        } else {
            EXPECT_TRUE(hi.x > frame.min.x && hi.y > frame.min.y && lo.x < frame.max.x &&
                        lo.y < frame.max.y)
                << step.title << ": " << e.blockName << " is not in the camera";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Lessons, ShippedLessonStep, testing::ValuesIn(shippedSteps()), caseName);

// A question that is not true of its setup is caught: `given` is checked at t = 0, before any
// frame, and names its place and both numbers.
TEST(LessonRunner, AGivenThatTheSetupDoesNotShowFails) {
    const std::string q = R"("question": "q?", "answer": "a", "choices": [
        {"text": "a", "if": "t >= 0", "correct": true}, {"text": "b", "if": "t < 0"}], )";
    const LessonStep right = onlyStep(
        lessonWith(q + R"("given": [{"block": "m1", "x": 4, "right": 4.5, "vx": 6, "mass": 1},
                         {"block": "m2", "left": 8.25, "top": 6.5, "bottom": 5.5},
                         {"frame_rate": 60, "bounciness": 1}])"));
    EXPECT_EQ(right.given.size(), 9u);
    EXPECT_TRUE(checkSetup(right).empty());
    // The gap between m1's right side and m2's left side is 3.75 m, not 4 m.
    const LessonStep wrong = onlyStep(
        lessonWith(q + R"("pause_at": {"collision": 1}, "given": [{"block": "m2", "left": 8.5}])"));
    const std::vector<std::string> failures = checkStep(wrong, runStepToPause(wrong));
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_NE(failures[0].find("steps[0].given[0]: left of \"m2\" is 8.25, expected 8.5"),
              std::string::npos)
        << failures[0];
    EXPECT_NE(failures[0].find("(at the setup, t = 0)"), std::string::npos) << failures[0];
    // What a question states: no question, no `given`.
    const LessonResult alone =
        parseLesson(lessonWith(R"("given": [{"block": "m1", "x": 4}])"), "test.json", context());
    ASSERT_FALSE(alone.lesson);
    EXPECT_NE(alone.error.text().find("steps[0].given"), std::string::npos) << alone.error.text();
}

TEST(Lesson, Lecture3FollowsTheLectureWithEnoughSteps) {
    const LessonResult r =
        loadLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    EXPECT_GE(r.lesson->steps.size(), 16u);
    std::size_t expectations = 0;
    for (const LessonStep& s : r.lesson->steps) expectations += s.expect.size();
    EXPECT_GE(expectations, 30u); // most steps say what the engine must reach
}

// Entering a step twice (or after another step) gives bit-identical states at the pause point.
TEST(Lesson, EnteringAStepIsExactEveryTime) {
    const LessonResult r =
        loadLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const Lesson& lesson = *r.lesson;
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const StepRun first = runStepToPause(lesson.steps[i]);
        runStepToPause(lesson.steps[(i + 1) % lesson.steps.size()]);
        const StepRun again = runStepToPause(lesson.steps[i]);
        EXPECT_EQ(stateHash(first.world), stateHash(again.world)) << lesson.steps[i].title;
        EXPECT_EQ(first.progress.frames, again.progress.frames);
        EXPECT_EQ(stateHash(stepStartWorld(lesson.steps[i])),
                  stateHash(makeWorld(*lesson.steps[i].scene)));
    }
}

// The lecture's example collides at t = 0.625 s, inside frame 38 (37/60 = 0.617 < 0.625 <=
// 38/60): each kind of event is that frame, and the formula's numbers hold there exactly (the
// perfect method resolves at the instant of impact; tolerance 1e-12 for rounding). A collision
// event is then watched for 1 s at the step's time scale (1): the pause is the first frame ending
// at or after 38/60 + 1 s, frame 98, with the blocks 1 s further apart; a time is its own moment.
TEST(LessonRunner, PausePointsStopAfterTheirFrame) {
    for (const char* pause :
         {R"("pause_at": {"collision": 1})", R"("pause_at": {"first_collision_of": "m1"})",
          R"("pause_at": {"collision_of": ["m2", "m1"]})", R"("pause_at": {"time": 0.63})"}) {
        const LessonStep step = onlyStep(lessonWith(pause));
        const StepRun run = runStepToPause(step);
        ASSERT_TRUE(run.reached) << pause;
        const bool time = step.pause.kind == LessonPause::Kind::Time;
        EXPECT_EQ(run.eventProgress.frames, 38) << pause;
        EXPECT_EQ(run.progress.frames, time ? 38 : 98) << pause;
        EXPECT_EQ(run.eventProgress.collisions, 1) << pause;
        EXPECT_EQ(run.progress.collisions, 1) << pause;
        EXPECT_NEAR(run.event.blocks[0].velocity.x, -2.0, 1e-12) << pause;
        EXPECT_NEAR(run.event.blocks[1].velocity.x, 4.0, 1e-12) << pause;
        const double apart = (run.world.blocks[1].position.x - run.world.blocks[0].position.x) -
                             (run.event.blocks[1].position.x - run.event.blocks[0].position.x);
        EXPECT_NEAR(apart, time ? 0.0 : 6.0, 1e-9) << pause; // 1 s at 4 - (-2) m/s
        if (time) continue;
        ASSERT_TRUE(run.hit) << pause;
        // Body 1 is the block the event names first (m2 for collision_of [m2, m1]).
        const bool m2First = step.pause.kind == LessonPause::Kind::PairCollision;
        EXPECT_EQ(run.hit->m1, m2First ? 2.0 : 1.0) << pause;
        EXPECT_NEAR(run.hit->v1After, m2First ? 4.0 : -2.0, 1e-12) << pause;
        EXPECT_NEAR(run.hit->u, 2.0, 1e-12) << pause;
    }
    const StepRun none = runStepToPause(onlyStep(lessonWith("")));
    EXPECT_EQ(none.progress.frames, 0);
    EXPECT_EQ(none.world.time, 0.0);
}

TEST(LessonRunner, APauseThatNeverComesIsReported) {
    // m2 has no collision within the runner's search: its first collision is m1's hit, so ask
    // for the 1,000th collision of a scene that has only a handful.
    const LessonStep step = onlyStep(lessonWith(R"("pause_at": {"collision": 1000000})"));
    const StepRun run = runStepToPause(step);
    EXPECT_FALSE(run.reached);
    const std::vector<std::string> failures = checkStep(step, run);
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_NE(failures[0].find("pause point was not reached"), std::string::npos) << failures[0];
    EXPECT_NE(failures[0].find("collisions in 120"), std::string::npos) << failures[0];
}

TEST(LessonRunner, AFailedExpectationNamesItsPlaceAndBothNumbers) {
    const LessonResult r =
        loadLessonFile(std::string(SANDBOX_TEST_DATA_DIR) + "/wrong_expectation.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const std::vector<std::string> failures = checkLesson(*r.lesson);
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_NE(failures[0].find("wrong_expectation.json: steps[1].expect[0]: vx of \"m1\" is -2"),
              std::string::npos)
        << failures[0];
    EXPECT_NE(failures[0].find("expected 6"), std::string::npos) << failures[0];
}

TEST(LessonRunner, RangesAndToleranceAreChecked) {
    const LessonStep step = onlyStep(lessonWith(
        R"("pause_at": {"collision": 1}, "expect": [{"block": "m1", "vx": {"min": -2.5, "max": -1.5}},
           {"block": "m2", "velocity": [4.1, null], "tolerance": 0.2}, {"momentum": [6, 0]},
           {"collisions": 1}, {"time": {"min": 0.625}}, {"kinetic_energy": 18}])"));
    EXPECT_EQ(step.expect.size(), 7u); // velocity [4.1, null] checks vx only; momentum is two
    EXPECT_TRUE(checkStep(step, runStepToPause(step)).empty());
    const LessonStep strict = onlyStep(lessonWith(
        R"("pause_at": {"collision": 1}, "expect": [{"block": "m2", "vx": 4.1, "tolerance": 0.05}])"));
    EXPECT_EQ(checkStep(strict, runStepToPause(strict)).size(), 1u);
}

TEST(Lesson, OverridesApplyAsSceneKeys) {
    const LessonStep step = onlyStep(lessonWith(
        R"("overrides": {"method": "turn-based", "bounciness": 0.5, "frame_rate": 30,
            "substeps": 2, "gravity": [0, -1], "time_scale": 0.25})"));
    EXPECT_EQ(step.scene->settings.method, Method::TurnBased);
    EXPECT_EQ(step.scene->settings.bounciness, 0.5);
    EXPECT_EQ(step.scene->settings.dt, 1.0 / 30.0);
    EXPECT_EQ(step.scene->settings.substeps, 2);
    EXPECT_EQ(step.scene->settings.gravity.y, -1.0);
    EXPECT_EQ(step.timeScale, 0.25);
    EXPECT_EQ(step.scene->blocks.size(), 2u);
    // They are edits of world keys, as a step's "edits" and the edit log write them (the app
    // prints each as the step's setup): "frame_rate" is the edit of dt, "time_scale" the step's.
    std::vector<std::string> keys;
    for (const Edit& e : step.overrides) {
        EXPECT_EQ(e.kind, Edit::Kind::SetWorld);
        keys.push_back(e.key);
    }
    EXPECT_EQ(keys,
              (std::vector<std::string>{"bounciness", "dt", "gravity", "method", "substeps"}));
}

// An override is checked by the edit door's rules, and named where the lesson writes it; a key
// that is neither a world key nor one of the step's own is refused with the keys it may be.
TEST(LessonErrors, OverridesAreCheckedAsEdits) {
    const auto errorWith = [](const std::string& fields) {
        const LessonResult r = parseLesson(lessonWith(fields), "t.json", context());
        EXPECT_FALSE(r.lesson) << fields;
        return r.error.text();
    };
    EXPECT_EQ(errorWith(R"("overrides": {"bounciness": 2})"),
              "t.json: steps[0].overrides.bounciness: must be from 0 to 1, not 2");
    const std::string unknown = errorWith(R"("overrides": {"rest_speed": 1})");
    EXPECT_NE(unknown.find("t.json: steps[0].overrides.rest_speed: unknown key \"rest_speed\" "
                           "(expected gravity, bounciness, method, dt,"),
              std::string::npos)
        << unknown;
    EXPECT_NE(unknown.find("friction, frame_rate, time_scale, bounds)"), std::string::npos)
        << unknown;
    // The bounds reshape the scene: its blocks must still fit, as in a scene file.
    EXPECT_NE(
        errorWith(R"("overrides": {"bounds": [0, 0, 5, 5]})").find("t.json: steps[0].overrides"),
        std::string::npos);
}

TEST(Lesson, ShippedScenePathsAndSelection) {
    const LessonStep step = onlyStep(
        R"({"name": "t", "steps": [{"title": "s", "caption": "one\ntwo\nthree",
            "scene": "single_bounce", "select": "ball", "camera": [0, 0, 10, 6],
            "overlays": ["plots", "poi"], "question": "q?", "answer": "a.",
            "choices": [{"text": "y", "if": "t >= 0", "correct": true}, {"text": "n", "if": "t < 0"}],
            "reveal": ["inspector"]}]})");
    EXPECT_EQ(fs::path(step.sceneSource).filename(), "single_bounce.json");
    EXPECT_EQ(step.selected, 0);
    ASSERT_TRUE(step.camera);
    EXPECT_EQ(step.camera->max.x, 10.0);
    EXPECT_EQ(step.overlays, (std::vector<std::string>{"plots", "poi"}));
    EXPECT_EQ(step.reveal, (std::vector<std::string>{"inspector"}));
    EXPECT_EQ(step.question, "q?");
}

// The moment may frame its evidence (issue 39): the step's camera at the setup, its
// "moment_camera" once the event came.
TEST(Lesson, AMomentCameraFramesTheMoment) {
    const LessonStep step = onlyStep(lessonWith(
        R"("camera": [0, 0, 10, 6], "moment_camera": [5, 0, 9, 3], "pause_at": {"time": 1})"));
    ASSERT_TRUE(step.camera && step.momentCamera);
    EXPECT_EQ(step.camera->max.x, 10.0);
    EXPECT_EQ(step.momentCamera->min.x, 5.0);
    EXPECT_EQ(step.momentCamera->max.y, 3.0);
    EXPECT_FALSE(onlyStep(lessonWith(R"("pause_at": {"time": 1})")).momentCamera);
}

TEST(Lesson, AStepCanTurnThrustOnForTheSelectedBlock) {
    const LessonStep step = onlyStep(lessonWith(R"("select": "m2", "thrust": 12.5)"));
    EXPECT_EQ(step.selected, 1);
    ASSERT_TRUE(step.thrust);
    EXPECT_EQ(*step.thrust, 12.5);
    EXPECT_FALSE(onlyStep(lessonWith(R"("select": "m2")")).thrust); // without it: off
    // A block without a mass cannot be pushed: the error says which and where.
    const LessonResult r = parseLesson(
        R"({"name": "t", "steps": [{"title": "s", "caption": "c", "scene": "platformer",
            "select": "lift", "thrust": 20}]})",
        "t.json", context());
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(r.error.text(), "t.json: steps[0].thrust: the selected block \"lift\" has no mass: "
                              "thrust pushes a dynamic block");
}

// A player on the floor of a frictionless world with g = 10 m/s^2 and dt = 1/20 s (frame times
// exact in binary up to rounding of 0.05).
std::string playerLesson(const std::string& stepFields) {
    return R"({"name": "t", "steps": [{"title": "s", "caption": "c", "scene": {"name": "p",
        "world": {"gravity": [0, -10], "dt": 0.05, "integrator": "exact", "bounciness": 0},
        "blocks": [{"name": "hero", "position": [2, 0.5], "size": 1, "mass": 1}],
        "player": {"block": "hero", "force": 10, "jump": 5}})" +
           (stepFields.empty() ? std::string() : ", " + stepFields) + "}]}";
}

TEST(Lesson, InputScriptsThePlayersKeysOverTime) {
    const LessonStep step = onlyStep(playerLesson(
        R"("input": [{"at": 0.5, "hold": ["right"], "for": 1.2}, {"at": 1.8, "press": "up"}])"));
    ASSERT_EQ(step.input.size(), 2u);
    EXPECT_EQ(step.input[0].at, 0.5);
    EXPECT_EQ(step.input[0].duration, 1.2);
    EXPECT_TRUE(step.input[0].keys.right && !step.input[0].keys.left && !step.input[0].keys.up);
    EXPECT_EQ(step.input[1].duration, 0.0);
    EXPECT_TRUE(step.input[1].keys.up);
    // Right in the frames starting at 0.5 .. 1.65 s (24 of them), up in the one starting at 1.8 s.
    int right = 0, up = 0;
    for (int frame = 0; frame < 60; ++frame) {
        const PlayerKeys keys = scriptedKeys(step.input, frame * 0.05, 0.05);
        right += keys.right;
        up += keys.up;
        if (keys.up) {
            EXPECT_EQ(frame, 36);
        }
        if (keys.right) {
            EXPECT_TRUE(frame >= 10 && frame < 34) << frame;
        }
    }
    EXPECT_EQ(right, 24);
    EXPECT_EQ(up, 1);
}

// The runner plays the script: 10 N on 1 kg for 1.2 s from 0.5 s moves the player 10/2·1.2² =
// 7.2 m and leaves it at 12 m/s (frictionless, exact integrator: to 1e-9, rounding only); the
// jump at 1.8 s leaves it 5·0.2 - 10/2·0.2² = 0.8 m up at 2 s.
TEST(Lesson, TheRunnerPlaysTheStepsInput) {
    const LessonStep step = onlyStep(playerLesson(
        R"("input": [{"at": 0.5, "hold": ["right"], "for": 1.2}, {"at": 1.8, "press": "up"}],
           "pause_at": {"time": 2})"));
    const StepRun run = runStepToPause(step);
    ASSERT_TRUE(run.reached);
    const Block& hero = run.world.blocks[0];
    EXPECT_NEAR(hero.position.x, 2.0 + 7.2 + 12.0 * 0.3, 1e-9);
    EXPECT_NEAR(hero.velocity.x, 12.0, 1e-9);
    EXPECT_NEAR(hero.position.y, 0.5 + 0.8, 1e-9);
    EXPECT_NEAR(hero.velocity.y, 5.0 - 10.0 * 0.2, 1e-9);
}

TEST(LessonErrors, InputErrorsNameTheirPlace) {
    struct Case {
        const char* fields;
        const char* where;
    } const cases[] = {
        {R"("input": {"at": 1, "press": "up"})", "steps[0].input"},
        {R"("input": [{"press": "up"}])", "steps[0].input[0]"},
        {R"("input": [{"at": -1, "press": "up"}])", "steps[0].input[0].at"},
        {R"("input": [{"at": 1, "press": "jump"}])", "steps[0].input[0].press"},
        {R"("input": [{"at": 1}])", "steps[0].input[0]"},
        {R"("input": [{"at": 1, "press": "up", "hold": ["left"], "for": 1}])", "steps[0].input[0]"},
        {R"("input": [{"at": 1, "press": "up", "for": 1}])", "steps[0].input[0].for"},
        {R"("input": [{"at": 1, "hold": ["left"]}])", "steps[0].input[0]"},
        {R"("input": [{"at": 1, "hold": [], "for": 1}])", "steps[0].input[0].hold"},
        {R"("input": [{"at": 1, "hold": ["left", 3], "for": 1}])", "steps[0].input[0].hold[1]"},
        {R"("input": [{"at": 1, "hold": ["left"], "for": 0}])", "steps[0].input[0].for"},
        {R"("input": [{"at": 1, "press": "up", "when": 2}])", "steps[0].input[0].when"},
    };
    for (const Case& c : cases) {
        const LessonResult r = parseLesson(playerLesson(c.fields), "t.json", context());
        ASSERT_FALSE(r.lesson) << c.fields;
        EXPECT_EQ(r.error.where, std::string("t.json: ") + c.where)
            << c.fields << " -> " << r.error.text();
    }
    // A scene without a player has no keys to script.
    const LessonResult r =
        parseLesson(lessonWith(R"("input": [{"at": 1, "press": "up"}])"), "t.json", context());
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(
        r.error.text(),
        "t.json: steps[0].input: needs a scene with a \"player\" (the block the keys control)");
}

TEST(Lesson, StepNumbersOutsideTheLessonAreErrors) {
    const LessonResult r =
        loadLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    std::string error;
    EXPECT_EQ(stepIndex(*r.lesson, 1, &error), std::optional<std::size_t>(0));
    const long long n = static_cast<long long>(r.lesson->steps.size());
    EXPECT_EQ(stepIndex(*r.lesson, n, &error), std::optional<std::size_t>(n - 1));
    for (long long bad : {0LL, -1LL, n + 1, 1LL << 40}) {
        EXPECT_FALSE(stepIndex(*r.lesson, bad, &error)) << bad;
        EXPECT_NE(error.find("lecture3.json: no step " + std::to_string(bad)), std::string::npos)
            << error;
    }
}

// ---- Malformed lessons: each error names its place ----

TEST(LessonErrors, UnknownOverlay) {
    EXPECT_TRUE(
        errorSays("unknown_overlay.json",
                  "unknown_overlay.json: steps[1].overlays[1]: unknown overlay \"sparkles\""));
}

TEST(LessonErrors, SceneThatFailsToLoad) {
    EXPECT_TRUE(errorSays("scene_fails.json",
                          "scene_fails.json: steps[0].scene: no scene \"no_such_scene\""));
    EXPECT_TRUE(errorSays("inline_scene_fails.json",
                          "inline_scene_fails.json: steps[1].scene.blocks[0].mass: "));
}

TEST(LessonErrors, BadExpectation) {
    EXPECT_TRUE(
        errorSays("bad_expectation.json",
                  "bad_expectation.json: steps[0].expect[1].block: no block named \"nobody\""));
}

TEST(LessonErrors, BadOverrideIsPlacedAtTheOverride) {
    EXPECT_TRUE(errorSays("bad_override.json",
                          "bad_override.json: steps[0].overrides.bounciness: must be from 0 to 1"));
}

TEST(LessonErrors, SyntaxErrorHasLineAndColumn) {
    const std::string e = errorOf("syntax.json");
    EXPECT_NE(e.find("syntax.json:4:29: "), std::string::npos) << e; // after the token
}

TEST(LessonErrors, ValuesNameTheirPath) {
    struct Case {
        std::string fields, where;
    };
    const Case cases[] = {
        {R"("pause_at": {"time": -1})", "steps[0].pause_at.time"},
        {R"("pause_at": {"collision": 1.5})", "steps[0].pause_at.collision"},
        {R"("pause_at": {"time": 1, "collision": 2})", "steps[0].pause_at"},
        {R"("pause_at": {"first_collision_of": "m3"})", "steps[0].pause_at.first_collision_of"},
        {R"("select": "m3")", "steps[0].select"},
        {R"("camera": [0, 0, -1, 5])", "steps[0].camera"},
        {R"("moment_camera": [0, 0, 5])", "steps[0].moment_camera"},
        {R"("moment_camera": [0, 0, 5, 5])", "steps[0].moment_camera"}, // no pause_at: no moment
        {R"("frame": "moving")", "steps[0].frame"},
        {R"("frame": 1)", "steps[0].frame"},
        {R"("overlays": "plots")", "steps[0].overlays"},
        {R"("question": "why?")", "steps[0]"},
        {R"("answer": "because")", "steps[0].answer"},
        {R"("expect": [{"block": "m1"}])", "steps[0].expect[0]"},
        {R"("expect": [{"vx": 1}])", "steps[0].expect[0]"},
        {R"("expect": [{"block": "m1", "speed": 1}])", "steps[0].expect[0].speed"},
        {R"("expect": [{"block": "m1", "velocity": [1]}])", "steps[0].expect[0].velocity"},
        {R"("expect": [{"block": "m1", "vx": {"min": 2, "max": 1}}])", "steps[0].expect[0].vx"},
        {R"("expect": [{"block": "m1", "vx": "fast"}])", "steps[0].expect[0].vx"},
        {R"("overrides": {"frame_rate": 0})", "steps[0].overrides.frame_rate"},
        {R"("overrides": {"method": "quick"})", "steps[0].overrides.method"},
        {R"("overrides": {"colour": 1})", "steps[0].overrides.colour"},
        {R"("overrides": {"bounds": [0, 0, 5, 5]})", "steps[0].overrides"},
        {R"("overrides": {"time_scale": 1000})", "steps[0].overrides.time_scale"},
        {R"("sparkle": true)", "steps[0].sparkle"},
        {R"("thrust": 5)", "steps[0].thrust"}, // no "select": no block to push
        {R"("select": "m1", "thrust": 0)", "steps[0].thrust"},
        {R"("select": "m1", "thrust": "strong")", "steps[0].thrust"},
    };
    for (const Case& c : cases) {
        const LessonResult r = parseLesson(lessonWith(c.fields), "t.json", context());
        ASSERT_FALSE(r.lesson) << c.fields;
        EXPECT_EQ(r.error.where, "t.json: " + c.where) << c.fields << " -> " << r.error.text();
    }
    const std::pair<std::string, std::string> top[] = {
        {R"({"name": "t"})", "t.json: (top level)"},
        {R"({"name": "t", "steps": []})", "t.json: steps"},
        {R"({"name": "t", "steps": [{"caption": "c", "scene": "single_bounce"}]})",
         "t.json: steps[0]"},
        {R"({"name": "t", "steps": [{"title": "a\nb", "caption": "c", "scene": "single_bounce"}]})",
         "t.json: steps[0].title"},
        {R"({"name": "t", "steps": [{"title": "a", "caption": "1\n2\n3\n4", "scene": "x"}]})",
         "t.json: steps[0].caption"},
        {R"({"name": "t", "steps": [{"title": "a", "caption": "c\u0007", "scene": "x"}]})",
         "t.json: steps[0].caption"},
        {R"({"name": "t", "steps": [{"title": "a", "caption": "c", "scene": 5}]})",
         "t.json: steps[0].scene"},
    };
    for (const auto& [text, where] : top) {
        const LessonResult r = parseLesson(text, "t.json", context());
        ASSERT_FALSE(r.lesson) << text;
        EXPECT_EQ(r.error.where, where) << text << " -> " << r.error.text();
    }
}

TEST(LessonErrors, EchoedNamesAreEscaped) {
    const LessonResult r =
        parseLesson(lessonWith(R"("select": "\u001b[31mred")"), "t.json", context());
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(r.error.text().find('\x1b'), std::string::npos) << r.error.text();
}

TEST(Lesson, LessonsAreToldApartFromScenesByTheirSteps) {
    EXPECT_TRUE(isLessonText(R"({"name": "x", "steps": []})"));
    EXPECT_FALSE(isLessonText(kExample));
    EXPECT_FALSE(isLessonText("{\"steps\": "));
    EXPECT_FALSE(isLessonText(std::string(100000, '[')));
    EXPECT_FALSE(isLessonText(R"({"name": "s", "world": {"steps": 1}, "blocks": []})"));
    EXPECT_FALSE(isLessonText(std::string("{\"steps\": []}\0", 14))); // a NUL byte
    EXPECT_FALSE(isLessonText(""));
    EXPECT_TRUE(isLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json"));
    EXPECT_FALSE(isLessonFile(std::string(SANDBOX_SCENES_DIR) + "/single_bounce.json"));
}

// A step's "edits" (docs/edits.md) apply at their frames in the runner as in a log: m2 made
// 4 kg at frame 0 (the setup shows it) and C set to 0 at frame 10, before the collision.
TEST(LessonEdits, AStepsEditsApplyAtTheirFrames) {
    const LessonStep step = onlyStep(lessonWith(
        R"("pause_at": {"collision": 1}, "edits": [{"frame": 0, "set": "m2.mass", "value": 4},
             {"frame": 10, "set": "bounciness", "value": 0}])"));
    ASSERT_EQ(step.edits.lines.size(), 2u);
    EXPECT_EQ(stepStartWorld(step).blocks[1].mass, 4.0);
    const StepRun run = runStepToPause(step);
    ASSERT_TRUE(run.reached);
    EXPECT_TRUE(run.editError.empty()) << run.editError;
    // Perfectly inelastic: both at u = (1·6 + 4·0) / 5 = 1.2 m/s (to rounding in the formula).
    EXPECT_NEAR(run.event.blocks[0].velocity.x, 1.2, 1e-12);
    EXPECT_NEAR(run.event.blocks[1].velocity.x, 1.2, 1e-12);
    // Run from the setup as the window runs it (runStepFrom): the frame-10 edit plays there too,
    // and the frame-0 one is not played twice.
    const StepRun live = runStepFrom(step, stepStartWorld(step), {"m1", "m2"}, 120.0, 1.0);
    ASSERT_TRUE(live.reached);
    EXPECT_EQ(live.event.frame, run.event.frame);
    EXPECT_EQ(live.event.blocks[1].velocity.x, run.event.blocks[1].velocity.x);
    // A refused edit is the step's failure, with its place and key.
    const LessonStep bad = onlyStep(lessonWith(
        R"("pause_at": {"collision": 1}, "edits": [{"frame": 3, "set": "m3.mass", "value": 2}])"));
    const std::vector<std::string> failures = checkStep(bad, runStepToPause(bad));
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0], "test.json: steps[0].edits[0]: m3.mass: no block is named \"m3\"");
    // A malformed one is refused when the lesson is read.
    const LessonResult r =
        parseLesson(lessonWith(R"("edits": [{"frame": 3, "set": "bouncyness", "value": 2}])"),
                    "t.json", context());
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(r.error.text().rfind("t.json: steps[0].edits[0].bouncyness: no such world key", 0),
              0u)
        << r.error.text();
}
