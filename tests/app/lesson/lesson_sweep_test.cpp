// The lesson sweep (issues 23 and 24): every step of lessons/lecture3.json at 1920x1080, default
// UI scale, at its setup (t = 0, the question asked) and at its moment (the answer shown), read
// back through the JSON sandbox-offscreen writes. One run of `--record-steps DIR` renders them
// all (DIR/step_NN_setup.* and DIR/step_NN_moment.*: the PNG, its .layout.json and .text.json);
// each test below checks one thing a person would check by eye, on every step and both states,
// and names the step, the state and the text or block when it fails.
//
// Which block a scene text belongs to, as far as the JSON tells: a text written wholly inside a
// block's rectangle is that block's (its name and mass are drawn on it), and a block's name is
// that block's wherever it stands; blocks that overlap (a BAD step's penetration) share the
// labels written inside them. Any other scene text that shares area with a block's
// rectangle (an arrow's value, an overlay's mark, the centre of mass, another block's name) is
// over a block it does not belong to.
#include "frame_json.h"
#include "lecture3_lesson.h"
#include "lesson.h"
#include "lesson_prompt.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Issue 23's numbers at 1080p.
constexpr double kCaptionPx = 36.0;    // 3.3% of the height: a slide's body text
constexpr double kSceneLabelPx = 24.0; // 2.2%
constexpr double kNamedBlockPx = 40.0; // a named block's short side
constexpr double kPlotPx = 140.0;      // a plot's height
constexpr double kWorldKept = 0.85;    // the world's area at the answer over its area at the setup
constexpr double kEffectPx = 12.0;     // issue 24: an effect a step asks about, in pixels

// One rendered state of one step.
struct Shot {
    std::size_t step = 0; // 1-based, as --step counts
    bool moment = false;  // false: the setup
    nlohmann::json layout, texts;
    std::string name() const {
        return "step " + std::to_string(step) + (moment ? " moment" : " setup");
    }
};

// The one run of the sweep: every step, setup then moment.
const std::vector<Shot>& shots() {
    static const std::vector<Shot> all = [] {
        const fs::path dir = fs::path(SANDBOX_SWEEP_OUTPUT_DIR);
        fs::remove_all(dir);
        std::string output;
        const int code =
            run(quote(SANDBOX_OFFSCREEN_EXE) +
                    " --lesson lecture3 --size 1920x1080 --record-steps " + quote(dir.string()),
                &output);
        EXPECT_EQ(code, 0) << output;
        std::vector<Shot> out;
        for (std::size_t step = 1; step <= lecture3().steps.size(); ++step) {
            for (const bool moment : {false, true}) {
                char base[48];
                std::snprintf(base, sizeof base, "step_%02zu_%s", step,
                              moment ? "moment" : "setup");
                Shot s{step, moment, readJson(dir / (std::string(base) + ".layout.json")),
                       readJson(dir / (std::string(base) + ".text.json"))};
                if (s.texts.is_object()) s.texts = s.texts.at("texts");
                out.push_back(std::move(s));
            }
        }
        return out;
    }();
    return all;
}

std::string said(const nlohmann::json& text) {
    return "'" + text.at("text").get<std::string>() + "' at " + printed(rectOf(text.at("rect")));
}

bool isPart(const nlohmann::json& text, const char* part) {
    return text.at("window") == part;
}

// `text` as one line of words: line breaks and runs of spaces are one space.
std::string oneLine(const std::string& text) {
    std::string out;
    for (char c : text) {
        const bool space = c == ' ' || c == '\n';
        if (space && (out.empty() || out.back() == ' ')) continue;
        out += space ? ' ' : c;
    }
    return out;
}

// The caption bar's texts as one line of words (its wrapping undone).
std::string captionWords(const Shot& s) {
    std::string joined;
    for (const auto& t : s.texts)
        if (isPart(t, "caption")) joined += t.at("text").get<std::string>() + " ";
    return oneLine(joined);
}

