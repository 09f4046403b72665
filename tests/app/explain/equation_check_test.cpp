// Every equation on screen holds with the numbers as printed (issue 23): the checker
// (app/formula/equation_check.h) on hand-made chains, then on every line the collision inspector
// and the point-of-impact overlay write over every shipped scene and every scene of the lecture's
// lesson, and on the lesson's own captions, questions and answers.
#include "equation_check.h"
#include "inspector_format.h"
#include "lesson.h"
#include "lesson_prompt.h"
#include "poi.h"
#include "printed_formula.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

namespace {

int expectInspectorHolds(const CollisionRecord& r, const std::string& name1,
                         const std::string& name2, const std::string& where);

std::string problems(const EquationReport& r) {
    std::string out;
    for (const EquationProblem& p : r.problems) out += "  " + p.chain + ": " + p.why + "\n";
    return out;
}

// The numbers the formulas carry are what strtod reads from their digits, bit for bit: the
// printed texts of random values at every number of digits, and texts of every other form.
TEST(PrintedFormula, ShownNumberIsStrtodsBitForBit) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> scale(-9, 14);
    std::vector<std::string> texts = {"0",
                                      "-0",
                                      "1.",
                                      ".5",
                                      "-.25",
                                      "",
                                      "-",
                                      ".",
                                      "007",
                                      "0.0012",
                                      "1e-5",
                                      "2.5e+12",
                                      "inf",
                                      "-inf",
                                      "nan",
                                      " 1",
                                      "+1",
                                      "2 kg",
                                      "1.2.3",
                                      "999999999999999",
                                      "9999999999999999",
                                      "0.1234567890123456789",
                                      "0.0000000000000000000001"};
    for (int i = 0; i < 20000; ++i) {
        const double v = unit(random) * std::pow(10.0, scale(random));
        texts.push_back(formatNumberWithDigits(v, i % 10));
        char text[64];
        std::snprintf(text, sizeof text, "%.*f", i % 23, v);
        texts.push_back(text);
    }
    for (const std::string& t : texts) {
        const double a = shownNumber(t.c_str()), b = std::strtod(t.c_str(), nullptr);
        EXPECT_TRUE(std::memcmp(&a, &b, sizeof a) == 0) << t << ": " << a << " vs " << b;
    }
}

TEST(EquationCheck, TheLecturesFormulaHolds) {
    const EquationReport r = checkEquations("u = (1·6 + 2·0)/(1 + 2) = 2");
    EXPECT_TRUE(r.holds()) << problems(r);
    EXPECT_EQ(r.checked, 1);
    EXPECT_TRUE(equationsHold("v1' = 2 - 1·(6 - 2) = -2      v2' = 2 - 1·(0 - 2) = 4"));
    EXPECT_TRUE(equationsHold("p after  = 1·(-2) + 2·4 = 6 kg·m/s"));
    EXPECT_TRUE(equationsHold("m1 = 1, m2 = 2, v1 = 6, v2 = 0, C = 1"));
}

TEST(EquationCheck, AWrongChainIsRejected) {
    // The two: the sum of step 9 is 2, and the giant's velocity printed as 1.
    const EquationReport fake = checkEquations("u = (1·6 + 2·0)/(1 + 2) = 0");
    ASSERT_EQ(fake.problems.size(), 1u);
    EXPECT_EQ(fake.problems[0].chain, "u = (1·6 + 2·0)/(1 + 2) = 0");
    EXPECT_FALSE(equationsHold("1·3.594 + 1000000·1 = 999997.136"));
    EXPECT_TRUE(equationsHold("1·3.594 + 1000000·0.99999354 = 999997.134"));
    EXPECT_FALSE(equationsHold("v1' = 0 - 1·(6 - 0) = 6"));
    EXPECT_FALSE(equationsHold("t = a/b = 0.05/0.1 = 0.4 of the frame"));
    // An equation with inf or nan is nothing a student can check.
    EXPECT_FALSE(equationsHold("p2 before = inf·0 = nan kg·m/s"));
    EXPECT_TRUE(equationsHold("m2 = inf, v2 = 0")); // a given, not an equation
}

