// The poll's vote and protocol without a network: every request as plain fields through
// PollProtocol::handle, a clock the test moves. What the real server adds (sizes, times,
// connections) is tested through sockets by poll_cli_test.py.
#include "lesson_poll_questions.h"
#include "poll_protocol.h"
#include "poll_qr.h"
#include "poll_session.h"
#include "poll_state.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

const std::string kAuthority = "127.0.0.1:5000";
const std::string kToken = "abcdefgh2345";

PollQuestion threeChoices() {
    return {2, "What does m1 do?", {"Stops", "Moves back", "Keeps going"}, 1};
}

struct PollProtocolTest : ::testing::Test {
    PollState state;
    double now = 100.0;
    PollProtocol protocol{state, kAuthority, kToken, [this] { return now; }};

    PollRequest get(const std::string& path) {
        PollRequest r;
        r.method = "GET";
        r.target = path;
        r.host = kAuthority;
        return r;
    }
    PollRequest post(const std::string& body, const std::string& path = "/" + kToken + "/vote") {
        PollRequest r;
        r.method = "POST";
        r.target = path;
        r.host = kAuthority;
        r.origin = "http://" + kAuthority;
        r.fetchSite = "same-origin";
        r.contentType = "application/json";
        r.body = body;
        return r;
    }
    int vote(const std::string& device, int choice) {
        return protocol
            .handle(post("{\"device\": \"" + device + "\", \"choice\": " + std::to_string(choice) +
                         "}"))
            .status;
    }
    std::vector<int> counts() { return state.snapshot().current.counts; }
};

TEST_F(PollProtocolTest, OneVotePerDeviceTheLastCounts) {
    state.open(threeChoices());
    EXPECT_EQ(vote("phone-0001", 0), 204);
    EXPECT_EQ(vote("phone-0002", 0), 204);
    EXPECT_EQ(vote("phone-0002", 2), 204); // changed
    EXPECT_EQ(vote("phone-0003", 1), 204);
    EXPECT_EQ(vote("phone-0003", 1), 204); // twice the same
    EXPECT_EQ(counts(), (std::vector<int>{1, 1, 1}));
    EXPECT_EQ(state.snapshot().current.voters, 3);
    const std::optional<PollRound> closed = state.close();
    ASSERT_TRUE(closed);
    EXPECT_EQ(closed->counts, (std::vector<int>{1, 1, 1}));
    EXPECT_EQ(closed->proved, 1);
    EXPECT_EQ(vote("phone-0004", 0), 409); // after close: not counted
    EXPECT_EQ(state.results().back().counts, (std::vector<int>{1, 1, 1}));
}

TEST_F(PollProtocolTest, VoteAgainIsASecondRoundKeptBesideTheFirst) {
    state.open(threeChoices());
    vote("phone-0001", 0);
    vote("phone-0002", 0);
    state.close();
    ASSERT_TRUE(state.revote());
    EXPECT_FALSE(state.revote()); // already open
    vote("phone-0001", 1);
    const PollRound second = *state.close();
    EXPECT_EQ(second.round, 2);
    EXPECT_EQ(second.counts, (std::vector<int>{0, 1, 0}));
    const PollSnapshot s = state.snapshot();
    ASSERT_EQ(s.rounds.size(), 2u);
    EXPECT_EQ(s.rounds[0].counts, (std::vector<int>{2, 0, 0}));
    EXPECT_EQ(s.rounds[1].counts, (std::vector<int>{0, 1, 0}));
    // Another step: its own rounds only.
    state.open({3, "Q", {"x", "y"}, 0});
    EXPECT_TRUE(state.snapshot().rounds.empty());
}

TEST_F(PollProtocolTest, StateSaysTheQuestionAndThisDevicesVote) {
    state.open(threeChoices());
    vote("phone-0001", 2);
    const auto j =
        nlohmann::json::parse(protocol.handle(get("/" + kToken + "/state?device=phone-0001")).body);
    EXPECT_EQ(j["step"], 2);
    EXPECT_EQ(j["round"], 1);
    EXPECT_EQ(j["open"], true);
    EXPECT_EQ(j["question"], "What does m1 do?");
    EXPECT_EQ(j["choices"].size(), 3u);
    EXPECT_EQ(j["mine"], 2);
    const auto other =
        nlohmann::json::parse(protocol.handle(get("/" + kToken + "/state?device=phone-0002")).body);
    EXPECT_TRUE(other["mine"].is_null());
    EXPECT_EQ(state.snapshot().joined, 2);
}