// The blocks a step is about: its selected block and every block its `expect` names.
std::set<std::string> namedBlocks(const LessonStep& step) {
    std::set<std::string> names;
    if (step.selected >= 0 && step.scene)
        names.insert(step.scene->blocks.at(static_cast<std::size_t>(step.selected)).name);
    for (const LessonExpect& e : step.expect)
        if (!e.blockName.empty()) names.insert(e.blockName);
    return names;
}

// The shot of step `step` (1-based) at its setup or its moment.
const Shot& shotOf(std::size_t step, bool moment) {
    return shots().at(2 * (step - 1) + (moment ? 1 : 0));
}

// Block `name` as drawn in `s` (an empty rectangle, and a failure, when it is not there).
Rect blockIn(const Shot& s, const std::string& name) {
    for (const auto& b : s.layout.at("blocks"))
        if (b.at("name") == name) return rectOf(b.at("rect"));
    ADD_FAILURE() << s.name() << ": no block '" << name << "' in the layout";
    return {};
}

// Where the moment's view draws a rectangle that the setup's view drew at `r`: the view may move
// and scale between the two (the answer's caption is taller than the question's), so both are
// read against the world's rectangle, which each view draws.
Rect inMomentView(const Rect& r, const Shot& setup, const Shot& moment) {
    const Rect from = rectOf(setup.layout.at("world")), to = rectOf(moment.layout.at("world"));
    const double kx = to.w / from.w, ky = to.h / from.h;
    return {to.x + (r.x - from.x) * kx, to.y + (r.y - from.y) * ky, r.w * kx, r.h * ky};
}

// The gap from the right side of `left` to the left side of `right` at the moment, in pixels.
double gapAtTheMoment(std::size_t step, const std::string& left, const std::string& right) {
    const Shot& m = shotOf(step, true);
    const Rect a = blockIn(m, left), b = blockIn(m, right);
    return b.x - (a.x + a.w);
}

// The point of impact overlay's mark `name` ("POI": the block where it touched) at the moment.
Rect markAtTheMoment(std::size_t step, const std::string& name) {
    const Shot& m = shotOf(step, true);
    for (const auto& mark : m.layout.at("marks"))
        if (mark.at("name") == name) return rectOf(mark.at("rect"));
    ADD_FAILURE() << m.name() << ": no mark '" << name << "' in the layout";
    return {};
}

// How far right block `name` moved from the setup to the moment, in the moment's pixels.
double movedRight(std::size_t step, const std::string& name) {
    const Shot &setup = shotOf(step, false), &moment = shotOf(step, true);
    return blockIn(moment, name).x - inMomentView(blockIn(setup, name), setup, moment).x;
}

// How far block `name` sank from the setup to the moment (its top), in the moment's pixels.
double sank(std::size_t step, const std::string& name) {
    const Shot &setup = shotOf(step, false), &moment = shotOf(step, true);
    return blockIn(moment, name).y - inMomentView(blockIn(setup, name), setup, moment).y;
}

// A block that moves in a straight line down onto the top of `ground`: how far right of where
// it touched (its setup rectangle moved along its velocity in the scene until its bottom meets
// the ground's top) its left side is at the moment.
double rightOfWhereItTouched(std::size_t step, const std::string& mover,
                             const std::string& ground) {
    const Shot &setup = shotOf(step, false), &moment = shotOf(step, true);
    const Rect start = inMomentView(blockIn(setup, mover), setup, moment);
    const Rect under = blockIn(moment, ground);
    Vec2 v;
    for (const BlockDef& b : lecture3().steps.at(step - 1).scene->blocks)
        if (b.name == mover) v = b.velocity;
    if (v.y >= 0.0) {
        ADD_FAILURE() << "step " << step << ": '" << mover << "' does not move down";
        return 0.0;
    }
    const double drop = under.y - (start.y + start.h); // px down to the ground's top
    const double touchedX = start.x + drop * v.x / -v.y;
    return blockIn(moment, mover).x - touchedX;
}

