#include "poll_protocol.h"

#include "poll_page_files.h" // generated from page/ by embed_page.cmake

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <random>

namespace {

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// Compares every character whatever the first difference (the token's check takes the same
// time for a near miss as for a far one).
bool sameToken(std::string_view given, std::string_view token) {
    unsigned diff = given.size() == token.size() ? 0u : 1u;
    for (std::size_t i = 0; i < token.size(); ++i)
        diff |= static_cast<unsigned char>(i < given.size() ? given[i] : 0) ^
                static_cast<unsigned char>(token[i]);
    return diff == 0;
}

PollResponse text(int status, std::string_view why) {
    PollResponse r;
    r.status = status;
    r.contentType = "text/plain; charset=utf-8";
    r.body = std::string(statusReason(status)) + ": " + std::string(why) + "\n";
    return r;
}

PollResponse file(std::string_view body, const char* type) {
    PollResponse r;
    r.contentType = type;
    r.body = std::string(body);
    return r;
}

// The value of `key` in a query string "a=1&device=XYZ" ("" when absent).
std::string_view queryValue(std::string_view query, std::string_view key) {
    while (!query.empty()) {
        const std::size_t amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        if (pair.size() > key.size() && pair.substr(0, key.size()) == key &&
            pair[key.size()] == '=')
            return pair.substr(key.size() + 1);
        if (amp == std::string_view::npos) break;
        query.remove_prefix(amp + 1);
    }
    return {};
}

double steadySeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

} // namespace

const char* statusReason(int status) {
    switch (status) {
    case 200:
        return "OK";
    case 204:
        return "No Content";
    case 400:
        return "Bad Request";
    case 403:
        return "Forbidden";
    case 404:
        return "Not Found";
    case 405:
        return "Method Not Allowed";
    case 409:
        return "Conflict";
    case 413:
        return "Content Too Large";
    case 415:
        return "Unsupported Media Type";
    case 421:
        return "Misdirected Request";
    case 422:
        return "Unprocessable Content";
    case 429:
        return "Too Many Requests";
    case 431:
        return "Request Header Fields Too Large";
    case 503:
        return "Service Unavailable";
    default:
        return "Error";
    }
}

std::string randomPollToken(std::size_t length) {
    static constexpr std::string_view kAlphabet = "23456789abcdefghjkmnpqrstuvwxyz"; // 31
    std::random_device source;                                                       // OS
    std::uniform_int_distribution<std::size_t> pick(0, kAlphabet.size() - 1);
    std::string token;
    for (std::size_t i = 0; i < length; ++i) token += kAlphabet[pick(source)];
    return token;
}

bool isDeviceId(std::string_view id) {
    return id.size() >= kPollMinDeviceId && id.size() <= kPollMaxDeviceId &&
           std::all_of(id.begin(), id.end(), [](char c) {
               return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
           });
}

