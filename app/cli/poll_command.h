// sandbox-cli poll: the class poll without a window (docs/cli.md, docs/poll.md).
#pragma once

#include "lesson.h"

#include <iosfwd>
#include <string>

struct PollCommandRequest {
    std::string lesson; // lesson file
    std::string bind;   // address to listen on ("": the default route's)
    std::string port;   // "0" or "": a free port; checked as bad input
    std::string csv;    // results written here at quit ("": not written)
};

// Serves the lesson's poll: prints one JSON line {"url", "token", "address", "port"}, then reads
// commands from `in`, one a line (open STEP, close, revote, status, save FILE, quit), answering
// each with one JSON line on `out` ({"error": ...} when refused; the message also on `err`).
// Returns at `quit` or the end of `in`, having stopped the server. An ExitCode.
// `lessons`: what the lesson file may name (as for sandbox-cli lesson).
int pollCommand(const PollCommandRequest& request, const LessonContext& lessons, std::istream& in,
                std::ostream& out, std::ostream& err);