TEST(EquationCheck, ToleranceIsHalfAUnitOfTheLastPrintedDigit) {
    EXPECT_TRUE(equationsHold("1/3 = 0.333"));  // 0.33333: 0.0003 off, within 0.0005
    EXPECT_FALSE(equationsHold("2/3 = 0.666")); // 0.66667: 0.00067 off
    EXPECT_TRUE(equationsHold("2/3 = 0.667"));
    EXPECT_TRUE(equationsHold("2/3 = 1"));    // one digit printed: +-0.5
    EXPECT_FALSE(equationsHold("2/3 = 1.0")); // +-0.05
    EXPECT_TRUE(equationsHold("4·1e+06 = 4e+06"));
    EXPECT_FALSE(equationsHold("4.2·1e+06 = 4.3e+06"));
    EXPECT_TRUE(equationsHold("0.5·2.3 = 1.15"));
    // The app's own lines: formatNumber rounds to 3 decimals and drops the zeros, so its "1" is
    // 1.000 and held to +-0.0005 (a giant's 0.99999 times 1 is not 1).
    EXPECT_FALSE(equationsHold("2/3 = 1", kFormatNumberUnit));
    EXPECT_TRUE(equationsHold("0.9999 = 1", kFormatNumberUnit));
    EXPECT_TRUE(equationsHold("1/8000 = 0.000125", kFormatNumberUnit));
    EXPECT_TRUE(equationsHold("4.21·1e+12 = 4.2e+12", kFormatNumberUnit)); // its own digits
}

// A chain as printed, and whether it holds.
struct Verdict {
    const char* text;
    bool holds;
};

void expectVerdicts(std::initializer_list<Verdict> verdicts) {
    for (const Verdict& v : verdicts) EXPECT_EQ(equationsHold(v.text), v.holds) << v.text;
}

TEST(EquationCheck, ReadsTheNotationOnScreen) {
    expectVerdicts({
        {"v' = -C·v = -0.5·(-4) = 2 m/s", true},
        {"v1' = -C·v1 = -1·6 = -6", true},
        {"2 × 3 = 6, 2 * 3 = 6, 6 − 1 = 5", true},
        {"|2 - 5| = 3 and sqrt(16) = 4 and √9 = 3 and 3² = 9 and 2^3 = 8", true},
        {"sqrt(16) = 5", false},
        {"t = 0.625 s: v1' = -2 m/s, v2' = 4 m/s", true},
        {"µ·g = 0.5·9.81 = 4.905 m/s²", true},
        {"µ·g = 0.5·9.81 = 4.91 m/s², then 1 + 1 = 3 m", false},
        // Prose around the chains: the left side starts where an expression starts.
        {"rel. vel. along x = v1 - v2 = 6 - 0 = 6 > 0: approaching", true},
        {"Momentum 1*(-2) + 2*4 = 5 kg m/s, the same as before", false},
        // A function the checker does not know leaves its whole chain unchecked, not half of it.
        {"makes ceil(pi/theta) - 1 = 3141 collisions", true},
        {"f(2)·3 = 7 and floor(2.5) + 1 = 3", true},
    });
}

// A chain wrapped before an operator (the inspector's narrow window, wrapFormula) reads as one;
// any other line break ends a chain.
TEST(EquationCheck, AChainWrappedBeforeAnOperatorReadsOn) {
    const EquationReport r = checkEquations("p before = 1·6 + 2·0\n  = 6 kg·m/s");
    EXPECT_TRUE(r.holds()) << problems(r);
    EXPECT_EQ(r.checked, 1);
    EXPECT_FALSE(equationsHold("p before = 1·6 + 2·0\n  = 7 kg·m/s"));
    EXPECT_FALSE(equationsHold("u = (1·6\n + 2·0)/(1 + 2) = 0"));
    EXPECT_TRUE(equationsHold("5 + 1\n  - 1 = 5")); // a binary minus continues the chain
    EXPECT_EQ(checkEquations("5 + 1\n  - 1 = 5").checked, 1);
    // A line starting with a number (or a negative one) starts a chain of its own.
    EXPECT_TRUE(equationsHold("v1' = 2 - 1·4 = -2\n-6 kg·m/s is not here\n1 + 1 = 2"));
    EXPECT_EQ(checkEquations("a = 1 + 1 = 2\nb = 2 + 2 = 4").checked, 2);
}

