// Screenshot tests: `sandbox-offscreen` renders the shipped scenes (OSMesa, no display) and the
// images are compared with tests/golden/ under a tolerance that survives small rasteriser
// differences; semantic checks look for a block's colour where the engine says the block is and
// for the controls panel. A failing comparison leaves NAME.png (actual) and NAME.diff.png in
// the build directory's screenshot-output/.
#include "app.h"
#include "image_compare.h"
#include "palette.h"
#include "scene.h"
#include "scene_library.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Tolerance: a pixel differs when a channel is off by more than 24 counts; a comparison fails
// when more than 0.5% of the pixels differ.
constexpr int kChannelThreshold = 24;
constexpr double kMaxDifferingFraction = 0.005;

std::string quote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

struct RunResult {
    int exitCode = -1;
    std::string output;
};

// Runs a command line through the shell with DISPLAY unset; stdout and stderr captured.
RunResult run(const std::string& commandLine) {
    RunResult result;
    const std::string command = "env -u DISPLAY " + commandLine + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) result.output += buffer;
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

fs::path outputDir() {
    const fs::path dir = SANDBOX_SCREENSHOT_OUTPUT_DIR;
    fs::create_directories(dir);
    return dir;
}

// Renders `args` (sandbox-offscreen's arguments) to `png`; fails the test on a non-zero exit.
Image render(const std::string& args, const fs::path& png) {
    const RunResult r =
        run(quote(SANDBOX_OFFSCREEN_EXE) + " " + args + " --screenshot " + quote(png.string()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const Image image = loadPng(png.string());
    EXPECT_FALSE(image.empty()) << "no image at " << png;
    return image;
}

struct Case {
    std::string name;
    std::string args;
};

std::vector<Case> loadCases() {
    std::vector<Case> cases;
    std::ifstream in(fs::path(SANDBOX_GOLDEN_DIR) / "cases.txt");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        Case c;
        words >> c.name;
        std::getline(words, c.args);
        cases.push_back(c);
    }
    return cases;
}

void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name << ":" << c.args;
}

class ScreenshotGolden : public ::testing::TestWithParam<Case> {};

TEST_P(ScreenshotGolden, MatchesGolden) {
    const Case& c = GetParam();
    const fs::path golden = fs::path(SANDBOX_GOLDEN_DIR) / (c.name + ".png");
    const fs::path actualPath = outputDir() / (c.name + ".png");
    const Image actual = render(c.args, actualPath);
    const Image expected = loadPng(golden.string());
    ASSERT_FALSE(expected.empty())
        << "missing golden " << golden << " (tests/golden/regenerate.sh writes it)";
    const Comparison cmp = compareImages(expected, actual, kChannelThreshold);
    ASSERT_TRUE(cmp.sameSize) << "size differs from " << golden;
    if (cmp.fraction() > kMaxDifferingFraction) {
        const fs::path diffPath = outputDir() / (c.name + ".diff.png");
        savePng(diffPath.string(), diffImage(expected, actual, kChannelThreshold));
        FAIL() << c.name << ": " << cmp.differing << " of " << cmp.total << " pixels differ ("
               << 100.0 * cmp.fraction() << "%)\n  actual: " << actualPath
               << "\n  diff:   " << diffPath << "\n  golden: " << golden;
    }
}

INSTANTIATE_TEST_SUITE_P(Shipped, ScreenshotGolden, ::testing::ValuesIn(loadCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.name;
                         });

// The engine's view of a scene after `frames` frames, and the camera the app would use.
App simulate(const std::string& sceneName, int frames, int width, int height, bool ui) {
    App app;
    const std::string path = resolveScenePath(sceneName, SANDBOX_SCENES_DIR);
    EXPECT_TRUE(loadScene(app, path)) << app.ui.messages.error;
    for (int i = 0; i < frames; ++i) stepSimulation(app);
    app.view.uiVisible = ui;
    updateCamera(app, width, height);
    return app;
}

// The share of sample points inside block `i` (its inner half, on a 7 x 7 grid) whose colour is
// within `tolerance` of the block's colour.
double colourMatch(const Image& image, const App& app, int i, int tolerance) {
    const Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
    const Color want = app.sim.blockDisplayColor(i);
    int hits = 0, samples = 0;
    for (int sy = 0; sy < 7; ++sy) {
        for (int sx = 0; sx < 7; ++sx) {
            const Vec2 p = b.position + Vec2{(sx / 6.0 - 0.5) * 0.5 * b.size.x,
                                             (sy / 6.0 - 0.5) * 0.5 * b.size.y};
            const Vec2 s = app.view.camera.worldToScreen(p);
            const int x = static_cast<int>(s.x), y = static_cast<int>(s.y);
            if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
            ++samples;
            const int r = image.at(x, y, 0), g = image.at(x, y, 1), bl = image.at(x, y, 2);
            if (std::abs(r - int(want.r * 255)) <= tolerance &&
                std::abs(g - int(want.g * 255)) <= tolerance &&
                std::abs(bl - int(want.b * 255)) <= tolerance) {
                ++hits;
            }
        }
    }
    return samples ? double(hits) / samples : 0.0;
}

