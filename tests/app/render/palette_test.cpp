// The palette for every reader: the blocks' colours and every group of marks drawn together stay
// at least kMinMarkDifference (CIEDE2000) apart for normal vision and under simulated protanopia,
// deuteranopia and tritanopia (Machado, Oliveira and Fernandes 2009, severity 1.0), in the dark
// and the light theme; and the colour science that says so, checked against published values.
#include "color_vision.h"
#include "palette.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace {

// Sharma, Wu and Dalal 2005, table 1 (pairs 1, 4, 7, 13, 17, 21, 25, 34): printed to 4 decimals,
// so the tolerance is half of the last digit.
TEST(ColorVision, Ciede2000MatchesSharmasTestData) {
    struct Pair {
        Lab x, y;
        double expected;
    };
    const Pair pairs[] = {
        {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
        {{50.0, -1.3802, -84.2814}, {50.0, 0.0, -82.7485}, 1.0000},
        {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
        {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0011}, 7.2195},
        {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
        {{50.0, 2.5, 0.0}, {50.0, 3.1736, 0.5854}, 1.0000},
        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
        {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    };
    for (const Pair& p : pairs) {
        EXPECT_NEAR(ciede2000(p.x, p.y), p.expected, 5e-5);
        EXPECT_NEAR(ciede2000(p.y, p.x), p.expected, 5e-5); // symmetric
    }
}

// The simulation against colorspacious 1.1.2 (an independent implementation of the same
// matrices): the colours are floats, so 1e-5.
TEST(ColorVision, SimulationMatchesColorspacious) {
    const Color red{0.9f, 0.36f, 0.33f, 1.0f}, blue{0.2f, 0.6f, 0.9f, 1.0f};
    struct Case {
        Color in;
        Vision vision;
        Color expected;
    };
    const Case cases[] = {
        {red, Vision::Protanopia, {0.49976509f, 0.46463952f, 0.32351266f, 1.0f}},
        {red, Vision::Deuteranopia, {0.63476421f, 0.58063411f, 0.31612817f, 1.0f}},
        {red, Vision::Tritanopia, {0.9842451f, 0.24920834f, 0.35655013f, 1.0f}},
        {blue, Vision::Protanopia, {0.46018618f, 0.6117064f, 0.9127608f, 1.0f}},
        {blue, Vision::Tritanopia, {0.0f, 0.67273214f, 0.70815111f, 1.0f}}, // clamped
        {red, Vision::Normal, red},
    };
    for (const Case& c : cases) {
        const Color s = simulateVision(c.in, c.vision);
        EXPECT_NEAR(s.r, c.expected.r, 1e-5) << visionName(c.vision);
        EXPECT_NEAR(s.g, c.expected.g, 1e-5) << visionName(c.vision);
        EXPECT_NEAR(s.b, c.expected.b, 1e-5) << visionName(c.vision);
    }
    // CIELab of the red (colorspacious: 57.0765, 52.9960, 32.1540 with its own white): 0.02.
    const Lab lab = toLab(red);
    EXPECT_NEAR(lab.L, 57.0828, 0.02);
    EXPECT_NEAR(lab.a, 52.9828, 0.02);
    EXPECT_NEAR(lab.b, 32.1613, 0.02);
}

// The smallest difference of any two colours of `colors` under any vision, with the pair named.
struct Closest {
    double difference = 1e9;
    std::string what;
};
Closest closestPair(const std::vector<std::pair<std::string, Color>>& colors) {
    Closest closest;
    for (Vision vision : kVisions) {
        for (std::size_t i = 0; i < colors.size(); ++i) {
            for (std::size_t j = i + 1; j < colors.size(); ++j) {
                const double d = ciede2000(toLab(simulateVision(colors[i].second, vision)),
                                           toLab(simulateVision(colors[j].second, vision)));
                if (d < closest.difference) {
                    closest.difference = d;
                    closest.what = colors[i].first + " and " + colors[j].first + " under " +
                                   visionName(vision);
                }
            }
        }
    }
    return closest;
}

TEST(Palette, BlocksStayApartForEveryReader) {
    std::vector<std::pair<std::string, Color>> colors;
    for (const NamedColor& c : blockPalette()) colors.emplace_back(c.name, c.color);
    const Closest closest = closestPair(colors);
    EXPECT_GE(closest.difference, kMinMarkDifference) << closest.what;
    // The pair the issue names: red and green are far apart for everyone.
    std::vector<std::pair<std::string, Color>> redGreen{{"red", blockColor(0, "")},
                                                        {"green", blockPalette()[6].color}};
    EXPECT_GE(closestPair(redGreen).difference, kMinMarkDifference);
    std::set<std::string> names;
    for (const NamedColor& c : blockPalette()) names.insert(c.name);
    EXPECT_EQ(names.size(), blockPalette().size());
}

TEST(Palette, MarksDrawnTogetherStayApartForEveryReaderInBothThemes) {
    for (bool light : {false, true}) {
        for (const MarkGroup& group : markGroups()) {
            const Color backdrop = backdropColor(group.backdrop, light);
            std::vector<std::pair<std::string, Color>> colors{{"the backdrop", backdrop}};
            for (Mark mark : group.marks) {
                const MarkColors& m = markTable()[static_cast<std::size_t>(mark)];
                colors.emplace_back(m.name, markColor(mark, light).over(backdrop));
            }
            const Closest closest = closestPair(colors);
            EXPECT_GE(closest.difference, kMinMarkDifference)
                << group.name << (light ? " (light theme): " : " (dark theme): ") << closest.what;
        }
    }
}

TEST(Palette, MarkTableIsInMarkOrderAndEveryMarkIsInAGroup) {
    std::set<Mark> grouped;
    for (const MarkGroup& group : markGroups())
        grouped.insert(group.marks.begin(), group.marks.end());
    for (std::size_t i = 0; i < markTable().size(); ++i) {
        const MarkColors& m = markTable()[i];
        EXPECT_EQ(static_cast<std::size_t>(m.mark), i) << m.name;
        EXPECT_TRUE(grouped.count(m.mark)) << m.name << " is in no group";
    }
}

// The arithmetic of the check itself: a pair that is plainly alike fails it, so the tests above
// can fail: the red and the green of the blocks' earlier palette look alike to a deuteranope
// (8.7 apart).
TEST(Palette, TheCheckCanFail) {
    std::vector<std::pair<std::string, Color>> alike{{"red", {0.90f, 0.36f, 0.33f, 1.0f}},
                                                     {"green", {0.40f, 0.78f, 0.45f, 1.0f}}};
    EXPECT_LT(closestPair(alike).difference, kMinMarkDifference);
}

} // namespace