// The effect a step asks the class to see (issue 24: its question and answer, or step 22's
// caption), in words, and how it is measured: in the pixels of the step's moment at 1920x1080,
// from the blocks' rectangles in the layout JSON, between blocks at the moment or a block at
// the moment against itself at the setup (read in the moment's view). An answer that is a
// velocity alone (steps 3, 9, 10, 12 to 15) is shown by its arrow and its printed value instead.
struct Effect {
    std::size_t step;
    const char* what;
    std::function<double()> pixels;
};

const std::vector<Effect>& effects() {
    static const std::vector<Effect> table = {
        {2, "how far past the wall the bullet is (it tunnelled)",
         [] { return gapAtTheMoment(2, "wall", "bullet"); }},
        {4,
         "the point of impact (x = 8.75 m) to the mover at the moment (x = 10 m, where moving "
         "back along y would have put it)",
         [] { return rightOfWhereItTouched(4, "mover", "floor step"); }},
        {5, "the gap between the mover and the left face it bounced off",
         [] { return gapAtTheMoment(5, "mover", "other"); }},
        {7, "how much further the small ship went than the big one (4 m and 1 m)",
         [] { return movedRight(7, "small ship, 1 kg") - movedRight(7, "big ship, 4 kg"); }},
        {18, "how far the top of the stack sank from where it started",
         [] { return sank(18, "top"); }},
        {19, "the order asymmetry, |gap(A, B) - gap(B, C)|",
         [] { return std::abs(gapAtTheMoment(19, "A", "B") - gapAtTheMoment(19, "B", "C")); }},
        // The moment pauses at the end of the frame that reset A ("watch": 0): where it was reset
        // is the point of impact's mark.
        {20, "how far short of D A is reset (no overlap): the point of impact's mark to D",
         [] {
             const Rect poi = markAtTheMoment(20, "POI");
             return blockIn(shotOf(20, true), "D").x - (poi.x + poi.w);
         }},
        {22, "where the mover touched the step to where it was put (the crooked result)",
         [] { return rightOfWhereItTouched(22, "mover", "floor step"); }},
        {23, "the gap the top pair opens (they part: no collision)",
         [] { return gapAtTheMoment(23, "m1", "m2"); }},
        {25, "how far the crate slid (3.67 m)", [] { return movedRight(25, "crate"); }},
    };
    return table;
}

TEST(LessonSweep, RendersEveryStepAtItsSetupAndItsMoment) {
    ASSERT_EQ(shots().size(), 2 * lecture3().steps.size());
    for (const Shot& s : shots()) {
        EXPECT_TRUE(s.layout.is_object()) << s.name();
        EXPECT_FALSE(s.texts.empty()) << s.name();
    }
}

// The Controls panel included: its step list, its sections and the panel itself show whole rows
// only (a row an edge would cut is hidden, not drawn: whole_rows.h), so nothing in view is cut.
TEST(LessonSweep, NoTextIsClipped) {
    for (const Shot& s : shots())
        for (const auto& t : s.texts)
            EXPECT_FALSE(t.at("clipped").get<bool>())
                << s.name() << ": " << said(t) << " clipped (" << t.at("window") << ")";
}

TEST(LessonSweep, CaptionsAndSceneLabelsAreSlideSized) {
    for (const Shot& s : shots()) {
        for (const auto& t : s.texts) {
            const double px = t.at("px").get<double>();
            if (isPart(t, "caption")) {
                EXPECT_GE(px, kCaptionPx) << s.name() << ": caption " << said(t);
            }
            if (isPart(t, "scene")) {
                EXPECT_GE(px, kSceneLabelPx) << s.name() << ": scene label " << said(t);
            }
        }
    }
}

TEST(LessonSweep, NoTwoSceneTextsIntersect) {
    for (const Shot& s : shots()) {
        for (std::size_t i = 0; i < s.texts.size(); ++i) {
            if (!isPart(s.texts[i], "scene")) continue;
            for (std::size_t j = i + 1; j < s.texts.size(); ++j) {
                if (!isPart(s.texts[j], "scene")) continue;
                EXPECT_FALSE(overlap(rectOf(s.texts[i].at("rect")), rectOf(s.texts[j].at("rect"))))
                    << s.name() << ": " << said(s.texts[i]) << " over " << said(s.texts[j]);
            }
        }
    }
}

