// Hostile and extreme input (issue 13): the limits table (input_limits.h), the one escaping
// function (printable.h), and the validator's verdicts at the edges of what the arithmetic
// carries. Every refusal names its place and the limit; every accepted value steps to a finite
// state.
#include "input_limits.h"
#include "overlap_check.h"
#include "printable.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

// ---- The limits table ----

TEST(InputLimits, NumbersAreWrittenShortAndExact) {
    EXPECT_EQ(limits::formatNumber(1e-6), "1e-6");
    EXPECT_EQ(limits::formatNumber(1e15), "1e15");
    EXPECT_EQ(limits::formatNumber(5e-324), "5e-324");
    EXPECT_EQ(limits::formatNumber(0.5), "0.5");
    EXPECT_EQ(limits::formatNumber(1.0 / 60.0), "0.016666666666666666");
    EXPECT_EQ(limits::formatNumber(-2.0), "-2");
    EXPECT_EQ(limits::describe(limits::kDt), "from 1e-6 to 1 s");
    EXPECT_EQ(limits::describe(limits::kSubsteps), "a whole number from 1 to 1000");
}

TEST(InputLimits, TextIsCountedInCharacters) {
    EXPECT_EQ(limits::characterCount("m1 = 1 kg"), 9u);
    EXPECT_EQ(limits::characterCount("µ = 0.4 · é"), 11u); // UTF-8: µ, · and é are one each
    EXPECT_EQ(limits::textLengthViolation(std::string(200, 'a'), 200), "");
    EXPECT_EQ(limits::textLengthViolation(std::string(100, 'a') + std::string(50, '\xc3'), 100),
              "must be at most 100 characters, not 150");
    std::string accents;
    for (int i = 0; i < 200; ++i) accents += "é"; // 400 bytes, 200 characters
    EXPECT_EQ(limits::textLengthViolation(accents, 200), "");
    EXPECT_EQ(limits::textLengthViolation(accents + "é", 200),
              "must be at most 200 characters, not 201");
}

TEST(InputLimits, ViolationsNameTheLimit) {
    EXPECT_EQ(limits::violation(limits::kDt, 1.0 / 60.0), "");
    EXPECT_EQ(limits::violation(limits::kDt, 5e-324), "must be from 1e-6 to 1 s, not 5e-324");
    EXPECT_EQ(limits::violation(limits::kMass, 1e15), ""); // the edges are inside
    EXPECT_EQ(limits::violation(limits::kMass, 1e-15), "");
    EXPECT_NE(limits::violation(limits::kMass, NAN), "");
    EXPECT_NE(limits::violation(limits::kSubsteps, 2.5), "");
    EXPECT_NE(limits::violation(limits::kGravity, 1e308), "");
    EXPECT_EQ(limits::lengthViolation(1.0, 5e8), "");
    EXPECT_NE(limits::lengthViolation(0.4, 5e8).find("at least 0.5 m at 5e8"), std::string::npos);
}

TEST(InputLimits, FlagsParseDecimalNumbersOnly) {
    double x = 0.0;
    for (const char* ok : {"1", "-2.5", "+3", ".5", "5.", "1e3", "1E-3", "0", "007"}) {
        EXPECT_TRUE(limits::parseNumber(ok, x)) << ok;
    }
    EXPECT_TRUE(limits::parseNumber("1e-400", x));
    EXPECT_EQ(x, 0.0); // underflow: 0, for the range check
    EXPECT_TRUE(limits::parseNumber("1e400", x));
    EXPECT_TRUE(std::isinf(x)); // overflow: refused by every range
    for (const char* bad : {"", "0x10", "inf", "nan", "-", ".", "e5", "1e", " 1", "1 ", "1,5",
                            "1e+", "--1", "1.2.3", "0x1p3"}) {
        EXPECT_FALSE(limits::parseNumber(bad, x)) << bad;
    }
}

// ---- printable() ----

TEST(Printable, EscapesControlsAndKeepsText) {
    EXPECT_EQ(printable("plain text"), "plain text");
    EXPECT_EQ(printable("\x1b]0;owned\x07"), "\\x1b]0;owned\\x07");
    EXPECT_EQ(printable("tab\tnew\nline\r"), "tab\\x09new\\x0aline\\x0d");
    EXPECT_EQ(printable("\x7f"), "\\x7f");
    EXPECT_EQ(printable("ünïcode €"), "ünïcode €"); // valid UTF-8 stays
    EXPECT_EQ(printable("\xc2\x9b"
                        "2J"),
              "\\xc2\\x9b2J"); // C1 CSI
    EXPECT_EQ(printable("a\xe2\x80\xae"
                        "b"),
              "a\\xe2\\x80\\xaeb");                          // right-to-left override
    EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");          // not UTF-8
    EXPECT_EQ(printable("\xc3"), "\\xc3");                   // truncated sequence
    EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");          // overlong '/'
    EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80"); // a surrogate
    EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
}

