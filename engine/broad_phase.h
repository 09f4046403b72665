// Broad phase: a uniform grid over the world's closed bounds. Each block registers a box that must
// contain wherever it goes for the rest of the step (its swept box); a query returns every block
// whose registered box meets the query box, each once. Shared by all three methods.
//
// Layout: build() sorts all boxes into cells at once (a counting sort into one contiguous array,
// each cell a slice of it), so queries read memory in order. set() moves one block later: a
// block that leaves a cell is marked dead in that slice, a block that enters a cell goes into
// that cell's small overflow list. Each cell stores copies of its boxes. A pair of boxes sharing
// several cells is reported only from the first cell they share (the lowest column and row of the
// intersection of their cell ranges), so nothing is reported twice and queries keep no state.
#pragma once

#include "collision.h"

#include <vector>

class BroadPhase {
  public:
    // Sizes the grid for the bounds and the blocks' typical size and registers every block i
    // with the box boxOf(i).
    template <class BoxOf>
    void build(const Bounds& bounds, const std::vector<Block>& blocks, BoxOf&& boxOf) {
        boxes_.resize(blocks.size());
        for (size_t i = 0; i < blocks.size(); ++i) boxes_[i] = boxOf(static_cast<int>(i));
        buildFromBoxes(bounds, blocks);
    }
    // Registers block `index` to `box` instead of its current box.
    void set(int index, const Aabb& box);
    const Aabb& box(int index) const { return boxes_[index]; }

    // Calls visit(j) once for every registered block j whose box meets `query` (touching counts:
    // resting contacts and faces about to meet are candidates).
    template <class Visit> void query(const Aabb& query, Visit&& visit) const;
    // Calls visit(i, j) once for every pair of registered blocks whose boxes overlap with
    // positive area.
    template <class Visit> void forEachOverlappingPair(Visit&& visit) const {
        forEachPair(visit, [](const Aabb& a, const Aabb& b) { return overlaps(a, b); });
    }
    // The same for every pair whose boxes meet (touching counts).
    template <class Visit> void forEachMeetingPair(Visit&& visit) const {
        forEachPair(visit, [](const Aabb& a, const Aabb& b) { return meets(a, b); });
    }

  private:
    struct CellRange {
        int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
        bool has(int x, int y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    };
    struct Entry {
        Aabb box;
        int index; // -1: the block left this cell
    };
    // The entries of one cell: its slice of the sorted array, then its overflow list.
    struct CellView {
        const Entry* sorted;
        size_t sortedCount;
        const std::vector<Entry>& overflow;
        size_t size() const { return sortedCount + overflow.size(); }
        const Entry& operator[](size_t k) const {
            return k < sortedCount ? sorted[k] : overflow[k - sortedCount];
        }
    };

    void buildFromBoxes(const Bounds& bounds, const std::vector<Block>& blocks);
    template <class Visit, class Test> void forEachPair(Visit& visit, Test test) const;
    CellRange rangeOf(const Aabb& box) const;
    size_t cellIndex(int x, int y) const { return static_cast<size_t>(y) * columns_ + x; }
    CellView cell(int x, int y) const {
        const size_t c = cellIndex(x, y);
        return {sorted_.data() + cellStart_[c], cellStart_[c + 1] - cellStart_[c], overflow_[c]};
    }
    Entry* find(int x, int y, int index);
    // Boxes that touch, or miss each other by less than kTouchTolerance: a box computed one way
    // may differ by rounding from the same box computed another, and no contact may be lost.
    static bool meets(const Aabb& a, const Aabb& b) {
        constexpr double t = kTouchTolerance;
        return a.max.x >= b.min.x - t && a.min.x <= b.max.x + t && a.max.y >= b.min.y - t &&
               a.min.y <= b.max.y + t;
    }
    // True in exactly one of the cells that the ranges a and b share.
    static bool firstSharedCell(int x, int y, const CellRange& a, const CellRange& b) {
        return x == std::max(a.x0, b.x0) && y == std::max(a.y0, b.y0);
    }

    Vec2 origin_;
    double inverseCellSize_ = 1.0;
    int columns_ = 1, rows_ = 1;
    std::vector<size_t> cellStart_;            // slice of sorted_ per cell (columns*rows + 1)
    std::vector<Entry> sorted_;                // entries sorted by cell
    std::vector<std::vector<Entry>> overflow_; // entries added by set(), per cell
    std::vector<size_t> overflowUsed_;         // cells whose overflow list is not empty
    std::vector<Aabb> boxes_;                  // registered box per block
    std::vector<CellRange> ranges_;            // cells each block is in
};

template <class Visit> void BroadPhase::query(const Aabb& query, Visit&& visit) const {
    const CellRange range = rangeOf(query);
    for (int y = range.y0; y <= range.y1; ++y) {
        for (int x = range.x0; x <= range.x1; ++x) {
            const CellView entries = cell(x, y);
            for (size_t k = 0, n = entries.size(); k < n; ++k) {
                const Entry& e = entries[k];
                if (e.index < 0 || !meets(e.box, query)) continue;
                if (firstSharedCell(x, y, range, ranges_[e.index])) visit(e.index);
            }
        }
    }
}

template <class Visit, class Test> void BroadPhase::forEachPair(Visit& visit, Test test) const {
    for (int y = 0; y < rows_; ++y) {
        for (int x = 0; x < columns_; ++x) {
            const CellView entries = cell(x, y);
            const size_t n = entries.size();
            for (size_t a = 0; a < n; ++a) {
                const Entry& ea = entries[a];
                if (ea.index < 0) continue;
                for (size_t b = a + 1; b < n; ++b) {
                    const Entry& eb = entries[b];
                    if (eb.index < 0 || !test(ea.box, eb.box)) continue;
                    if (firstSharedCell(x, y, ranges_[ea.index], ranges_[eb.index]))
                        visit(ea.index, eb.index);
                }
            }
        }
    }
}
