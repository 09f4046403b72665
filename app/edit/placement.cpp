#include "placement.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <vector>

namespace {

bool overlapsPositively(Vec2 pa, Vec2 sa, Vec2 pb, Vec2 sb) {
    const double ox = (sa.x + sb.x) * 0.5 - std::abs(pa.x - pb.x);
    const double oy = (sa.y + sb.y) * 0.5 - std::abs(pa.y - pb.y);
    return ox > 0.0 && oy > 0.0;
}

double clampAxis(double v, double lo, double hi, double half) {
    if (hi - lo <= 2.0 * half) return (lo + hi) * 0.5;
    return std::clamp(v, lo + half, hi - half);
}

} // namespace

int pickBlock(const World& world, Vec2 p, double tolerance) {
    for (int i = static_cast<int>(world.blocks.size()) - 1; i >= 0; --i) {
        const Block& b = world.blocks[static_cast<std::size_t>(i)];
        const Vec2 h = b.halfSize();
        if (std::abs(p.x - b.position.x) <= h.x + tolerance &&
            std::abs(p.y - b.position.y) <= h.y + tolerance) {
            return i;
        }
    }
    return -1;
}

Vec2 clampIntoBounds(const Bounds& bounds, Vec2 position, Vec2 size) {
    return {clampAxis(position.x, bounds.min.x, bounds.max.x, size.x * 0.5),
            clampAxis(position.y, bounds.min.y, bounds.max.y, size.y * 0.5)};
}

bool overlapsAnyBlock(const World& world, int ignore, Vec2 position, Vec2 size) {
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        if (static_cast<int>(i) == ignore) continue;
        const Block& b = world.blocks[i];
        if (overlapsPositively(position, size, b.position, b.size)) return true;
    }
    return false;
}

std::optional<Vec2> placeWithoutOverlap(const World& world, int ignore, Vec2 desired, Vec2 size) {
    if (!std::isfinite(desired.x) || !std::isfinite(desired.y)) return std::nullopt;
    const Vec2 start = clampIntoBounds(world.bounds, desired, size);
    if (!overlapsAnyBlock(world, ignore, start, size)) return start;

    // Breadth-first search over spots beside the blocks in the way: each blocked spot proposes
    // the four spots touching the sides of every block it overlaps. The best free spot is the
    // one nearest to `desired`.
    constexpr int kMaxVisited = 256;
    std::deque<Vec2> queue{start};
    std::vector<Vec2> visited;
    std::optional<Vec2> best;
    double bestDistance = 0.0;
    auto seen = [&visited](Vec2 p) {
        for (const Vec2& q : visited) {
            if (approxEqual(p, q, 1e-9)) return true;
        }
        return false;
    };
    while (!queue.empty() && static_cast<int>(visited.size()) < kMaxVisited) {
        const Vec2 p = queue.front();
        queue.pop_front();
        for (std::size_t i = 0; i < world.blocks.size(); ++i) {
            if (static_cast<int>(i) == ignore) continue;
            const Block& b = world.blocks[i];
            if (!overlapsPositively(p, size, b.position, b.size)) continue;
            const double dx = (b.size.x + size.x) * 0.5 + kPlacementGap;
            const double dy = (b.size.y + size.y) * 0.5 + kPlacementGap;
            const Vec2 candidates[4] = {{b.position.x - dx, p.y},
                                        {b.position.x + dx, p.y},
                                        {p.x, b.position.y - dy},
                                        {p.x, b.position.y + dy}};
            for (Vec2 c : candidates) {
                c = clampIntoBounds(world.bounds, c, size);
                if (seen(c)) continue;
                visited.push_back(c);
                if (!overlapsAnyBlock(world, ignore, c, size)) {
                    const double d = lengthSquared(c - desired);
                    if (!best || d < bestDistance) {
                        best = c;
                        bestDistance = d;
                    }
                } else {
                    queue.push_back(c);
                }
            }
        }
    }
    return best;
}