TEST(Printable, CutsLongTextWithAnEllipsis) {
    const std::string name(10'000'000, 'A');
    const std::string shown = printable(name);
    EXPECT_LE(shown.size(), kPrintableDefault + 30);
    EXPECT_EQ(shown, std::string(kPrintableDefault, 'A') + "...(10000000 bytes)");
    // Never inside a character or an escape.
    EXPECT_EQ(printable("ééé", 5), "éé...(6 bytes)");
    EXPECT_EQ(printable("ab\x1b", 5), "ab...(3 bytes)");
    EXPECT_EQ(printable("abcde", 5), "abcde");
}

// ---- The validator ----

SceneResult parse(const std::string& text) {
    return parseScene(text, "t.json");
}

std::string blocks(const std::string& list, const std::string& world = "") {
    return R"({"name": "t", "world": {)" + world + R"(}, "blocks": [)" + list + "]}";
}

// Refused at `where`, with a message containing `says`.
void expectRefused(const std::string& text, const std::string& where, const std::string& says) {
    const SceneResult r = parse(text);
    ASSERT_FALSE(r.scene) << "accepted: " << text.substr(0, 200);
    EXPECT_EQ(r.error.where, where) << r.error.text();
    EXPECT_NE(r.error.message.find(says), std::string::npos) << r.error.text();
}

// Every byte of an error is printable ASCII or UTF-8 text: no control bytes.
void expectNoControlBytes(const SceneError& e) {
    for (const char c : e.text())
        EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 || c == 0x7f) << e.text();
}

TEST(HostileScenes, ValuesThatTheArithmeticCannotCarryAreRefusedWithTheLimit) {
    expectRefused(blocks(R"({"position": [5, 5], "size": 1, "mass": 5e-324})"),
                  "t.json: blocks[0].mass", "from 1e-15 to 1e15 kg, not 5e-324");
    expectRefused(blocks("", R"("dt": 5e-324)"), "t.json: world.dt", "from 1e-6 to 1 s");
    expectRefused(blocks("", R"("gravity": [0, -1e10])"), "t.json: world.gravity[1]",
                  "from -1e9 to 1e9 m/s^2");
    expectRefused(blocks("", R"("substeps": 1e9)"), "t.json: world.substeps", "1 to 1000");
    expectRefused(blocks("", R"("bounds": [0, 0, 1e-300, 1])"), "t.json: world.bounds (width)",
                  "from 1e-6 to 2e9 m");
    expectRefused(blocks("", R"("bounds": [1e8, 0, 100000000.05, 1])"),
                  "t.json: world.bounds (width)", "at least 1e-9 of the coordinates it sits at");
}

TEST(HostileScenes, ATinyBlockBesideABigOneIsRefusedForItsSizeNotAsOverlapping) {
    // A 1e-30 m block at (5, 6) and a 1 m block at (8, 6), 2.5 m apart: the tiny one's edges
    // round onto its centre. It is refused for its size, naming the limit.
    expectRefused(blocks(R"({"position": [5, 6], "size": 1e-30}, {"position": [8, 6], "size": 1})"),
                  "t.json: blocks[0].size", "from 1e-6 to 1e9 m, not 1e-30");
    // The smallest size is fine there.
    EXPECT_TRUE(
        parse(blocks(R"({"position": [5, 6], "size": 1e-6}, {"position": [8, 6], "size": 1})"))
            .scene);
}

TEST(HostileScenes, SizesBelowWhatThePositionResolvesAreRefused) {
    // Two 1e-12 m blocks at (1e8, 5e8) were points to the arithmetic (they passed through each
    // other); 1e-6 m ones are refused by the resolution rule: at least 1e-9 of the coordinate.
    const std::string world = R"("bounds": [0, 0, 1e9, 1e9])";
    expectRefused(blocks(R"({"position": [1e8, 5e8], "size": 1e-12})", world),
                  "t.json: blocks[0].size", "not 1e-12");
    expectRefused(blocks(R"({"position": [1e8, 5e8], "size": 1e-6})", world),
                  "t.json: blocks[0].size", "at least 0.5 m at 5e8");
    expectRefused(blocks(R"({"position": [1e8, 5e8], "size": [0.05, 1]})", world),
                  "t.json: blocks[0].size[0]", "at least 0.1 m at 1e8");
    // Two blocks at the limit on the same spot are seen to overlap.
    expectRefused(blocks(R"({"position": [1e8, 5e8], "size": 0.5},
                            {"position": [1e8, 5e8], "size": 0.5})",
                         world),
                  "t.json: blocks[1]", "overlaps");
}

