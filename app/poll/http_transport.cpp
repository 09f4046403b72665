#include "http_transport.h"

#include "http_request.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <algorithm>
#include <atomic>
#include <optional>
#include <thread>

#include <sys/resource.h>

namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

struct Shared {
    PollHandler handler;
    std::atomic<int> connections{0};
};

// One phone's connection: wait (idle) for a request's first byte, read the request within its
// time and size, answer, and wait again; any error or timeout drops the connection.
class Connection : public std::enable_shared_from_this<Connection> {
  public:
    Connection(tcp::socket socket, Shared& shared) : stream_(std::move(socket)), shared_(shared) {
        ++shared_.connections;
    }
    ~Connection() { --shared_.connections; }

    void start() { waitForRequest(); }

  private:
    void waitForRequest() {
        if (buffer_.size() > 0) return readRequest(); // pipelined: already here
        stream_.expires_after(std::chrono::seconds(kPollIdleSeconds));
        stream_.async_read_some(buffer_.prepare(512),
                                [self = shared_from_this()](beast::error_code ec, std::size_t n) {
                                    if (ec) return self->drop();
                                    self->buffer_.commit(n);
                                    self->readRequest();
                                });
    }

    void readRequest() {
        parser_.emplace();
        capRequest(*parser_);
        stream_.expires_after(std::chrono::seconds(kPollRequestSeconds));
        http::async_read(
            stream_, buffer_, *parser_,
            [self = shared_from_this()](beast::error_code ec, std::size_t) { self->onRead(ec); });
    }

    void onRead(beast::error_code ec) {
        if (ec) {
            if (std::optional<PollResponse> refusal = readRefusal(ec))
                return respond(*refusal, false);
            return drop(); // closed, timed out, reset
        }
        respond(shared_.handler(pollRequest(parser_->get())), parser_->get().keep_alive());
    }

    void respond(const PollResponse& r, bool keepAlive) {
        response_ = {};
        response_.version(11);
        response_.result(static_cast<unsigned>(r.status));
        response_.reason(statusReason(r.status));
        response_.set(http::field::server, "sandbox-poll");
        for (const auto& [name, value] : PollProtocol::safetyHeaders()) response_.set(name, value);
        for (const auto& [name, value] : r.headers) response_.set(name, value);
        if (!r.contentType.empty()) response_.set(http::field::content_type, r.contentType);
        response_.body() = r.body;
        response_.keep_alive(keepAlive);
        response_.prepare_payload();
        stream_.expires_after(std::chrono::seconds(kPollRequestSeconds));
        http::async_write(
            stream_, response_,
            [self = shared_from_this(), keepAlive](beast::error_code ec, std::size_t) {
                if (ec) return self->drop();
                if (!keepAlive) return self->lingerAndDrop();
                self->waitForRequest();
            });
    }

    // After the last response: stop sending, then read and discard what the phone still sends
    // (the rest of a body over the cap) for a moment before closing. Closing with unread bytes
    // would reset the connection, and the phone could lose the response it was sent.
    void lingerAndDrop() {
        beast::error_code ignored;
        stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
        buffer_.clear();
        stream_.expires_after(std::chrono::seconds(2));
        stream_.async_read_some(buffer_.prepare(1024),
                                [self = shared_from_this()](beast::error_code ec, std::size_t n) {
                                    if (ec || (self->discarded_ += n) > 65536) return self->drop();
                                    self->buffer_.clear();
                                    self->lingerAndDrop();
                                });
    }

    void drop() {
        beast::error_code ignored;
        stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
        stream_.close();
    }

    beast::tcp_stream stream_;
    Shared& shared_;
    beast::flat_buffer buffer_{kPollMaxHeader + kPollMaxBody + 1024};
    std::optional<HttpParser> parser_;
    http::response<http::string_body> response_;
    std::size_t discarded_ = 0; // bytes read and dropped after the last response
};

