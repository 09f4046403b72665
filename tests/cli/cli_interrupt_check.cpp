// Ctrl+C during a long `sandbox-cli run` (issue 13): the run stops after the current frame and
// still prints its summary, a valid JSON object with "interrupted": true, and exits 130. The
// signal is sent once the first progress line (--progress: one a second) has been read, so the
// handler is certainly installed and the run is under way; no clock is read here.
// Usage: cli_interrupt_check SANDBOX_CLI SCENE
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <string>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

int fail(const std::string& why, const std::string& out, const std::string& err) {
    std::fprintf(stderr, "FAIL: %s\nstdout:\n%s\nstderr:\n%s\n", why.c_str(), out.c_str(),
                 err.c_str());
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) return 2;
    int outPipe[2], errPipe[2];
    if (pipe(outPipe) != 0 || pipe(errPipe) != 0) return 2;
    const pid_t child = fork();
    if (child < 0) return 2;
    if (child == 0) {
        dup2(outPipe[1], 1);
        dup2(errPipe[1], 2);
        close(outPipe[0]), close(errPipe[0]), close(outPipe[1]), close(errPipe[1]);
        // The whole frame budget: it never ends by itself within the test's time.
        execl(argv[1], argv[1], "run", argv[2], "--steps", "10000000", "--json", "--progress",
              static_cast<char*>(nullptr));
        _exit(127);
    }
    close(outPipe[1]), close(errPipe[1]);
    std::string out, err;
    bool sent = false, outOpen = true, errOpen = true;
    while (outOpen || errOpen) {
        pollfd fds[2] = {{outPipe[0], POLLIN, 0}, {errPipe[0], POLLIN, 0}};
        if (poll(fds, 2, -1) < 0) return fail("poll", out, err);
        char buffer[4096];
        for (int k = 0; k < 2; ++k) {
            if (!(fds[k].revents & (POLLIN | POLLHUP))) continue;
            const ssize_t n = read(fds[k].fd, buffer, sizeof buffer);
            if (n <= 0) {
                (k == 0 ? outOpen : errOpen) = false;
                continue;
            }
            (k == 0 ? out : err).append(buffer, static_cast<size_t>(n));
        }
        if (!sent && err.find("sandbox-cli run: frame ") != std::string::npos &&
            err.find('\n') != std::string::npos) {
            kill(child, SIGINT);
            sent = true;
        }
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!sent) return fail("no progress line before the end", out, err);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 130)
        return fail("expected exit 130, got status " + std::to_string(status), out, err);
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(out);
    } catch (const std::exception& e) {
        return fail(std::string("stdout is not one JSON object: ") + e.what(), out, err);
    }
    if (!j.value("interrupted", false)) return fail("\"interrupted\" is not true", out, err);
    const auto steps = j.value("steps", std::int64_t{-1});
    if (steps <= 0 || steps >= 10000000) return fail("steps out of range", out, err);
    if (!j["sim_time"].is_number() || !j["kinetic_energy"].is_number())
        return fail("missing numbers", out, err);
    std::printf("interrupted after %lld steps: ok\n", static_cast<long long>(steps));
    return 0;
}