std::string phoneViewJson(const PhoneView& v) {
    nlohmann::json j;
    j["asking"] = v.asking;
    j["open"] = v.open;
    j["step"] = v.step;
    j["round"] = v.round;
    j["question"] = v.question;
    j["choices"] = v.choices;
    j["mine"] = v.mine ? nlohmann::json(*v.mine) : nlohmann::json(nullptr);
    j["changed"] = v.setupChanged;
    // Invalid UTF-8 in a lesson's text is replaced, never a failure.
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

const std::vector<std::pair<std::string, std::string>>& PollProtocol::safetyHeaders() {
    static const std::vector<std::pair<std::string, std::string>> headers = {
        {"Cache-Control", "no-store"},
        {"X-Content-Type-Options", "nosniff"},
        // "no-referrer" would make a browser send "Origin: null" with the page's own POST.
        {"Referrer-Policy", "same-origin"},
        {"X-Frame-Options", "DENY"},
        {"Cross-Origin-Resource-Policy", "same-origin"},
        {"Content-Security-Policy",
         "default-src 'none'; script-src 'self'; style-src 'self'; connect-src 'self'; "
         "img-src data:; base-uri 'none'; form-action 'none'; frame-ancestors 'none'"},
    };
    return headers;
}

PollResponse PollProtocol::refusal(int status, std::string_view why) {
    return text(status, why);
}

PollProtocol::PollProtocol(PollState& state, std::string authority, std::string token, Clock clock)
    : state_(state), authority_(std::move(authority)), token_(std::move(token)),
      clock_(clock ? std::move(clock) : Clock(steadySeconds)) {}

bool PollProtocol::allow(const std::string& device) {
    const double now = clock_();
    auto it = buckets_.find(device);
    if (it == buckets_.end()) {
        if (buckets_.size() >= kMaxPollDevices) return false;
        it = buckets_.emplace(device, Bucket{kPollBurst, now}).first;
    }
    Bucket& b = it->second;
    b.tokens = std::min(kPollBurst, b.tokens + std::max(0.0, now - b.at) * kPollRate);
    b.at = now;
    if (b.tokens < 1.0) return false;
    b.tokens -= 1.0;
    return true;
}

PollResponse PollProtocol::handle(const PollRequest& request) {
    // The Host header must name the served address: a page of another site that made its name
    // resolve to this address (DNS rebinding) sends its own name.
    if (!equalsIgnoreCase(request.host, authority_))
        return text(421, "this poll is served as " + authority_);
    std::string_view target = request.target;
    std::string_view query;
    if (const std::size_t q = target.find('?'); q != std::string_view::npos) {
        query = target.substr(q + 1);
        target = target.substr(0, q);
    }
    if (target.empty() || target[0] != '/') return text(400, "the path must start with /");
    target.remove_prefix(1);
    const std::size_t slash = target.find('/');
    if (!sameToken(target.substr(0, slash), token_)) return text(403, "wrong or missing token");
    const std::string_view rest =
        slash == std::string_view::npos ? std::string_view{} : target.substr(slash + 1);

    // Every request of another site is refused (a browser says so in Sec-Fetch-Site and, for a
    // POST, in Origin); a phone's own page is same-origin or typed in (none).
    if (!request.fetchSite.empty() && request.fetchSite != "same-origin" &&
        request.fetchSite != "none")
        return text(403, "cross-site request");
    if (!request.origin.empty() && request.origin != "http://" + authority_)
        return text(403, "cross-site request");

    const bool get = request.method == "GET";
    if (rest.empty() || rest == "index.html") return get ? page() : text(405, "GET the page");
    if (rest == "poll.js")
        return get ? file(poll_page::poll_js, "text/javascript; charset=utf-8")
                   : text(405, "GET the script");
    if (rest == "poll.css")
        return get ? file(poll_page::poll_css, "text/css; charset=utf-8")
                   : text(405, "GET the style");
    if (rest == "state") return get ? state(query) : text(405, "GET the state");
    if (rest == "vote") return request.method == "POST" ? vote(request) : text(405, "POST a vote");
    return text(404, "no such page");
}

PollResponse PollProtocol::page() const {
    std::string html(poll_page::index_html);
    static constexpr std::string_view kBase = "{{BASE}}";
    for (std::size_t at; (at = html.find(kBase)) != std::string::npos;)
        html.replace(at, kBase.size(), "/" + token_);
    return file(html, "text/html; charset=utf-8");
}

PollResponse PollProtocol::state(std::string_view query) {
    const std::string device(queryValue(query, "device"));
    if (!device.empty()) {
        if (!isDeviceId(device)) return text(400, "device: 8 to 64 of A-Z a-z 0-9 - _");
        if (!allow(device)) return text(429, "too many requests from this device");
    }
    PollResponse r = file(phoneViewJson(state_.view(device)), "application/json");
    return r;
}

PollResponse PollProtocol::vote(const PollRequest& request) {
    // JSON only: a form of another site cannot send it without asking first (CORS), and this
    // server answers no such question.
    const std::string_view type =
        std::string_view(request.contentType).substr(0, request.contentType.find(';'));
    if (!equalsIgnoreCase(type, "application/json"))
        return text(415, "send the vote as application/json");
    if (request.body.size() > kPollMaxBody) return text(413, "the body is too large");
    const nlohmann::json body = nlohmann::json::parse(request.body, nullptr, false);
    if (body.is_discarded() || !body.is_object())
        return text(400, "the body must be a JSON object {\"device\": ID, \"choice\": INDEX}");
    if (body.size() != 2 || !body.contains("device") || !body.contains("choice"))
        return text(400, "the body must have exactly \"device\" and \"choice\"");
    const nlohmann::json& device = body["device"];
    const nlohmann::json& choice = body["choice"];
    if (!device.is_string() || !isDeviceId(device.get_ref<const std::string&>()))
        return text(400, "device: 8 to 64 of A-Z a-z 0-9 - _");
    if (!choice.is_number_integer()) return text(400, "choice: an integer index");
    const std::string& id = device.get_ref<const std::string&>();
    if (!allow(id)) return text(429, "too many requests from this device");
    const long long index = choice.get<long long>();
    const int at = index < 0 || index > kMaxPollChoices ? -1 : static_cast<int>(index);
    switch (state_.vote(id, at)) {
    case PollState::Vote::Counted: {
        PollResponse r;
        r.status = 204;
        return r;
    }
    case PollState::Vote::Closed:
        return text(409, "the vote is closed");
    case PollState::Vote::OutOfRange:
        return text(422, "no such choice");
    case PollState::Vote::TooManyDevices:
        return text(503, "too many devices");
    }
    return text(503, "unreachable");
}
