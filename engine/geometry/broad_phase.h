// Broad phase: a uniform grid over the world's closed bounds. Each block registers a box that must
// contain wherever it goes for the rest of the step (its swept box); a query returns every block
// whose registered box meets the query box, each once. Shared by all three methods.
//
// Layout: build() sorts all boxes into cells at once (a counting sort into one contiguous array,
// each cell a slice of it), so queries read memory in order. set() moves one block later: a
// block that leaves a cell is marked dead in that slice, a block that enters a cell goes into
// that cell's small overflow list. A pair of boxes sharing several cells is reported only from the
// first cell they share (the lowest column and row of the intersection of their cell ranges), so
// nothing is reported twice and queries keep no state.
//
// Speed: a large world's queries wait on memory and on mispredicted branches, so a cell entry is
// small (20 bytes): a copy of the box in floats, rounded outward, and a tag: the block index (up
// to 2^29 blocks) with a flag for static blocks and two saying whether this cell is the first
// column or row of the block's range (the test for the first shared cell). A query tests an entry
// against the float box, the flags and the asking block in one branch that nearly always goes the
// same way (almost every entry fails), and only then reads the registered double box for the exact
// test: the float box contains it, so the answers, and their order, are exactly those of double
// boxes. The slices of a row's cells are adjacent, so a query scans each row of its range as one
// span.
//
// Pairs of two static blocks are never reported: they never move, so they are never resolved
// (scene files let them overlap). A tag flag marks static entries; with many static blocks, build()
// also links each slot of the sorted array to the next slot of a moving block, so a static
// entry is paired with the moving ones only, in the same order as before (20,000 overlapping
// static blocks in one cell cost 20,000 pair tests, not 200 million).
#pragma once

#include "collision.h"

#include <cfloat>
#include <cstdint>
#include <vector>

class BroadPhase {
  public:
    // Sizes the grid for the bounds and the blocks' typical size and registers every block i
    // with the box boxOf(i).
    template <class BoxOf>
    void build(const Bounds& bounds, const std::vector<Block>& blocks, BoxOf&& boxOf) {
        sizeGrid(bounds, blocks);
        // Counting sort of the entries into cells, pass 1: count the entries of each cell.
        const size_t n = blocks.size();
        boxes_.resize(n);
        ranges_.resize(n);
        statics_.clear();
        staticCount_ = 0;
        for (size_t i = 0; i < n; ++i) {
            if (blocks[i].kind == BodyKind::Static) {
                if (statics_.empty()) statics_.resize(n);
                statics_[i] = 1;
                ++staticCount_;
            }
            const Aabb box = boxes_[i] = boxOf(static_cast<int>(i));
            const CellRange r = ranges_[i] = rangeOf(box);
            if (isSmall(r)) {
                // At most 2x2 cells, without branches: a cell that is not in the range aliases
                // one that is, and gets + 0.
                const int dx = r.x1 - r.x0, dy = r.y1 - r.y0;
                const size_t c = cellIndex(r.x0, r.y0), up = static_cast<size_t>(dy) * columns_;
                ++cells_[c].start;
                cells_[c + dx].start += dx;
                cells_[c + up].start += dy;
                cells_[c + dx + up].start += dx & dy;
                continue;
            }
            for (int y = r.y0; y <= r.y1; ++y)
                for (int x = r.x0; x <= r.x1; ++x) ++cells_[cellIndex(x, y)].start;
        }
        fillCells();
    }
    // Registers block `index` to `box` instead of its current box.
    void set(int index, const Aabb& box);
    const Aabb& box(int index) const { return boxes_[index]; }

