// An HTTP request as Beast parses it, turned into the protocol's plain fields: the one place the
// server (http_transport.cpp) and the request fuzzer (tests/fuzz/poll_fuzzer.cpp) read requests,
// with the same caps.
#pragma once

#include "poll_protocol.h"

#include <boost/beast/http.hpp>

#include <optional>

using HttpParser = boost::beast::http::request_parser<boost::beast::http::string_body>;

// Sets the caps: kPollMaxHeader bytes of request line and headers, kPollMaxBody of body.
void capRequest(HttpParser& parser);
// The refusal for a read that failed with `ec` (413 a body over the cap, 431 headers over it,
// 400 not HTTP/1.x); none when the connection is simply to be dropped (closed, timed out).
std::optional<PollResponse> readRefusal(boost::beast::error_code ec);
// The fields the protocol reads. Two Host headers read as none (the protocol refuses it).
PollRequest pollRequest(const HttpParser::value_type& message);