// The rule is in the file's comment: a text inside a block is that block's, a block's name is
// that block's; anything else touching a block is over a block it does not belong to.
TEST(LessonSweep, NoSceneTextCoversABlockItDoesNotBelongTo) {
    for (const Shot& s : shots()) {
        for (const auto& t : s.texts) {
            if (!isPart(t, "scene")) continue;
            const Rect r = rectOf(t.at("rect"));
            const auto& blocks = s.layout.at("blocks");
            if (std::any_of(blocks.begin(), blocks.end(),
                            [&r](const auto& b) { return inside(r, rectOf(b.at("rect"))); }))
                continue; // written on its block (which may overlap another: a BAD step's)
            for (const auto& b : blocks) {
                const Rect block = rectOf(b.at("rect"));
                if (!overlap(r, block) || t.at("text") == b.at("name")) continue;
                ADD_FAILURE() << s.name() << ": " << said(t) << " over block '"
                              << b.at("name").get<std::string>() << "' at " << printed(block);
            }
        }
    }
}

// The status badge (method, t, collisions, PAUSED) is drawn over the scene's top left: a label
// or an axis number under it was hidden (steps 3, 8 and 23 before the badge was placed first).
TEST(LessonSweep, NoSceneTextIsUnderTheStatusBadge) {
    for (const Shot& s : shots()) {
        for (const auto& badge : s.texts) {
            if (!isPart(badge, "status")) continue;
            for (const auto& t : s.texts) {
                if (isPart(t, "scene") && overlap(rectOf(t.at("rect")), rectOf(badge.at("rect"))))
                    ADD_FAILURE() << s.name() << ": " << said(t) << " under the badge's "
                                  << said(badge);
            }
        }
    }
}

// An overlay's marks (the point of impact's boxes old, new, POI and moved back: the layout's
// "marks") are the picture's point: no scene text covers one, the marks' own labels included
// (steps 4 and 20 wrote "moved back" over its own box). A text wholly inside a block is that
// block's and stays where it is.
TEST(LessonSweep, NoSceneTextCoversAnOverlaysMark) {
    int marks = 0;
    for (const Shot& s : shots()) {
        const auto& blocks = s.layout.at("blocks");
        for (const auto& m : s.layout.at("marks")) {
            ++marks;
            const Rect mark = rectOf(m.at("rect"));
            for (const auto& t : s.texts) {
                if (!isPart(t, "scene")) continue;
                const Rect r = rectOf(t.at("rect"));
                if (std::any_of(blocks.begin(), blocks.end(),
                                [&r](const auto& b) { return inside(r, rectOf(b.at("rect"))); }))
                    continue;
                if (overlap(r, mark))
                    ADD_FAILURE() << s.name() << ": " << said(t) << " over the mark '"
                                  << m.at("name").get<std::string>() << "' at " << printed(mark);
            }
        }
    }
    EXPECT_GE(marks, 4 * 4) << "steps 4, 5, 20 and 22 show the point of impact at their moment";
}

