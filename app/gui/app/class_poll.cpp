#include "class_poll.h"

#include "lesson_session.h"

#ifndef __EMSCRIPTEN__
#include "lesson_poll_questions.h"
#include "net_addresses.h"
#include "poll_qr.h"
#include "poll_session.h"
#endif

ClassPoll::ClassPoll() = default;
ClassPoll::~ClassPoll() = default;
ClassPoll::ClassPoll(ClassPoll&&) noexcept = default;
ClassPoll& ClassPoll::operator=(ClassPoll&&) noexcept = default;

#ifdef __EMSCRIPTEN__

bool pollAvailable() {
    return false;
}
void listPollAddresses(ClassPoll&) {}
bool startPoll(ClassPoll& poll, const LessonSession&, const SimulationSession&,
               const std::string&) {
    poll.error = kPollUnavailable;
    return false;
}
void stopPoll(ClassPoll&) {}
void followLesson(ClassPoll&, const LessonSession&, const SimulationSession&) {}
void closePollVote(ClassPoll&) {}
bool pollVoteAgain(ClassPoll&) {
    return false;
}
void castDemoVotes(ClassPoll&, const std::vector<int>&) {}
PollScreen pollScreen(const ClassPoll&, const LessonSession&) {
    return {};
}
std::string pollUrl(const ClassPoll&) {
    return "";
}

#else

bool pollAvailable() {
    return true;
}

void listPollAddresses(ClassPoll& poll) {
    poll.addresses.clear();
    for (const NetAddress& a : netAddresses()) poll.addresses.push_back(a.address);
    if (poll.addresses.empty()) poll.addresses.push_back("127.0.0.1");
    if (poll.address >= poll.addresses.size()) poll.address = 0;
}

bool startPoll(ClassPoll& poll, const LessonSession& lesson, const SimulationSession& sim,
               const std::string& address) {
    poll.error.clear();
    if (!lesson.active()) {
        poll.error = "Open a lesson first: the poll asks its steps' questions.";
        return false;
    }
    // The file's questions as written (what `question` answers); the window asks the live one.
    PollQuestions questions = lessonPollQuestions(std::make_shared<const Lesson>(*lesson.lesson));
    if (poll.addresses.empty()) listPollAddresses(poll);
    const std::string at = address.empty() ? poll.addresses[poll.address] : address;
    std::unique_ptr<PollSession> session =
        PollSession::start(std::move(questions), at, 0, &poll.error);
    if (!session) return false;
    poll.session = std::move(session);
    const QrModules qr = qrModules(poll.session->url());
    poll.qrSize = qr.size;
    poll.qrDark = qr.dark;
    poll.lessonPath = lesson.lesson->path;
    poll.followedStep = static_cast<std::size_t>(-1);
    followLesson(poll, lesson, sim);
    return true;
}

void stopPoll(ClassPoll& poll) {
    poll.session.reset(); // stops the server
    poll.note.clear();
}

namespace {

// The step's question as the world on screen reads it, the lecturer's changes included
// (lesson_prompt); none when the setup asks nothing (`why` says why).
std::optional<PollQuestion> liveQuestion(const LessonSession& lesson, const SimulationSession& sim,
                                         std::string* why) {
    const int number = static_cast<int>(lesson.current) + 1;
    return pollQuestion(number, lessonPrompt(lesson, sim), -1, why);
}

} // namespace

void followLesson(ClassPoll& poll, const LessonSession& lesson, const SimulationSession& sim) {
    if (!poll.session) return;
    if (!lesson.active() || lesson.lesson->path != poll.lessonPath) return stopPoll(poll);
    const bool atSetup = lesson.phase == LessonSession::Phase::Setup;
    if (lesson.current != poll.followedStep) {
        poll.followedStep = lesson.current;
        poll.asked = false;
        poll.proved = false;
        poll.session->clear();
        poll.note = atSetup ? "" : "the vote opens at a step's setup (R)";
    }
    if (atSetup && !poll.asked) {
        poll.asked = true;
        poll.proved = false;
        poll.note.clear();
        if (const std::optional<PollQuestion> q = liveQuestion(lesson, sim, &poll.note))
            poll.session->open(*q);
        poll.askedAt = sim.changes;
    } else if (atSetup && poll.asked && sim.changes != poll.askedAt) {
        // The lecturer changed the setup (C, a mass, the method, a block moved) while the step
        // is asked: the phones are asked the question as the world now reads it, and a vote
        // cast for the old wording is dropped (docs/poll.md, "The setup changed").
        poll.askedAt = sim.changes;
        if (poll.session->snapshot().open) {
            std::string why;
            const std::optional<PollQuestion> q = liveQuestion(lesson, sim, &why);
            if (q) {
                poll.session->reword(*q);
            } else { // the changed setup asks nothing any more
                poll.session->clear();
                poll.note = why;
            }
        }
    }
    // Whatever plays the step closes its vote: P, the bar's Play, PageDown.
    if (poll.session->snapshot().open && (!atSetup || !sim.paused)) poll.session->close();
    // At the moment, the choice the live run proved (in whatever world the lecturer made); a
    // replay ("Vote again", R) proves it again at its own moment.
    if (lesson.phase != LessonSession::Phase::Moment) poll.proved = false;
    if (!poll.proved && poll.asked && lesson.phase == LessonSession::Phase::Moment) {
        if (const std::optional<StepAnswer> answer = lessonAnswer(lesson, sim)) {
            poll.proved = true;
            poll.session->prove(answer->reached ? provedChoice(answer->proved) : -1);
        }
    }
}

void closePollVote(ClassPoll& poll) {
    if (poll.session) poll.session->close();
}

bool pollVoteAgain(ClassPoll& poll) {
    return poll.session && poll.session->revote();
}

void castDemoVotes(ClassPoll& poll, const std::vector<int>& counts) {
    if (!poll.session) return;
    static int devices = 0;
    for (std::size_t choice = 0; choice < counts.size(); ++choice)
        for (int i = 0; i < counts[choice]; ++i)
            poll.session->castVote("demo-" + std::to_string(++devices), static_cast<int>(choice));
}

std::string pollUrl(const ClassPoll& poll) {
    return poll.session ? poll.session->url() : "";
}

PollScreen pollScreen(const ClassPoll& poll, const LessonSession& lesson) {
    PollScreen s;
    if (!poll.session) return s;
    s.on = true;
    s.url = poll.session->url();
    s.qrSize = poll.qrSize;
    s.qrDark = poll.qrDark;
    s.note = poll.note;
    const PollSnapshot snap = poll.session->snapshot();
    s.asking = snap.asking;
    s.open = snap.open;
    s.joined = snap.joined;
    s.voted = snap.current.voters;
    if (!snap.asking) return s;
    s.step = snap.current.step;
    s.question = snap.current.question;
    s.choices = snap.current.choices;
    s.proved = snap.current.proved;
    for (const PollRound& r : snap.rounds) s.rounds.push_back(r.counts);
    // The counts stay hidden until the vote is closed and the class has seen the moment.
    s.histogram = !snap.open && !s.rounds.empty() && lesson.phase == LessonSession::Phase::Moment;
    return s;
}

#endif
