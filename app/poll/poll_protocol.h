// The phone protocol (docs/poll.md), apart from any transport: a request as plain fields in, a
// response out. The HTTP server (http_transport.h) and anything standing in for it (a relay)
// hand every request to PollProtocol::handle, so the checks below hold whatever carries them:
// the Host header names the served address (no DNS rebinding), the token is in every path, a
// vote comes from the same site as JSON, a device votes at a bounded rate, and nothing a phone
// sends is kept but its anonymous id and its choice.
#pragma once

#include "poll_state.h"

#include <chrono>
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// Caps on what a phone may send (the transport enforces the sizes while reading).
inline constexpr std::size_t kPollMaxBody = 1024;   // bytes of a request body: else 413
inline constexpr std::size_t kPollMaxHeader = 4096; // bytes of the request line and headers
inline constexpr std::size_t kPollMaxDeviceId = 64; // characters of a device id
inline constexpr std::size_t kPollMinDeviceId = 8;
// A device's requests: a bucket of kPollBurst, refilled at kPollRate a second (else 429). A
// phone asks for the state every 2 s and votes a few times; a script flooding is refused.
inline constexpr double kPollBurst = 20.0;
inline constexpr double kPollRate = 4.0;

struct PollRequest {
    std::string method;      // "GET", "POST", ...
    std::string target;      // "/TOKEN/state?device=ID"
    std::string host;        // the Host header ("" when missing)
    std::string origin;      // the Origin header ("" when missing)
    std::string fetchSite;   // Sec-Fetch-Site ("" when missing)
    std::string contentType; // Content-Type ("" when missing)
    std::string body;
};

struct PollResponse {
    int status = 200;
    std::string contentType; // "" for no body
    std::string body;
    std::vector<std::pair<std::string, std::string>> headers; // besides the fixed safety headers
};

class PollProtocol {
  public:
    using Clock = std::function<double()>; // seconds, monotonic

    // `authority`: "ADDRESS:PORT" as served (what the Host header must say); `token`: the path's
    // first segment. `clock` defaults to the steady clock (tests give their own).
    PollProtocol(PollState& state, std::string authority, std::string token, Clock clock = {});

    PollResponse handle(const PollRequest& request);
    // Responses the transport makes itself, in the same form (413, 431, 503, 400).
    static PollResponse refusal(int status, std::string_view why);
    // The fixed headers every response carries (no caching, no sniffing, no framing, the page's
    // content security policy).
    static const std::vector<std::pair<std::string, std::string>>& safetyHeaders();

    const std::string& token() const { return token_; }
    const std::string& authority() const { return authority_; }

  private:
    bool allow(const std::string& device); // the device's rate
    PollResponse page() const;
    PollResponse state(std::string_view query);
    PollResponse vote(const PollRequest& request);

    PollState& state_;
    std::string authority_;
    std::string token_;
    Clock clock_;
    struct Bucket {
        double tokens = kPollBurst;
        double at = 0.0;
    };
    std::map<std::string, Bucket> buckets_; // at most kMaxPollDevices
};

// A random token of `length` characters from an alphabet without look-alikes (no 0/o, 1/l/i):
// about 5 bits each, from the operating system's random source.
std::string randomPollToken(std::size_t length = 12);
// True when `id` is a device id: kPollMinDeviceId..kPollMaxDeviceId of [A-Za-z0-9_-].
bool isDeviceId(std::string_view id);
// The JSON the phone reads (GET /TOKEN/state).
std::string phoneViewJson(const PhoneView& view);
// The reason phrase of a status ("Too Many Requests").
const char* statusReason(int status);
