// The docked layout, end to end: the layout and text JSON of every shipped scene at the classroom
// sizes (1280x720 and 1920x1080, UI scale 1 and 1.5) with every overlay on. No window may cover
// the world's rectangle, every window lies inside the image, and the scene view holds the world.
// In present mode (--present) there is no window at all. The shipped scenes' cases share one run
// of `sandbox-offscreen --record-scenes DIR --screens ...` (JSON only, nothing rasterised), which
// ctest runs as one test (Layout.everyShippedScene, tests/app/CMakeLists.txt): one program per
// case cost about 1.3 s each, 165 of the Release ctest's 1,110 test-seconds (CI time).
#include "frame_json.h"
#include "overlays.h"
#include "scene_library.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
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

const std::pair<int, int> kSizes[] = {{1280, 720}, {1920, 1080}};
const double kUiScales[] = {1.0, 1.5};

std::vector<Case> cases() {
    std::vector<Case> out;
    for (const SceneEntry& e : listScenes(SANDBOX_SCENES_DIR)) {
        const std::string stem = fs::path(e.path).stem().string();
        for (const auto& size : kSizes) {
            for (double scale : kUiScales) out.push_back({stem, size.first, size.second, scale});
        }
    }
    return out;
}

fs::path outputDir() {
    const fs::path dir = fs::path(SANDBOX_SCREENSHOT_OUTPUT_DIR) / "layout";
    fs::create_directories(dir);
    return dir;
}

// One offscreen frame's two JSON files: --layout-json and --text-json.
struct Frame {
    nlohmann::json layout, texts;
};

// Runs sandbox-offscreen with `args` and reads back both files (written next to `base`.png).
Frame render(const fs::path& base, const std::string& args) {
    const std::string png = base.string() + ".png", layout = base.string() + ".layout.json",
                      texts = base.string() + ".text.json";
    fs::remove(layout);
    fs::remove(texts);
    std::string output;
    const int code = run(quote(SANDBOX_OFFSCREEN_EXE) + " " + args + " --screenshot " + quote(png) +
                             " --layout-json " + quote(layout) + " --text-json " + quote(texts),
                         &output);
    EXPECT_EQ(code, 0) << output;
    Frame f;
    std::ifstream l(layout), t(texts);
    EXPECT_TRUE(l.good() && t.good()) << output;
    if (l && t) {
        f.layout = nlohmann::json::parse(l);
        f.texts = nlohmann::json::parse(t).at("texts");
    }
    return f;
}

// The case's scene with every overlay on, at its size and UI scale (`extra`: more flags).
Frame everyOverlay(const Case& c, const std::string& extra) {
    char size[32];
    std::snprintf(size, sizeof size, "%dx%d", c.width, c.height);
    return render(outputDir() / (c.name() + extra.substr(0, extra.find(' '))),
                  quote(c.scene) + " --frames 30 --show " + kEveryOverlay + " --size " + size +
                      " --ui-scale " + std::to_string(c.uiScale) + " " + extra);
}

// The shipped scenes' frames, from one run at every size and UI scale of cases(): the frame of
// `c`, 30 frames in with every overlay on (read from DIR/WxH_uiS/SCENE.layout.json and
// SCENE.text.json; ClassroomScreen::name names the folders).
Frame shippedFrame(const Case& c) {
    static const fs::path dir = [] {
        const fs::path out = fs::path(SANDBOX_SCREENSHOT_OUTPUT_DIR) / "layout-shipped";
        fs::remove_all(out);
        struct Screen {
            int width, height;
            double uiScale;
        };
        std::vector<Screen> screens;
        for (const auto& size : kSizes)
            for (double scale : kUiScales) screens.push_back({size.first, size.second, scale});
        std::string output;
        const int code =
            run(quote(SANDBOX_OFFSCREEN_EXE) + " --record-scenes " + quote(out.string()) +
                    " --frames 30 --screens " + screensOption(screens) + " --show " + kEveryOverlay,
                &output);
        EXPECT_EQ(code, 0) << output;
        return out;
    }();
    char screen[48];
    std::snprintf(screen, sizeof screen, "%dx%d_ui%g", c.width, c.height, c.uiScale);
    Frame f;
    f.layout = readJson(dir / screen / (c.scene + ".layout.json"));
    const nlohmann::json texts = readJson(dir / screen / (c.scene + ".text.json"));
    if (texts.is_object()) f.texts = texts.at("texts");
    return f;
}

