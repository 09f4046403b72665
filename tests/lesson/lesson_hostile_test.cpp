// Lessons are input like scenes (issue 28). Cases by class, not by example:
//   paths:    every way a step's "scene" string may name what it must not (absolute, outside the
//             folder by ".." or by a link, a directory, a FIFO, a device, the lesson itself);
//   echoes:   every name from the file reaches a message escaped and cut;
//   bounds:   a valid pause is reached whatever its frame rate and time; one beyond the step's
//             budget is refused at its place; one that never comes ends within the budget, at
//             its place; a scene named by many steps is held once; the blocks of all scenes are
//             capped;
//   steps:    only the lesson's step numbers are steps.
#include "lesson.h"
#include "lesson_runner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const char* const kBall = R"({"name": "b", "world": {"bounds": [0, 0, 20, 12], "gravity": [0, 0]},
  "blocks": [{"name": "ball", "position": [10, 6], "size": 1, "velocity": [0, 0], "mass": 1}]})";

LessonContext context() {
    LessonContext c;
    c.scenesDir = SANDBOX_SCENES_DIR;
    return c;
}

std::string lessonOn(const std::string& scene, const std::string& more = "") {
    return R"({"name": "t", "steps": [{"title": "s", "caption": "c", "scene": )" + scene +
           (more.empty() ? "" : ", " + more) + "}]}";
}

// A lesson folder with a scene in it and one outside it.
struct LessonFolder {
    fs::path root, dir;
    LessonFolder() {
        root = fs::temp_directory_path() / ("lesson_hostile_" + std::to_string(getpid()));
        dir = root / "lesson";
        fs::remove_all(root);
        fs::create_directories(dir / "scenes");
        std::ofstream(dir / "scenes" / "ball.json") << kBall;
        std::ofstream(root / "outside.json") << kBall;
    }
    ~LessonFolder() { fs::remove_all(root); }
    // Writes lesson.json naming `scene` and loads it.
    LessonResult load(const std::string& scene) const {
        const fs::path file = dir / "lesson.json";
        std::ofstream(file) << lessonOn("\"" + scene + "\"");
        return loadLessonFile(file.string(), context());
    }
};

void expectRefused(const LessonResult& r, const std::string& why) {
    ASSERT_FALSE(r.lesson);
    EXPECT_NE(r.error.text().find("lesson.json: steps[0].scene"), std::string::npos)
        << r.error.text();
    EXPECT_NE(r.error.text().find(why), std::string::npos) << r.error.text();
}

} // namespace

TEST(LessonHostile, ScenePathsStayInTheLessonsFolder) {
    LessonFolder f;
    ASSERT_TRUE(f.load("scenes/ball.json").lesson) << f.load("scenes/ball.json").error.text();
    ASSERT_TRUE(f.load("./scenes/../scenes/ball.json").lesson); // inside after ".."
    expectRefused(f.load((f.root / "outside.json").string()), "is an absolute path");
    expectRefused(f.load("../outside.json"), "is outside the lesson's folder");
    expectRefused(f.load("scenes/../../outside.json"), "is outside the lesson's folder");
    expectRefused(f.load("../nothing_there.json"), "is outside the lesson's folder");
    fs::create_symlink(f.root / "outside.json", f.dir / "link.json");
    expectRefused(f.load("link.json"), "is outside the lesson's folder");
}

TEST(LessonHostile, ScenePathsThatAreNotSceneFiles) {
    LessonFolder f;
    expectRefused(f.load("scenes"), "is not a regular file");
    ASSERT_EQ(mkfifo((f.dir / "pipe.json").c_str(), 0600), 0);
    expectRefused(f.load("pipe.json"), "is not a regular file"); // and it does not block
    fs::create_symlink("/dev/zero", f.dir / "zero.json");        // a device, by a link
    expectRefused(f.load("zero.json"), "is outside the lesson's folder");
    expectRefused(f.load("lesson.json"), "is the lesson file itself");
    expectRefused(f.load("missing.json"), "no scene \"missing.json\"");
}