    // Calls visit(j) once for every registered block j whose box meets `query` (touching counts:
    // resting contacts and faces about to meet are candidates).
    template <class Visit> void query(const Aabb& query, Visit&& visit) const {
        queryOthers(query, -1, visit);
    }
    // The same, leaving out block `self` (a block asking for its neighbours: it is found in
    // every cell of its own path, and skipping it there is cheaper than visiting it).
    template <class Visit> void queryOthers(const Aabb& query, int self, Visit&& visit) const;
    // Calls visit(i, j) once for every pair of registered blocks, not both static, whose boxes
    // overlap with positive area.
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
    // A box in floats, rounded outward: it contains the double box it stands for.
    struct FloatBox {
        float minX, minY, maxX, maxY;
    };
    // Tag bits: the block index shifted left by three, whether the block is static, and whether
    // this cell is the block's first column or row. kDead: the block left this cell (its static
    // flag is set too, so moving-block links skip it).
    static constexpr std::uint32_t kFirstColumn = 1, kFirstRow = 2, kStatic = 4;
    static constexpr std::uint32_t kDead = ~std::uint32_t{0};
    struct Entry {
        FloatBox box;
        std::uint32_t tag;
        int index() const { return static_cast<int>(tag >> 3); }
    };
    static_assert(sizeof(Entry) == 20, "a cell entry is 20 bytes");
    struct Cell {
        std::uint32_t start = 0;    // first entry in sorted_ (the next cell's start ends it)
        std::uint32_t overflow = 0; // 0, or 1 + the slot of its list in overflow_
    };
    // The entries of one cell: its slice of the sorted array, then its overflow list.
    struct CellView {
        const Entry* sorted;
        size_t sortedCount;
        const Entry* overflow;
        size_t overflowCount;
        size_t size() const { return sortedCount + overflowCount; }
        const Entry& operator[](size_t k) const {
            return k < sortedCount ? sorted[k] : overflow[k - sortedCount];
        }
    };

    // Chooses the cell size and the grid's extent; every cell empty.
    void sizeGrid(const Bounds& bounds, const std::vector<Block>& blocks);
    // Counting sort, pass 2: turns the counts into slices and fills them in block order.
    void fillCells();
    // With kStatics false (fewer than two static blocks: no static pair exists) the pair test
    // leaves out the static flags.
    template <class Visit, class Test> void forEachPair(Visit& visit, Test test) const {
        if (staticCount_ < 2)
            forEachPairOf<false>(visit, test);
        else
            forEachPairOf<true>(visit, test);
    }
    template <bool kStatics, class Visit, class Test>
    void forEachPairOf(Visit& visit, Test test) const;
    CellRange rangeOf(const Aabb& box) const {
        // v clamped to [0, count - 1] (NaN to 0), then truncated: the cell's column or row.
        auto clampCell = [](double v, int count) {
            const double last = count - 1;
            v = 0.0 < v ? v : 0.0;
            return static_cast<int>(last < v ? last : v);
        };
        // Widened by the touch tolerance, like meets(): boxes that nearly touch share a cell.
        const double t = kTouchTolerance;
        return {clampCell((box.min.x - t - origin_.x) * inverseCellSize_, columns_),
                clampCell((box.min.y - t - origin_.y) * inverseCellSize_, rows_),
                clampCell((box.max.x + t - origin_.x) * inverseCellSize_, columns_),
                clampCell((box.max.y + t - origin_.y) * inverseCellSize_, rows_)};
    }
    size_t cellIndex(int x, int y) const { return static_cast<size_t>(y) * columns_ + x; }
    CellView cell(int x, int y) const {
        const size_t c = cellIndex(x, y);
        const Cell& first = cells_[c];
        CellView view{sorted_.data() + first.start, cells_[c + 1].start - first.start, nullptr, 0};
        if (first.overflow) {
            const std::vector<Entry>& list = overflow_[first.overflow - 1];
            view.overflow = list.data();
            view.overflowCount = list.size();
        }
        return view;
    }
    // Spans at most 2x2 cells (nearly every block: the cell size is twice the median extent).
    static bool isSmall(const CellRange& r) { return r.x1 - r.x0 <= 1 && r.y1 - r.y0 <= 1; }
    std::vector<Entry>& overflowList(size_t c);
    Entry* find(int x, int y, int index);
    std::uint32_t tagOf(int index) const {
        return (static_cast<std::uint32_t>(index) << 3) |
               (staticCount_ && statics_[index] ? kStatic : 0u);
    }
    std::uint32_t tagOf(int index, int x, int y, const CellRange& range) const {
        return tagOf(index) | (x == range.x0 ? kFirstColumn : 0u) |
               (y == range.y0 ? kFirstRow : 0u);
    }
    // A float no greater (floatBelow) or no less (floatAbove) than v: v moved outward by more
    // than rounding to float can move it back (half a float ulp is at most 2^-24·|v|, the
    // absolute 2^-120 covers the subnormals), kept inside the float range on the side it moved
    // away from. Infinities stay infinite; NaN stays NaN (and then meets nothing, as in double).
    static float floatBelow(double v) {
        const double w = (v > 0.0 ? v * (1.0 - 0x1p-22) : v * (1.0 + 0x1p-22)) - 0x1p-120;
        return static_cast<float>(w > FLT_MAX ? FLT_MAX : w);
    }
    static float floatAbove(double v) {
        const double w = (v < 0.0 ? v * (1.0 - 0x1p-22) : v * (1.0 + 0x1p-22)) + 0x1p-120;
        return static_cast<float>(w < -FLT_MAX ? -FLT_MAX : w);
    }
    static FloatBox floatBoxOf(const Aabb& b) {
        return {floatBelow(b.min.x), floatBelow(b.min.y), floatAbove(b.max.x), floatAbove(b.max.y)};
    }
    static Aabb aabbOf(const FloatBox& f) { return {{f.minX, f.minY}, {f.maxX, f.maxY}}; }

