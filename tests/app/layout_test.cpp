// The docked layout, end to end: `sandbox-offscreen --layout-json` for every shipped scene at the
// classroom sizes (1280x720 and 1920x1080, UI scale 1 and 1.5) with every overlay on. No window
// may cover the world's rectangle, every window lies inside the image, and the scene view holds
// the world. In present mode (--present) there is no window at all.
#include "overlays.h"
#include "scene_library.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Every row of the overlay table, so a new overlay is checked too.
const std::string kEveryOverlay = [] {
    std::string list;
    for (const std::string& name : overlayNames()) list += (list.empty() ? "" : ",") + name;
    return list;
}();

struct Rect {
    double x = 0, y = 0, w = 0, h = 0;
};

Rect rectOf(const nlohmann::json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(),
            j.at(3).get<double>()};
}

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

bool inside(const Rect& in, const Rect& out) {
    return in.x >= out.x && in.y >= out.y && in.x + in.w <= out.x + out.w &&
           in.y + in.h <= out.y + out.h;
}

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

int run(const std::string& commandLine, std::string* output) {
    FILE* pipe = popen(("env -u DISPLAY " + commandLine + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) *output += buffer;
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Case {
    std::string scene; // file stem
    int width = 1280, height = 720;
    double uiScale = 1.0;
    std::string name() const {
        char text[160];
        std::snprintf(text, sizeof text, "%s_%dx%d_ui%s", scene.c_str(), width, height,
                      uiScale == 1.0 ? "1" : "1_5");
        return text;
    }
};

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name();
}

std::vector<Case> cases() {
    std::vector<Case> out;
    for (const SceneEntry& e : listScenes(SANDBOX_SCENES_DIR)) {
        const std::string stem = fs::path(e.path).stem().string();
        for (const auto& size : {std::pair<int, int>{1280, 720}, {1920, 1080}}) {
            for (double scale : {1.0, 1.5}) out.push_back({stem, size.first, size.second, scale});
        }
    }
    return out;
}

fs::path outputDir() {
    const fs::path dir = fs::path(SANDBOX_SCREENSHOT_OUTPUT_DIR) / "layout";
    fs::create_directories(dir);
    return dir;
}

nlohmann::json layoutOf(const Case& c, const std::string& extra) {
    const fs::path png = outputDir() / (c.name() + extra.substr(0, extra.find(' ')) + ".png");
    const fs::path json = outputDir() / (c.name() + extra.substr(0, extra.find(' ')) + ".json");
    fs::remove(json);
    char size[32];
    std::snprintf(size, sizeof size, "%dx%d", c.width, c.height);
    std::string output;
    const int code =
        run(quote(SANDBOX_OFFSCREEN_EXE) + " " + quote(c.scene) + " --frames 30 --show " +
                kEveryOverlay + " --size " + size + " --ui-scale " + std::to_string(c.uiScale) +
                " " + extra + " --screenshot " + quote(png.string()) + " --layout-json " +
                quote(json.string()),
            &output);
    EXPECT_EQ(code, 0) << output;
    std::ifstream in(json);
    EXPECT_TRUE(in.good()) << "no " << json << "\n" << output;
    if (!in) return {};
    return nlohmann::json::parse(in);
}

class EveryOverlay : public ::testing::TestWithParam<Case> {};

TEST_P(EveryOverlay, NoWindowCoversTheWorldAndNoneLeavesTheImage) {
    const Case& c = GetParam();
    const nlohmann::json j = layoutOf(c, "");
    ASSERT_TRUE(j.is_object());
    const Rect image{0, 0, double(c.width), double(c.height)};
    const Rect scene = rectOf(j.at("scene"));
    const Rect world = rectOf(j.at("world"));
    EXPECT_TRUE(inside(scene, image));
    EXPECT_TRUE(inside(world, scene)) << "the world is not inside the scene view";
    EXPECT_GT(world.w, 0.0);
    EXPECT_GT(world.h, 0.0);
    const auto& windows = j.at("windows");
    EXPECT_GE(windows.size(), 7u) << "the panel and six overlay windows";
    for (const auto& w : windows) {
        const std::string name = w.at("name").get<std::string>();
        const Rect r = rectOf(w.at("rect"));
        EXPECT_TRUE(inside(r, image)) << name << " leaves the image";
        EXPECT_FALSE(overlap(r, world)) << name << " covers the world";
        EXPECT_GT(r.w, 0.0) << name;
        EXPECT_GT(r.h, 0.0) << name;
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryOverlay, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.name();
                         });

TEST(PresentMode, LeavesNoWindowAndTheWholeImageToTheScene) {
    for (double scale : {1.0, 1.5}) {
        const Case c{"lecture_example_1", 1920, 1080, scale};
        const nlohmann::json j = layoutOf(c, "--present");
        ASSERT_TRUE(j.is_object());
        EXPECT_TRUE(j.at("windows").empty()) << j.dump();
        const Rect scene = rectOf(j.at("scene"));
        EXPECT_EQ(scene.w, 1920.0);
        EXPECT_EQ(scene.h, 1080.0);
        EXPECT_TRUE(inside(rectOf(j.at("world")), scene));
    }
}

} // namespace