TEST(LessonHostile, NamesInMessagesAreEscapedAndCut) {
    // A block name with an OSC title sequence and a bell; a 10 MB name; a scene name with C1 and
    // bidirectional controls. No raw control byte and no message beyond a few KB.
    const std::string tenMegabytes(10 << 20, 'A');
    const std::string cases[] = {
        lessonOn(kBall, R"("select": "\u001b]0;owned\u0007")"),
        lessonOn(kBall, "\"select\": \"" + tenMegabytes + "\""),
        lessonOn(kBall, R"("pause_at": {"first_collision_of": "\u009b31m\u202eevil"})"),
        lessonOn("\"\\u001b[2Jmissing\""),
        lessonOn(kBall, R"("expect": [{"block": "\u001bc", "vx": 0}])"),
    };
    for (const std::string& text : cases) {
        const LessonResult r = parseLesson(text, "t\x1b]0;x\x07.json", context());
        ASSERT_FALSE(r.lesson);
        const std::string message = r.error.text();
        EXPECT_LT(message.size(), 2000u);
        for (const char c : message) {
            const auto byte = static_cast<unsigned char>(c);
            EXPECT_FALSE(byte < 0x20 || byte == 0x7f) << message;
        }
        EXPECT_EQ(message.find("\xc2\x9b"), std::string::npos) << message;     // C1 CSI
        EXPECT_EQ(message.find("\xe2\x80\xae"), std::string::npos) << message; // RLO
        EXPECT_NE(message.find("t\\x1b]0;x\\x07.json: steps[0]"), std::string::npos) << message;
    }
}

TEST(LessonHostile, LargestRateAndTimeAreNotCapped) {
    // 600 s at 10000 frames per second (both maxima): 6,000,002 frames are allowed (the old
    // undocumented cap was 200,000); run at 60 s here to keep ctest small: 600,002 frames.
    for (const double time : {600.0, 60.0}) {
        const LessonResult r = parseLesson(
            lessonOn(kBall, R"("overrides": {"frame_rate": 10000}, "pause_at": {"time": )" +
                                std::to_string(time) + "}"),
            "t.json", context());
        ASSERT_TRUE(r.lesson) << r.error.text();
        const LessonStep& step = r.lesson->steps[0];
        EXPECT_GE(static_cast<double>(maxStepFrames(step)), pauseFrames(step));
        if (time > 100) continue;
        const StepRun run = runStepToPause(step);
        EXPECT_TRUE(run.reached);
        EXPECT_TRUE(checkStep(step, run).empty());
        // 60 s within the frame's rounding: frame times are sums of dt = 1e-4.
        EXPECT_NEAR(run.world.time, 60.0, 1e-4 + 1e-9);
    }
}

TEST(LessonHostile, TimePauseBeyondTheBudgetIsRefusedAtItsPlace) {
    // 20 blocks x 6,000,002 frames x 1 substep > 1e8 block-steps.
    std::string blocks;
    for (int i = 0; i < 20; ++i)
        blocks += (i ? "," : "") + std::string(R"({"position": [)") + std::to_string(1 + i * 0.9) +
                  R"(, 6], "size": 0.5, "velocity": [0, 0], "mass": 1})";
    const std::string scene =
        R"({"name": "row", "world": {"bounds": [0, 0, 20, 12]}, "blocks": [)" + blocks + "]}";
    const LessonResult r = parseLesson(
        lessonOn(scene, R"("overrides": {"frame_rate": 10000}, "pause_at": {"time": 600})"),
        "t.json", context());
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(r.error.where, "t.json: steps[0].pause_at.time") << r.error.text();
    EXPECT_NE(r.error.message.find("1e8 block-steps"), std::string::npos) << r.error.text();
}