TEST(EquationCheck, ComparisonsHoldAsPrinted) {
    const EquationReport r =
        checkEquations("friction along y: |dvt| = 0.4 < mu·|dvn| = 0.5·2.3 = 1.15 m/s");
    EXPECT_TRUE(r.holds()) << problems(r);
    EXPECT_EQ(r.checked, 2); // 0.5·2.3 = 1.15, and 0.4 < 1.15
    expectVerdicts({
        {"|dvt| = 1.2 < mu·|dvn| = 0.5·2.3 = 1.15 m/s", false},
        {"rel. vel. = 3 - 4 = -1 > 0", false},
        {"3 - 4 = -1 m/s < 0, separating", true},
        {"1 <= 1 >= 0.5 ≤ 2 ≥ 2", true},
        {"2 ≤ 1", false},
    });
}

// The inspector's formulas that the issue found wrong, from records as the engine writes them.
TEST(EquationCheck, ReflectPrintsTheRuleThatActed) {
    CollisionRecord r; // step 9, "without Newton": m1 = 1 kg at 6 m/s, m2 = 2 kg at rest
    r.other = 1;
    r.m1 = 1.0, r.m2 = 2.0, r.v1 = 6.0, r.v2 = 0.0, r.u = 0.0, r.C = 1.0;
    r.v1After = -6.0, r.v2After = 0.0;
    r.rule = ResolveRule::Reflect;
    const CollisionFormula f = collisionFormula(r, "m1", "m2");
    EXPECT_EQ(f.u.find("u = ("), std::string::npos) << f.u; // no centre-of-mass formula
    EXPECT_EQ(f.v1After, "v1' = -C·v1 = -1·6 = -6");
    EXPECT_EQ(f.v2After, "v2' = -C·v2 = -1·0 = 0");
    EXPECT_EQ(f.momentumAfter, "p after  = 1·(-6) + 2·0 = -6 kg·m/s");
    EXPECT_FALSE(f.note.empty());
}

TEST(EquationCheck, AGiantsVelocityGetsTheDigitsItsProductNeeds) {
    CollisionRecord r; // the pi scene: 1 kg and a 1000000 kg giant at nearly 1 m/s
    r.other = 1;
    r.m1 = 1.0, r.m2 = 1e6, r.v1 = 3.594, r.v2 = 0.99999354123, r.C = 1.0;
    r.u = (r.m1 * r.v1 + r.m2 * r.v2) / (r.m1 + r.m2);
    r.v1After = r.u - (r.v1 - r.u), r.v2After = r.u - (r.v2 - r.u);
    const CollisionFormula f = collisionFormula(r, "small", "giant");
    EXPECT_EQ(f.momentumBefore.rfind("p before = 1·3.594 + 1000000·0.99999354", 0), 0u)
        << f.momentumBefore;
    for (const std::string& line :
         {f.relative, f.u, f.v1After, f.v2After, f.momentumBefore, f.momentumAfter, f.given}) {
        const EquationReport c = checkEquations(line, kFormatNumberUnit);
        EXPECT_TRUE(c.holds()) << line << "\n" << problems(c);
    }
}

