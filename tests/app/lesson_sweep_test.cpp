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
#include "lesson.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kLecture3 = std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json";

// Issue 23's numbers at 1080p.
constexpr double kCaptionPx = 36.0;    // 3.3% of the height: a slide's body text
constexpr double kSceneLabelPx = 24.0; // 2.2%
constexpr double kNamedBlockPx = 40.0; // a named block's short side
constexpr double kPlotPx = 140.0;      // a plot's height
constexpr double kWorldKept = 0.85;    // the world's area at the answer over its area at the setup

// One rendered state of one step.
struct Shot {
    std::size_t step = 0; // 1-based, as --step counts
    bool moment = false;  // false: the setup
    nlohmann::json layout, texts;
    std::string name() const {
        return "step " + std::to_string(step) + (moment ? " moment" : " setup");
    }
};

const Lesson& lecture3() {
    static const Lesson lesson = [] {
        LessonContext context;
        context.scenesDir = SANDBOX_SCENES_DIR;
        LessonResult loaded = loadLessonFile(kLecture3, context);
        EXPECT_TRUE(loaded.lesson.has_value()) << loaded.error.message;
        return loaded.lesson.value_or(Lesson{});
    }();
    return lesson;
}

nlohmann::json readJson(const fs::path& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "no " << path;
    if (!in) return {};
    return nlohmann::json::parse(in);
}

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

TEST(LessonSweep, TheSetupAsksTheQuestionAndTheMomentAnswersIt) {
    for (const Shot& s : shots()) {
        const LessonStep& step = lecture3().steps.at(s.step - 1);
        if (step.question.empty()) continue;
        const std::string caption = captionWords(s);
        const std::string question = "Predict: " + oneLine(step.question);
        const std::string answer = "Answer: " + oneLine(step.answer);
        const bool asked = caption.find(question) != std::string::npos;
        const bool answered = caption.find(answer) != std::string::npos;
        EXPECT_EQ(asked, !s.moment) << s.name() << ": the question\n" << caption;
        EXPECT_EQ(answered, s.moment) << s.name() << ": the answer\n" << caption;
    }
}

} // namespace