// A text as a failure message names it: its window, its characters and its rectangle.
std::string describe(const nlohmann::json& t) {
    return "[" + t.at("window").get<std::string>() + "] '" + t.at("text").get<std::string>() +
           "' at " + t.at("rect").dump();
}

// What issue 23's Done-when checks on a shipped scene with every overlay on, as a person would
// by eye: texts cut at an edge, scene texts over each other (a positive area in common), plots
// lower than 13% of the image's height (140 px at 1080p).
struct ScreenFaults {
    std::vector<std::string> clipped, overlapping, lowPlots;
};

ScreenFaults screenFaults(const Frame& f, double imageHeight) {
    ScreenFaults out;
    std::vector<const nlohmann::json*> scene;
    for (const auto& t : f.texts) {
        if (t.at("clipped").get<bool>()) out.clipped.push_back(describe(t));
        if (t.at("window") == "scene") scene.push_back(&t);
    }
    for (std::size_t i = 0; i < scene.size(); ++i) {
        for (std::size_t j = i + 1; j < scene.size(); ++j) {
            if (overlap(rectOf(scene[i]->at("rect")), rectOf(scene[j]->at("rect"))))
                out.overlapping.push_back(describe(*scene[i]) + " and " + describe(*scene[j]));
        }
    }
    for (const auto& p : f.layout.at("plots")) {
        if (rectOf(p.at("rect")).h < 0.13 * imageHeight - 0.5) out.lowPlots.push_back(p.dump());
    }
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += "\n  " + l;
    return out;
}

// Which checks hold at each size and UI scale: all three at 1920x1080, UI scale 1 (issue 23's
// Done-when); the plots' height everywhere; at 1920x1080, UI scale 1.5, no text is clipped but in
// the methods' table (it scrolls sideways: 118 clipped cells over the shipped scenes). What is
// not asserted is printed (measured: 1920x1080 UI scale 1.5, 10 scene-text overlaps, all
// jammed_box's point-of-impact caption over labels; 1280x720 UI scale 1, 18 clipped texts in
// the inspector and the methods' table, 11 overlaps, that caption and gas_500's; UI scale 1.5 at
// 1280x720 is the crowded case: hundreds of clipped texts in small windows).
struct Checked {
    bool unclipped = false; // no text clipped...
    std::string clippedIn;  // ...but in this window (reported there)
    bool apart = false;     // no two scene texts overlap
    bool plotsHigh = true;  // every plot >= 13% of the height
};

Checked checkedAt(const Case& c) {
    if (c.width == 1920 && c.uiScale == 1.0) return {true, "", true, true};
    if (c.width == 1920) return {true, "Methods side by side", false, true};
    return {};
}

class EveryOverlay : public ::testing::TestWithParam<Case> {};

TEST_P(EveryOverlay, NoWindowCoversTheWorldAndNoneLeavesTheImage) {
    const Case& c = GetParam();
    const Frame f = shippedFrame(c);
    const nlohmann::json& j = f.layout;
    ASSERT_TRUE(j.is_object());
    const Rect image{0, 0, double(c.width), double(c.height)};
    const Rect scene = rectOf(j.at("scene"));
    const Rect world = rectOf(j.at("world"));
    EXPECT_TRUE(inside(scene, image));
    EXPECT_TRUE(inside(world, scene)) << "the world is not inside the scene view";
    EXPECT_GT(world.w, 0.0);
    EXPECT_GT(world.h, 0.0);
    const auto& windows = j.at("windows");
    // Windows that do not fit side by side fold into tabs (issue 39): the shown ones and the
    // folded ones ("folded", each behind a tab) together.
    const std::size_t folded = j.contains("folded") ? j.at("folded").size() : 0;
    EXPECT_GE(windows.size() + folded, 7u) << "the panel and six overlay windows";
    for (const auto& w : windows) {
        const std::string name = w.at("name").get<std::string>();
        const Rect r = rectOf(w.at("rect"));
        EXPECT_TRUE(inside(r, image)) << name << " leaves the image";
        EXPECT_FALSE(overlap(r, world)) << name << " covers the world";
        EXPECT_GT(r.w, 0.0) << name;
        EXPECT_GT(r.h, 0.0) << name;
    }
    // Issue 23: nothing cut, no scene text over another, plots big enough to see.
    const ScreenFaults faults = screenFaults(f, c.height);
    const Checked checked = checkedAt(c);
    const std::string where = c.name() + ": ";
    if (checked.unclipped) {
        std::vector<std::string> clipped;
        for (const std::string& t : faults.clipped) {
            if (checked.clippedIn.empty() || t.rfind("[" + checked.clippedIn + "]", 0) != 0)
                clipped.push_back(t);
        }
        EXPECT_TRUE(clipped.empty()) << where << joined(clipped);
    }
    if (checked.apart) {
        EXPECT_TRUE(faults.overlapping.empty()) << where << joined(faults.overlapping);
    }
    if (checked.plotsHigh) {
        EXPECT_TRUE(faults.lowPlots.empty()) << where << joined(faults.lowPlots);
    }
    std::printf("screen check %s: %zu texts, %zu clipped, %zu scene-text overlaps, %zu low plots\n",
                c.name().c_str(), f.texts.size(), faults.clipped.size(), faults.overlapping.size(),
                faults.lowPlots.size());
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryOverlay, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                             return info.param.name();
                         });

