// Broad phase: a uniform grid over the world's closed bounds. Each block registers a box that must
// contain wherever it goes for the rest of the step (its swept box); a query returns every block
// whose registered box meets the query box, each once. Shared by all three methods.
#pragma once

#include "collision.h"

#include <cstdint>
#include <vector>

class BroadPhase {
  public:
    // Sizes the grid for the bounds and the blocks' typical size; registers no block.
    void reset(const Bounds& bounds, const std::vector<Block>& blocks);
    // Registers (or moves) block `index` to `box`.
    void set(int index, const Aabb& box);
    const Aabb& box(int index) const { return boxes_[index]; }

    // Calls visit(j) once for every registered block j whose box overlaps `query`.
    template <class Visit> void query(const Aabb& query, Visit&& visit);

  private:
    struct CellRange {
        int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    };
    CellRange rangeOf(const Aabb& box) const;
    void insert(int index, const CellRange& range);
    void erase(int index, const CellRange& range);

    Vec2 origin_;
    double inverseCellSize_ = 1.0;
    int columns_ = 1, rows_ = 1;
    std::vector<std::vector<int>> cells_; // block indices per cell, row-major
    std::vector<Aabb> boxes_;             // registered box per block
    std::vector<CellRange> ranges_;       // cells each block is in
    std::vector<std::uint32_t> visited_;  // query stamp per block, to report each block once
    std::uint32_t stamp_ = 0;
};

template <class Visit> void BroadPhase::query(const Aabb& query, Visit&& visit) {
    const CellRange range = rangeOf(query);
    if (++stamp_ == 0) { // wrapped: clear the stamps once every 4 billion queries
        std::fill(visited_.begin(), visited_.end(), 0u);
        stamp_ = 1;
    }
    for (int y = range.y0; y <= range.y1; ++y) {
        for (int x = range.x0; x <= range.x1; ++x) {
            for (int j : cells_[static_cast<size_t>(y) * columns_ + x]) {
                if (visited_[j] == stamp_) continue;
                visited_[j] = stamp_;
                const Aabb& other = boxes_[j];
                // Touching counts: resting contacts and faces about to meet are candidates.
                if (other.max.x >= query.min.x && other.min.x <= query.max.x &&
                    other.max.y >= query.min.y && other.min.y <= query.max.y)
                    visit(j);
            }
        }
    }
}
