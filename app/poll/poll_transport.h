// How phones' requests reach the poll: an interface, so that the HTTP server on the classroom
// network (http_transport.h) or a relay for a class beyond the room (docs/poll.md, "Past one
// laptop") carries the same protocol. A transport hands each request to the handler and sends
// back its response; the handler (PollProtocol::handle) holds every check.
#pragma once

#include "poll_protocol.h"

#include <functional>
#include <string>

using PollHandler = std::function<PollResponse(const PollRequest&)>;

class PollTransport {
  public:
    virtual ~PollTransport() = default;
    // "ADDRESS:PORT" as phones reach it (the Host header they send).
    virtual std::string authority() const = 0;
    // Starts handing requests to `handler`, on the transport's own thread: the caller never
    // waits for a phone.
    virtual void serve(PollHandler handler) = 0;
    // Stops serving and drops every connection; returns when no request is being handled.
    virtual void stop() = 0;
};
