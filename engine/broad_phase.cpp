#include "broad_phase.h"

#include <algorithm>
#include <cmath>

void BroadPhase::buildFromBoxes(const Bounds& bounds, const std::vector<Block>& blocks) {
    // Cell size: twice the median moving block's extent (a block then spans at most 2x2 cells),
    // but no more cells than about four per block, so huge empty worlds stay cheap.
    std::vector<double> extents;
    extents.reserve(blocks.size());
    for (const Block& b : blocks)
        if (b.kind != BodyKind::Static) extents.push_back(std::max(b.size.x, b.size.y));
    const Vec2 span = bounds.max - bounds.min;
    double cellSize = std::max(span.x, span.y);
    if (!extents.empty()) {
        std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
        cellSize = 2.0 * extents[extents.size() / 2];
    }
    const double maxCells = 4.0 * static_cast<double>(blocks.size()) + 64.0;
    cellSize = std::max(cellSize, std::sqrt(span.x * span.y / maxCells));
    origin_ = bounds.min;
    inverseCellSize_ = 1.0 / cellSize;
    columns_ = std::max(1, static_cast<int>(std::ceil(span.x * inverseCellSize_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(span.y * inverseCellSize_)));
    const size_t cellCount = static_cast<size_t>(columns_) * rows_;

    // Counting sort of the entries into cells.
    const size_t n = boxes_.size();
    ranges_.resize(n);
    cellStart_.assign(cellCount + 1, 0);
    for (size_t i = 0; i < n; ++i) {
        const CellRange r = ranges_[i] = rangeOf(boxes_[i]);
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x) ++cellStart_[cellIndex(x, y) + 1];
    }
    for (size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
    sorted_.resize(cellStart_[cellCount]);
    std::vector<size_t>& fill = overflowUsed_; // reused as the fill cursor, cleared below
    fill.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (size_t i = 0; i < n; ++i) {
        const CellRange& r = ranges_[i];
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x)
                sorted_[fill[cellIndex(x, y)]++] = {boxes_[i], static_cast<int>(i)};
    }
    fill.clear();
    if (overflow_.size() != cellCount) overflow_.assign(cellCount, {});
    for (auto& list : overflow_)
        if (!list.empty()) list.clear();
}

BroadPhase::CellRange BroadPhase::rangeOf(const Aabb& box) const {
    auto clampCell = [](double v, int count) {
        if (!(v > 0.0)) return 0; // also catches NaN
        return v >= count - 1 ? count - 1 : static_cast<int>(v);
    };
    // Widened by the touch tolerance, like meets(): boxes that nearly touch share a cell.
    const double t = kTouchTolerance;
    return {clampCell((box.min.x - t - origin_.x) * inverseCellSize_, columns_),
            clampCell((box.min.y - t - origin_.y) * inverseCellSize_, rows_),
            clampCell((box.max.x + t - origin_.x) * inverseCellSize_, columns_),
            clampCell((box.max.y + t - origin_.y) * inverseCellSize_, rows_)};
}

BroadPhase::Entry* BroadPhase::find(int x, int y, int index) {
    const size_t c = cellIndex(x, y);
    for (size_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
        if (sorted_[k].index == index) return &sorted_[k];
    for (Entry& e : overflow_[c])
        if (e.index == index) return &e;
    return nullptr;
}

void BroadPhase::set(int index, const Aabb& box) {
    boxes_[index] = box;
    const CellRange range = rangeOf(box);
    CellRange& old = ranges_[index];
    // Refresh the box in the cells it stays in; leave the cells it no longer covers.
    for (int y = old.y0; y <= old.y1; ++y) {
        for (int x = old.x0; x <= old.x1; ++x) {
            Entry* e = find(x, y, index);
            if (!e) continue;
            if (range.has(x, y)) {
                e->box = box;
                continue;
            }
            std::vector<Entry>& list = overflow_[cellIndex(x, y)];
            if (e >= list.data() && e < list.data() + list.size()) {
                *e = list.back();
                list.pop_back();
            } else {
                e->index = -1;
            }
        }
    }
    // Enter the cells it newly covers.
    for (int y = range.y0; y <= range.y1; ++y)
        for (int x = range.x0; x <= range.x1; ++x)
            if (!old.has(x, y)) overflow_[cellIndex(x, y)].push_back({box, index});
    old = range;
}