void expectBlocksWhereTheEngineSays(const std::string& scene, int frames) {
    const fs::path png = outputDir() / ("semantic_" + scene + ".png");
    const Image image = render(scene + " --frames " + std::to_string(frames) + " --show none", png);
    ASSERT_FALSE(image.empty());
    const App app = simulate(scene, frames, image.width, image.height, false);
    int checked = 0;
    for (int i = 0; i < static_cast<int>(app.sim.world().blocks.size()); ++i) {
        const Block& b = app.sim.world().blocks[static_cast<std::size_t>(i)];
        if (!b.isDynamic() || app.view.camera.metresToPixels(std::min(b.size.x, b.size.y)) < 12)
            continue;
        // The block's name is drawn on it: on a small block its anti-aliased letters cover up
        // to about 45% of the sampled centre (the palette's darker red: 29 of 49 samples match);
        // a block drawn elsewhere matches next to none.
        EXPECT_GE(colourMatch(image, app, i, 40), 0.5)
            << scene << ": block " << app.sim.blockDisplayName(i) << " at (" << b.position.x << ", "
            << b.position.y << ") not drawn there; see " << png;
        ++checked;
    }
    EXPECT_GT(checked, 0);
}

TEST(ScreenshotSemantic, BlocksAreDrawnWhereTheEngineSaysLectureExample) {
    expectBlocksWhereTheEngineSays("lecture_example_1", 45);
}

TEST(ScreenshotSemantic, BlocksAreDrawnWhereTheEngineSaysBouncingSquares) {
    expectBlocksWhereTheEngineSays("bouncing_squares", 90);
}

// The share of a 9 x 9 grid of points, spread over the world's bounds (or, with `outside`, a
// band 30 px beyond its left and right walls), whose colour is `want` to within 2 counts (the
// clear's colour, exactly but for rounding: the grid's thin lines and the blocks cover a few).
double shareOfColour(const Image& image, const App& app, const Color& want, bool outside) {
    const Bounds& bounds = app.sim.world().bounds;
    const Vec2 lo = app.view.camera.worldToScreen(bounds.min);
    const Vec2 hi = app.view.camera.worldToScreen(bounds.max);
    int hits = 0, samples = 0;
    for (int sy = 0; sy < 9; ++sy) {
        for (int sx = 0; sx < 9; ++sx) {
            const double fy = (sy + 0.3) / 9.0; // off the grid's lines (every 0.5 m)
            double x = std::min(lo.x, hi.x) + (sx + 0.3) / 9.0 * std::abs(hi.x - lo.x);
            if (outside) x = sx < 5 ? std::min(lo.x, hi.x) - 30 : std::max(lo.x, hi.x) + 30;
            const double y = std::min(lo.y, hi.y) + fy * std::abs(hi.y - lo.y);
            const int px = static_cast<int>(x), py = static_cast<int>(y);
            if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
            ++samples;
            hits += std::abs(image.at(px, py, 0) - int(std::lround(want.r * 255))) <= 2 &&
                    std::abs(image.at(px, py, 1) - int(std::lround(want.g * 255))) <= 2 &&
                    std::abs(image.at(px, py, 2) - int(std::lround(want.b * 255))) <= 2;
        }
    }
    return samples ? double(hits) / samples : 0.0;
}

// The arena (inside the bounds) in its theme's colour, the rest of the view in the background's,
// in both themes (the arena's clear once never ran: its rows were taken the wrong way up).
TEST(ScreenshotSemantic, ArenaAndBackgroundEachInTheirThemesColour) {
    for (const bool light : {false, true}) {
        const std::string theme = light ? "light" : "dark";
        const fs::path png = outputDir() / ("semantic_arena_" + theme + ".png");
        const Image image = render("lecture_example_1 --show none --theme " + theme, png);
        ASSERT_FALSE(image.empty());
        const App app = simulate("lecture_example_1", 0, image.width, image.height, false);
        const SceneTheme& colours = sceneTheme(light);
        EXPECT_GE(shareOfColour(image, app, colours.arena, false), 0.8) << png;
        EXPECT_EQ(shareOfColour(image, app, colours.background, false), 0.0) << png;
        EXPECT_GE(shareOfColour(image, app, colours.background, true), 0.8) << png;
    }
}

// The controls panel's title bar: ImGuiCol_TitleBg of the theme (ui_style.cpp), 41 74 122.
bool titleBarAt(const Image& image, int x, int y) {
    return std::abs(image.at(x, y, 0) - 41) <= 12 && std::abs(image.at(x, y, 1) - 74) <= 12 &&
           std::abs(image.at(x, y, 2) - 122) <= 12;
}