// The lecturer changed the setup while the vote is open: the phones read the new wording, the
// votes for the old one are dropped, and a phone that had voted is told to vote again until it
// does; the same wording changes nothing.
TEST_F(PollProtocolTest, ASetupChangedWhileTheVoteIsOpenAsksAgain) {
    state.open(threeChoices());
    vote("phone-0001", 2);
    vote("phone-0002", 0);
    EXPECT_FALSE(state.reword(threeChoices()));
    EXPECT_EQ(state.snapshot().current.voters, 2);
    PollQuestion changed = threeChoices();
    changed.question = "With C = 0.5: what does m1 do?";
    EXPECT_TRUE(state.reword(changed));
    const auto stateOf = [&](const std::string& device) {
        return nlohmann::json::parse(
            protocol.handle(get("/" + kToken + "/state?device=" + device)).body);
    };
    const auto j = stateOf("phone-0001");
    EXPECT_EQ(j["question"], "With C = 0.5: what does m1 do?");
    EXPECT_EQ(j["round"], 1);
    EXPECT_TRUE(j["mine"].is_null());
    EXPECT_EQ(j["changed"], true);
    EXPECT_EQ(stateOf("phone-0003")["changed"], false); // it had not voted
    EXPECT_EQ(counts(), (std::vector<int>{0, 0, 0}));
    EXPECT_EQ(vote("phone-0001", 1), 204);
    EXPECT_EQ(stateOf("phone-0001")["changed"], false);
    EXPECT_EQ(stateOf("phone-0002")["changed"], true);
    EXPECT_EQ(counts(), (std::vector<int>{0, 1, 0}));
    // Closed, the question is what it was when it closed: no reword.
    state.close();
    changed.question = "With C = 0.25: what does m1 do?";
    EXPECT_FALSE(state.reword(changed));
    EXPECT_EQ(state.results().back().question, "With C = 0.5: what does m1 do?");
    EXPECT_EQ(stateOf("phone-0002")["changed"], false);
}

TEST_F(PollProtocolTest, ThePageCarriesTheTokenAndNoLessonText) {
    state.open({2, "<script>alert(1)</script>", {"<b>x</b>", "y"}, 0});
    const PollResponse page = protocol.handle(get("/" + kToken + "/"));
    EXPECT_EQ(page.status, 200);
    EXPECT_NE(page.body.find("/" + kToken + "/poll.js"), std::string::npos);
    EXPECT_EQ(page.body.find("alert"), std::string::npos); // the question comes as JSON only
    EXPECT_EQ(protocol.handle(get("/" + kToken)).status, 200);
    EXPECT_EQ(protocol.handle(get("/" + kToken + "/poll.js")).status, 200);
    EXPECT_EQ(protocol.handle(get("/" + kToken + "/poll.css")).status, 200);
    EXPECT_EQ(protocol.handle(get("/" + kToken + "/nothing")).status, 404);
}

