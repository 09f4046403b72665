// Random sets of boxes for the broad-phase tests (CornerGrid, BroadPhase), and the brute-force
// answers they are compared with.
#pragma once

#include "collision.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace box_sets {

struct BoxSet {
    Bounds bounds{{-3.0, 2.0}, {17.0, 14.0}};
    std::vector<Block> blocks;
    std::vector<Aabb> boxes;
};

// `count` boxes: most 0.2 to 0.6 m wide, one in 50 up to 6 m (large for the cells), one in 50
// sticking out of the bounds; every tenth block static.
inline BoxSet randomSetup(std::uint64_t seed, int count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    BoxSet s;
    for (int i = 0; i < count; ++i) {
        const bool large = i % 50 == 7;
        const double maxSize = large ? 6.0 : 0.6;
        const Vec2 size{0.2 + (maxSize - 0.2) * unit(rng), 0.2 + (maxSize - 0.2) * unit(rng)};
        const double margin = unit(rng) < 1.0 / 50.0 ? 2.0 : 0.0;
        const Vec2 min{s.bounds.min.x - margin + 20.0 * unit(rng),
                       s.bounds.min.y - margin + 12.0 * unit(rng)};
        Block b;
        b.size = size;
        b.kind = i % 10 == 0 ? BodyKind::Static : BodyKind::Dynamic;
        s.blocks.push_back(b);
        s.boxes.push_back({min, min + size});
    }
    return s;
}

inline std::vector<int> bruteForceQuery(const std::vector<Aabb>& boxes, const Aabb& query,
                                        int self) {
    std::vector<int> found;
    for (int j = 0; j < static_cast<int>(boxes.size()); ++j)
        if (j != self && meets(boxes[j], query)) found.push_back(j);
    return found;
}

// Registers a random box of `s` anew: moved by up to `reach` (m) along each axis, one in twenty
// grown fivefold, some shrunk to a fifth. Returns its index.
inline int moveRandomBox(BoxSet& s, std::mt19937_64& rng, double reach) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int i = static_cast<int>(unit(rng) * static_cast<double>(s.boxes.size()));
    const Vec2 shift{reach * (2.0 * unit(rng) - 1.0), reach * (2.0 * unit(rng) - 1.0)};
    const double grow = unit(rng) < 0.05 ? 5.0 : unit(rng) < 0.1 ? 0.2 : 1.0;
    const Vec2 size = (s.boxes[i].max - s.boxes[i].min) * grow;
    s.boxes[i].min += shift;
    s.boxes[i].max = s.boxes[i].min + size;
    return i;
}

// A query box anywhere in and around the bounds of randomSetup(), up to 3 m on a side.
inline Aabb randomQueryBox(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Vec2 corner{-4.0 + 22.0 * unit(rng), 1.0 + 14.0 * unit(rng)};
    return {corner, corner + Vec2{3.0 * unit(rng), 3.0 * unit(rng)}};
}

// Every pair a < b, not both static, for which test(boxes[a], boxes[b]) holds, in order (the
// broad phases never report two static blocks: they are never resolved).
template <class Test> std::vector<std::pair<int, int>> bruteForcePairs(const BoxSet& s, Test test) {
    std::vector<std::pair<int, int>> pairs;
    const int n = static_cast<int>(s.boxes.size());
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            if (test(s.boxes[a], s.boxes[b]) &&
                !(s.blocks[a].kind == BodyKind::Static && s.blocks[b].kind == BodyKind::Static))
                pairs.emplace_back(a, b);
    return pairs;
}

// The blocks a broad phase's query visits, sorted: `query(visit)` runs the query with `visit`.
template <class Query> std::vector<int> sortedVisits(Query query) {
    std::vector<int> found;
    query([&](int j) { found.push_back(j); });
    std::sort(found.begin(), found.end());
    return found;
}

// The touching row: 0 and 1 share an edge, 2 starts 5e-10 m after 1 ends (within the touch
// tolerance of 1e-9 m), so the pairs that meet are {0, 1} and {1, 2}.
inline BoxSet touchingRow() {
    BoxSet s;
    s.blocks.assign(3, Block{});
    s.boxes = {
        {{1.0, 3.0}, {1.5, 3.5}}, {{1.5, 3.0}, {2.0, 3.5}}, {{2.0 + 5e-10, 3.0}, {2.5, 3.5}}};
    return s;
}

// Two queries compared with the brute-force answer: a random block's own box (leaving that block
// out), and a box anywhere. `answer(query, self)` is the broad phase's sorted answer (self -1:
// no block left out).
template <class Answer>
void expectQueriesExact(const BoxSet& s, std::mt19937_64& rng, Answer answer) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int self = static_cast<int>(unit(rng) * static_cast<double>(s.boxes.size()));
    EXPECT_EQ(answer(s.boxes[self], self), bruteForceQuery(s.boxes, s.boxes[self], self));
    const Aabb anywhere = randomQueryBox(rng);
    EXPECT_EQ(answer(anywhere, -1), bruteForceQuery(s.boxes, anywhere, -1));
}

} // namespace box_sets
