#include "broad_phase.h"

#include <algorithm>
#include <cmath>

void BroadPhase::reset(const Bounds& bounds, const std::vector<Block>& blocks) {
    // Cell size: twice the median block extent (a block then spans at most 2x2 cells), but no
    // more cells than about four per block, so huge empty worlds stay cheap.
    std::vector<double> extents;
    extents.reserve(blocks.size());
    for (const Block& b : blocks)
        if (b.kind != BodyKind::Static) extents.push_back(std::max(b.size.x, b.size.y));
    const Vec2 span = bounds.max - bounds.min;
    double cell = std::max(span.x, span.y);
    if (!extents.empty()) {
        std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
        cell = 2.0 * extents[extents.size() / 2];
    }
    const double maxCells = 4.0 * static_cast<double>(blocks.size()) + 64.0;
    cell = std::max(cell, std::sqrt(span.x * span.y / maxCells));
    origin_ = bounds.min;
    inverseCellSize_ = 1.0 / cell;
    columns_ = std::max(1, static_cast<int>(std::ceil(span.x * inverseCellSize_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(span.y * inverseCellSize_)));

    cells_.resize(static_cast<size_t>(columns_) * rows_);
    for (auto& c : cells_) c.clear();
    boxes_.assign(blocks.size(), Aabb{});
    ranges_.assign(blocks.size(), CellRange{});
    visited_.assign(blocks.size(), 0u);
    stamp_ = 0;
}

BroadPhase::CellRange BroadPhase::rangeOf(const Aabb& box) const {
    auto clampCell = [](double v, int count) {
        if (!(v > 0.0)) return 0; // also catches NaN
        return v >= count - 1 ? count - 1 : static_cast<int>(v);
    };
    return {clampCell((box.min.x - origin_.x) * inverseCellSize_, columns_),
            clampCell((box.min.y - origin_.y) * inverseCellSize_, rows_),
            clampCell((box.max.x - origin_.x) * inverseCellSize_, columns_),
            clampCell((box.max.y - origin_.y) * inverseCellSize_, rows_)};
}

void BroadPhase::insert(int index, const CellRange& range) {
    for (int y = range.y0; y <= range.y1; ++y)
        for (int x = range.x0; x <= range.x1; ++x)
            cells_[static_cast<size_t>(y) * columns_ + x].push_back(index);
}

void BroadPhase::erase(int index, const CellRange& range) {
    for (int y = range.y0; y <= range.y1; ++y) {
        for (int x = range.x0; x <= range.x1; ++x) {
            auto& cell = cells_[static_cast<size_t>(y) * columns_ + x];
            auto it = std::find(cell.begin(), cell.end(), index);
            if (it != cell.end()) {
                *it = cell.back();
                cell.pop_back();
            }
        }
    }
}

void BroadPhase::set(int index, const Aabb& box) {
    boxes_[index] = box;
    const CellRange range = rangeOf(box);
    CellRange& old = ranges_[index];
    if (range.x0 == old.x0 && range.y0 == old.y0 && range.x1 == old.x1 && range.y1 == old.y1)
        return;
    erase(index, old);
    insert(index, range);
    old = range;
}
