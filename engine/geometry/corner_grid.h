// Corner grid: the perfect method's broad phase for blocks of similar size. Each registered box
// (a block's path for the rest of the substep) is filed under one cell only, the one holding its
// lower-left corner, and the cells are larger than the boxes (plus the touch tolerance). Two boxes
// that meet then have their corners in the same or in neighbouring cells, so building the grid
// writes one entry per block (the BroadPhase writes one per covered cell, about 2.3 in a gas) and
// every pair is found by looking at a cell and four of its neighbours. The few boxes larger than
// that (a big static block, a bullet's long path) are kept in a list that every query reads.
//
// What it answers is exactly what the BroadPhase answers for the same registered boxes: the
// blocks j whose box meets the query box (meets(), touching and the tolerance count), and every
// pair of boxes that meet, tested as meets(box of the lower index, box of the higher), except
// pairs of two static blocks (never resolved: scene files let them overlap). Only the order of the
// answers differs.
#pragma once

#include "collision.h"

#include <algorithm>
#include <cstdint>
#include <vector>

class CornerGrid {
  public:
    // Registers every block i with the box boxOf(i). Returns false when too many boxes are too
    // large for cells sized by the typical box (very mixed sizes): the grid is then unusable, and
    // the caller uses the BroadPhase, whose cost does not depend on that (box() stays valid).
    template <class BoxOf>
    bool build(const Bounds& bounds, const std::vector<Block>& blocks, BoxOf&& boxOf) {
        // The moving blocks' extents (static ones do not count: a floor may be as wide as the
        // world), their largest and their sum, for the cell size.
        Extents extents;
        boxes_.resize(blocks.size());
        staticList_.clear();
        for (size_t i = 0; i < blocks.size(); ++i) {
            const Aabb& b = boxes_[i] = boxOf(static_cast<int>(i));
            if (blocks[i].kind == BodyKind::Static) {
                staticList_.push_back(static_cast<int>(i));
                continue;
            }
            const double extent = std::max(b.max.x - b.min.x, b.max.y - b.min.y);
            extents.largest = extent > extents.largest ? extent : extents.largest;
            extents.sum += extent;
            ++extents.count;
        }
        return fileAll(bounds, extents);
    }
    // Registers block `index` to `box` instead of its current box.
    void set(int index, const Aabb& box);
    const Aabb& box(int index) const { return boxes_[index]; }

    // Calls visit(j) once for every registered block j other than `self` with meets(box(j),
    // query).
    template <class Visit> void queryOthers(const Aabb& query, int self, Visit&& visit) const;
    // Calls visit(i, j), i < j, once for every pair, not both static, with meets(box(i), box(j)).
    // Only right after build() (no set() since).
    template <class Visit> void forEachMeetingPair(Visit&& visit) const;

  private:
    static constexpr int kLarge = -1; // cell of a box too large for the cells
    static constexpr int kDead = -1;  // a slot whose block has left the cell

    struct Extents {
        double largest = 0.0; // m
        double sum = 0.0;     // m
        int count = 0;
    };
    // Sizes the cells for the boxes and files every box (a counting sort by cell); false when
    // too many are large (see build()).
    bool fileAll(const Bounds& bounds, const Extents& extents);
    // Fits into a cell: both extents at most maxSmallExtent_ (NaN never fits).
    bool isSmall(const Aabb& b) const {
        return (b.max.x - b.min.x <= maxSmallExtent_) & (b.max.y - b.min.y <= maxSmallExtent_);
    }
    static int clampCell(double v, int count) {
        // v clamped to [0, count - 1] (NaN to 0), then truncated: monotone in v.
        const double last = count - 1;
        v = 0.0 < v ? v : 0.0;
        return static_cast<int>(last < v ? last : v);
    }
    int column(double x) const { return clampCell((x - origin_.x) * inverseCellSize_, columns_); }
    int row(double y) const { return clampCell((y - origin_.y) * inverseCellSize_, rows_); }
    int cellOf(const Aabb& b) const {
        return isSmall(b) ? row(b.min.y) * columns_ + column(b.min.x) : kLarge;
    }
    std::vector<int>& overflowList(int cell);
    // Every small block j whose corner lies in cells [x0, x1] x [y0, y1] (clamped to the grid).
    template <class Visit> void forEachInCells(int x0, int y0, int x1, int y1, Visit&& visit) const;

    Vec2 origin_;
    double inverseCellSize_ = 1.0;
    double maxSmallExtent_ = 0.0; // m: boxes up to this wide and high go into cells
    int columns_ = 1, rows_ = 1;
    // Per cell: its first slot in sorted_ (the next cell's start ends it; one more entry ends
    // the last), and 0 or 1 + the index of its list in overflow_. Arrays of integers, so that
    // zeroing them is a memset.
    std::vector<std::uint32_t> cellStart_;    // columns*rows + 1
    std::vector<std::uint32_t> cellOverflow_; // columns*rows
    std::vector<int> sorted_;                 // block indices sorted by cell (kDead: moved away)
    std::vector<std::vector<int>> overflow_;  // blocks that entered a cell after build(), reused
    size_t overflowInUse_ = 0;                // lists of overflow_ owned by a cell
    std::vector<int> large_;                  // blocks whose box is too large for the cells
    std::vector<int> cell_;                   // per block: its cell, or kLarge
    std::vector<Aabb> boxes_;                 // registered box per block
    std::vector<int> staticList_;             // the static blocks
    std::vector<std::uint8_t> statics_;       // per block: 1 if static (empty without any)
    // With at least 16 static blocks (else empty): per slot of sorted_ (and one past the end),
    // the first slot at or after it holding a moving block, so that a static block is tested
    // against the moving ones only (20,000 overlapping static blocks in a cell: 20,000 tests,
    // not 200 million).
    std::vector<std::uint32_t> nextMoving_;
};

