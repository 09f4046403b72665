// What the offscreen tests read back from sandbox-offscreen: its --layout-json and --text-json
// rectangles ([x, y, w, h], image pixels from the top-left) and the program run through a shell.
// Shared by layout_test.cpp and the lesson sweeps (lesson_sweep_test.cpp, lesson_screens_test.cpp).
#pragma once

#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
};

inline Rect rectOf(const nlohmann::json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(),
            j.at(3).get<double>()};
}

// The two rectangles share an area (touching edges do not count).
inline bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

inline bool inside(const Rect& in, const Rect& out) {
    return in.x >= out.x && in.y >= out.y && in.x + in.w <= out.x + out.w &&
           in.y + in.h <= out.y + out.h;
}

// "[x, y, w, h]" for a failure message.
inline std::string printed(const Rect& r) {
    char text[96];
    std::snprintf(text, sizeof text, "[%g, %g, %g, %g]", r.x, r.y, r.w, r.h);
    return text;
}

// A JSON file the program wrote (a failure, and null, when it is missing).
inline nlohmann::json readJson(const std::filesystem::path& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "no " << path;
    if (!in) return {};
    return nlohmann::json::parse(in);
}

// `s` in single quotes for the shell.
inline std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// Runs `commandLine` without a display (offscreen only), its stdout and stderr into `output`;
// returns its exit code (-1 when it did not exit).
inline int run(const std::string& commandLine, std::string* output) {
    FILE* pipe = popen(("env -u DISPLAY " + commandLine + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) *output += buffer;
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The --screens argument of a sweep's screens ("1280x800@1,1920x1080@1.5"): each screen has
// width, height and uiScale.
template <class Screens> std::string screensOption(const Screens& screens) {
    std::string out;
    for (const auto& s : screens) {
        char item[48];
        std::snprintf(item, sizeof item, "%s%dx%d@%g", out.empty() ? "" : ",", s.width, s.height,
                      s.uiScale);
        out += item;
    }
    return out;
}
