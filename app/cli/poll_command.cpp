#include "poll_command.h"

#include "commands.h"
#include "lesson_poll_questions.h"
#include "net_addresses.h"
#include "poll_session.h"
#include "printable.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <iostream>
#include <sstream>

namespace {

std::string dump(const nlohmann::ordered_json& j) {
    return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

nlohmann::ordered_json roundJson(const PollRound& r) {
    return {{"step", r.step},
            {"round", r.round},
            {"counts", r.counts},
            {"voters", r.voters},
            {"proved",
             r.proved < 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.proved)}};
}

bool parseInt(const std::string& text, long long lo, long long hi, long long& value) {
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, value);
    return ec == std::errc() && ptr == end && value >= lo && value <= hi;
}

} // namespace

int pollCommand(const PollCommandRequest& request, const LessonContext& lessons, std::istream& in,
                std::ostream& out, std::ostream& err) {
    long long port = 0;
    if (!request.port.empty() && !parseInt(request.port, 0, 65535, port)) {
        err << "sandbox-cli poll: --port: " << printable(request.port)
            << " is not a port (0 to 65535; 0: a free one)\n";
        return kExitBadInput;
    }
    std::string error;
    std::optional<PollQuestions> questions = lessonPollQuestions(request.lesson, lessons, &error);
    if (!questions) {
        err << "sandbox-cli poll: " << printable(error, 4 * kPrintableDefault) << "\n";
        return kExitBadInput;
    }
    const std::string address = request.bind.empty() ? defaultPollAddress() : request.bind;
    std::unique_ptr<PollSession> poll =
        PollSession::start(*questions, address, static_cast<int>(port), &error);
    if (!poll) {
        err << "sandbox-cli poll: " << printable(error, 4 * kPrintableDefault) << "\n";
        return kExitBadInput;
    }
    const std::string url = poll->url();
    const std::size_t colon = url.rfind(':');
    const std::string portText = url.substr(colon + 1, url.find('/', colon) - colon - 1);
    out << dump({{"url", url},
                 {"token", poll->token()},
                 {"address", address},
                 {"port", std::stoi(portText)}})
        << std::endl;

    auto refuse = [&](int line, const std::string& why) {
        err << "sandbox-cli poll: stdin line " << line << ": "
            << printable(why, 4 * kPrintableDefault) << "\n";
        out << dump({{"error", why}}) << std::endl;
    };
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line);
        std::string command, argument, extra;
        words >> command >> argument >> extra;
        if (command.empty()) continue;
        if (!extra.empty()) {
            refuse(number, "too many words: " + line);
        } else if (command == "open") {
            long long step = 0;
            if (!parseInt(argument, 1, 1000000, step)) {
                refuse(number, "open STEP: a step number from 1");
            } else if (!poll->open(static_cast<int>(step), &error)) {
                refuse(number, error);
            } else {
                const PollSnapshot s = poll->snapshot();
                out << dump({{"step", s.current.step},
                             {"round", s.current.round},
                             {"open", true},
                             {"choices", s.current.choices.size()}})
                    << std::endl;
            }
        } else if (command == "close" && argument.empty()) {
            if (std::optional<PollRound> r = poll->close())
                out << dump(roundJson(*r)) << std::endl;
            else
                refuse(number, "no vote is open");
        } else if (command == "revote" && argument.empty()) {
            if (poll->revote()) {
                const PollSnapshot s = poll->snapshot();
                out << dump({{"step", s.current.step}, {"round", s.current.round}, {"open", true}})
                    << std::endl;
            } else {
                refuse(number, poll->snapshot().asking ? "revote: the vote is still open"
                                                       : "revote: no question is asked");
            }
        } else if (command == "status" && argument.empty()) {
            const PollSnapshot s = poll->snapshot();
            out << dump({{"step", s.asking ? s.current.step : 0},
                         {"round", s.asking ? s.current.round : 0},
                         {"open", s.open},
                         {"joined", s.joined},
                         {"voted", s.current.voters}})
                << std::endl;
        } else if (command == "save" && !argument.empty()) {
            if (savePollResults(argument, poll->results(), &error))
                out << dump({{"saved", argument}}) << std::endl;
            else
                refuse(number, error);
        } else if (command == "quit" && argument.empty()) {
            break;
        } else {
            refuse(number, "unknown command: " + line +
                               " (open STEP, close, revote, status, save FILE.csv, quit)");
        }
    }
    poll->close(); // a round still open counts as it stands
    const std::vector<PollRound> results = poll->results();
    poll.reset(); // the server stops before the results are written
    if (!request.csv.empty() && !savePollResults(request.csv, results, &error)) {
        err << "sandbox-cli poll: " << error << "\n";
        return kExitBadInput;
    }
    return kExitOk;
}