TEST(PresentMode, LeavesNoWindowAndTheWholeImageToTheScene) {
    for (double scale : {1.0, 1.5}) {
        const Case c{"lecture_example_1", 1920, 1080, scale};
        const nlohmann::json j = everyOverlay(c, "--present").layout;
        ASSERT_TRUE(j.is_object());
        EXPECT_TRUE(j.at("windows").empty()) << j.dump();
        const Rect scene = rectOf(j.at("scene"));
        EXPECT_EQ(scene.w, 1920.0);
        EXPECT_EQ(scene.h, 1080.0);
        EXPECT_TRUE(inside(rectOf(j.at("world")), scene));
    }
}

Frame frameOf(const std::string& name, const std::string& args) {
    return render(outputDir() / name, args);
}

TEST(LayoutJson, ListsEveryBlockAndPlotAsDrawn) {
    const Frame f = frameOf("blocks_and_plots", "lecture_example_1 --frames 30 --show plots");
    ASSERT_TRUE(f.layout.is_object());
    const Rect world = rectOf(f.layout.at("world"));
    const auto& blocks = f.layout.at("blocks");
    ASSERT_EQ(blocks.size(), 2u); // m1 and m2
    for (const auto& b : blocks) {
        const Rect r = rectOf(b.at("rect"));
        EXPECT_TRUE(inside(r, world)) << b.dump();
        EXPECT_GT(r.w, 10.0) << b.dump();
        // Its name is drawn (the scene's label, read back from --text-json), on it or beside it.
        bool labelled = false;
        for (const auto& t : f.texts)
            labelled = labelled || (t.at("text") == b.at("name") && t.at("window") == "scene");
        EXPECT_TRUE(labelled) << b.dump();
    }
    EXPECT_FALSE(overlap(rectOf(blocks.at(0).at("rect")), rectOf(blocks.at(1).at("rect"))));
    Rect plotsWindow;
    for (const auto& w : f.layout.at("windows"))
        if (w.at("name") == "Plots") plotsWindow = rectOf(w.at("rect"));
    const auto& plots = f.layout.at("plots");
    ASSERT_EQ(plots.size(), 3u);
    const char* names[] = {"velocity", "momentum", "energy"};
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(plots.at(i).at("name"), names[i]);
        const Rect r = rectOf(plots.at(i).at("rect"));
        EXPECT_TRUE(inside(r, plotsWindow)) << plots.at(i).dump();
        EXPECT_GT(r.h, 40.0);
        if (i > 0) { // one under another
            EXPECT_GE(r.y, rectOf(plots.at(i - 1).at("rect")).y + 40.0);
        }
    }
}