TEST(HostileScenes, DuplicateKeysAreComparedDecoded) {
    expectRefused(blocks(R"({"position": [5, 5], "size": 1, "mass": 1, "m\u0061ss": "static"})"),
                  "t.json:1:82", "duplicate key \"mass\" (written \"m\\u0061ss\")");
    expectRefused(R"({"name": "a", "n\u0061me": "b", "blocks": []})", "t.json:1:15", "\"name\"");
    // A pair of surrogates and the character itself; an escaped quote and backslash.
    expectRefused(R"({"name": "a", "blocks": [], "world": {}, "\ud83d\ude00": 1, "😀": 2})",
                  "t.json:1:61", "duplicate key");
    expectRefused(R"({"name": "a", "blocks": [], "a\"\\": 1, "a\u0022\u005c": 2})", "t.json:1:41",
                  "duplicate key");
    // Keys that only look alike are different keys (then unknown).
    expectRefused(R"({"name": "a", "blocks": [], "nam\u0065s": 1})", "t.json: names",
                  "unknown key");
}

TEST(HostileScenes, EchoedTextHasNoControlBytes) {
    const char* const cases[] = {
        R"({"name": "t", "world": {"method": "\u001b]0;owned\u0007"}, "blocks": []})",
        R"({"name": "t", "\u001b]0;owned\u0007": 1, "blocks": []})",
        R"({"name": "t", "blocks": [{"name": "\u001b[2J\u009b", "position": [5, 5], "size": 1},
            {"position": [5.5, 5], "size": 1}]})",
        R"({"name": "t", "blocks": [], "\u001b": 1, "\u001b": 2})",
    };
    for (const char* text : cases) {
        const SceneResult r = parse(text);
        ASSERT_FALSE(r.scene) << text;
        expectNoControlBytes(r.error);
        EXPECT_NE(r.error.text().find("\\x1b"), std::string::npos) << r.error.text();
    }
    // A raw escape in the text: the parser's message quotes it (as <U+001B>).
    const SceneResult raw = parse("{\"name\": \"t\", \"blocks\": [\x1b]}");
    ASSERT_FALSE(raw.scene);
    expectNoControlBytes(raw.error);
    // The file's name too.
    const SceneResult r = parseScene("{", "evil\x1b]0;x\x07.json");
    ASSERT_FALSE(r.scene);
    expectNoControlBytes(r.error);
}

