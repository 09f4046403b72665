#include "poll_session.h"

#include "csv.h"
#include "http_transport.h"
#include "safe_file.h"

#include <mutex>

std::unique_ptr<PollSession> PollSession::start(PollQuestions questions, const std::string& address,
                                                int port, std::string* error) {
    std::unique_ptr<PollTransport> transport = listenHttp(address, port, error);
    if (!transport) return nullptr;
    return std::make_unique<PollSession>(std::move(questions), std::move(transport));
}

PollSession::PollSession(PollQuestions questions, std::unique_ptr<PollTransport> transport)
    : questions_(std::move(questions)), token_(randomPollToken()),
      transport_(std::move(transport)) {
    protocol_ = std::make_unique<PollProtocol>(state_, transport_->authority(), token_);
    // One protocol, called from the transport's thread; the lock keeps a transport that calls
    // from several threads (a relay's) safe too.
    auto lock = std::make_shared<std::mutex>();
    transport_->serve([protocol = protocol_.get(), lock](const PollRequest& request) {
        std::lock_guard guard(*lock);
        return protocol->handle(request);
    });
}

PollSession::~PollSession() {
    transport_->stop();
}

std::string PollSession::url() const {
    return "http://" + transport_->authority() + "/" + token_;
}

std::optional<PollQuestion> PollSession::question(int step, std::string* error) const {
    return questions_(step, error);
}

bool PollSession::open(int step, std::string* error) {
    std::optional<PollQuestion> q = questions_(step, error);
    if (!q) return false;
    state_.open(*q);
    return true;
}

std::optional<PollRound> PollSession::close() {
    return state_.close();
}

bool PollSession::revote() {
    return state_.revote();
}

void PollSession::clear() {
    state_.clear();
}

std::string pollResultsCsv(const std::vector<PollRound>& rounds) {
    std::string csv = "step,round,choice,text,count,voters,proved,question\n";
    for (const PollRound& r : rounds)
        for (std::size_t i = 0; i < r.choices.size(); ++i) {
            const int index = static_cast<int>(i);
            csv += std::to_string(r.step) + "," + std::to_string(r.round) + "," + choiceLetter(i) +
                   "," + csvField(r.choices[i]) + "," + std::to_string(r.counts[i]) + "," +
                   std::to_string(r.voters) + "," + (r.proved == index ? "yes" : "no") + "," +
                   csvField(r.question) + "\n";
        }
    return csv;
}

bool savePollResults(const std::string& path, const std::vector<PollRound>& rounds,
                     std::string* error) {
    return writeFileSafely(path, pollResultsCsv(rounds), error);
}
