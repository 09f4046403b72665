#include "corner_grid.h"

#include <algorithm>
#include <cmath>

bool CornerGrid::fileAll(const Bounds& bounds, const Extents& extents) {
    // Boxes up to twice the mean extent of the moving blocks' boxes go into cells, and the cells
    // are only as large as the largest of those: a few outliers (a bullet) do not make every cell
    // large.
    const double limit = extents.count > 0 ? 2.0 * extents.sum / extents.count : 0.0;
    maxSmallExtent_ = limit < extents.largest ? limit : extents.largest; // NaN limit: ignored
    // Boxes that large compared with the world (blocks crossing much of it in a substep) make a
    // handful of cells anyway: then every box goes into cells, which costs a query no more than
    // a list of large boxes would, where the BroadPhase would file each in all of its cells (and
    // move each through all of them on set(): a 1000-block storm at 1e9 m/s spent 90% there).
    const Vec2 span = bounds.max - bounds.min;
    if (maxSmallExtent_ >= 0.25 * std::max(span.x, span.y)) maxSmallExtent_ = extents.largest;
    // The cell: more than maxSmallExtent + t, so that the corners of two small boxes that meet
    // are at most one cell apart (see queryOthers()), with room for rounding: a relative 2^-20,
    // and 2^-40 of the coordinates' magnitude, where one step of rounding loses 2^-53. No more
    // cells than about four per block (BroadPhase's rule), nor more columns or rows than that.
    const size_t n = boxes_.size();
    const double maxCells = 4.0 * static_cast<double>(n) + 64.0;
    const double magnitude = std::max(std::abs(bounds.min.x), std::abs(bounds.min.y)) +
                             std::max(std::abs(span.x), std::abs(span.y));
    double cellSize =
        (maxSmallExtent_ + 2.0 * kTouchTolerance) * (1.0 + 0x1p-20) + magnitude * 0x1p-40;
    cellSize = std::max(
        {cellSize, std::sqrt(span.x * span.y / maxCells), std::max(span.x, span.y) / maxCells});
    if (!(cellSize < kNever)) return false; // infinite or NaN sizes: no cells fit
    origin_ = bounds.min;
    inverseCellSize_ = 1.0 / cellSize;
    columns_ = std::max(1, static_cast<int>(std::ceil(span.x * inverseCellSize_)));
    rows_ = std::max(1, static_cast<int>(std::ceil(span.y * inverseCellSize_)));

    // Counting sort by cell, pass 1: each block's cell, and the count of each cell.
    const size_t cellCount = static_cast<size_t>(columns_) * rows_;
    // Zeroed by std::fill with a constant 0, which the compiler makes a memset; assign() with a
    // value is a loop of stores (it was 5% of a 1,000-block gas's step).
    cellStart_.resize(cellCount + 1);
    cellOverflow_.resize(cellCount);
    std::fill(cellStart_.begin(), cellStart_.end(), 0u);
    std::fill(cellOverflow_.begin(), cellOverflow_.end(), 0u);
    cell_.resize(n);
    large_.clear();
    overflowInUse_ = 0;
    for (size_t i = 0; i < n; ++i) {
        const int c = cell_[i] = cellOf(boxes_[i]);
        if (c == kLarge)
            large_.push_back(static_cast<int>(i));
        else
            ++cellStart_[c];
    }
    // Each large box is read by every query: a handful at most.
    if (large_.size() > 8 + n / 64) return false;
    // Pass 2: the counts become the ends of the slices (a running sum), then the blocks are put
    // in from the end, in reverse order, so each slice is in block order and each cell's cursor
    // ends at the start of its slice.
    for (size_t c = 1; c <= cellCount; ++c) cellStart_[c] += cellStart_[c - 1];
    sorted_.resize(cellStart_[cellCount]);
    for (size_t i = n; i-- > 0;)
        if (cell_[i] != kLarge) sorted_[--cellStart_[cell_[i]]] = static_cast<int>(i);
    // Which blocks are static, and with many of them links to the next moving block's slot
    // (forEachMeetingPair()).
    statics_.clear();
    nextMoving_.clear();
    if (staticList_.empty()) return true;
    statics_.resize(n);
    for (int i : staticList_) statics_[i] = 1;
    if (staticList_.size() < 16) return true;
    nextMoving_.resize(sorted_.size() + 1);
    auto next = static_cast<std::uint32_t>(sorted_.size());
    nextMoving_[sorted_.size()] = next;
    for (size_t k = sorted_.size(); k-- > 0;) {
        if (!statics_[sorted_[k]]) next = static_cast<std::uint32_t>(k);
        nextMoving_[k] = next;
    }
    return true;
}

std::vector<int>& CornerGrid::overflowList(int cell) {
    std::uint32_t& list = cellOverflow_[cell];
    if (!list) {
        if (overflowInUse_ == overflow_.size()) overflow_.emplace_back();
        overflow_[overflowInUse_].clear();
        list = static_cast<std::uint32_t>(++overflowInUse_);
    }
    return overflow_[list - 1];
}

void CornerGrid::set(int index, const Aabb& box) {
    boxes_[index] = box;
    const int from = cell_[index], to = cellOf(box);
    if (to == from) return;
    cell_[index] = to;
    // Leave the old place: the large list, the cell's slice (the slot is marked dead) or the
    // cell's overflow list.
    auto removeFrom = [index](std::vector<int>& list) {
        const auto it = std::find(list.begin(), list.end(), index);
        *it = list.back();
        list.pop_back();
    };
    if (from == kLarge) {
        removeFrom(large_);
    } else {
        const auto begin = sorted_.begin() + cellStart_[from];
        const auto end = sorted_.begin() + cellStart_[from + 1];
        const auto slot = std::find(begin, end, index);
        if (slot != end)
            *slot = kDead;
        else
            removeFrom(overflow_[cellOverflow_[from] - 1]);
    }
    if (to == kLarge)
        large_.push_back(index);
    else
        overflowList(to).push_back(index);
}