template <class Visit>
void CornerGrid::forEachInCells(int x0, int y0, int x1, int y1, Visit&& visit) const {
    x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0;
    x1 = x1 < columns_ ? x1 : columns_ - 1, y1 = y1 < rows_ ? y1 : rows_ - 1;
    for (int y = y0; y <= y1; ++y) {
        // The slices of a row's cells are adjacent in sorted_: one span.
        const size_t first = static_cast<size_t>(y) * columns_ + x0;
        const size_t last = static_cast<size_t>(y) * columns_ + x1;
        for (std::uint32_t k = cellStart_[first]; k < cellStart_[last + 1]; ++k)
            if (sorted_[k] != kDead) visit(sorted_[k]);
        if (overflowInUse_ == 0) continue;
        for (size_t c = first; c <= last; ++c)
            if (cellOverflow_[c])
                for (int j : overflow_[cellOverflow_[c] - 1]) visit(j);
    }
}

// Why the cells searched suffice: a small box P whose corner is left of (or level with) that of
// a box Q it meets has Q.min.x <= P.max.x + t <= P.min.x + maxSmallExtent + t (up to rounding),
// which is less than a cell (fileAll() sizes the cells with a margin for the rounding), so their
// corners' columns differ by at most one; the same for rows. So a block that meets the query
// has its corner no more than one column left of the query's corner, and (meets() tests
// box.min.x <= query.max.x + t, and column() is monotone) no further right than
// column(query.max.x + t).
template <class Visit>
void CornerGrid::queryOthers(const Aabb& query, int self, Visit&& visit) const {
    constexpr double t = kTouchTolerance;
    auto test = [&](int j) {
        if (j != self && meets(boxes_[j], query)) visit(j);
    };
    forEachInCells(column(query.min.x) - 1, row(query.min.y) - 1, column(query.max.x + t),
                   row(query.max.y + t), test);
    for (int j : large_) test(j);
}

template <class Visit> void CornerGrid::forEachMeetingPair(Visit&& visit) const {
    auto test = [&](int a, int b) {
        const int lo = a < b ? a : b, hi = a < b ? b : a;
        if (meets(boxes_[lo], boxes_[hi])) visit(lo, hi);
    };
    // Small pairs: a block and the blocks after it in its cell, in the next cell of its row, and
    // in the three cells above those; each pair of neighbouring cells is looked at once. Block by
    // block, row by row (most cells are empty: visiting each would cost more than the tests).
    for (int y = 0; y < rows_; ++y) {
        const size_t rowStart = static_cast<size_t>(y) * columns_;
        const bool rowAbove = y + 1 < rows_;
        const std::uint32_t rowEnd = cellStart_[rowStart + columns_];
        for (std::uint32_t s = cellStart_[rowStart]; s < rowEnd; ++s) {
            const int a = sorted_[s];
            const size_t c = static_cast<size_t>(cell_[a]);
            const size_t x = c - rowStart;
            const size_t right = x + 1 < static_cast<size_t>(columns_) ? 1 : 0;
            const size_t left = x > 0 ? 1 : 0;
            // The slots [from, to) after block a; after a static one only the moving blocks
            // among them (by the links when there are many static blocks).
            auto span = [&](std::uint32_t from, std::uint32_t to) {
                if (statics_.empty() || !statics_[a]) {
                    for (std::uint32_t k = from; k < to; ++k) test(a, sorted_[k]);
                } else if (nextMoving_.empty()) {
                    for (std::uint32_t k = from; k < to; ++k)
                        if (!statics_[sorted_[k]]) test(a, sorted_[k]);
                } else {
                    for (std::uint32_t k = nextMoving_[from]; k < to; k = nextMoving_[k + 1])
                        test(a, sorted_[k]);
                }
            };
            span(s + 1, cellStart_[c + right + 1]);
            if (!rowAbove) continue;
            const size_t above = c + columns_;
            span(cellStart_[above - left], cellStart_[above + right + 1]);
        }
    }
    // Large boxes against the small ones (one more column and row on the right and top: here the
    // test may be meets(small, large), which rounds b.min - t instead of b.max + t), then against
    // each other.
    constexpr double t = kTouchTolerance;
    for (size_t g = 0; g < large_.size(); ++g) {
        const int a = large_[g];
        const Aabb& box = boxes_[a];
        forEachInCells(column(box.min.x) - 1, row(box.min.y) - 1, column(box.max.x + t) + 1,
                       row(box.max.y + t) + 1, [&](int b) {
                           if (statics_.empty() || !(statics_[a] & statics_[b])) test(a, b);
                       });
        for (size_t h = g + 1; h < large_.size(); ++h)
            if (statics_.empty() || !(statics_[a] & statics_[large_[h]])) test(a, large_[h]);
    }
}
