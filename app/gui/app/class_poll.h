// The class poll in the app (docs/poll.md): the lecturer turns it on for a lesson on an address
// of this machine; it then follows the lesson by itself. At a step's setup it asks the step's
// question (when it has choices) on every phone, reworded when the lecturer changes the setup
// while the vote is open (the votes for the old wording dropped); whatever plays the step (P,
// the bar's Play, PageDown) closes the vote; at the moment the counts show beside the choice the
// run proved. "Vote again" replays the step to its setup with a second round. The server runs on
// its own thread; the frame reads a snapshot and never waits for a phone. Plain logic, no ImGui.
// The browser build cannot serve: there the poll says so and never starts.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

struct LessonSession;
struct SimulationSession;
class PollSession;

// What the projector's poll window shows, copied each frame.
struct PollScreen {
    bool on = false;
    bool asking = false;    // the step's question is on the phones (open or closed)
    bool open = false;      // votes are taken
    bool histogram = false; // the counts show (the vote is closed and the step at its moment)
    std::string url;
    int qrSize = 0;           // QR modules per side
    std::vector<bool> qrDark; // qrSize x qrSize, row by row
    int joined = 0, voted = 0;
    int step = 0;
    std::string question;
    std::vector<std::string> choices;
    int proved = -1;
    std::vector<std::vector<int>> rounds; // the counts of each closed round of this question
    std::string note;                     // why the step is not polled ("step 1 asks nothing")
};

struct ClassPoll {
    ClassPoll();
    ~ClassPoll();
    ClassPoll(ClassPoll&&) noexcept;
    ClassPoll& operator=(ClassPoll&&) noexcept;

    std::shared_ptr<PollSession> session; // none: off
    std::vector<std::string> addresses;   // this machine's, the default route's first
    std::size_t address = 0;              // the one picked
    std::string error;                    // the last start's failure
    std::size_t followedStep = static_cast<std::size_t>(-1); // the step the poll follows
    bool asked = false;  // its question was put to the phones (at its setup)
    bool proved = false; // the run's proved choice was given to the poll (at the moment)
    // SimulationSession::changes when the question was last read from the world: a change
    // since, while the vote is open, rewords it on the phones.
    std::uint64_t askedAt = 0;
    std::string lessonPath; // the lesson it asks from
    std::string note;       // why this step is not polled
    int qrSize = 0;         // the URL's QR code
    std::vector<bool> qrDark;

    bool on() const { return session != nullptr; }
};

// False in the browser build (a page cannot serve): the panel says so instead of the button.
bool pollAvailable();
// The words where the button would be, in the browser.
inline constexpr const char* kPollUnavailable =
    "A class poll needs the sandbox on a laptop: a browser page cannot serve one.";
// The machine's addresses into poll.addresses (the default route's first).
void listPollAddresses(ClassPoll& poll);
// Starts the server for the open lesson on poll.addresses[poll.address] (or `address` when
// given), a free port; false with poll.error when no lesson is open or the address cannot be had.
bool startPoll(ClassPoll& poll, const LessonSession& lesson, const SimulationSession& sim,
               const std::string& address = "");
void stopPoll(ClassPoll& poll);
// Once a frame: the lesson closed (the server stops), a new step (its question, as the world on
// screen asks it, is put to the phones), the step playing (the vote closes), the moment (the
// choice the live run proved is marked).
void followLesson(ClassPoll& poll, const LessonSession& lesson, const SimulationSession& sim);
// "Close vote" at the setup, and "Vote again": the next round (the caller replays the step to
// its setup).
void closePollVote(ClassPoll& poll);
bool pollVoteAgain(ClassPoll& poll);
// sandbox-offscreen's --poll-votes: `counts[i]` votes for choice i, from made-up devices.
void castDemoVotes(ClassPoll& poll, const std::vector<int>& counts);
PollScreen pollScreen(const ClassPoll& poll, const LessonSession& lesson);
// "http://ADDRESS:PORT/TOKEN"; "" when off.
std::string pollUrl(const ClassPoll& poll);