    Vec2 origin_;
    double inverseCellSize_ = 1.0;
    int columns_ = 1, rows_ = 1;
    std::vector<Cell> cells_;                  // columns*rows + 1 (the last one ends the array)
    std::vector<Entry> sorted_;                // entries sorted by cell
    std::vector<std::vector<Entry>> overflow_; // lists of entries added by set(), reused
    size_t overflowInUse_ = 0;                 // lists of overflow_ owned by a cell
    std::vector<Aabb> boxes_;                  // registered box per block (in rangeOf(box) cells)
    std::vector<CellRange> ranges_;            // scratch of build: rangeOf(boxes_[i])
    std::vector<double> extents_;              // scratch of sizeGrid
    std::vector<std::uint8_t> statics_;        // per block: 1 if static (empty without any)
    size_t staticCount_ = 0;
    // With at least kLinkStatics static blocks: per slot of sorted_ (and one past the end), the
    // first slot at or after it that holds a live moving block's entry (or sorted_.size()).
    static constexpr size_t kLinkStatics = 16;
    std::vector<std::uint32_t> nextMoving_;
};

template <class Visit>
void BroadPhase::queryOthers(const Aabb& query, int self, Visit&& visit) const {
    const CellRange range = rangeOf(query);
    // meets(box, query) for every box inside an entry's float box implies the float test below:
    // the query, widened by the tolerance in double as meets() does, then rounded outward.
    constexpr double t = kTouchTolerance;
    const float minX = floatBelow(query.min.x - t), minY = floatBelow(query.min.y - t);
    const float maxX = floatAbove(query.max.x + t), maxY = floatAbove(query.max.y + t);
    // Visits the entries [begin, end) of cells in the query's first column (or not) and first
    // row (or not). The first shared cell of the query and an entry: its column is the larger of
    // their first columns, so (the cell being in both ranges) the query's first column or the
    // entry's; the same for rows.
    auto scan = [&](const Entry* begin, const Entry* end, bool firstColumn, bool firstRow) {
        const std::uint32_t need = (firstColumn ? 0 : kFirstColumn) | (firstRow ? 0 : kFirstRow);
        for (const Entry* e = begin; e != end; ++e) {
            // Every test that needs no more than the entry in one expression with non-short-
            // circuit &: a single branch, nearly always taken the same way (few entries pass;
            // `self`, which would pass in each of its cells, is left out here).
            const FloatBox& f = e->box;
            const bool candidate = (f.maxX >= minX) & (f.minX <= maxX) & (f.maxY >= minY) &
                                   (f.minY <= maxY) & ((e->tag & need) == need) &
                                   ((e->tag >> 3) != static_cast<std::uint32_t>(self));
            if (!candidate || e->tag == kDead) continue;
            const int j = e->index();
            if (meets(boxes_[j], query)) visit(j);
        }
    };
    for (int y = range.y0; y <= range.y1; ++y) {
        const bool firstRow = y == range.y0;
        const size_t first = cellIndex(range.x0, y), last = cellIndex(range.x1, y);
        // The slices of a row's cells lie next to each other in sorted_: one span, unless a cell
        // has an overflow list (whose entries come right after its slice).
        bool overflow = false;
        for (size_t c = first; c <= last; ++c) overflow |= cells_[c].overflow != 0;
        if (!overflow) {
            const Entry* entries = sorted_.data();
            scan(entries + cells_[first].start, entries + cells_[first + 1].start, true, firstRow);
            scan(entries + cells_[first + 1].start, entries + cells_[last + 1].start, false,
                 firstRow);
            continue;
        }
        for (int x = range.x0; x <= range.x1; ++x) {
            const CellView entries = cell(x, y);
            const bool firstColumn = x == range.x0;
            scan(entries.sorted, entries.sorted + entries.sortedCount, firstColumn, firstRow);
            scan(entries.overflow, entries.overflow + entries.overflowCount, firstColumn, firstRow);
        }
    }
}

