// The CornerGrid answers exactly what a test of every box against every other answers: the same
// blocks for a query, the same pairs, with boxes of mixed sizes, a few large ones, boxes outside
// the bounds, and after boxes are registered again (moved to other cells or to the large list).
#include "corner_grid.h"

#include "box_sets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace {

using box_sets::BoxSet;
using box_sets::randomSetup;

std::vector<int> queryAnswer(const CornerGrid& grid, const Aabb& query, int self) {
    return box_sets::sortedVisits([&](auto visit) { grid.queryOthers(query, self, visit); });
}

TEST(CornerGrid, PairsAreExactlyTheBoxesThatMeet) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const BoxSet s = randomSetup(seed, 300);
        CornerGrid grid;
        ASSERT_TRUE(grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; }));
        std::vector<std::pair<int, int>> pairs;
        grid.forEachMeetingPair([&](int a, int b) { pairs.emplace_back(a, b); });
        std::sort(pairs.begin(), pairs.end());
        // Every pair that meets, except two static blocks (never resolved, never reported).
        const auto expected = box_sets::bruteForcePairs(s, meets);
        EXPECT_EQ(pairs, expected) << "seed " << seed;
        EXPECT_FALSE(expected.empty());
    }
}

TEST(CornerGrid, QueriesFindExactlyTheBoxesThatMeetAlsoAfterSet) {
    std::mt19937_64 rng(7);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        BoxSet s = randomSetup(seed, 300);
        CornerGrid grid;
        ASSERT_TRUE(grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; }));
        for (int round = 0; round < 200; ++round) {
            // Register a block again: moved a little (often into another cell), sometimes grown
            // into a large box or shrunk back.
            const int i = box_sets::moveRandomBox(s, rng, 0.5);
            grid.set(i, s.boxes[i]);
            EXPECT_EQ(grid.box(i).max.x, s.boxes[i].max.x);
            // Query a block's own box, and a box anywhere.
            box_sets::expectQueriesExact(s, rng, [&](const Aabb& query, int self) {
                return queryAnswer(grid, query, self);
            });
        }
    }
}

TEST(CornerGrid, TouchingAndNearlyTouchingBoxesMeet) {
    const BoxSet s = box_sets::touchingRow();
    CornerGrid grid;
    ASSERT_TRUE(grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; }));
    std::vector<std::pair<int, int>> pairs;
    grid.forEachMeetingPair([&](int a, int c) { pairs.emplace_back(a, c); });
    std::sort(pairs.begin(), pairs.end());
    EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
}

// One box in three 12 m wide, the others 0.1 m: twice the mean extent is 8.3 m, so 34 boxes are
// too large for cells sized by the typical box.
BoxSet mixedSizes() {
    BoxSet s;
    Block b;
    for (int i = 0; i < 100; ++i) {
        const double size = i % 3 == 0 ? 12.0 : 0.1;
        s.blocks.push_back(b);
        const Vec2 min{-3.0 + 0.15 * i, 2.0};
        s.boxes.push_back({min, min + Vec2{size, 0.1}});
    }
    return s;
}

TEST(CornerGrid, DeclinesWhenManyBoxesAreLargeForTheCells) {
    BoxSet s = mixedSizes();
    // In a world 100 m wide (8.3 m is less than a quarter of it: see the next test).
    s.bounds = {{-3.0, 2.0}, {97.0, 14.0}};
    CornerGrid grid;
    EXPECT_FALSE(grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; }));
    EXPECT_EQ(grid.box(3).max.x, s.boxes[3].max.x) << "the boxes stay readable";
}

TEST(CornerGrid, TakesEveryBoxWhenTheBoxesSpanMuchOfTheWorld) {
    // The same boxes in the 20 m world: 8.3 m is more than a quarter of it, so a cell holds
    // every box (paths of blocks crossing the world, issue 13), and the answers stay exact.
    const BoxSet s = mixedSizes();
    CornerGrid grid;
    ASSERT_TRUE(grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; }));
    std::vector<std::pair<int, int>> pairs, expected;
    grid.forEachMeetingPair([&](int i, int j) { pairs.emplace_back(i, j); });
    for (int i = 0; i < 100; ++i)
        for (int j = i + 1; j < 100; ++j)
            if (meets(s.boxes[i], s.boxes[j])) expected.emplace_back(i, j);
    std::sort(pairs.begin(), pairs.end());
    EXPECT_EQ(pairs, expected);
}

} // namespace