// The momentum arrow beside the inspector (lecture3 step 17) writes the giant's p = m2·v2' from
// the inspector's own digits: the same quantity, the same digits, and the product holds as
// printed. formatNumber alone wrote the arrow's 999999.917 against the inspector's
// 1000000·0.9999999175 = 999999.9175.
TEST(EquationCheck, AMomentumArrowWritesTheInspectorsDigits) {
    CollisionRecord r; // the pi scene's last collision: the giant leaves at 0.9999999175 m/s
    r.other = 1;
    r.m1 = 1.0, r.m2 = 1e6, r.v1 = 1.5937, r.v2 = 0.99999873006, r.C = 1.0;
    r.u = (r.m1 * r.v1 + r.m2 * r.v2) / (r.m1 + r.m2);
    r.v1After = r.u - (r.v1 - r.u), r.v2After = r.u - (r.v2 - r.u);
    const CollisionFormula f = collisionFormula(r, "small", "giant");
    EXPECT_EQ(f.m2Text, "1000000");
    EXPECT_NE(f.v2After.find(" = " + f.v2AfterText), std::string::npos) << f.v2After;
    const std::string p2 = productAsPrinted(f.m2Text, f.v2AfterText);
    ASSERT_FALSE(p2.empty());
    EXPECT_NE(p2, formatNumber(r.m2 * r.v2After)); // three decimals would not be the product
    const std::string arrow = f.m2Text + "·" + f.v2AfterText + " = " + p2;
    EXPECT_TRUE(equationsHold(arrow)) << arrow; // exact: only the digits printed count
    // and true of the momentum itself, to half a unit of its last digit (4 decimals here)
    EXPECT_NEAR(std::stod(p2), r.m2 * r.v2After, 0.5e-4) << p2;
    EXPECT_EQ(productAsPrinted("-2", "1.5"), "3"); // magnitudes: an arrow's length
    EXPECT_EQ(productAsPrinted("1e+15", "2"), ""); // no plain decimal, no product
}

TEST(EquationCheck, InfiniteMassesPrintNoInfiniteMomentum) {
    CollisionRecord r; // a platform (kinematic) reverses on a wall
    r.other = kWallRight;
    r.m1 = INFINITY, r.m2 = INFINITY, r.v1 = 2.0, r.u = 0.0, r.C = 1.0, r.v1After = -2.0;
    r.rule = ResolveRule::Reverse;
    const CollisionFormula f = collisionFormula(r, "lift", wallName(r.other));
    EXPECT_EQ(f.v1After, "v' = -v = -2   (infinite mass: it reverses)");
    EXPECT_TRUE(f.momentumBefore.empty()) << f.momentumBefore;
    // Two platforms meet: no u of a centre of mass, each reverses.
    CollisionRecord k;
    k.other = 1;
    k.m1 = INFINITY, k.m2 = INFINITY, k.v1 = 1.0, k.v2 = -3.0, k.C = 1.0;
    k.v1After = -1.0, k.v2After = 3.0;
    k.rule = ResolveRule::Reverse;
    const CollisionFormula g = collisionFormula(k, "A", "B");
    EXPECT_EQ(g.u.find("u = vB"), std::string::npos) << g.u;
    EXPECT_EQ(g.v2After, "vB' = -vB = 3   (infinite mass: it reverses)");
    EXPECT_TRUE(g.momentumBefore.empty()) << g.momentumBefore;
}

TEST(EquationCheck, TheRestRulePrintsTheGroupsVelocity) {
    CollisionRecord r; // a block lands slowly on one that rests on the floor: both stop
    r.other = 1;
    r.axis = 1;
    r.m1 = 1.0, r.m2 = 1.0, r.v1 = -0.01, r.v2 = 0.0, r.C = 0.0, r.u = 0.0;
    r.v1After = 0.0, r.v2After = 0.0;
    r.rest = true;
    r.rule = ResolveRule::RestAnchored;
    r.restBodies = 2;
    r.firstBelow = false;
    const CollisionFormula f = collisionFormula(r, "top", "base");
    // Not the pair's formula, (1·(-0.01) + 1·0)/(1 + 1) = -0.005: the group rests on the floor.
    EXPECT_EQ(f.u.find("u = ("), std::string::npos) << f.u;
    EXPECT_EQ(f.u.rfind("u = 0   (rest rule", 0), 0u) << f.u;
    EXPECT_TRUE(equationsHold(f.v1After)) << f.v1After;
}

