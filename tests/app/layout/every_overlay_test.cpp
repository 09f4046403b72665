// Every shipped scene with every overlay on (issue 39), at a hall projector (1280x800) and at
// 1920x1080, each at UI scales 1 and 1.5: no text is clipped and no window (nor a table in one)
// has to be scrolled sideways to be read. One run of `sandbox-offscreen --record-scenes DIR
// --frames 20 --screens ... --show EVERY` writes each scene's layout and text JSON at each screen
// (nothing rasterised: DIR/WxH_uiS/SCENE.layout.json and SCENE.text.json, and where windows fold
// into tabs, SCENE.folded.text.json and SCENE.folded.layout.json: each folded window as drawn when
// its tab is picked); the figures per screen are printed.
#include "frame_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Every overlay --show knows (docs/cli.md), "none" aside.
constexpr const char* kEveryOverlay = "trails,vectors,plots,inspector,com,poi,contacts,ghost,"
                                      "sidebyside,timeline,velocityspace,cost";

// Each scene a third of a second in (20 frames): the plots have lines, the methods side by side
// their table, the inspector its first collisions where a scene has them that soon.
constexpr int kFrames = 20;

struct Screen {
    int width, height;
    double uiScale;
    const char* dir; // as sandbox-offscreen names it (ClassroomScreen::name)
};
const Screen kScreens[] = {
    {1280, 800, 1.0, "1280x800_ui1"},
    {1280, 800, 1.5, "1280x800_ui1.5"},
    {1920, 1080, 1.0, "1920x1080_ui1"},
    {1920, 1080, 1.5, "1920x1080_ui1.5"},
};

struct Shot {
    const Screen* screen = nullptr;
    std::string scene;
    nlohmann::json layout, texts;
    // The windows folded behind tabs, each drawn with its tab picked: their texts, and what of
    // them scrolls sideways ("sideways").
    nlohmann::json foldedLayout, foldedTexts;
    std::string name() const { return std::string(screen->dir) + " " + scene; }
};

// The shipped scenes by file name (without .json), as sandbox-offscreen names their files.
std::vector<std::string> shippedScenes() {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(SANDBOX_SCENES_DIR))
        if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The one run: every screen, every scene.
const std::vector<Shot>& shots() {
    static const std::vector<Shot> all = [] {
        const fs::path dir = fs::path(SANDBOX_SWEEP_OUTPUT_DIR);
        fs::remove_all(dir);
        const std::string screens = screensOption(kScreens);
        std::string output;
        const int code = run(quote(SANDBOX_OFFSCREEN_EXE) + " --record-scenes " +
                                 quote(dir.string()) + " --frames " + std::to_string(kFrames) +
                                 " --screens " + screens + " --show " + kEveryOverlay,
                             &output);
        EXPECT_EQ(code, 0) << output;
        std::vector<Shot> out;
        for (const Screen& screen : kScreens) {
            for (const std::string& scene : shippedScenes()) {
                const fs::path at = dir / screen.dir;
                Shot s{&screen,
                       scene,
                       readJson(at / (scene + ".layout.json")),
                       readJson(at / (scene + ".text.json")),
                       readJson(at / (scene + ".folded.layout.json")),
                       readJson(at / (scene + ".folded.text.json"))};
                if (s.texts.is_object()) s.texts = s.texts.at("texts");
                if (s.foldedTexts.is_object()) s.foldedTexts = s.foldedTexts.at("texts");
                out.push_back(std::move(s));
            }
        }
        return out;
    }();
    return all;
}

TEST(EveryOverlay, RendersEveryShippedSceneAtEveryScreen) {
    ASSERT_GE(shippedScenes().size(), 20u); // the scenes directory, not an empty one
    ASSERT_EQ(shots().size(), std::size(kScreens) * shippedScenes().size());
    for (const Shot& s : shots()) {
        ASSERT_TRUE(s.layout.is_object()) << s.name();
        EXPECT_FALSE(s.texts.empty()) << s.name();
        ASSERT_TRUE(s.foldedLayout.is_object()) << s.name();
        ASSERT_TRUE(s.foldedTexts.is_array()) << s.name();
        // Every overlay on: each of its windows is shown, or folded behind a tab and drawn with
        // it picked (a window missing would pass unseen).
        std::vector<std::string> windows;
        for (const auto& w : s.layout.at("windows")) windows.push_back(w.at("name"));
        if (s.layout.contains("folded"))
            for (const auto& w : s.layout.at("folded")) {
                windows.push_back(w.at("name"));
                const std::string name = w.at("name");
                EXPECT_TRUE(std::any_of(s.foldedTexts.begin(), s.foldedTexts.end(),
                                        [&](const auto& t) { return t.at("window") == name; }))
                    << s.name() << ": folded window " << name << " drawn with no text";
            }
        for (const char* title :
             {"Plots", "Collision inspector", "Momenta", "Methods side by side", "Timeline"})
            EXPECT_NE(std::find(windows.begin(), windows.end(), title), windows.end())
                << s.name() << ": no window " << title;
    }
}

TEST(EveryOverlay, NoTextIsClipped) {
    for (const Screen& screen : kScreens) {
        int clipped = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen) continue;
            for (const nlohmann::json* texts : {&s.texts, &s.foldedTexts})
                for (const auto& t : *texts) {
                    if (!t.at("clipped").get<bool>()) continue;
                    ++clipped;
                    ADD_FAILURE() << s.name() << ": '" << t.at("text").get<std::string>() << "' in "
                                  << t.at("window").get<std::string>() << " at "
                                  << printed(rectOf(t.at("rect"))) << " clipped";
                }
        }
        std::printf("%s: %d clipped texts over %zu scenes\n", screen.dir, clipped,
                    shippedScenes().size());
    }
}

TEST(EveryOverlay, NoWindowScrollsSideways) {
    for (const Screen& screen : kScreens) {
        int sideways = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen) continue;
            for (const nlohmann::json* layout : {&s.layout, &s.foldedLayout}) {
                if (!layout->contains("sideways")) continue;
                for (const auto& w : layout->at("sideways")) {
                    ++sideways;
                    ADD_FAILURE() << s.name() << ": " << w.at("name").get<std::string>() << " "
                                  << printed(rectOf(w.at("rect"))) << " scrolls sideways";
                }
            }
        }
        std::printf("%s: %d windows scrolled sideways over %zu scenes\n", screen.dir, sideways,
                    shippedScenes().size());
    }
}

} // namespace
