// The lesson sweep at the lecture halls' screens (issue 39): every step of lessons/lecture3.json
// at its setup and its moment at 1024x768, 1280x720, 1280x800, 1366x768, 1920x1080, 1920x1200
// and 3840x2160, each at UI scales 1, 1.25, 1.5 and 2 where the controls panel fits (its 350 px
// x scale at most 45% of the width, view.h's panelFits: 1024 px takes 1 and 1.25, 1280 and
// 1366 px up to 1.5, 1920 and 3840 px all four: kScreens, 23 screens), from one run of
// `sandbox-offscreen --record-steps DIR --screens ...` (the layout and text JSON of each, nothing
// rasterised: DIR/WxH_uiS/step_NN_setup.* and step_NN_moment.*). Checked on each: the caption bar
// takes at most 30% of the height and none of its text is cut, the setup asks and the moment
// answers whole, and the world at the answer keeps at least 85% of its area at the setup (the
// windows the moment opens do not squeeze the scene); no text drawn over the scene runs out of
// it, overlaps another or a block or mark it does not name; the blocks a step names are big enough
// to see. The figures per screen are printed.
#include "equation_check.h"
#include "frame_json.h"
#include "lecture3_lesson.h"
#include "lesson.h"
#include "text_format.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr double kCaptionShare = 0.30; // of the screen's height, at most
constexpr double kWorldKept = 0.85;    // the world's area at the answer over its area at the setup

struct Screen {
    int width, height;
    double uiScale;
    const char* dir; // as sandbox-offscreen names it (ClassroomScreen::name)
};
// The halls' projectors and laptops, at the UI scales a lecturer sets on them (and the panel
// fits at; not: 1024x768 at 1.5 and 2, 1280x720, 1280x800 and 1366x768 at 2, where the panel
// would take 51%, 68%, 55% and 51% of the width and is squeezed to 45%): one sandbox-offscreen
// run writes them all (about 0.2 CPU s a screen).
const Screen kScreens[] = {
    {1024, 768, 1.0, "1024x768_ui1"},       {1024, 768, 1.25, "1024x768_ui1.25"},
    {1280, 720, 1.0, "1280x720_ui1"},       {1280, 720, 1.25, "1280x720_ui1.25"},
    {1280, 720, 1.5, "1280x720_ui1.5"},     {1280, 800, 1.0, "1280x800_ui1"},
    {1280, 800, 1.25, "1280x800_ui1.25"},   {1280, 800, 1.5, "1280x800_ui1.5"},
    {1366, 768, 1.0, "1366x768_ui1"},       {1366, 768, 1.25, "1366x768_ui1.25"},
    {1366, 768, 1.5, "1366x768_ui1.5"},     {1920, 1080, 1.0, "1920x1080_ui1"},
    {1920, 1080, 1.25, "1920x1080_ui1.25"}, {1920, 1080, 1.5, "1920x1080_ui1.5"},
    {1920, 1080, 2.0, "1920x1080_ui2"},     {1920, 1200, 1.0, "1920x1200_ui1"},
    {1920, 1200, 1.25, "1920x1200_ui1.25"}, {1920, 1200, 1.5, "1920x1200_ui1.5"},
    {1920, 1200, 2.0, "1920x1200_ui2"},     {3840, 2160, 1.0, "3840x2160_ui1"},
    {3840, 2160, 1.25, "3840x2160_ui1.25"}, {3840, 2160, 1.5, "3840x2160_ui1.5"},
    {3840, 2160, 2.0, "3840x2160_ui2"},
};

struct Shot {
    const Screen* screen = nullptr;
    std::size_t step = 0; // 1-based
    bool moment = false;
    nlohmann::json layout, texts;
    std::string name() const {
        return std::string(screen->dir) + " step " + std::to_string(step) +
               (moment ? " moment" : " setup");
    }
};