// Records as the engine writes them for each rule, with numbers of every size (a fixed seed: the
// same records every run): every line holds, whatever digits it takes.
TEST(EquationCheck, InspectorLinesHoldForRecordsOfEveryRule) {
    std::mt19937 random(23);
    auto pick = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(random);
    };
    auto magnitude = [&] { // 1e-6 .. 1e7, either sign
        const double v = std::pow(10.0, pick(-6.0, 7.0));
        return pick(0.0, 1.0) < 0.5 ? -v : v;
    };
    const ResolveRule rules[] = {ResolveRule::Formula,      ResolveRule::Reflect,
                                 ResolveRule::Reverse,      ResolveRule::RestFree,
                                 ResolveRule::RestAnchored, ResolveRule::RestCrushed};
    for (int n = 0; n < 3000; ++n) {
        CollisionRecord r;
        r.rule = rules[n % 6];
        r.other = n % 4 == 0 ? kWallRight : 1;
        r.time = pick(0.0, 100.0);
        r.m1 = std::abs(magnitude());
        r.m2 = r.other < 0 || pick(0.0, 1.0) < 0.2 ? INFINITY : std::abs(magnitude());
        if (r.rule == ResolveRule::Reverse) r.m1 = r.m2 = INFINITY;
        if (r.rule == ResolveRule::Reflect) r.other = 1, r.m2 = std::abs(magnitude()); // blocks
        r.v1 = magnitude();
        r.v2 = r.other < 0 ? 0.0 : magnitude();
        r.C = n % 3 == 0 ? 1.0 : pick(0.0, 1.0);
        r.rest = r.rule >= ResolveRule::RestFree;
        if (r.rest) r.C = 0.0, r.restBodies = 2 + n % 3;
        if (r.rule == ResolveRule::RestFree && r.restBodies == 2 && std::isinf(r.m2))
            r.restBodies = 3; // a free pair has two finite masses
        // What the engine computes for each rule (resolve.cpp).
        if (r.rule == ResolveRule::Reflect) {
            r.u = 0.0;
        } else if (r.rule == ResolveRule::Reverse) {
            r.u = 0.0;
        } else if (r.rest && !(r.rule == ResolveRule::RestFree && r.restBodies == 2) &&
                   !(r.rule == ResolveRule::RestAnchored && std::isinf(r.m2))) {
            r.u = magnitude(); // the group's: not the pair's numbers
        } else if (std::isinf(r.m2)) {
            r.u = r.v2;
        } else {
            r.u = (r.m1 * r.v1 + r.m2 * r.v2) / (r.m1 + r.m2);
        }
        auto after = [&](double m, double v) {
            if (r.rule == ResolveRule::Reverse) return -v;
            if (std::isinf(m)) return r.rule == ResolveRule::RestCrushed ? -v : v;
            return r.rule == ResolveRule::Reflect ? -r.C * v : r.u - r.C * (v - r.u);
        };
        r.v1After = after(r.m1, r.v1);
        r.v2After = r.other < 0 ? 0.0 : after(r.m2, r.v2);
        if (n % 5 == 0) { // friction along the other axis
            r.mu = pick(0.0, 1.0), r.dvn = magnitude();
            r.dvt = r.mu * std::abs(r.dvn) * (n % 10 == 0 ? 1.0 : pick(0.0, 1.0));
        }
        expectInspectorHolds(r, "A", r.other < 0 ? wallName(r.other) : "B",
                             "record " + std::to_string(n));
        if (HasFailure()) break; // one record's lines are enough to read
    }
}