TEST(HostileScenes, LongNamesAndNumbersAreCutInMessages) {
    const std::string name(10'000'000, 'A');
    // A name at the limit (200 characters) is quoted cut in an overlap's message.
    const SceneResult r = parse(blocks(R"({"name": ")" + name.substr(0, 200) +
                                       R"(", "position": [5, 5], "size": 1},
                                          {"position": [5.5, 5], "size": 1})"));
    ASSERT_FALSE(r.scene);
    EXPECT_LT(r.error.text().size(), 1000u) << r.error.text().substr(0, 300);
    EXPECT_NE(r.error.message.find("...(200 bytes)"), std::string::npos) << r.error.message;
    // A longer one is refused for its length, the length said, nothing quoted.
    const SceneResult longer =
        parse(blocks(R"({"name": ")" + name + R"(", "position": [5, 5], "size": 1})"));
    ASSERT_FALSE(longer.scene);
    EXPECT_EQ(longer.error.text(),
              "t.json: blocks[0].name: must be at most 200 characters, not 10000000");
    const SceneResult n =
        parse(blocks(R"({"position": [5, )" + std::string(300'000, '9') + R"(], "size": 1})"));
    ASSERT_FALSE(n.scene);
    EXPECT_LT(n.error.text().size(), 1000u) << n.error.text().substr(0, 300);
    EXPECT_EQ(n.error.where, "t.json:1:56");
    const SceneResult key = parse(R"({"name": "t", "blocks": [], ")" + name + R"(": 1})");
    ASSERT_FALSE(key.scene);
    EXPECT_LT(key.error.text().size(), 1000u);
}

TEST(HostileScenes, NamesAndTheDescriptionHaveTheirLengths) {
    // Each at its limit is taken; one character more is refused, naming the field and the limit.
    const std::string name(limits::kMaxNameChars, 'n');
    const std::string description(limits::kMaxDescriptionChars, 'd');
    const std::string scene =
        R"({"name": ")" + name + R"(", "description": ")" + description + R"(", "blocks": []})";
    ASSERT_TRUE(parse(scene).scene) << parse(scene).error.text();
    expectRefused(R"({"name": ")" + name + R"(n", "blocks": []})", "t.json: name",
                  "must be at most 200 characters, not 201");
    expectRefused(R"({"name": "t", "description": ")" + description + R"(d", "blocks": []})",
                  "t.json: description", "must be at most 10000 characters, not 10001");
    expectRefused(R"({"name": ")" + std::string(20 << 20, 'A') + R"(", "blocks": []})",
                  "t.json: name", "must be at most 200 characters, not 20971520");
}

TEST(HostileScenes, ASymlinkLoopSaysSo) {
    const std::filesystem::path dir = testing::TempDir() + "hostile_symlink_loop";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::filesystem::create_symlink(dir / "b.json", dir / "a.json");
    std::filesystem::create_symlink(dir / "a.json", dir / "b.json");
    const SceneResult r = loadSceneFile((dir / "a.json").string());
    ASSERT_FALSE(r.scene);
    EXPECT_EQ(r.error.message.find("no such file"), std::string::npos) << r.error.text();
    EXPECT_NE(r.error.message.find("symbolic links"), std::string::npos) << r.error.text();
    std::filesystem::remove_all(dir);
}

TEST(HostileScenes, BoxesWithoutAreaOverlapNothing) {
    // A zero-width box used to leave the sweep before entering it, and then "overlapped" a
    // box far to its right.
    const std::vector<overlap_check::Box> boxes = {{5.0, 6.0, 5.0, 6.0}, {7.5, 5.5, 8.5, 6.5}};
    EXPECT_FALSE(overlap_check::findOverlap(boxes));
}

// ---- Accepted extremes step to finite states ----

// The extreme masses under move-and-correct (1/m of 5e-324 kg overflowed to a NaN position):
// at the limits, a head-on collision keeps the state finite and conserves momentum. Tolerance: a
// relative 1e-12 of the largest momentum (a few roundings of products up to 1e15 · 3).
TEST(HostileScenes, ExtremeMassesStayFiniteAndConserveMomentum) {
    const SceneResult r = parse(blocks(R"({"position": [5, 5], "size": 1, "mass": 1e-15,
        "velocity": [3, 0]}, {"position": [6.5, 5], "size": 1, "mass": 1e15, "velocity": [-1, 0]})",
                                       R"("gravity": [0, 0], "method": "move-and-correct")"));
    ASSERT_TRUE(r.scene) << r.error.text();
    World world = makeWorld(*r.scene);
    const Vec2 before = totalMomentum(world);
    int collisions = 0;
    for (int i = 0; i < 120; ++i) collisions += world.step().collisions;
    EXPECT_GT(collisions, 0);
    for (const Block& b : world.blocks) {
        EXPECT_TRUE(std::isfinite(b.position.x) && std::isfinite(b.position.y));
        EXPECT_TRUE(std::isfinite(b.velocity.x) && std::isfinite(b.velocity.y));
    }
    // Only the light block meets a wall in these 2 s (the heavy one moves 2 m of the 6 m to
    // it), and its momentum is 1e-30 of the total.
    EXPECT_NEAR(totalMomentum(world).x, before.x, 1e-12 * 1e15);
}

// The largest gravity, coordinates and masses give finite energies (they gave inf for
// --gravity 1e308,1e308).
TEST(HostileScenes, LargestValuesGiveFiniteEnergies) {
    const SceneResult r = parse(blocks(R"({"position": [-999999999, 999999999], "size": 1,
        "mass": 1e15, "velocity": [1e9, -1e9]})",
                                       R"("bounds": [-1e9, -1e9, 1e9, 1e9],
                                          "gravity": [1e9, -1e9])"));
    ASSERT_TRUE(r.scene) << r.error.text();
    World world = makeWorld(*r.scene);
    for (int i = 0; i < 60; ++i) world.step();
    EXPECT_TRUE(std::isfinite(kineticEnergy(world)));
    EXPECT_TRUE(std::isfinite(potentialEnergy(world)));
    EXPECT_TRUE(std::isfinite(totalMomentum(world).x));
}

} // namespace
