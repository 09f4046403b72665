// The vote as plain data: the open question, one vote per device per round, the rounds of each
// step, the phones that joined. Thread-safe: the server's thread counts votes while the app's
// frame loop (or sandbox-cli) reads a snapshot and opens, closes and reopens the vote.
#pragma once

#include "poll_question.h"

#include <cstddef>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

// The most devices one poll keeps (joined or voting): bounds its memory; more are refused.
inline constexpr std::size_t kMaxPollDevices = 10000;

// One round of one step, as counted when it closed (or as it stands while open).
struct PollRound {
    int step = 0;  // 1-based
    int round = 1; // 1: the first vote; 2, 3, ...: "Vote again"
    std::string question;
    std::vector<std::string> choices;
    std::vector<int> counts; // one per choice
    int voters = 0;          // devices whose vote is counted (the sum of counts)
    int proved = -1;         // the choice the run proves, -1: none
};

// What the projector shows, copied out under the lock.
struct PollSnapshot {
    bool asking = false;           // a question is on (open or closed)
    bool open = false;             // votes are taken
    int joined = 0;                // devices that loaded the question since the poll started
    PollRound current;             // the round on (its counts stay hidden while open)
    std::vector<PollRound> rounds; // every closed round of the current step, in order
};

// What a phone sees (GET /TOKEN/state).
struct PhoneView {
    bool asking = false;
    bool open = false;
    int step = 0;
    int round = 0;
    std::string question;
    std::vector<std::string> choices;
    std::optional<int> mine; // this device's vote in this round
    // Its vote was dropped because the setup changed (PollState::reword) and it has not voted
    // again: the page says "the setup changed: vote again".
    bool setupChanged = false;
};

class PollState {
  public:
    enum class Vote { Counted, Closed, OutOfRange, TooManyDevices };

    // Asks `q` (round 1): a round still open is closed first and kept.
    void open(const PollQuestion& q);
    // Closes the open round and returns it; none when no round is open.
    std::optional<PollRound> close();
    // Opens the next round of the current question ("Vote again"); false when none is asked or
    // a round is still open.
    bool revote();
    // The choice the run proved (-1: none), once the class has seen it: the current question's
    // rounds, closed and open, say so (a changed world may prove another than the step as
    // written).
    void prove(int choice);
    // The setup changed while the round is open (the lecturer changed C, a mass, the method):
    // when `q` reads otherwise than the question asked, it is asked instead in the same round,
    // and the votes cast so far are dropped (a prediction about another setup is another
    // prediction); the phones that had voted are told to vote again (PhoneView::setupChanged).
    // False, nothing changed, when no round is open or `q` reads the same.
    bool reword(const PollQuestion& q);
    // Stops asking (the step changed): an open round is closed and kept.
    void clear();

    // A device's vote; a second one in the round replaces the first.
    Vote vote(const std::string& device, int choice);
    // What `device` ("" for none) sees; the device counts as joined.
    PhoneView view(const std::string& device);

    PollSnapshot snapshot() const;
    // Every closed round of every step since the poll started, in order.
    std::vector<PollRound> results() const;

  private:
    bool join(const std::string& device); // false when the device table is full
    void closeLocked();

    mutable std::mutex mutex_;
    bool asking_ = false;
    bool open_ = false;
    PollRound current_;
    std::map<std::string, int> votes_; // device -> choice, this round
    std::set<std::string> dropped_;    // devices whose vote a reword dropped, not voted since
    std::set<std::string> devices_;    // joined
    std::vector<PollRound> results_;
    std::size_t firstRound_ = 0; // results_[firstRound_..]: the current question's rounds
};
