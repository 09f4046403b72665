// Pairs of two static blocks are never reported by the broad phases (issue 13): they never move,
// so they are never resolved, and 20,000 overlapping ones made every pair search quadratic. The
// other pairs stay exactly those of before, in the same order: the same blocks with the static
// ones registered as kinematic (same sizes, so the same grid) give the same sequence of pairs
// once the pairs of two (originally) static blocks are taken out.
#include "broad_phase.h"
#include "corner_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

namespace {

using Pairs = std::vector<std::pair<int, int>>;

struct Pile {
    Bounds bounds{{0.0, 0.0}, {20.0, 12.0}};
    std::vector<Block> blocks;
};

// `count` blocks of 0.5 m, `statics` of them static; most statics piled up where the moving
// blocks are, so that they overlap each other and the moving ones.
Pile pile(std::uint64_t seed, int count, int statics) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Pile s;
    for (int i = 0; i < count; ++i) {
        Block b;
        b.size = {0.5, 0.5};
        const bool fixed = i % (count / statics) == 0;
        b.kind = fixed ? BodyKind::Static : BodyKind::Dynamic;
        const double spread = fixed && unit(rng) < 0.8 ? 0.3 : 19.0;
        b.position = {0.5 + spread * unit(rng), 0.5 + (spread < 1 ? spread : 11.0) * unit(rng)};
        s.blocks.push_back(b);
    }
    return s;
}

std::vector<Block> staticAsKinematic(std::vector<Block> blocks) {
    for (Block& b : blocks)
        if (b.kind == BodyKind::Static) b.kind = BodyKind::Kinematic;
    return blocks;
}

Pairs withoutStaticPairs(const Pairs& pairs, const std::vector<Block>& blocks) {
    Pairs out;
    for (const auto& [a, b] : pairs)
        if (!(blocks[a].kind == BodyKind::Static && blocks[b].kind == BodyKind::Static))
            out.emplace_back(a, b);
    return out;
}

template <class Grid> Pairs meetingPairs(Grid& grid) {
    Pairs pairs;
    grid.forEachMeetingPair([&](int a, int b) { pairs.emplace_back(a, b); });
    return pairs;
}

Pairs overlappingPairs(const BroadPhase& grid) {
    Pairs pairs;
    grid.forEachOverlappingPair([&](int a, int b) { pairs.emplace_back(a, b); });
    return pairs;
}

TEST(StaticPairs, BroadPhaseSkipsThemAndKeepsTheOrderOfTheRest) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const Pile s = pile(seed, 600, seed % 2 ? 60 : 6); // with and without the links
        const std::vector<Block> kinematic = staticAsKinematic(s.blocks);
        auto boxOf = [&](int i) { return aabbOf(s.blocks[i]); };
        BroadPhase with, without;
        with.build(s.bounds, s.blocks, boxOf);
        without.build(s.bounds, kinematic, boxOf);
        const Pairs expectedMeeting = withoutStaticPairs(meetingPairs(without), s.blocks);
        const Pairs expectedOverlapping = withoutStaticPairs(overlappingPairs(without), s.blocks);
        EXPECT_EQ(meetingPairs(with), expectedMeeting) << "seed " << seed;
        EXPECT_EQ(overlappingPairs(with), expectedOverlapping) << "seed " << seed;
        EXPECT_GT(meetingPairs(without).size(), expectedMeeting.size()) << "seed " << seed;
        // Moved blocks (overflow lists, dead slots) change nothing of that.
        for (int i = 1; i < 600; i += 7) {
            Aabb moved = aabbOf(s.blocks[i]);
            moved.min.x += 0.7, moved.max.x += 0.7;
            if (s.blocks[i].kind != BodyKind::Static) with.set(i, moved), without.set(i, moved);
        }
        EXPECT_EQ(overlappingPairs(with), withoutStaticPairs(overlappingPairs(without), s.blocks))
            << "seed " << seed;
    }
}

TEST(StaticPairs, CornerGridSkipsThemAndKeepsTheOrderOfTheRest) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const Pile s = pile(seed, 600, seed % 2 ? 60 : 6);
        const std::vector<Block> kinematic = staticAsKinematic(s.blocks);
        auto boxOf = [&](int i) { return aabbOf(s.blocks[i]); };
        CornerGrid with, without;
        ASSERT_TRUE(with.build(s.bounds, s.blocks, boxOf));
        ASSERT_TRUE(without.build(s.bounds, kinematic, boxOf));
        const Pairs all = meetingPairs(without);
        EXPECT_EQ(meetingPairs(with), withoutStaticPairs(all, s.blocks)) << "seed " << seed;
        EXPECT_GT(all.size(), withoutStaticPairs(all, s.blocks).size()) << "seed " << seed;
    }
}

// Large boxes (the corner grid's list, tested against the cells and each other), static ones
// among them: the pairs are those of a test of every pair, but for pairs of static blocks.
TEST(StaticPairs, CornerGridWithLargeStaticBlocks) {
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        Pile s = pile(seed, 600, seed % 2 ? 60 : 6);
        for (int i = 0; i < 600; i += 100) s.blocks[i].size = {3.0, 2.0}; // static
        for (int i = 3; i < 600; i += 150) s.blocks[i].size = {2.0, 3.0}; // moving
        auto boxOf = [&](int i) { return aabbOf(s.blocks[i]); };
        CornerGrid grid;
        ASSERT_TRUE(grid.build(s.bounds, s.blocks, boxOf));
        Pairs pairs = meetingPairs(grid), expected;
        std::sort(pairs.begin(), pairs.end());
        for (int a = 0; a < 600; ++a)
            for (int b = a + 1; b < 600; ++b)
                if (meets(boxOf(a), boxOf(b))) expected.emplace_back(a, b);
        EXPECT_EQ(pairs, withoutStaticPairs(expected, s.blocks)) << "seed " << seed;
    }
}

// The case: 20,000 static blocks on one spot and one block touching them. Only the
// 20,000 pairs with the moving block remain (of 200 million).
TEST(StaticPairs, TwentyThousandOverlappingStaticBlocks) {
    Pile s;
    for (int i = 0; i < 20000; ++i) {
        Block b;
        b.position = {10.0, 2.0};
        b.size = {1.0, 1.0};
        b.kind = BodyKind::Static;
        s.blocks.push_back(b);
    }
    Block falling;
    falling.position = {10.3, 3.0}; // resting on the pile
    falling.size = {1.0, 1.0};
    s.blocks.push_back(falling);
    auto boxOf = [&](int i) { return aabbOf(s.blocks[i]); };
    BroadPhase grid;
    grid.build(s.bounds, s.blocks, boxOf);
    const Pairs pairs = meetingPairs(grid);
    ASSERT_EQ(pairs.size(), 20000u);
    for (const auto& [a, b] : pairs) EXPECT_EQ(b, 20000);
    EXPECT_TRUE(overlappingPairs(grid).empty()); // touching is not overlap
    CornerGrid corners;
    ASSERT_TRUE(corners.build(s.bounds, s.blocks, boxOf));
    EXPECT_EQ(meetingPairs(corners).size(), 20000u);
}

} // namespace
