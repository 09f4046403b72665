// The poll's two requests on cpp-httplib (Debian's libcpp-httplib-dev), to measure it against
// the Beast server the poll uses (tests/bench/poll_bench.py --server httplib; built by
// poll_bench.sh, not by CMake). GET /t/state answers a small JSON, POST /t/vote 204. Prints the
// port on its first line. Binds 127.0.0.1 only.
#include <httplib.h>

#include <cstdio>

int main() {
    httplib::Server server;
    server.Get("/t/state", [](const httplib::Request&, httplib::Response& res) {
        res.set_content("{\"asking\":true,\"open\":true,\"step\":2,\"round\":1}",
                        "application/json");
    });
    server.Post("/t/vote", [](const httplib::Request&, httplib::Response& res) {
        res.status = 204;
    });
    const int port = server.bind_to_any_port("127.0.0.1");
    std::printf("%d\n", port);
    std::fflush(stdout);
    server.listen_after_bind();
}