// The point of impact of a block at rest that is hit: a and b are how far the facing sides close
// (the mover's 6 m/s), so a/b is still t. Before, a = b = 0 m (its own speed) printed 0/0.
TEST(EquationCheck, APointOfImpactOfABlockThatIsHitHolds) {
    std::vector<Block> blocks(2);
    blocks[0].size = blocks[1].size = Vec2{1.0, 1.0};
    blocks[0].position = Vec2{5.0, 5.0}; // at rest, its left face at 4.5
    blocks[1].position = Vec2{3.75, 5.0};
    blocks[1].velocity = Vec2{6.0, 0.0}; // its right face at 4.25: 0.25 m to go
    WorldSettings s;
    s.gravity = Vec2{0.0, 0.0};
    s.dt = 0.1;
    const PoiView p = computePoi(blocks, Bounds{{0.0, 0.0}, {10.0, 10.0}}, s, 0.0, 0);
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.other, 1);
    EXPECT_NEAR(p.a, 0.25, 1e-12); // m: the gap
    EXPECT_NEAR(p.b, 0.6, 1e-12);  // m: 6 m/s over 0.1 s
    EXPECT_NEAR(p.t, 0.25 / 0.6, 1e-12);
    EXPECT_EQ(poiEquation(p), "t = a/b = 0.25/0.6 = 0.417 of the frame   (a, b: m along x)");
    // The brief form of a narrow scene's plate: the same numbers.
    EXPECT_EQ(poiEquation(p, false), "t = a/b = 0.25/0.6 = 0.417 of frame");
}

// Every line the inspector writes of `r`, and the checks of each.
int expectInspectorHolds(const CollisionRecord& r, const std::string& name1,
                         const std::string& name2, const std::string& where) {
    int checked = 0;
    const CollisionFormula f = collisionFormula(r, name1, name2);
    for (const std::string& line : {f.title, f.given, f.relative, f.u, f.v1After, f.v2After,
                                    f.momentumBefore, f.momentumAfter, f.note, f.friction}) {
        const EquationReport c = checkEquations(line, kFormatNumberUnit);
        checked += c.checked;
        EXPECT_TRUE(c.holds()) << where << "\n  " << line << "\n" << problems(c);
    }
    return checked;
}

std::string blockName(const World& w, const Scene& scene, int i) {
    if (i < 0) return wallName(i);
    const std::string& name = scene.blocks[static_cast<std::size_t>(i)].name;
    return nameWithMass(name.empty() ? "block " + std::to_string(i) : name,
                        w.blocks[static_cast<std::size_t>(i)].mass);
}

// Runs `scene` headless for `frames` frames and checks the inspector's lines of its first
// `sample` collisions (resting contacts of the rest rule included) and the point-of-impact line
// of each collider in those frames.
// Returns how many relations were checked.
int checkScene(const Scene& scene, const std::string& where, int frames, std::size_t sample) {
    int checked = 0;
    World w = makeWorld(scene);
    std::vector<CollisionRecord> log;
    std::size_t seen = 0;
    for (int f = 0; f < frames && seen < sample; ++f) {
        const std::vector<Block> before = w.blocks;
        const double frameStart = w.time;
        log.clear();
        w.step(&log);
        for (const CollisionRecord& r : log) {
            if (seen++ >= sample) break;
            const std::string at = where + ", frame " + std::to_string(f + 1);
            checked += expectInspectorHolds(r, blockName(w, scene, r.block),
                                            blockName(w, scene, r.other), at);
            const PoiView p = computePoi(before, w.bounds, w.settings, frameStart, r.block);
            if (p.valid) {
                const std::string line = poiEquation(p);
                const EquationReport c = checkEquations(line, kFormatNumberUnit);
                checked += c.checked;
                EXPECT_TRUE(c.holds()) << at << "\n  " << line << "\n" << problems(c);
            }
        }
    }
    return checked;
}

// The shipped lecture's lesson, its scenes from the shipped folder.
LessonResult lectureLesson() {
    LessonContext context;
    context.scenesDir = SANDBOX_SCENES_DIR;
    return loadLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", context);
}

