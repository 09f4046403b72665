// The poll's two requests on civetweb (Debian's libcivetweb-dev), to measure it against the
// Beast server the poll uses (tests/bench/poll_bench.py --server civetweb; built by
// poll_bench.sh, not by CMake). GET /t/state answers a small JSON, POST /t/vote 204. Prints the
// port on its first line. Binds 127.0.0.1 only; civetweb's default of 50 worker threads.
#include <civetweb.h>

#include <cstdio>
#include <cstring>
#include <unistd.h>

static int handle(mg_connection* conn, void*) {
    const mg_request_info* info = mg_get_request_info(conn);
    char body[2048];
    while (mg_read(conn, body, sizeof body) > 0) {
    }
    if (std::strcmp(info->request_method, "POST") == 0) {
        mg_printf(conn, "HTTP/1.1 204 No Content\r\nContent-Length: 0\r\n\r\n");
        return 204;
    }
    const char* json = "{\"asking\":true,\"open\":true,\"step\":2,\"round\":1}";
    mg_printf(conn,
              "HTTP/1.1 200 OK\r\nContent-Type: application/json\r\nContent-Length: %zu\r\n\r\n%s",
              std::strlen(json), json);
    return 200;
}

int main() {
    const char* options[] = {"listening_ports", "127.0.0.1:0", "enable_keep_alive", "yes",
                             nullptr};
    mg_init_library(0);
    mg_callbacks callbacks{};
    mg_context* ctx = mg_start(&callbacks, nullptr, options);
    if (!ctx) return 1;
    mg_set_request_handler(ctx, "/t/", handle, nullptr);
    mg_server_port ports[1];
    if (mg_get_server_ports(ctx, 1, ports) < 1) return 1;
    std::printf("%d\n", ports[0].port);
    std::fflush(stdout);
    for (;;) pause();
}