// The tick labels of a plot's y axis: numbers in the Plots window, right-aligned just left of
// the plot's area (within the widget's rectangle, in its left quarter, above the x labels).
int yTickLabels(const nlohmann::json& texts, const Rect& plot) {
    int n = 0;
    for (const auto& t : texts) {
        const std::string text = t.at("text");
        if (t.at("window") != "Plots" || text.empty() ||
            text.find_first_not_of("-0123456789.e+") != std::string::npos)
            continue;
        // Above the x axis's labels (the last 1.4 line heights of the widget).
        const Rect r = rectOf(t.at("rect"));
        const double px = t.at("px").get<double>();
        n += inside(r, plot) && r.x + r.w < plot.x + plot.w * 0.25 && r.y > plot.y + 10.0 &&
             r.y + r.h < plot.y + plot.h - 0.6 * px;
    }
    return n;
}

// Issue 23: the plots that prove lecture3's answers (steps 3, 9 and 10, at their moment) are at
// least 140 px high at 1080p, each labels three values or more on its y axis, and they take room
// from the panel, not from the scene (they lie in the panel's column, under it). Also at UI scale
// 1.5 with every overlay on, where the right column squeezed them to about 40 px: there a 154 px
// plot has 88 px for 24 px numbers, and three that do not touch (issue 39: plot_widget.cpp) fit
// only where a step of 1, 2, 2.5 or 5 allows it (the momentum plot's -25, 0, 25); the velocity
// plot's range of 9.5 m/s writes two ("-4", "0"; it wrote -4, -2, 0, 2 18 px apart, touching).
TEST(LayoutJson, PlotsAre140PxHighWithThreeYLabelsAt1080p) {
    struct Shot {
        std::string name, args;
    };
    const std::vector<Shot> shots = {
        {"plots_step3", "--lesson lecture3 --step 3 --size 1920x1080"},
        {"plots_step9", "--lesson lecture3 --step 9 --size 1920x1080"},
        {"plots_step10", "--lesson lecture3 --step 10 --size 1920x1080"},
        {"plots_every_overlay_ui1_5",
         "bouncing_squares --frames 30 --size 1920x1080 --ui-scale 1.5 --show " + kEveryOverlay},
    };
    for (const Shot& shot : shots) {
        SCOPED_TRACE(shot.name);
        const Frame f = frameOf(shot.name, shot.args);
        ASSERT_TRUE(f.layout.is_object());
        Rect panel, plotsWindow;
        for (const auto& w : f.layout.at("windows")) {
            if (w.at("name") == "Controls") panel = rectOf(w.at("rect"));
            if (w.at("name") == "Plots") plotsWindow = rectOf(w.at("rect"));
        }
        EXPECT_EQ(plotsWindow.x, 0.0);
        EXPECT_EQ(plotsWindow.w, panel.w); // the panel's column
        EXPECT_GE(plotsWindow.y, panel.y + panel.h);
        EXPECT_FALSE(overlap(plotsWindow, rectOf(f.layout.at("scene"))));
        int shown = 0;
        for (const auto& p : f.layout.at("plots")) {
            if (p.at("name") == "tradeoff") continue; // the cost window's chart
            ++shown;
            const Rect r = rectOf(p.at("rect"));
            EXPECT_GE(r.h, 140.0) << p.dump();
            EXPECT_TRUE(inside(r, plotsWindow)) << p.dump();
            const bool squeezed =
                shot.name == "plots_every_overlay_ui1_5" && p.at("name") == "velocity";
            EXPECT_GE(yTickLabels(f.texts, r), squeezed ? 2 : 3) << p.dump();
        }
        EXPECT_EQ(shown, 3);
    }
}

// Issue 23: step 17's inspector printed `p before = 1·1.59369958 + 1000000·0.99999873 = ...` cut
// at its window's edge; now every line of it wraps (before an operator) and nothing is clipped.
TEST(TextJson, TheInspectorOfStep17IsNotClipped) {
    const Frame f = frameOf("inspector_step17", "--lesson lecture3 --step 17 --size 1920x1080");
    int lines = 0;
    bool momentum = false;
    for (const auto& t : f.texts) {
        if (t.at("window") != "Collision inspector") continue;
        ++lines;
        const std::string text = t.at("text");
        momentum = momentum || text.rfind("p before = ", 0) == 0;
        EXPECT_FALSE(t.at("clipped").get<bool>()) << t.dump();
    }
    EXPECT_GE(lines, 8);
    EXPECT_TRUE(momentum);
}

