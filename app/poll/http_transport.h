// The poll's HTTP server: Boost.Beast on Boost.Asio, one thread and one event loop for every
// connection (no thread per phone: docs/poll.md says why, with the measurements). It enforces
// the sizes and times a request may take and the number of connections, and hands each complete
// request to the protocol.
#pragma once

#include "poll_transport.h"

#include <memory>
#include <string>

// Connections held at once; more are closed as they come.
inline constexpr int kPollMaxConnections = 4000;
// A connection with no request on the way is dropped after this many seconds (a sleeping phone
// or a half-open connection); a request must arrive whole, headers and body, within
// kPollRequestSeconds of its first byte (a slow trickle is dropped); a response must be taken
// within kPollRequestSeconds.
inline constexpr int kPollIdleSeconds = 60;
inline constexpr int kPollRequestSeconds = 5;

// Listens on `address` ("192.168.1.5", "127.0.0.1", "::1") and `port` (0: a free one). None,
// with `error` ("cannot listen on 10.0.0.9:8080: Cannot assign requested address"), when the
// address or port cannot be had.
std::unique_ptr<PollTransport> listenHttp(const std::string& address, int port, std::string* error);