TEST(ScreenshotSemantic, ControlsPanelIsPresentAndHiddenByShowNone) {
    const Image withUi = render("lecture_example_1", outputDir() / "semantic_panel.png");
    ASSERT_FALSE(withUi.empty());
    const App app = simulate("lecture_example_1", 0, withUi.width, withUi.height, true);
    const int right = static_cast<int>(app.view.camera.viewport().x) - 20;
    EXPECT_TRUE(titleBarAt(withUi, right, 8)) << "no panel title bar at (" << right << ", 8)";
    EXPECT_TRUE(titleBarAt(withUi, right / 2, 4));
    const Image noUi = render("lecture_example_1 --show none", outputDir() / "semantic_noui.png");
    ASSERT_FALSE(noUi.empty());
    EXPECT_FALSE(titleBarAt(noUi, right, 8));
}

// The inspector on the lecture's first worked example after the collision at t = 0.625 s: the
// formula with the numbers filled in (printed by --verbose from the same strings it draws), and
// the window drawn (its title bar colour where the window docks: the top of the right column).
TEST(ScreenshotSemantic, InspectorShowsTheLectureNumbers) {
    const fs::path png = outputDir() / "semantic_inspector.png";
    const RunResult r =
        run(quote(SANDBOX_OFFSCREEN_EXE) +
            " lecture_example_1 --frames 45 --show inspector --verbose --screenshot " +
            quote(png.string()));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("inspector u = (1·6 + 2·0)/(1 + 2) = 2"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("inspector v1' = 2 - 1·(6 - 2) = -2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("inspector v2' = 2 - 1·(0 - 2) = 4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("t = 0.625 s"), std::string::npos) << r.output;
    const Image image = loadPng(png.string());
    ASSERT_FALSE(image.empty());
    int titlePixels = 0;
    for (int y = 0; y < image.height / 8; ++y) {
        titlePixels += titleBarAt(image, image.width - 60, y) ? 1 : 0;
    }
    EXPECT_GT(titlePixels, 10) << "no inspector title bar in the upper right of " << png;
    // Without the overlay, no formula is printed.
    const RunResult none =
        run(quote(SANDBOX_OFFSCREEN_EXE) +
            " lecture_example_1 --frames 45 --verbose --screenshot " + quote(png.string()));
    EXPECT_EQ(none.output.find("inspector u ="), std::string::npos);
}

TEST(ScreenshotCommandLine, SizeIsRespected) {
    const Image image = render("lecture_example_1 --size 640x360", outputDir() / "size.png");
    EXPECT_EQ(image.width, 640);
    EXPECT_EQ(image.height, 360);
}

TEST(ScreenshotCommandLine, BadArgumentsExitNonZeroWithAMessage) {
    const std::string exe = quote(SANDBOX_OFFSCREEN_EXE);
    const fs::path png = outputDir() / "never.png";
    RunResult r = run(exe + " lecture_example_1 --show bogus --screenshot " + quote(png.string()));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("bogus"), std::string::npos) << r.output;
    r = run(exe + " no_such_scene.json --screenshot " + quote(png.string()));
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("no_such_scene"), std::string::npos) << r.output;
    r = run(exe + " lecture_example_1 --size 0x0 --screenshot " + quote(png.string()));
    EXPECT_NE(r.exitCode, 0);
    r = run(exe + " lecture_example_1 --screenshot /nonexistent-dir/a.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_FALSE(fs::exists(png));
}

TEST(ScreenshotCommandLine, SandboxWithoutDisplayRendersTheDefaultScene) {
    const fs::path dir = outputDir() / "no_display";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const RunResult r = run(
        "sh -c " + quote("cd " + quote(dir.string()) + " && exec " + quote(SANDBOX_WINDOW_EXE)));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("sandbox-screenshot.png"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
    EXPECT_FALSE(loadPng((dir / "sandbox-screenshot.png").string()).empty());
}

TEST(ScreenshotCommandLine, SandboxForwardsScreenshotToTheOffscreenRenderer) {
    const fs::path png = outputDir() / "forwarded.png";
    fs::remove(png);
    const RunResult r = run(quote(SANDBOX_WINDOW_EXE) + " lecture_example_1 --screenshot " +
                            quote(png.string()) + " --size 320x200");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(loadPng(png.string()).width, 320);
}

TEST(ScreenshotCommandLine, RecordWritesNumberedFrames) {
    const fs::path dir = outputDir() / "record";
    fs::remove_all(dir);
    const RunResult r = run(quote(SANDBOX_OFFSCREEN_EXE) + " lecture_example_1 --size 320x200 " +
                            "--frames 3 --record " + quote(dir.string()));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    for (int i = 0; i < 3; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.png", i);
        EXPECT_FALSE(loadPng((dir / name).string()).empty()) << name;
    }
    const Image first = loadPng((dir / "frame_00000.png").string());
    const Image last = loadPng((dir / "frame_00002.png").string());
    EXPECT_GT(compareImages(first, last, kChannelThreshold).differing, 0) << "nothing moved";
}

} // namespace