// Issue 23: an arrow too long for the view ends at its edge with its value written there (step 6:
// the heavy block's momentum, 20 kg at 9.81 m/s, went through the floor and off the screen).
TEST(TextJson, AnOverLongArrowsValueIsWrittenInsideTheView) {
    const Frame f = frameOf("arrow_step6", "--lesson lecture3 --step 6 --size 1920x1080");
    const Rect scene = rectOf(f.layout.at("scene"));
    bool written = false;
    for (const auto& t : f.texts) {
        if (t.at("window") != "scene" || t.at("text") != "196.2 kg·m/s") continue;
        written = true;
        EXPECT_TRUE(inside(rectOf(t.at("rect")), scene)) << t.dump();
        EXPECT_FALSE(t.at("clipped").get<bool>());
    }
    EXPECT_TRUE(written) << f.texts.dump(1);
}

// Texts of `part` ("caption", "scene", ...), their smallest line height; 0 when there are none.
double smallestPx(const nlohmann::json& texts, const std::string& part) {
    double least = 0.0;
    for (const auto& t : texts)
        if (t.at("window") == part)
            least =
                least == 0.0 ? t.at("px").get<double>() : std::min(least, t.at("px").get<double>());
    return least;
}

// In a lesson and in present mode the caption is 3.3% of the window's height and the scene's
// labels 2.2% (36 and 24 px at 1080, 24 and 16 at 720), whatever the UI scale; outside them the UI
// scale sets the labels' size as before (16 px at scale 1).
TEST(TextJson, ClassroomTextIsSlideSizedWhateverTheUiScale) {
    for (const char* scale : {"1", "2"}) {
        const Frame f =
            frameOf(std::string("lesson_ui") + scale,
                    "--lesson lecture3 --step 3 --size 1920x1080 --ui-scale " + std::string(scale));
        EXPECT_GE(smallestPx(f.texts, "caption"), 36.0) << scale;
        EXPECT_GE(smallestPx(f.texts, "scene"), 24.0) << scale;
    }
    const Frame small = frameOf("lesson_720", "--lesson lecture3 --step 3 --size 1280x720");
    EXPECT_GE(smallestPx(small.texts, "caption"), 24.0);
    EXPECT_GE(smallestPx(small.texts, "scene"), 16.0);
    const Frame present = frameOf("present_1080", "lecture_example_1 --present --size 1920x1080");
    EXPECT_GE(smallestPx(present.texts, "scene"), 24.0);
    const Frame plain = frameOf("plain_1080", "lecture_example_1 --size 1920x1080");
    EXPECT_EQ(smallestPx(plain.texts, "scene"), 16.0);
    EXPECT_EQ(smallestPx(plain.texts, "caption"), 0.0); // no caption outside lessons
}

TEST(TextJson, ListsTheLessonsCaptionTheBadgeAndThePanel) {
    const Frame f = frameOf("lesson_step9", "--lesson lecture3 --step 9 --size 1920x1080");
    bool title = false, status = false, panel = false, label = false;
    for (const auto& t : f.texts) {
        const std::string text = t.at("text"), part = t.at("window");
        title = title || (part == "caption" && text.find("9 / ") == 0);
        status = status || (part == "status" && text.find("t = ") != std::string::npos);
        panel = panel || (part == "Controls" && text == "Controls");
        label = label || (part == "scene" && text == "m1");
        EXPECT_FALSE(t.at("clipped").get<bool>() && (part == "caption" || part == "scene"))
            << t.dump();
    }
    EXPECT_TRUE(title && status && panel && label) << f.texts.dump(1);
}

// A scene changed since it was loaded says so in the panel's scene picker: its name describes
// the file ("Lecture example 1": bounciness 1), not a world whose C the lecturer set to 0.5.
TEST(TextJson, AnEditedSceneIsMarkedEditedInThePicker) {
    const auto picker = [](const Frame& f) {
        for (const auto& t : f.texts) {
            const std::string text = t.at("text");
            if (t.at("window") == "Controls" && text.rfind("Lecture example 1", 0) == 0)
                return text;
        }
        return std::string("(not found)");
    };
    EXPECT_EQ(picker(frameOf("picker_as_loaded", "lecture_example_1")), "Lecture example 1");
    EXPECT_EQ(picker(frameOf("picker_edited", "lecture_example_1 --set bounciness=0.5")),
              "Lecture example 1 (edited)");
}

} // namespace