TEST_F(PollProtocolTest, RefusalsChangeNoCount) {
    state.open(threeChoices());
    vote("phone-0001", 0);
    const std::vector<int> before = counts();
    // Token: wrong, missing, a prefix, longer.
    EXPECT_EQ(protocol.handle(get("/wrongtoken12/state")).status, 403);
    EXPECT_EQ(protocol.handle(get("/")).status, 403);
    EXPECT_EQ(protocol.handle(get("/state")).status, 403);
    EXPECT_EQ(protocol.handle(get("/" + kToken.substr(0, 11) + "/state")).status, 403);
    EXPECT_EQ(
        protocol.handle(post("{\"device\":\"phone-0009\",\"choice\":1}", "/" + kToken + "x/vote"))
            .status,
        403);
    // Host: foreign, missing, the port changed.
    PollRequest foreign = post("{\"device\":\"phone-0009\",\"choice\":1}");
    foreign.host = "evil.example:5000";
    EXPECT_EQ(protocol.handle(foreign).status, 421);
    foreign.host = "";
    EXPECT_EQ(protocol.handle(foreign).status, 421);
    foreign.host = "127.0.0.1:5001";
    EXPECT_EQ(protocol.handle(foreign).status, 421);
    // Cross-site: another origin, Sec-Fetch-Site cross-site or same-site.
    PollRequest cross = post("{\"device\":\"phone-0009\",\"choice\":1}");
    cross.origin = "http://evil.example";
    EXPECT_EQ(protocol.handle(cross).status, 403);
    cross.origin = "null";
    EXPECT_EQ(protocol.handle(cross).status, 403);
    cross = post("{\"device\":\"phone-0009\",\"choice\":1}");
    cross.fetchSite = "cross-site";
    EXPECT_EQ(protocol.handle(cross).status, 403);
    cross.fetchSite = "same-site";
    EXPECT_EQ(protocol.handle(cross).status, 403);
    // A form's content type (a cross-site form needs no preflight): refused.
    PollRequest form = post("{\"device\":\"phone-0009\",\"choice\":1}");
    form.contentType = "text/plain";
    EXPECT_EQ(protocol.handle(form).status, 415);
    form.contentType = "";
    EXPECT_EQ(protocol.handle(form).status, 415);
    // The body: too large, malformed, not an object, extra or missing keys, wrong types.
    EXPECT_EQ(protocol.handle(post(std::string(kPollMaxBody + 1, ' '))).status, 413);
    for (const char* body :
         {"", "{", "{\"device\":\"phone-0009\",\"choice\":1", "[]", "1", "null",
          "{\"device\":\"phone-0009\"}", "{\"choice\":1}",
          "{\"device\":\"phone-0009\",\"choice\":1,\"name\":\"Ann\"}",
          "{\"device\":\"phone-0009\",\"choice\":\"1\"}",
          "{\"device\":\"phone-0009\",\"choice\":1.5}", "{\"device\":9,\"choice\":1}",
          "{\"device\":\"short\",\"choice\":1}", "{\"device\":\"<b>phone-09</b>\",\"choice\":1}",
          "{\"device\":\"phone-0009\",\"choice\":true}"})
        EXPECT_EQ(protocol.handle(post(body)).status, 400) << body;
    // A choice out of range.
    for (int choice : {-1, 3, 4, 1000000}) EXPECT_EQ(vote("phone-0009", choice), 422) << choice;
    EXPECT_EQ(
        protocol.handle(post("{\"device\":\"phone-0009\",\"choice\":9223372036854775807}")).status,
        422);
    // Methods.
    EXPECT_EQ(protocol.handle(get("/" + kToken + "/vote")).status, 405);
    PollRequest put = post("{}", "/" + kToken + "/state");
    EXPECT_EQ(protocol.handle(put).status, 405);
    EXPECT_EQ(counts(), before);
    EXPECT_EQ(state.snapshot().current.voters, 1);
}

TEST_F(PollProtocolTest, AFloodFromOneDeviceIsRefusedOthersStillVote) {
    state.open(threeChoices());
    int refused = 0;
    for (int i = 0; i < 100; ++i) refused += vote("phone-flood", i % 3) == 429;
    EXPECT_EQ(refused, 100 - static_cast<int>(kPollBurst));
    EXPECT_EQ(vote("phone-0002", 0), 204); // another device is not held back
    now += 1.0;                            // a second later: kPollRate more
    EXPECT_EQ(vote("phone-flood", 0), 204);
    EXPECT_EQ(state.snapshot().current.voters, 2);
}

TEST_F(PollProtocolTest, NoQuestionNoVote) {
    EXPECT_EQ(vote("phone-0001", 0), 409);
    const auto j = nlohmann::json::parse(protocol.handle(get("/" + kToken + "/state")).body);
    EXPECT_EQ(j["asking"], false);
}

LessonContext lessonContext() {
    LessonContext c;
    c.scenesDir = SANDBOX_SCENES_DIR;
    return c;
}

