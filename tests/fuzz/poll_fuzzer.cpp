// libFuzzer target on the poll's request handling (issue 40): any bytes as an HTTP request, read
// with the server's caps (http_request.h) and, when they parse, handled by the protocol with a
// question open. Fails on a crash, a sanitizer report, a status the protocol does not document,
// or counts that no longer add up to the voters.
#include "http_request.h"
#include "poll_protocol.h"
#include "poll_state.h"

#include <boost/asio/buffer.hpp>

#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <set>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static PollState state;
    static double now = 0.0;
    static PollProtocol protocol(state, "127.0.0.1:5000", "abcdefgh2345", [] { return now; });
    static const bool opened = (state.open({2, "Q?", {"a", "b", "c"}, 1}), true);
    (void)opened;
    static const std::set<int> documented = {200, 204, 400, 403, 404, 405, 409,
                                             413, 415, 421, 422, 429, 431, 503};
    now += 0.05;

    HttpParser parser;
    capRequest(parser);
    parser.eager(true);
    boost::beast::error_code ec;
    parser.put(boost::asio::buffer(data, size), ec);
    if (!ec && !parser.is_done()) parser.put_eof(ec);
    if (ec) {
        if (const auto refusal = readRefusal(ec); refusal && !documented.count(refusal->status))
            std::abort();
        return 0;
    }
    if (!parser.is_done()) return 0;
    const PollResponse response = protocol.handle(pollRequest(parser.get()));
    if (!documented.count(response.status)) std::abort();
    const PollSnapshot s = state.snapshot();
    if (std::accumulate(s.current.counts.begin(), s.current.counts.end(), 0) != s.current.voters)
        std::abort();
    return 0;
}
