// Random sets of boxes for the broad-phase tests (CornerGrid, BroadPhase), and the brute-force
// answers they are compared with.
#pragma once

#include "collision.h"

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

// Every pair a < b for which test(boxes[a], boxes[b]) holds, in order.
template <class Test>
std::vector<std::pair<int, int>> bruteForcePairs(const std::vector<Aabb>& boxes, Test test) {
    std::vector<std::pair<int, int>> pairs;
    const int n = static_cast<int>(boxes.size());
    for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
            if (test(boxes[a], boxes[b])) pairs.emplace_back(a, b);
    return pairs;
}

} // namespace box_sets