std::vector<std::pair<std::string, Scene>> shippedScenes() {
    std::vector<std::pair<std::string, Scene>> out;
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(SANDBOX_SCENES_DIR))
        if (e.path().extension() == ".json") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    for (const std::string& file : files) {
        const SceneResult s = loadSceneFile(file);
        EXPECT_TRUE(s.scene) << file << ": " << s.error.message;
        if (s.scene) out.push_back({std::filesystem::path(file).stem().string(), *s.scene});
    }
    const LessonResult lesson = lectureLesson();
    EXPECT_TRUE(lesson.lesson) << lesson.error.message;
    if (lesson.lesson) {
        for (std::size_t i = 0; i < lesson.lesson->steps.size(); ++i)
            out.push_back(
                {"lecture3 step " + std::to_string(i + 1), *lesson.lesson->steps[i].scene});
    }
    return out;
}

// The text after a line's last " = ", up to the unit: its result as printed.
std::string resultOf(const std::string& line) {
    const std::size_t at = line.rfind(" = ");
    if (at == std::string::npos) return "";
    const std::string rest = line.substr(at + 3);
    return rest.substr(0, rest.find(' '));
}

// "v2 = 0.9999987301" of the givens: the text after "symbol = ", up to the comma.
std::string givenOf(const std::string& given, const std::string& symbol) {
    const std::size_t at = given.find(symbol + " = ");
    if (at == std::string::npos) return "";
    const std::size_t from = at + symbol.size() + 3;
    return given.substr(from, given.find_first_of(",;", from) - from);
}

// As an operand after an operator: "(-2)" for a negative number.
std::string asOperand(const std::string& number) {
    return !number.empty() && number[0] == '-' ? "(" + number + ")" : number;
}

// Step 17, the pi scene (a 1000000 kg giant at nearly 1 m/s): every quantity the inspector
// prints is written the same in every line, with the digits the most demanding line needs. Before,
// the u line wrote the giant's v2 = 0.9999987301 as "1" ("u = (1·1.594 + 1000000·1)/(1 +
// 1000000) = 1"), v2' as "1 - 1·(1 - 1) = 1" and v1' as 0.406 where p after took 0.4062990663.
TEST(EquationCheck, ThePiStepWritesEachQuantityTheSameInEveryLine) {
    const LessonResult lesson = lectureLesson();
    ASSERT_TRUE(lesson.lesson) << lesson.error.message;
    ASSERT_GE(lesson.lesson->steps.size(), 17u);
    const Scene& scene = *lesson.lesson->steps[16].scene;
    ASSERT_EQ(scene.blocks.size(), 2u);
    World w = makeWorld(scene);
    std::vector<CollisionRecord> log;
    int pairs = 0, walls = 0;
    for (int frame = 0; frame < 1200 && !HasFailure(); ++frame) { // 20 s: the 3141 are in 16
        log.clear();
        w.step(&log);
        for (const CollisionRecord& r : log) {
            const std::string name1 = blockName(w, scene, r.block);
            const std::string name2 = blockName(w, scene, r.other);
            const std::string where = "t = " + std::to_string(r.time);
            expectInspectorHolds(r, name1, name2, where);
            const CollisionFormula f = collisionFormula(r, name1, name2);
            // A block on a wall keeps its own symbol, none here: v.
            const std::string v1 = givenOf(f.given, r.other < 0 ? "v" : "v1");
            const std::string w1 = resultOf(f.v1After);
            ASSERT_FALSE(v1.empty()) << f.given;
            EXPECT_NE(f.v1After.find("·(" + v1 + " - "), std::string::npos) << where << "\n"
                                                                            << f.given << "\n"
                                                                            << f.v1After;
            EXPECT_NE(f.momentumBefore.find("·" + asOperand(v1)), std::string::npos)
                << where << "\n"
                << f.given << "\n"
                << f.momentumBefore;
            EXPECT_NE(f.momentumAfter.find("·" + asOperand(w1)), std::string::npos)
                << where << "\n"
                << f.v1After << "\n"
                << f.momentumAfter;
            if (r.other < 0) {
                ++walls;
                continue;
            }
            ++pairs;
            // u's formula takes the givens' v1 and v2, and v1', v2' take u as printed.
            const std::string v2 = givenOf(f.given, "v2"), u = resultOf(f.u);
            const std::string w2 = resultOf(f.v2After);
            for (const std::string& v : {v1, v2})
                EXPECT_NE(f.u.find("·" + asOperand(v)), std::string::npos) << where << "\n"
                                                                           << f.given << "\n"
                                                                           << f.u;
            EXPECT_EQ(f.v1After.rfind("v1' = " + u + " - ", 0), 0u) << f.u << "\n" << f.v1After;
            EXPECT_EQ(f.v2After.rfind("v2' = " + u + " - 1·(" + v2 + " - " + asOperand(u) + ")", 0),
                      0u)
                << f.given << "\n"
                << f.u << "\n"
                << f.v2After;
            EXPECT_NE(f.momentumAfter.find("·" + asOperand(w2) + " = "), std::string::npos)
                << where << "\n"
                << f.v2After << "\n"
                << f.momentumAfter;
            // The rel. vel. line takes them too.
            EXPECT_NE(f.relative.find(" = " + v1 + " - " + asOperand(v2) + " = "),
                      std::string::npos)
                << where << "\n"
                << f.given << "\n"
                << f.relative;
        }
    }
    EXPECT_EQ(pairs + walls, 3141); // every collision of the step was read
}

