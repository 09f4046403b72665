// What a screen reader is told: the collision in the inspector's words, the live region's pace,
// and the screen's texts as sentences.
#include "app.h"
#include "collision_announcer.h"
#include "input_map.h"
#include "lesson_session.h"
#include "spoken_text.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace {

// lecture_example_1 up to its one collision (t = 0.625 s, the 38th frame).
App playedThroughTheCollision() {
    App app;
    EXPECT_TRUE(loadScene(app, SANDBOX_SCENES_DIR "/lecture_example_1.json"))
        << app.ui.messages.error;
    for (int i = 0; i < 40 && app.sim.run.totals.collisions == 0; ++i) stepSimulation(app);
    return app;
}

TEST(SpokenText, ACollisionInTheInspectorsWords) {
    App app = playedThroughTheCollision();
    ASSERT_EQ(app.sim.run.lastLog.size(), 1u);
    const CollisionRecord& r = app.sim.run.lastLog[0];
    EXPECT_EQ(
        collisionSentence(r, app.sim.blockDisplayName(r.block), app.sim.blockDisplayName(r.other)),
        "m1 hits m2 along x at t = 0.625 s: v1' = -2 m/s, v2' = 4 m/s");
    CollisionRecord wall = r;
    wall.other = kWallLeft;
    EXPECT_EQ(collisionSentence(wall, "ball", ""),
              "ball hits the left wall along x at t = 0.625 s: v1' = -2 m/s");
}

TEST(SpokenText, AtMostOneAnnouncementASecondAndABusySceneSummedUp) {
    App app = playedThroughTheCollision();
    const auto name = [&app](int i) { return app.sim.blockDisplayName(i); };
    // The app noted its collision as it stepped.
    EXPECT_EQ(app.sim.announcer.announce(10.0, name),
              "m1 hits m2 along x at t = 0.625 s: v1' = -2 m/s, v2' = 4 m/s");
    EXPECT_EQ(app.sim.announcer.announce(10.5, name), ""); // nothing new
    CollisionAnnouncer a;
    CollisionRecord r = app.sim.run.lastLog[0];
    a.note({r});
    EXPECT_NE(a.announce(0.0, name), "");
    r.time += 0.1;
    a.note({r});
    EXPECT_EQ(a.announce(0.5, name), ""); // within the second: waits
    EXPECT_NE(a.announce(1.0, name).find("hits"), std::string::npos);
    // 40 collisions 0.03 s apart, 2.0 .. 3.17 s: 34 of them within the last simulated second
    // (2.18 .. 3.17 s; 2.15 s is 1.02 s before the last).
    std::vector<CollisionRecord> busy;
    for (int i = 0; i < 40; ++i) {
        r.time = 2.0 + i * 0.03;
        busy.push_back(r);
    }
    a.note(busy);
    EXPECT_EQ(a.announce(2.0, name), "34 collisions in the last second");
    // Time going back (a reset) forgets what was noted.
    r.time = 0.1;
    a.note({r});
    EXPECT_NE(a.announce(3.0, name).find("hits"), std::string::npos);
}

TEST(SpokenText, TheScreenAsSentences) {
    App app;
    ASSERT_TRUE(loadScene(app, SANDBOX_SCENES_DIR "/lecture_example_1.json"))
        << app.ui.messages.error;
    SpokenScreen s = spokenScreen(app);
    EXPECT_EQ(s.scene, "Lecture example 1");
    EXPECT_EQ(s.description, app.sim.scene.description);
    EXPECT_EQ(s.status, "perfect method, t = 0 s, paused, 0 collisions");
    EXPECT_EQ(s.lesson, "");
    app = playedThroughTheCollision();
    app.sim.paused = false;
    EXPECT_EQ(spokenScreen(app).status, "perfect method, t = 0.633 s, running, 1 collision");
}

// Issue 38: a screen reader hears each step entered (its title and question with the choices),
// the answer at the moment, and every error, once each (spokenChanges; the browser page's live
// region says these lines: tests/web/browser_test.py).
TEST(SpokenText, StepsAnswersAndErrorsAreAnnouncedOnce) {
    App app;
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    ASSERT_TRUE(openLesson(app, std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", 2))
        << app.ui.messages.error;
    SpokenScreen before;
    SpokenScreen now = spokenScreen(app);
    std::vector<std::string> said = spokenChanges(before, now);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said[0].rfind("Lesson: Lecture 3: Newton's laws & collisions, step 3 of 27: "
                            "Bounciness C and kinetic energy. Predict: 1 kg at 4 m/s (8 J) hits "
                            "the right wall with C = 0.5. Its velocity after, and its kinetic "
                            "energy? A. -2 m/s and 2 J. B.",
                            0),
              0u)
        << said[0];
    EXPECT_TRUE(spokenChanges(now, spokenScreen(app)).empty()); // nothing new: nothing said
    before = now;
    lessonShowPausePoint(app);
    now = spokenScreen(app);
    said = spokenChanges(before, now);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said[0].rfind("Answer: A. v' = -C·v = -0.5·4 = -2 m/s", 0), 0u) << said[0];
    before = now;
    lessonTypeDigit(app.lesson, 9);
    lessonTypeDigit(app.lesson, 9);
    applyLessonAction(app, Action::LessonJump);
    now = spokenScreen(app);
    said = spokenChanges(before, now);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_NE(said[0].find("Error: "), std::string::npos) << said[0];
    EXPECT_NE(said[0].find("no step 99 (the lesson has steps 1 to 27)"), std::string::npos)
        << said[0];
}

// A change the lecturer makes mid-demo that changes the step's question is said as the change
// and the question as it now reads (the browser's live region says it); a change that reads
// nothing otherwise is not said; undone, the question as written is said again.
TEST(SpokenText, AChangeThatRewordsTheQuestionIsSaid) {
    App app;
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    ASSERT_TRUE(openLesson(app, std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", 2))
        << app.ui.messages.error;
    SpokenScreen before = spokenScreen(app);
    ASSERT_TRUE(app.sim.apply(Edit::setWorld("bounciness", 0.9)).empty());
    SpokenScreen now = spokenScreen(app);
    std::vector<std::string> said = spokenChanges(before, now);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said[0].rfind("bounciness C is now 0.90; the question now reads: Predict: ", 0), 0u)
        << said[0];
    EXPECT_NE(said[0].find("C = 0.9"), std::string::npos) << said[0];
    before = now;
    ASSERT_TRUE(app.sim.apply(Edit::setWorld("bounciness", 0.9)).empty()); // the same C again
    now = spokenScreen(app);
    EXPECT_TRUE(spokenChanges(before, now).empty());
    before = now;
    ASSERT_TRUE(app.sim.undo());
    ASSERT_TRUE(app.sim.undo());
    now = spokenScreen(app);
    said = spokenChanges(before, now);
    ASSERT_EQ(said.size(), 1u);
    EXPECT_EQ(said[0].rfind("bounciness C is now 0.50; the question now reads: Predict: 1 kg at "
                            "4 m/s (8 J) hits the right wall with C = 0.5.",
                            0),
              0u)
        << said[0];
}

} // namespace
