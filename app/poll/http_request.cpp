#include "http_request.h"

namespace http = boost::beast::http;

void capRequest(HttpParser& parser) {
    parser.header_limit(static_cast<std::uint32_t>(kPollMaxHeader));
    parser.body_limit(kPollMaxBody);
}

std::optional<PollResponse> readRefusal(boost::beast::error_code ec) {
    if (ec == http::error::body_limit) return PollProtocol::refusal(413, "the body is too large");
    if (ec == http::error::header_limit || ec == http::error::buffer_overflow)
        return PollProtocol::refusal(431, "the request line and headers are too large");
    if (ec.category() == http::make_error_code(http::error::bad_method).category() &&
        ec != http::error::end_of_stream && ec != http::error::partial_message &&
        ec != http::error::need_more)
        return PollProtocol::refusal(400, "not an HTTP/1.1 request");
    return std::nullopt;
}

PollRequest pollRequest(const HttpParser::value_type& message) {
    PollRequest r;
    r.method = std::string(message.method_string());
    r.target = std::string(message.target());
    if (message.count(http::field::host) == 1) r.host = std::string(message[http::field::host]);
    r.origin = std::string(message[http::field::origin]);
    r.fetchSite = std::string(message["Sec-Fetch-Site"]);
    r.contentType = std::string(message[http::field::content_type]);
    r.body = message.body();
    return r;
}