// The one run: every screen, every step, setup then moment.
const std::vector<Shot>& shots() {
    static const std::vector<Shot> all = [] {
        const fs::path dir = fs::path(SANDBOX_SWEEP_OUTPUT_DIR);
        fs::remove_all(dir);
        const std::string screens = screensOption(kScreens);
        std::string output;
        const int code = run(quote(SANDBOX_OFFSCREEN_EXE) + " --lesson lecture3 --record-steps " +
                                 quote(dir.string()) + " --screens " + screens,
                             &output);
        EXPECT_EQ(code, 0) << output;
        std::vector<Shot> out;
        for (const Screen& screen : kScreens) {
            for (std::size_t step = 1; step <= lecture3().steps.size(); ++step) {
                for (const bool moment : {false, true}) {
                    char base[48];
                    std::snprintf(base, sizeof base, "step_%02zu_%s", step,
                                  moment ? "moment" : "setup");
                    const fs::path at = dir / screen.dir;
                    Shot s{&screen, step, moment,
                           readJson(at / (std::string(base) + ".layout.json")),
                           readJson(at / (std::string(base) + ".text.json"))};
                    if (s.texts.is_object()) s.texts = s.texts.at("texts");
                    out.push_back(std::move(s));
                }
            }
        }
        return out;
    }();
    return all;
}

// The caption bar's rectangle (a failure, and an empty one, when there is none).
Rect captionBar(const Shot& s) {
    if (s.layout.is_object())
        for (const auto& w : s.layout.at("windows"))
            if (w.at("name") == "Lesson caption") return rectOf(w.at("rect"));
    ADD_FAILURE() << s.name() << ": no caption bar in the layout";
    return {};
}

std::string captionWords(const Shot& s) {
    std::string out;
    for (const auto& t : s.texts)
        if (t.at("window") == "caption") {
            for (char c : t.at("text").get<std::string>()) {
                const bool space = c == ' ' || c == '\n';
                if (space && (out.empty() || out.back() == ' ')) continue;
                out += space ? ' ' : c;
            }
            if (!out.empty() && out.back() != ' ') out += ' ';
        }
    return out;
}

bool onIt(const Rect& in, const Rect& out);
bool knownText(const Shot& s, const std::string& text);
void expectKnownStillOut(const std::vector<std::string>& seen);

double area(const Rect& r) {
    return r.w * r.h;
}

TEST(LessonScreens, RendersEveryStepAtEveryScreen) {
    ASSERT_EQ(shots().size(), std::size(kScreens) * 2 * lecture3().steps.size());
    for (const Shot& s : shots()) {
        EXPECT_TRUE(s.layout.is_object()) << s.name();
        EXPECT_FALSE(s.texts.empty()) << s.name();
    }
}

TEST(LessonScreens, TheCaptionBarTakesAtMost30PercentOfTheHeight) {
    for (const Screen& screen : kScreens) {
        double most = 0.0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen) continue;
            const double share = captionBar(s).h / screen.height;
            most = std::max(most, share);
            EXPECT_LE(share, kCaptionShare) << s.name() << ": the caption bar is "
                                            << printed(captionBar(s)) << " of " << screen.height;
        }
        std::printf("%s: the caption bar at most %.1f%% of the height\n", screen.dir, 100.0 * most);
    }
}

// The texts a student reads as the answer, whole: the caption's, and the collision inspector's
// equations (step 17's u, "(1·1.5937 + 1000000·0.99999873006)/(1 + 1000000)", ran past the
// docked inspector's edge at 1280x720 and 1280x800 UI 1.5 and 1024x768 UI 1.25, its last digits
// cut; a text wider than its window is "clipped" in the JSON, screen_text.h).
TEST(LessonScreens, NoCaptionTextOrInspectorEquationIsClipped) {
    for (const Screen& screen : kScreens) {
        int clipped = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen) continue;
            for (const auto& t : s.texts) {
                const std::string text = t.at("text").get<std::string>();
                const bool equation = t.at("window") == "Collision inspector" &&
                                      text.find(" = ") != std::string::npos;
                if ((t.at("window") != "caption" && !equation) || !t.at("clipped").get<bool>())
                    continue;
                ++clipped;
                ADD_FAILURE() << s.name() << ": '" << text << "' at "
                              << printed(rectOf(t.at("rect"))) << " clipped";
            }
        }
        std::printf("%s: %d clipped caption texts and equations\n", screen.dir, clipped);
    }
}