class HttpTransport final : public PollTransport {
  public:
    HttpTransport() : acceptor_(io_) {}
    ~HttpTransport() override { stop(); }

    bool listen(const std::string& address, int port, std::string* error) {
        beast::error_code ec;
        const net::ip::address ip = net::ip::make_address(address, ec);
        if (ec) {
            if (error) *error = "not an IP address: " + address;
            return false;
        }
        const tcp::endpoint endpoint(ip, static_cast<unsigned short>(port));
        const std::string host = ip.is_v6() ? "[" + address + "]" : address;
        acceptor_.open(endpoint.protocol(), ec);
        if (!ec) acceptor_.set_option(net::socket_base::reuse_address(true), ec);
        if (!ec) acceptor_.bind(endpoint, ec);
        if (!ec) acceptor_.listen(1024, ec);
        unsigned short bound = 0;
        if (!ec) bound = acceptor_.local_endpoint(ec).port();
        if (ec) {
            if (error)
                *error =
                    "cannot listen on " + host + ":" + std::to_string(port) + ": " + ec.message();
            return false;
        }
        authority_ = host + ":" + std::to_string(bound);
        maxConnections_ = connectionCap();
        return true;
    }

    std::string authority() const override { return authority_; }

    void serve(PollHandler handler) override {
        shared_.handler = std::move(handler);
        accept();
        thread_ = std::thread([this] { io_.run(); });
    }

    void stop() override {
        if (stopped_.exchange(true)) return;
        io_.stop();
        if (thread_.joinable()) thread_.join();
        beast::error_code ignored;
        acceptor_.close(ignored);
    }

  private:
    void accept() {
        acceptor_.async_accept([this](beast::error_code ec, tcp::socket socket) {
            if (!acceptor_.is_open()) return;
            if (ec) { // out of file descriptors, say: try again in a moment, not in a loop
                retry_.expires_after(std::chrono::milliseconds(100));
                retry_.async_wait([this](beast::error_code) { accept(); });
                return;
            }
            if (shared_.connections.load() >= maxConnections_) {
                socket.close(ec); // full: dropped at once
            } else {
                socket.set_option(tcp::no_delay(true), ec);
                std::make_shared<Connection>(std::move(socket), shared_)->start();
            }
            accept();
        });
    }

    // kPollMaxConnections, or fewer where the process may not open that many files: the soft
    // limit is raised to the hard one first (up to what the cap needs), with a margin kept for
    // the rest of the program.
    static int connectionCap() {
        constexpr rlim_t kWanted = kPollMaxConnections + 256;
        rlimit limit{};
        if (getrlimit(RLIMIT_NOFILE, &limit) != 0) return 256;
        if (limit.rlim_cur < kWanted && limit.rlim_cur != RLIM_INFINITY) {
            rlimit raised = limit;
            raised.rlim_cur =
                limit.rlim_max == RLIM_INFINITY ? kWanted : std::min(kWanted, limit.rlim_max);
            if (setrlimit(RLIMIT_NOFILE, &raised) == 0) limit = raised;
        }
        if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur >= kWanted)
            return kPollMaxConnections;
        return static_cast<int>(std::max<rlim_t>(limit.rlim_cur, 320) - 256);
    }

    // Destroyed in reverse: the io_context (and with it every connection) after the acceptor,
    // `shared_` outliving both.
    Shared shared_;
    net::io_context io_{1};
    tcp::acceptor acceptor_;
    net::steady_timer retry_{io_};
    int maxConnections_ = kPollMaxConnections;
    std::thread thread_;
    std::atomic<bool> stopped_{false};
    std::string authority_;
};

} // namespace

std::unique_ptr<PollTransport> listenHttp(const std::string& address, int port,
                                          std::string* error) {
    auto transport = std::make_unique<HttpTransport>();
    if (!transport->listen(address, port, error)) return nullptr;
    return transport;
}