TEST(PollQuestions, ReadThroughTheLessonLibraryWithTheChoiceTheRunProves) {
    std::string error;
    const auto questions =
        lessonPollQuestions(SANDBOX_POLL_DATA_DIR "/poll_lesson.json", lessonContext(), &error);
    ASSERT_TRUE(questions) << error;
    const std::optional<PollQuestion> q = (*questions)(2, &error);
    ASSERT_TRUE(q) << error;
    // The question's numbers computed from the step's world, as the caption shows them.
    EXPECT_EQ(q->question,
              "m1 = 1 kg at 6 m/s hits m2 = 2 kg at rest with C = 1. What does m1 do after?");
    EXPECT_EQ(q->choices,
              (std::vector<std::string>{"Stops", "Moves back at 2 m/s", "Keeps going at 2 m/s"}));
    EXPECT_EQ(q->proved, 1); // the run: m1 leaves at -2 m/s
    const std::optional<PollQuestion> four = (*questions)(3, &error);
    ASSERT_TRUE(four) << error;
    EXPECT_EQ(four->proved, 3);
    EXPECT_FALSE((*questions)(1, &error));
    EXPECT_NE(error.find("step 1 asks nothing"), std::string::npos) << error;
    EXPECT_FALSE((*questions)(5, &error));
    EXPECT_NE(error.find("no step 5"), std::string::npos) << error;
    EXPECT_FALSE(
        lessonPollQuestions(SANDBOX_POLL_DATA_DIR "/missing.json", lessonContext(), &error));
    EXPECT_NE(error.find("missing.json"), std::string::npos) << error;
}

TEST(PollQuestions, Lecture3AsksEveryStepAndTheRunProvesItsCorrectChoice) {
    std::string error;
    LessonResult lesson = loadLessonFile(SANDBOX_LESSONS_DIR "/lecture3.json", lessonContext());
    ASSERT_TRUE(lesson.lesson) << lesson.error.text();
    const PollQuestions questions =
        lessonPollQuestions(std::make_shared<const Lesson>(*lesson.lesson));
    for (std::size_t i = 0; i < lesson.lesson->steps.size(); ++i) {
        const LessonStep& step = lesson.lesson->steps[i];
        const std::optional<PollQuestion> q = questions(static_cast<int>(i) + 1, &error);
        ASSERT_TRUE(q) << error;
        EXPECT_EQ(q->question, stepPrompt(step).question) << "step " << i + 1;
        EXPECT_EQ(q->choices.size(), step.choices.size()) << "step " << i + 1;
        EXPECT_EQ(q->proved, step.correct) << "step " << i + 1;
    }
}

TEST(PollState, TheRunsProvedChoiceMarksEveryRoundOfTheQuestion) {
    PollState state;
    state.open(PollQuestion{2, "Q", {"a", "b", "c"}, -1});
    state.close();
    ASSERT_TRUE(state.revote());
    state.prove(2);
    state.close();
    for (const PollRound& r : state.results()) EXPECT_EQ(r.proved, 2) << "round " << r.round;
    EXPECT_EQ(state.snapshot().current.proved, 2);
}

TEST(PollResults, CsvHasEveryRoundAndQuotesText) {
    PollRound r{2, 1, "Why \"this\"?", {"a,b", "c"}, {3, 4}, 7, 1};
    EXPECT_EQ(pollResultsCsv({r}), "step,round,choice,text,count,voters,proved,question\n"
                                   "2,1,A,\"a,b\",3,7,no,\"Why \"\"this\"\"?\"\n"
                                   "2,1,B,\"c\",4,7,yes,\"Why \"\"this\"\"?\"\n");
}

TEST(PollQr, EncodesTheUrlInAVersionAPhoneReads) {
    const QrModules m = qrModules("http://192.168.100.200:65535/abcdefgh2345");
    EXPECT_EQ(m.size, 29); // version 3: 29 modules, up to 42 bytes at medium correction
    EXPECT_TRUE(m.at(0, 0) && m.at(6, 6) && !m.at(7, 7)); // a finder pattern's corner
}

} // namespace