// The collision inspector's equations hold as printed, read as a student reads them, line by
// line (equation_check.h: a line that starts with an operator continues the chain): step 17's v1'
// at 1280x720 UI 1.5 was broken after its minus, "v1' = 0.99999932376 -" over
// "1·(1.5937 - 0.99999932376) = 0.4063", a second chain that does not hold.
TEST(LessonScreens, EveryInspectorEquationHoldsAsPrinted) {
    int checked = 0;
    for (const Shot& s : shots()) {
        for (const auto& t : s.texts) {
            if (t.at("window") != "Collision inspector") continue;
            const std::string text = t.at("text").get<std::string>();
            const EquationReport report = checkEquations(text, kFormatNumberUnit);
            checked += report.checked;
            for (const EquationProblem& p : report.problems)
                ADD_FAILURE() << s.name() << ": '" << text << "': " << p.chain << ": " << p.why;
        }
    }
    std::printf("%d relations of the inspector's equations checked\n", checked);
    EXPECT_GT(checked, 0);
}

// No text drawn over the scene (labels, values, axis numbers, a caption plate) runs out of the
// scene's rectangle, under a docked window or the caption bar (step 2's wall had its name above
// the scene; step 5's point-of-impact plate, wider than a 438 px scene at 1280x800 UI 1.5, ran
// under the inspector, "crook").
TEST(LessonScreens, EverySceneTextLiesInTheScene) {
    std::vector<std::string> knownSeen; // the known cases found out of the scene still
    for (const Screen& screen : kScreens) {
        int outside = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen || !s.layout.is_object()) continue;
            const Rect scene = rectOf(s.layout.at("scene"));
            for (const auto& t : s.texts) {
                if (t.at("window") != "scene" || onIt(rectOf(t.at("rect")), scene)) continue;
                if (knownText(s, t.at("text").get<std::string>())) {
                    knownSeen.push_back(s.name());
                    continue;
                }
                ++outside;
                ADD_FAILURE() << s.name() << ": '" << t.at("text").get<std::string>() << "' "
                              << printed(rectOf(t.at("rect"))) << " out of the scene "
                              << printed(scene);
            }
        }
        std::printf("%s: %d scene texts out of the scene (known cases skipped: kKnownOverlaps)\n",
                    screen.dir, outside);
    }
    expectKnownStillOut(knownSeen);
}

// The question (with "Predict:") at the setup and the answer or why there is none at the moment
// are never what the bar cuts for room: only the caption above them is ("... (more)").
TEST(LessonScreens, TheSetupAsksAndTheMomentAnswers) {
    for (const Shot& s : shots()) {
        if (lecture3().steps.at(s.step - 1).question.empty()) continue;
        const std::string words = captionWords(s);
        if (s.moment) {
            EXPECT_TRUE(words.find("Answer: ") != std::string::npos ||
                        words.find("No answer: ") != std::string::npos)
                << s.name() << ": no answer in\n"
                << words;
        } else {
            EXPECT_NE(words.find("Predict: "), std::string::npos)
                << s.name() << ": no question in\n"
                << words;
        }
    }
}

TEST(LessonScreens, TheAnswerKeepsAtLeast85PercentOfTheWorld) {
    const std::vector<Shot>& all = shots();
    for (const Screen& screen : kScreens) {
        double least = 1e9;
        for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
            if (all[i].screen != &screen || !all[i].layout.is_object() ||
                !all[i + 1].layout.is_object())
                continue;
            const Rect setup = rectOf(all[i].layout.at("world"));
            const Rect moment = rectOf(all[i + 1].layout.at("world"));
            least = std::min(least, area(moment) / area(setup));
            EXPECT_GE(area(moment), kWorldKept * area(setup))
                << all[i].name() << ": the world " << printed(setup) << " at the setup, "
                << printed(moment) << " at the moment";
        }
        std::printf("%s: the world at the answer keeps at least %.1f%% of its setup area\n",
                    screen.dir, 100.0 * least);
    }
}

// The two share more than a pixel each way (antialiased edges and shadows touch).
bool sharesAPixel(const Rect& a, const Rect& b) {
    const double w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 1.0 && h > 1.0;
}

