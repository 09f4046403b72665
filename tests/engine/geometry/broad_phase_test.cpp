// The BroadPhase (the grid all three methods use) answers exactly what a test of every box against
// every other answers: each query's blocks once, each overlapping or meeting pair once, with boxes
// of mixed sizes (some spanning many cells), boxes outside the bounds, touching boxes, and after
// boxes are registered again (entering cells through the overflow lists, leaving them dead).
#include "broad_phase.h"

#include "box_sets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace {

using box_sets::BoxSet;
using box_sets::bruteForcePairs;
using box_sets::randomSetup;

std::vector<int> queryAnswer(const BroadPhase& grid, const Aabb& query, int self) {
    std::vector<int> found = box_sets::sortedVisits([&](auto visit) {
        if (self < 0)
            grid.query(query, visit);
        else
            grid.queryOthers(query, self, visit);
    });
    const size_t visited = found.size();
    found.erase(std::unique(found.begin(), found.end()), found.end());
    EXPECT_EQ(found.size(), visited) << "a block was visited twice";
    return found;
}

template <class ForEach> std::vector<std::pair<int, int>> pairsOf(ForEach forEach) {
    std::vector<std::pair<int, int>> pairs;
    forEach([&](int a, int b) { pairs.emplace_back(std::min(a, b), std::max(a, b)); });
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

TEST(BroadPhase, PairsAreExactlyTheBoxesThatOverlapOrMeet) {
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        const BoxSet s = randomSetup(seed, 300);
        BroadPhase grid;
        grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; });
        const auto meeting = pairsOf([&](auto visit) { grid.forEachMeetingPair(visit); });
        const auto overlapping = pairsOf([&](auto visit) { grid.forEachOverlappingPair(visit); });
        EXPECT_EQ(meeting, bruteForcePairs(s, meets)) << "seed " << seed;
        EXPECT_EQ(overlapping, bruteForcePairs(s, overlaps)) << "seed " << seed;
        EXPECT_FALSE(overlapping.empty());
    }
}

TEST(BroadPhase, QueriesFindExactlyTheBoxesThatMeetAlsoAfterSet) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        BoxSet s = randomSetup(seed, 300);
        BroadPhase grid;
        grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; });
        for (int round = 0; round < 200; ++round) {
            // Register a block again: moved (often into other cells), sometimes grown over many
            // cells or shrunk back, sometimes moved back where it was (re-entering a cell).
            const BoxSet before = s;
            const int i = box_sets::moveRandomBox(s, rng, 1.0);
            grid.set(i, s.boxes[i]);
            if (unit(rng) < 0.2) {
                s.boxes[i] = before.boxes[i];
                grid.set(i, s.boxes[i]);
            }
            EXPECT_EQ(grid.box(i).max.x, s.boxes[i].max.x);
            box_sets::expectQueriesExact(s, rng, [&](const Aabb& query, int self) {
                return queryAnswer(grid, query, self);
            });
        }
        // After all the moves, the pairs too (overflow lists and dead slots).
        const auto meeting = pairsOf([&](auto visit) { grid.forEachMeetingPair(visit); });
        EXPECT_EQ(meeting, bruteForcePairs(s, meets)) << "seed " << seed;
    }
}

TEST(BroadPhase, TouchingAndNearlyTouchingBoxesMeetButDoNotOverlap) {
    const BoxSet s = box_sets::touchingRow();
    BroadPhase grid;
    grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; });
    EXPECT_EQ(pairsOf([&](auto visit) { grid.forEachMeetingPair(visit); }),
              (std::vector<std::pair<int, int>>{{0, 1}, {1, 2}}));
    EXPECT_TRUE(pairsOf([&](auto visit) { grid.forEachOverlappingPair(visit); }).empty());
    // kTouchTolerance is 1e-9 m: a gap of 2e-9 m does not meet.
    EXPECT_EQ(queryAnswer(grid, {{2.5 + 2e-9, 3.0}, {3.0, 3.5}}, -1), std::vector<int>{});
    EXPECT_EQ(queryAnswer(grid, {{2.5 + 5e-10, 3.0}, {3.0, 3.5}}, -1), std::vector<int>{2});
}

TEST(BroadPhase, QueryOthersLeavesOutOnlyTheAskingBlock) {
    BoxSet s;
    s.blocks.assign(2, Block{});
    s.boxes = {{{1.0, 3.0}, {2.0, 4.0}}, {{1.5, 3.5}, {2.5, 4.5}}};
    BroadPhase grid;
    grid.build(s.bounds, s.blocks, [&](int i) { return s.boxes[i]; });
    EXPECT_EQ(queryAnswer(grid, s.boxes[0], -1), (std::vector<int>{0, 1}));
    EXPECT_EQ(queryAnswer(grid, s.boxes[0], 0), std::vector<int>{1});
    EXPECT_EQ(queryAnswer(grid, s.boxes[0], 1), std::vector<int>{0});
}

} // namespace
