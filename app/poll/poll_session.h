// A running poll: the vote (PollState), the protocol that checks every request, and the
// transport that carries them, started together and stopped together. The app and sandbox-cli
// own one while the poll is on; dropping it stops the server.
#pragma once

#include "poll_protocol.h"
#include "poll_question.h"
#include "poll_state.h"
#include "poll_transport.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

class PollSession {
  public:
    // Serves over HTTP on `address` and `port` (0: a free one); none, with `error`, when the
    // address or port cannot be had.
    static std::unique_ptr<PollSession> start(PollQuestions questions, const std::string& address,
                                              int port, std::string* error);
    // Serves over a transport of the caller's (a relay, a test's).
    PollSession(PollQuestions questions, std::unique_ptr<PollTransport> transport);
    ~PollSession(); // stops the transport first: no request is handled after
    PollSession(const PollSession&) = delete;
    PollSession& operator=(const PollSession&) = delete;

    // "http://ADDRESS:PORT/TOKEN": what the projector shows and the QR code holds.
    std::string url() const;
    const std::string& token() const { return token_; }

    // Asks step `step`'s question (round 1); false, with `error`, when the step asks nothing.
    bool open(int step, std::string* error);
    // Asks `q` as given (the window asks the question of the world the lecturer made).
    void open(const PollQuestion& q) { state_.open(q); }
    // The setup changed while the vote is open: `q` asked instead, the votes for the old
    // wording dropped (PollState::reword).
    bool reword(const PollQuestion& q) { return state_.reword(q); }
    // The choice the run proved at the moment (-1: none): PollState::prove.
    void prove(int choice) { state_.prove(choice); }
    std::optional<PollRound> close();
    bool revote();
    void clear(); // the lesson left the step: nothing asked
    // A vote as if a phone had sent it (sandbox-offscreen's --poll-votes, tests): the same
    // count, no network.
    PollState::Vote castVote(const std::string& device, int choice) {
        return state_.vote(device, choice);
    }
    PollSnapshot snapshot() const { return state_.snapshot(); }
    std::vector<PollRound> results() const { return state_.results(); }
    // The question of a step, as open() would ask it (the projector shows its choices).
    std::optional<PollQuestion> question(int step, std::string* error) const;

  private:
    PollQuestions questions_;
    PollState state_;
    std::string token_;
    std::unique_ptr<PollTransport> transport_;
    std::unique_ptr<PollProtocol> protocol_;
};

// The results as CSV: one row per step, round and choice (step, round, choice letter, choice
// text, count, voters, whether the run proved it, the question).
std::string pollResultsCsv(const std::vector<PollRound>& rounds);
// Writes them to `path` safely (a failed write leaves the old file); false with `error`.
bool savePollResults(const std::string& path, const std::vector<PollRound>& rounds,
                     std::string* error);