// Step 17's giant: its momentum arrow's value and the inspector's v2' are one quantity, p = m2·v2',
// and print the same digits: the arrow's number is 1000000 times the inspector's v2' as printed
// (999999.9175 for 0.9999999175; formatNumber alone wrote 999999.917).
TEST(LessonSweep, TheGiantsMomentumArrowReadsAsTheInspectorsVelocity) {
    const Shot& s = shots().at(2 * (17 - 1) + 1);
    ASSERT_TRUE(s.moment && s.step == 17);
    std::string v2After, arrow;
    for (const auto& t : s.texts) {
        const std::string text = t.at("text");
        if (isPart(t, "Collision inspector") && text.rfind("v2' = ", 0) == 0)
            v2After = oneLine(text).substr(oneLine(text).rfind(" = ") + 3);
        const std::string unit = " kg·m/s";
        if (isPart(t, "scene") && text.size() > unit.size() &&
            text.compare(text.size() - unit.size(), unit.size(), unit) == 0)
            arrow = text.substr(0, text.size() - unit.size());
    }
    ASSERT_FALSE(v2After.empty()) << "no v2' in the inspector";
    ASSERT_FALSE(arrow.empty()) << "no momentum value at the giant's arrow";
    const std::size_t point = v2After.find('.');
    const std::size_t decimals = point == std::string::npos ? 0 : v2After.size() - point - 1;
    // 1000000·v2' has six decimals fewer than v2': the arrow prints them all (none dropped).
    EXPECT_NEAR(std::stod(arrow), 1e6 * std::stod(v2After), 1e-7) << arrow << " vs " << v2After;
    EXPECT_GE(decimals, 7u) << v2After;
}

// A block whose velocity and momentum arrows both carry their value prints one quantity twice:
// p = m·|v| must hold with the digits shown (step 27's green block, 4 kg, wrote 8.366 m/s and
// 33.465 kg·m/s: 4·8.366 = 33.464; step 8's stone 8.405 and 16.809). A speed and a momentum on
// screen are taken as one block's when a mass of the step's scene makes them agree to 1%.
TEST(LessonSweep, ABlocksSpeedAndMomentumHoldAsPrinted) {
    const auto number = [](const std::string& text, const std::string& unit) -> std::string {
        if (text.size() <= unit.size() ||
            text.compare(text.size() - unit.size(), unit.size(), unit) != 0)
            return "";
        const std::string n = text.substr(0, text.size() - unit.size());
        return n.find_first_not_of("0123456789.") == std::string::npos ? n : "";
    };
    int pairs = 0;
    for (const Shot& s : shots()) {
        const LessonStep& step = lecture3().steps.at(s.step - 1);
        if (!step.scene) continue;
        std::vector<std::string> speeds, momenta;
        for (const auto& t : s.texts) {
            if (!isPart(t, "scene")) continue;
            const std::string text = t.at("text");
            const std::string p = number(text, " kg·m/s"), v = number(text, " m/s");
            if (!p.empty())
                momenta.push_back(p);
            else if (!v.empty())
                speeds.push_back(v);
        }
        for (const std::string& p : momenta) {
            const std::size_t point = p.find('.');
            const int decimals =
                point == std::string::npos ? 0 : static_cast<int>(p.size() - point - 1);
            const double halfUnit = 0.5 * std::pow(10.0, -decimals) * (1.0 + 1e-9);
            for (const std::string& v : speeds) {
                for (const BlockDef& b : step.scene->blocks) {
                    const double m = b.mass, product = m * std::stod(v), shown = std::stod(p);
                    if (b.kind != BodyKind::Dynamic || std::abs(product - shown) > 0.01 * shown)
                        continue;
                    ++pairs;
                    EXPECT_LE(std::abs(product - shown), halfUnit)
                        << s.name() << ": " << b.name << " (" << m << " kg) at " << v
                        << " m/s prints " << p << " kg·m/s";
                }
            }
        }
    }
    EXPECT_GE(pairs, 3) << "steps 4, 8 and 27 write a block's speed and momentum";
}

// The x axis is read off the screen (a question's "x = 3 m", an answer's 6.67 m): every view
// writes at least two numbers along it and its unit, on one row. Step 25's close camera
// (x = 2..8 m) wrote only "5"; steps 11, 16, 17 and 24 wrote no "m" where a window stood after
// the last number.
TEST(LessonSweep, EveryViewNumbersItsXAxis) {
    for (const Shot& s : shots()) {
        const nlohmann::json* unit = nullptr;
        for (const auto& t : s.texts)
            if (isPart(t, "scene") && t.at("text") == "m") unit = &t;
        if (unit == nullptr) {
            ADD_FAILURE() << s.name() << ": no unit 'm' on the x axis";
            continue;
        }
        const double row = rectOf(unit->at("rect")).y;
        int numbers = 0;
        for (const auto& t : s.texts) {
            const std::string text = t.at("text");
            if (isPart(t, "scene") && rectOf(t.at("rect")).y == row && !text.empty() &&
                text.find_first_not_of("0123456789.-") == std::string::npos)
                ++numbers;
        }
        EXPECT_GE(numbers, 2) << s.name() << ": " << numbers << " number on the x axis";
    }
}