TEST(LessonHostile, PauseThatNeverComesEndsWithItsPlace) {
    // A ball at rest without gravity never collides: the search ends after 120 s (the frame
    // ending at 120 s, the 120,000th at 1000 Hz) with the step's place in the failure.
    const LessonResult r = parseLesson(lessonOn(kBall, R"("overrides": {"frame_rate": 1000},
                                      "pause_at": {"collision": 1})"),
                                       "t.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    const StepRun run = runStepToPause(r.lesson->steps[0]);
    EXPECT_FALSE(run.reached);
    EXPECT_EQ(run.progress.frames, 120000);
    const std::vector<std::string> failures = checkStep(r.lesson->steps[0], run);
    ASSERT_EQ(failures.size(), 1u);
    EXPECT_EQ(failures[0].rfind("t.json: steps[0].pause_at: the pause point was not reached", 0),
              0u)
        << failures[0];
}

TEST(LessonHostile, ManyBlocksSearchWithinTheBudget) {
    // 10,000 blocks: the collision search stops at 1e8 / 10,000 = 10,000 frames, not 120,002.
    std::string blocks;
    for (int i = 0; i < 10000; ++i)
        blocks += (i ? "," : "") + std::string(R"({"position": [)") +
                  std::to_string(0.5 + (i % 100) * 1.0) + ", " + std::to_string(0.5 + (i / 100)) +
                  R"(], "size": 0.5, "velocity": [0, 0], "mass": 1})";
    const std::string scene = R"({"name": "grid", "world": {"bounds": [0, 0, 100, 100],
        "gravity": [0, 0]}, "blocks": [)" +
                              blocks + "]}";
    const LessonResult r = parseLesson(lessonOn(scene, R"("overrides": {"frame_rate": 1000},
                                       "pause_at": {"collision": 1})"),
                                       "t.json", context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    EXPECT_EQ(maxStepFrames(r.lesson->steps[0]), 10000);
}

TEST(LessonHostile, SceneNamedByManyStepsIsHeldOnce) {
    LessonFolder f;
    std::string steps;
    for (int i = 0; i < 1000; ++i) // the documented maximum of steps
        steps += std::string(i ? "," : "") +
                 R"({"title": "s", "caption": "c", "scene": "scenes/ball.json"})";
    std::ofstream(f.dir / "many.json") << R"({"name": "t", "steps": [)" + steps + "]}";
    const LessonResult r = loadLessonFile((f.dir / "many.json").string(), context());
    ASSERT_TRUE(r.lesson) << r.error.text();
    ASSERT_EQ(r.lesson->steps.size(), 1000u);
    for (const LessonStep& step : r.lesson->steps)
        EXPECT_EQ(step.scene.get(), r.lesson->steps[0].scene.get());
}

TEST(LessonHostile, BlocksOfAllScenesAreCapped) {
    // Two inline scenes of one block each against a cap of 1 (the real cap is 2,000,000).
    LessonContext c = context();
    c.maxBlocks = 1;
    const std::string step =
        R"({"title": "s", "caption": "c", "scene": )" + std::string(kBall) + "}";
    const LessonResult r =
        parseLesson(R"({"name": "t", "steps": [)" + step + "," + step + "]}", "t.json", c);
    ASSERT_FALSE(r.lesson);
    EXPECT_EQ(r.error.where, "t.json: steps[1].scene") << r.error.text();
    EXPECT_NE(r.error.message.find("more than 1 blocks in all"), std::string::npos);
}

TEST(LessonHostile, OnlyTheLessonsStepNumbers) {
    const LessonResult r = parseLesson(lessonOn(kBall), "t.json", context());
    ASSERT_TRUE(r.lesson);
    EXPECT_TRUE(stepIndex(*r.lesson, 1, nullptr));
    for (const long long n : {0LL, -1LL, 2LL, 1000001LL, -9223372036854775807LL - 1}) {
        std::string error;
        EXPECT_FALSE(stepIndex(*r.lesson, n, &error)) << n;
        EXPECT_NE(error.find("(the lesson has steps 1 to 1)"), std::string::npos) << error;
    }
}
