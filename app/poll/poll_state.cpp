#include "poll_state.h"

#include <algorithm>

void PollState::open(const PollQuestion& q) {
    std::lock_guard lock(mutex_);
    closeLocked();
    firstRound_ = results_.size();
    asking_ = true;
    open_ = true;
    current_ = PollRound{
        q.step, 1, q.question, q.choices, std::vector<int>(q.choices.size(), 0), 0, q.proved};
    votes_.clear();
    dropped_.clear();
}

bool PollState::reword(const PollQuestion& q) {
    std::lock_guard lock(mutex_);
    if (!open_ || (q.question == current_.question && q.choices == current_.choices)) return false;
    for (const auto& vote : votes_) dropped_.insert(vote.first);
    votes_.clear();
    current_.question = q.question;
    current_.choices = q.choices;
    current_.counts.assign(q.choices.size(), 0);
    current_.voters = 0;
    current_.proved = q.proved;
    return true;
}

void PollState::closeLocked() {
    if (!open_) return;
    open_ = false;
    results_.push_back(current_);
}

std::optional<PollRound> PollState::close() {
    std::lock_guard lock(mutex_);
    if (!open_) return std::nullopt;
    closeLocked();
    return current_;
}

bool PollState::revote() {
    std::lock_guard lock(mutex_);
    if (!asking_ || open_) return false;
    open_ = true;
    current_.round += 1;
    std::fill(current_.counts.begin(), current_.counts.end(), 0);
    current_.voters = 0;
    votes_.clear();
    dropped_.clear();
    return true;
}

void PollState::prove(int choice) {
    std::lock_guard lock(mutex_);
    if (!asking_) return;
    current_.proved = choice;
    for (std::size_t r = firstRound_; r < results_.size(); ++r) results_[r].proved = choice;
}

void PollState::clear() {
    std::lock_guard lock(mutex_);
    closeLocked();
    asking_ = false;
    votes_.clear();
    dropped_.clear();
}

bool PollState::join(const std::string& device) {
    if (devices_.count(device)) return true;
    if (devices_.size() >= kMaxPollDevices) return false;
    devices_.insert(device);
    return true;
}

PollState::Vote PollState::vote(const std::string& device, int choice) {
    std::lock_guard lock(mutex_);
    if (!open_) return Vote::Closed;
    if (choice < 0 || choice >= static_cast<int>(current_.counts.size())) return Vote::OutOfRange;
    if (!join(device)) return Vote::TooManyDevices;
    dropped_.erase(device);
    auto [it, inserted] = votes_.try_emplace(device, choice);
    if (inserted) {
        current_.voters += 1;
    } else {
        current_.counts[static_cast<std::size_t>(it->second)] -= 1;
        it->second = choice;
    }
    current_.counts[static_cast<std::size_t>(choice)] += 1;
    return Vote::Counted;
}

PhoneView PollState::view(const std::string& device) {
    std::lock_guard lock(mutex_);
    if (!device.empty()) join(device);
    PhoneView v;
    v.asking = asking_;
    v.open = open_;
    if (!asking_) return v;
    v.step = current_.step;
    v.round = current_.round;
    v.question = current_.question;
    v.choices = current_.choices;
    if (auto it = votes_.find(device); it != votes_.end() && !device.empty()) v.mine = it->second;
    v.setupChanged = open_ && !device.empty() && dropped_.count(device) > 0;
    return v;
}

PollSnapshot PollState::snapshot() const {
    std::lock_guard lock(mutex_);
    PollSnapshot s;
    s.asking = asking_;
    s.open = open_;
    s.joined = static_cast<int>(devices_.size());
    s.current = current_;
    if (asking_) s.rounds.assign(results_.begin() + static_cast<long>(firstRound_), results_.end());
    return s;
}

std::vector<PollRound> PollState::results() const {
    std::lock_guard lock(mutex_);
    return results_;
}
