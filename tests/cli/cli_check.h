// Shared by the sandbox-cli check programs: a failure counter and running a command.
#pragma once

#include <cstdio>
#include <iostream>
#include <string>

namespace cli_check {

inline int failures = 0;

inline void check(bool ok, const std::string& what) {
    if (!ok) {
        ++failures;
        std::cerr << "FAILED: " << what << "\n";
    }
}

// Runs a shell command and returns its standard output; `status` gets the exit status.
inline std::string capture(const std::string& command, int& status) {
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return out;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    status = pclose(pipe);
    return out;
}

} // namespace cli_check