TEST(LessonSweep, TheBlocksAStepNamesAreAtLeast40Px) {
    for (const Shot& s : shots()) {
        const std::set<std::string> named = namedBlocks(lecture3().steps.at(s.step - 1));
        std::set<std::string> seen;
        for (const auto& b : s.layout.at("blocks")) {
            const std::string name = b.at("name");
            if (!named.count(name)) continue;
            seen.insert(name);
            const Rect r = rectOf(b.at("rect"));
            EXPECT_GE(std::min(r.w, r.h), kNamedBlockPx)
                << s.name() << ": block '" << name << "' at " << printed(r);
        }
        EXPECT_EQ(seen, named) << s.name() << ": a named block is not in the layout";
    }
}

TEST(LessonSweep, EveryPlotIsAtLeast140PxHigh) {
    for (const Shot& s : shots())
        for (const auto& p : s.layout.at("plots"))
            EXPECT_GE(rectOf(p.at("rect")).h, kPlotPx)
                << s.name() << ": plot " << p.at("name") << " at " << printed(rectOf(p.at("rect")));
}

TEST(LessonSweep, TheAnswerKeepsAtLeast85PercentOfTheWorld) {
    const std::vector<Shot>& all = shots();
    for (std::size_t i = 0; i + 1 < all.size(); i += 2) {
        const Rect setup = rectOf(all[i].layout.at("world"));
        const Rect moment = rectOf(all[i + 1].layout.at("world"));
        EXPECT_GE(moment.w * moment.h, kWorldKept * setup.w * setup.h)
            << "step " << all[i].step << ": the world " << printed(setup) << " at the setup, "
            << printed(moment) << " at the moment";
    }
}

TEST(LessonSweep, EveryEffectAStepAsksAboutIsAtLeast12Px) {
    for (const Effect& e : effects()) {
        const double px = e.pixels();
        char figure[32];
        std::snprintf(figure, sizeof figure, "%.1f px", px);
        EXPECT_GE(px, kEffectPx) << "step " << e.step << ": " << e.what << " is " << figure
                                 << " at 1920x1080, less than " << kEffectPx << " px";
        std::printf("step %zu: %s: %s\n", e.step, e.what, figure);
    }
}

TEST(LessonSweep, TheSetupAsksTheQuestionAndTheMomentAnswersIt) {
    for (const Shot& s : shots()) {
        const LessonStep& step = lecture3().steps.at(s.step - 1);
        if (step.question.empty()) continue;
        const std::string caption = captionWords(s);
        // As shown: computed from the step as written (lesson_prompt.h), the choices lettered.
        const StepPrompt prompt = stepPrompt(step);
        const std::string question = "Predict: " + oneLine(prompt.question);
        const std::string answer =
            "Answer: " + oneLine(stepAnswer(step, runStepToPause(step), {}, nullptr).text);
        const bool asked = caption.find(question) != std::string::npos;
        const bool answered = caption.find(answer) != std::string::npos;
        EXPECT_EQ(asked, !s.moment) << s.name() << ": the question\n" << caption;
        EXPECT_EQ(answered, s.moment) << s.name() << ": the answer\n" << caption;
        for (std::size_t c = 0; c < prompt.choices.size(); ++c) {
            const std::string choice = choiceLetter(c) + ". " + oneLine(prompt.choices[c]);
            EXPECT_EQ(caption.find(choice) != std::string::npos, !s.moment)
                << s.name() << ": choice " << choiceLetter(c) << "\n"
                << caption;
        }
    }
}

} // namespace