// A scene text "names" a block or a mark when it says its name as a word (saysWord: "m2",
// "m1 = 1 kg", "centre of mass  u = ..."), or lies wholly on that block (onIt: its own label's
// second line, "2 kg").
bool onIt(const Rect& in, const Rect& out) {
    return inside(in, Rect{out.x - 1.0, out.y - 1.0, out.w + 2.0, out.h + 2.0});
}

// Known, not yet fixed (issue 39), each at the screens named: a scene text over another.
struct KnownOverlap {
    const char* screen;
    std::size_t step;
    bool moment;
    const char* textStart; // the known text (only it is skipped in that shot)
    const char* why;
};
// None now: step 5's point-of-impact plate at its moment (four lines, about 600 px wide at UI 1.5)
// ran out of a 340-440 px scene under the inspector ("crook") at 1024x768 UI 1.25 and 1280x720,
// 1280x800 and 1366x768 UI 1.5; it is placed before the boxes' labels now, in its brief form
// where the scene is narrow, never wider than the scene (drawSceneCaption). Only the listed text
// is skipped, by both checks (out of the scene, over another text); a listed case whose text lies
// in the scene fails the first, so that the list only shrinks.
const std::vector<KnownOverlap> kKnownOverlaps = {};

bool knownCase(const KnownOverlap& k, const Shot& s) {
    return s.screen->dir == std::string(k.screen) && s.step == k.step && s.moment == k.moment;
}

bool knownText(const Shot& s, const std::string& text) {
    for (const KnownOverlap& k : kKnownOverlaps)
        if (knownCase(k, s) && text.rfind(k.textStart, 0) == 0) return true;
    return false;
}

// A known case that is out of the scene no more fails, so that the list only shrinks.
void expectKnownStillOut(const std::vector<std::string>& seen) {
    for (const Shot& s : shots())
        for (const KnownOverlap& k : kKnownOverlaps) {
            if (!knownCase(k, s)) continue;
            EXPECT_NE(std::find(seen.begin(), seen.end(), s.name()), seen.end())
                << s.name() << ": '" << k.textStart << "...' lies in the scene now: take it "
                << "out of kKnownOverlaps";
        }
}

// Labels never lie about whom they name: no text drawn over the scene (labels, values, axis
// numbers, the overlays' labels) overlaps another, or a block or a mark (the point of impact's
// boxes, the centre of mass) it does not name.
TEST(LessonScreens, NoSceneTextOverlapsAnotherOrWhatItDoesNotName) {
    for (const Screen& screen : kScreens) {
        int overlaps = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen || !s.layout.is_object()) continue;
            std::vector<const nlohmann::json*> scene;
            for (const auto& t : s.texts)
                if (t.at("window") == "scene" && !knownText(s, t.at("text").get<std::string>()))
                    scene.push_back(&t);
            for (std::size_t i = 0; i < scene.size(); ++i) {
                const std::string text = scene[i]->at("text").get<std::string>();
                const Rect r = rectOf(scene[i]->at("rect"));
                for (std::size_t j = i + 1; j < scene.size(); ++j) {
                    if (!sharesAPixel(r, rectOf(scene[j]->at("rect")))) continue;
                    ++overlaps;
                    ADD_FAILURE() << s.name() << ": '" << text << "' " << printed(r)
                                  << " overlaps '" << scene[j]->at("text").get<std::string>()
                                  << "' " << printed(rectOf(scene[j]->at("rect")));
                }
                for (const char* list : {"blocks", "marks"}) {
                    for (const auto& b : s.layout.at(list)) {
                        const std::string name = b.at("name").get<std::string>();
                        const Rect box = rectOf(b.at("rect"));
                        if (!sharesAPixel(r, box) || saysWord(text, name) ||
                            (list == std::string("blocks") && onIt(r, box)))
                            continue;
                        ++overlaps;
                        ADD_FAILURE() << s.name() << ": '" << text << "' " << printed(r) << " over "
                                      << name << " " << printed(box);
                    }
                }
            }
        }
        std::printf("%s: %d scene texts over another or over what they do not name (known "
                    "cases skipped: kKnownOverlaps)\n",
                    screen.dir, overlaps);
    }
}

// Steps whose named blocks are still under the size at some screen, in the scene and in every
// magnifier (magnifier.h). Each is printed; a step listed that passes at every screen fails the
// test, so that the list only shrinks. (Step 26 was: its moment's coin, 12-23 px on the floor far
// from the others, found no fifth inset; its "moment_camera" now frames the shelf, the player and
// the coin.)
const std::vector<std::size_t> kStepsStillSmall = {};