// The "done when": every shipped scene and the lesson's, the three methods, resolve
// momentum and reflect, without friction and with 0.5; up to 1200 frames (20 s at 60 Hz: the pi
// scene's first hits come after 9 s), the first 20 collisions of each run (a jam's thousands
// would cost seconds and add no new kind of line).
TEST(EquationCheck, EveryInspectorLineHoldsOverEveryShippedScene) {
    int runs = 0, checked = 0;
    for (const auto& [name, scene] : shippedScenes()) {
        for (const Method method : {Method::Perfect, Method::MoveAndCorrect, Method::TurnBased}) {
            for (const Resolve resolve : {Resolve::Momentum, Resolve::Reflect}) {
                for (const double friction : {0.0, 0.5}) {
                    Scene s = scene;
                    s.settings.method = method;
                    s.settings.resolve = resolve;
                    s.settings.friction = friction;
                    checked +=
                        checkScene(s,
                                   name + " " + methodName(method) + " " + resolveName(resolve) +
                                       " friction " + std::to_string(friction),
                                   1200, 20);
                    ++runs;
                }
            }
        }
    }
    EXPECT_GE(runs, 12 * 50);  // 30 scenes and 26 steps
    EXPECT_GT(checked, 20000); // the lines were read, not skipped
    std::printf("%d runs, %d relations checked\n", runs, checked);
}

// The lesson's own text, as shown (computed from the step as written: lesson_prompt.h): whatever
// a caption, question, choice or answer writes as an equation holds.
TEST(EquationCheck, EveryEquationInTheLectureLessonHolds) {
    const LessonResult lesson = lectureLesson();
    ASSERT_TRUE(lesson.lesson) << lesson.error.message;
    int checked = 0;
    for (std::size_t i = 0; i < lesson.lesson->steps.size(); ++i) {
        const LessonStep& step = lesson.lesson->steps[i];
        const StepPrompt prompt = stepPrompt(step);
        std::vector<std::string> texts{step.title, prompt.caption, prompt.question,
                                       stepAnswer(step, runStepToPause(step), {}, nullptr).text};
        texts.insert(texts.end(), prompt.choices.begin(), prompt.choices.end());
        for (const std::string& text : texts) {
            const EquationReport c = checkEquations(text);
            checked += c.checked;
            EXPECT_TRUE(c.holds()) << "step " << i + 1 << ": " << text << "\n" << problems(c);
        }
    }
    EXPECT_GT(checked, 10); // the answers' worked numbers were read, not skipped
}

} // namespace