template <bool kStatics, class Visit, class Test>
void BroadPhase::forEachPairOf(Visit& visit, Test test) const {
    const bool linked = kStatics && !nextMoving_.empty();
    for (int y = 0; y < rows_; ++y) {
        for (int x = 0; x < columns_; ++x) {
            const CellView entries = cell(x, y);
            const size_t n = entries.size();
            for (size_t a = 0; a < n; ++a) {
                const Entry& ea = entries[a];
                if (ea.tag == kDead) continue;
                const Aabb fa = aabbOf(ea.box);
                auto pair = [&](const Entry& eb) {
                    // Everything that needs no more than the entries in one branch, as in
                    // queryOthers(): b is alive, not both are static, this is the first cell the
                    // pair shares (one of them in its first column, one in its first row), and
                    // the test holds for the float boxes (both tests are monotone, so it holds
                    // whenever it holds for the double boxes inside them). The order of the tests
                    // changes no answer.
                    const std::uint32_t flags = ea.tag | eb.tag;
                    const bool candidate = (eb.tag != kDead) & ((flags & kFirstColumn) != 0) &
                                           ((flags & kFirstRow) != 0) &
                                           (!kStatics || (ea.tag & eb.tag & kStatic) == 0) &
                                           test(fa, aabbOf(eb.box));
                    if (candidate && test(boxes_[ea.index()], boxes_[eb.index()]))
                        visit(ea.index(), eb.index());
                };
                size_t b = a + 1;
                if (linked && (ea.tag & kStatic) && b < entries.sortedCount) {
                    // A static entry: only the moving ones after it in the slice, then the
                    // overflow list.
                    const auto start = static_cast<size_t>(entries.sorted - sorted_.data());
                    const size_t end = start + entries.sortedCount;
                    for (size_t k = nextMoving_[start + b]; k < end; k = nextMoving_[k + 1])
                        pair(sorted_[k]);
                    b = entries.sortedCount;
                }
                for (; b < n; ++b) pair(entries[b]);
            }
        }
    }
}
