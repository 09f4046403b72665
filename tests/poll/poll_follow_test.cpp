// The poll in the app follows the lesson (app/gui/app/class_poll.h): when the lecturer changes
// the setup while the vote is open, the phones are asked the question as the world now reads
// it and the votes for the old wording are dropped. Served on 127.0.0.1 only.
#include "app.h"
#include "class_poll.h"
#include "lesson_prompt.h"
#include "lesson_session.h"
#include "poll_session.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <string>

namespace {

const std::string kLecture3 = std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json";

} // namespace

TEST(PollFollowsTheLesson, ASetupChangedWhileTheVoteIsOpenIsAskedAgain) {
    App app;
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    ASSERT_TRUE(openLesson(app, kLecture3, 2)) << app.ui.messages.error; // step 3: C = 0.5
    ClassPoll poll;
    ASSERT_TRUE(startPoll(poll, app.lesson, app.sim, "127.0.0.1")) << poll.error;
    const PollSnapshot asked = poll.session->snapshot();
    ASSERT_TRUE(asked.open);
    poll.session->castVote("phone-0001", 0);
    poll.session->castVote("phone-0002", 1);
    followLesson(poll, app.lesson, app.sim); // nothing changed: the votes stand
    EXPECT_EQ(poll.session->snapshot().current.voters, 2);
    EXPECT_EQ(poll.session->snapshot().current.question, asked.current.question);

    ASSERT_TRUE(app.sim.apply(Edit::setWorld("bounciness", 0.9)).empty());
    followLesson(poll, app.lesson, app.sim);
    const PollSnapshot changed = poll.session->snapshot();
    EXPECT_TRUE(changed.open);
    EXPECT_NE(changed.current.question, asked.current.question);
    EXPECT_EQ(changed.current.question, lessonPrompt(app.lesson, app.sim).question);
    EXPECT_NE(changed.current.question.find("0.9"), std::string::npos) << changed.current.question;
    EXPECT_EQ(changed.current.voters, 0);
    EXPECT_EQ(changed.current.round, 1);
    EXPECT_TRUE(changed.rounds.empty()); // the old wording's votes are not a round of this one

    // Undone, the step reads as written again, and is asked so.
    poll.session->castVote("phone-0001", 1);
    ASSERT_TRUE(app.sim.undo());
    followLesson(poll, app.lesson, app.sim);
    EXPECT_EQ(poll.session->snapshot().current.question, asked.current.question);
    EXPECT_EQ(poll.session->snapshot().current.voters, 0);

    // Once the step plays, the vote is closed: a change then does not reword the closed round.
    poll.session->castVote("phone-0003", 2);
    poll.session->close();
    ASSERT_TRUE(app.sim.apply(Edit::setWorld("bounciness", 0.25)).empty());
    followLesson(poll, app.lesson, app.sim);
    EXPECT_EQ(poll.session->snapshot().rounds.back().question, asked.current.question);
    EXPECT_EQ(poll.session->snapshot().rounds.back().voters, 1);
    stopPoll(poll);
}
