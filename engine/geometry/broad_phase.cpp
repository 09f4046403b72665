#include "broad_phase.h"

#include <algorithm>
#include <cmath>

void BroadPhase::sizeGrid(const Bounds& bounds, const std::vector<Block>& blocks) {
    // Cell size: twice the median moving block's extent (a block then spans at most 2x2 cells),
    // but no more cells than about four per block, so huge empty worlds stay cheap.
    std::vector<double>& extents = extents_;
    extents.clear();
    bool allEqual = true; // then the median is any of them (a gas of equal blocks): no selection
    for (const Block& b : blocks) {
        if (b.kind == BodyKind::Static) continue;
        extents.push_back(std::max(b.size.x, b.size.y));
        allEqual &= extents.back() == extents.front();
    }
    const Vec2 span = bounds.max - bounds.min;
    double cellSize = std::max(span.x, span.y);
    if (!extents.empty() && allEqual) {
        cellSize = 2.0 * extents.front();
    } else if (!extents.empty()) {
        std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
        cellSize = 2.0 * extents[extents.size() / 2];
    }
    const double maxCells = 4.0 * static_cast<double>(blocks.size()) + 64.0;
    cellSize = std::max(cellSize, std::sqrt(span.x * span.y / maxCells));
    origin_ = bounds.min;
    inverseCellSize_ = 1.0 / cellSize;
    columns_ = std::max(1, static_cast<int>(std::ceil(span.x * inverseCellSize_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(span.y * inverseCellSize_)));
    cells_.assign(static_cast<size_t>(columns_) * rows_ + 1, Cell{});
    overflowInUse_ = 0;
}

void BroadPhase::fillCells() {
    // Each cell's count becomes the end of its slice (a running sum); the last cell ends them all.
    const size_t cellCount = cells_.size() - 1;
    for (size_t c = 1; c < cellCount; ++c) cells_[c].start += cells_[c - 1].start;
    cells_[cellCount].start = cells_[cellCount - 1].start;
    // One slot more than the slices hold: a trash slot for the branch-free fill below.
    const std::uint32_t trash = cells_[cellCount].start;
    sorted_.resize(size_t{trash} + 1);
    // Filled from the end, blocks in reverse order: each slice ends up in block order, and each
    // cell's cursor ends up at the start of its slice.
    for (size_t i = boxes_.size(); i-- > 0;) {
        const CellRange r = ranges_[i];
        const FloatBox box = floatBoxOf(boxes_[i]);
        const auto index = static_cast<int>(i);
        if (isSmall(r)) {
            // At most 2x2 cells, without branches (as in build()): a cell not in the range
            // aliases one that is, keeps its cursor, and its entry goes to the trash slot.
            const int dx = r.x1 - r.x0, dy = r.y1 - r.y0;
            const size_t c = cellIndex(r.x0, r.y0), up = static_cast<size_t>(dy) * columns_;
            auto put = [&](size_t cell, int present, std::uint32_t flags) {
                std::uint32_t& cursor = cells_[cell].start;
                cursor -= present;
                sorted_[present ? cursor : trash] = {box, tagOf(index) | flags};
            };
            put(c, 1, kFirstColumn | kFirstRow);
            put(c + dx, dx, kFirstRow);
            put(c + up, dy, kFirstColumn);
            put(c + dx + up, dx & dy, 0);
            continue;
        }
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x)
                sorted_[--cells_[cellIndex(x, y)].start] = {box, tagOf(index, x, y, r)};
    }
    // Links to the next moving block's slot, for forEachPair() with many static blocks.
    nextMoving_.clear();
    if (staticCount_ < kLinkStatics) return;
    nextMoving_.resize(sorted_.size() + 1);
    auto next = static_cast<std::uint32_t>(sorted_.size());
    nextMoving_[sorted_.size()] = next;
    for (size_t k = sorted_.size(); k-- > 0;) {
        if (!(sorted_[k].tag & kStatic)) next = static_cast<std::uint32_t>(k);
        nextMoving_[k] = next;
    }
}

std::vector<BroadPhase::Entry>& BroadPhase::overflowList(size_t c) {
    Cell& cell = cells_[c];
    if (!cell.overflow) {
        if (overflowInUse_ == overflow_.size()) overflow_.emplace_back();
        overflow_[overflowInUse_].clear();
        cell.overflow = static_cast<std::uint32_t>(++overflowInUse_);
    }
    return overflow_[cell.overflow - 1];
}

BroadPhase::Entry* BroadPhase::find(int x, int y, int index) {
    const size_t c = cellIndex(x, y);
    for (std::uint32_t k = cells_[c].start; k < cells_[c + 1].start; ++k)
        if (sorted_[k].tag != kDead && sorted_[k].index() == index) return &sorted_[k];
    if (cells_[c].overflow)
        for (Entry& e : overflow_[cells_[c].overflow - 1])
            if (e.index() == index) return &e;
    return nullptr;
}

void BroadPhase::set(int index, const Aabb& box) {
    const CellRange old = rangeOf(boxes_[index]);
    const CellRange range = rangeOf(box);
    const FloatBox floatBox = floatBoxOf(box);
    boxes_[index] = box;
    // Refresh the box (and the first-column/row flags) in the cells it stays in; leave the cells
    // it no longer covers.
    for (int y = old.y0; y <= old.y1; ++y) {
        for (int x = old.x0; x <= old.x1; ++x) {
            Entry* e = find(x, y, index);
            if (!e) continue;
            if (range.has(x, y)) {
                *e = {floatBox, tagOf(index, x, y, range)};
                continue;
            }
            const Cell& cell = cells_[cellIndex(x, y)];
            std::vector<Entry>* list = cell.overflow ? &overflow_[cell.overflow - 1] : nullptr;
            if (list && e >= list->data() && e < list->data() + list->size()) {
                *e = list->back();
                list->pop_back();
            } else {
                e->tag = kDead;
            }
        }
    }
    // Enter the cells it newly covers.
    for (int y = range.y0; y <= range.y1; ++y)
        for (int x = range.x0; x <= range.x1; ++x)
            if (!old.has(x, y))
                overflowList(cellIndex(x, y)).push_back({floatBox, tagOf(index, x, y, range)});
}