bool stillSmall(std::size_t step) {
    return std::find(kStepsStillSmall.begin(), kStepsStillSmall.end(), step) !=
           kStepsStillSmall.end();
}

// The short side of block `name` as a magnifier draws it (magnifier.h: its part in the inset),
// 0 where none does.
double magnifiedSide(const Shot& s, const std::string& name) {
    double side = 0.0;
    if (s.layout.contains("magnified"))
        for (const auto& b : s.layout.at("magnified"))
            if (b.at("name") == name) {
                const Rect r = rectOf(b.at("rect"));
                side = std::max(side, std::min(r.w, r.h));
            }
    return side;
}

// A magnified view states its scale: each magnifier is a mark ("magnifier ×4") inside the scene,
// with its factor written in it, and the blocks it draws lie in one.
TEST(LessonScreens, EveryMagnifierStatesItsScale) {
    int magnifiers = 0;
    for (const Shot& s : shots()) {
        if (!s.layout.is_object()) continue;
        std::vector<Rect> insets;
        for (const auto& m : s.layout.at("marks")) {
            const std::string name = m.at("name").get<std::string>();
            if (name.rfind("magnifier \u00d7", 0) != 0) continue;
            const Rect r = rectOf(m.at("rect"));
            insets.push_back(r);
            ++magnifiers;
            EXPECT_TRUE(inside(r, rectOf(s.layout.at("scene")))) << s.name() << ": " << name;
            const std::string factor = name.substr(std::string("magnifier ").size());
            bool written = false;
            for (const auto& t : s.texts)
                written |= t.at("window") == "magnifier" && t.at("text") == factor &&
                           inside(rectOf(t.at("rect")), r) && !t.at("clipped").get<bool>();
            EXPECT_TRUE(written) << s.name() << ": " << name << " does not write " << factor;
        }
        if (!s.layout.contains("magnified")) continue;
        for (const auto& b : s.layout.at("magnified")) {
            const Rect r = rectOf(b.at("rect"));
            EXPECT_TRUE(std::any_of(insets.begin(), insets.end(),
                                    [&r](const Rect& in) { return onIt(r, in); }))
                << s.name() << ": " << b.at("name") << " magnified outside every magnifier";
        }
    }
    std::printf("%d magnifiers over the screens\n", magnifiers);
}

// The share of `box` inside `scene` (0 to 1).
double shownShare(const Rect& box, const Rect& scene) {
    const double w = std::min(box.x + box.w, scene.x + scene.w) - std::max(box.x, scene.x);
    const double h = std::min(box.y + box.h, scene.y + scene.h) - std::max(box.y, scene.y);
    return std::max(0.0, w) * std::max(0.0, h) / area(box);
}

// The evidence is big enough: every block the step names (its name a word of the caption bar's
// text) and the view shows at least 40 px on its short side at the setup and the moment, 28 px
// on a 1024x768 screen, in the scene or in a magnifier. At a moment its "moment_camera" frames, a
// block mostly out of the scene (under half of it in) is framed out, not drawn small, and not
// magnified (magnifier.cpp): the platformer's moment frames the shelf, the player and the coin on
// the floor, not the crate and the lift behind; what its answer names it shows
// (TheMomentCameraShowsWhatTheAnswerNames).
TEST(LessonScreens, TheBlocksAStepNamesAreBigEnough) {
    std::vector<bool> small(lecture3().steps.size() + 1, false);
    for (const Screen& screen : kScreens) {
        const double least = screen.width <= 1024 ? 28.0 : 40.0;
        double smallest = 1e9;
        int under = 0, known = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen || !s.layout.is_object()) continue;
            const std::string words = captionWords(s);
            const Rect scene = rectOf(s.layout.at("scene"));
            const bool framed = s.moment && lecture3().steps.at(s.step - 1).momentCamera;
            for (const auto& b : s.layout.at("blocks")) {
                const std::string name = b.at("name").get<std::string>();
                if (!saysWord(words, name)) continue;
                const Rect box = rectOf(b.at("rect"));
                if (framed && shownShare(box, scene) < 0.5) continue; // framed out (mostly)
                const double side = std::max(std::min(box.w, box.h), magnifiedSide(s, name));
                smallest = std::min(smallest, side);
                if (side >= least) continue;
                small[s.step] = true;
                if (stillSmall(s.step)) {
                    ++known;
                    continue;
                }
                ++under;
                ADD_FAILURE() << s.name() << ": " << name << " is " << printed(box) << ", under "
                              << least << " px";
            }
        }
        std::printf("%s: the blocks the steps name at least %.1f px (under %.0f px: %d, and %d in "
                    "the steps still to frame)\n",
                    screen.dir, smallest, least, under, known);
    }
    for (const std::size_t step : kStepsStillSmall)
        EXPECT_TRUE(small.at(step)) << "step " << step
                                    << " is big enough at every screen now: take it out of "
                                       "kStepsStillSmall";
}

// A moment that frames its evidence ("moment_camera", docs/lesson-format.md) shows every block its
// answer names in the scene, at least 90% of it (the platformer's: the coin on the floor, the
// player and the shelf it stands on, whose left end may run out of a narrow view), at every
// screen.
TEST(LessonScreens, TheMomentCameraShowsWhatTheAnswerNames) {
    int framed = 0;
    for (const Shot& s : shots()) {
        const LessonStep& step = lecture3().steps.at(s.step - 1);
        if (!s.moment || !step.momentCamera || !s.layout.is_object()) continue;
        ++framed;
        const Rect scene = rectOf(s.layout.at("scene"));
        int named = 0;
        for (const auto& b : s.layout.at("blocks")) {
            const std::string name = b.at("name").get<std::string>();
            if (!saysWord(step.answer, name)) continue;
            ++named;
            const Rect box = rectOf(b.at("rect"));
            const double shown = shownShare(box, scene);
            EXPECT_GE(shown, 0.9) << s.name() << ": " << name << " " << printed(box)
                                  << ", the scene " << printed(scene);
        }
        EXPECT_GT(named, 0) << s.name() << ": the answer names no block";
    }
    std::printf("%d moments framed by their moment camera\n", framed);
    // Step 26 (the platformer) has one: a check that found none would assert nothing.
    EXPECT_GE(framed, static_cast<int>(std::size(kScreens)));
}

// The plots' axis numbers never touch (issue 39: step 10's "v of m1" at 1280x800 UI 1.5 wrote
// "4", "2", "0", "-2", "-4" 11 px apart in 24 px lines): a short plot numbers every second or
// third tick (plot_widget.cpp, labelStride).
TEST(LessonScreens, NoTwoAxisNumbersOfAPlotTouch) {
    for (const Screen& screen : kScreens) {
        int numbers = 0, touching = 0;
        for (const Shot& s : shots()) {
            if (s.screen != &screen) continue;
            std::vector<const nlohmann::json*> axis;
            for (const auto& t : s.texts) {
                const std::string text = t.at("text").get<std::string>();
                const std::size_t digit = text.rfind('-', 0) == 0 ? 1 : 0;
                if (t.at("window") == "Plots" && text.size() > digit &&
                    std::isdigit(static_cast<unsigned char>(text[digit])))
                    axis.push_back(&t);
            }
            numbers += static_cast<int>(axis.size());
            for (std::size_t i = 0; i < axis.size(); ++i)
                for (std::size_t j = i + 1; j < axis.size(); ++j) {
                    const Rect a = rectOf(axis[i]->at("rect")), b = rectOf(axis[j]->at("rect"));
                    if (!sharesAPixel(a, b)) continue;
                    ++touching;
                    ADD_FAILURE() << s.name() << ": '" << axis[i]->at("text").get<std::string>()
                                  << "' " << printed(a) << " touches '"
                                  << axis[j]->at("text").get<std::string>() << "' " << printed(b);
                }
        }
        std::printf("%s: %d plot numbers, %d touching another\n", screen.dir, numbers, touching);
        // Steps 3 and 6 to 12 show plots: none found at a screen means the check looked at
        // nothing (a window renamed, no texts written).
        EXPECT_GT(numbers, 0) << screen.dir;
    }
}

} // namespace
