// How much of a list of rectangles a rectangle covers (cover_grid.h).
#include "cover_grid.h"

#include <algorithm>
#include <cfloat>

namespace {

// The cells along one axis that the span from `lo` to `hi` shares positive length with, and that
// length: (cell, length) into `out`, cleared first. Cell k runs from edges[k] to edges[k + 1].
void cellsOf(const std::vector<double>& edges, double lo, double hi,
             std::vector<std::pair<std::size_t, double>>& out) {
    out.clear();
    if (!(lo < hi)) return; // (and a NaN side: overlapArea finds no positive area with it)
    const auto first = std::upper_bound(edges.begin(), edges.end(), lo);
    std::size_t k =
        first == edges.begin() ? 0 : static_cast<std::size_t>(first - edges.begin()) - 1;
    for (; k + 1 < edges.size() && edges[k] < hi; ++k) {
        const double length = std::min(edges[k + 1], hi) - std::max(edges[k], lo);
        if (length > 0.0) out.emplace_back(k, length);
    }
}

} // namespace

// Why touches() is exact: a rectangle from X0 to X1 (grid edges) shares positive length along x
// with a span (lo, hi) exactly when lo < X1 and X0 < hi (overlapArea's test: a difference of
// doubles is positive exactly where the first is the larger); then the open interval between
// max(lo, X0) and min(hi, X1) is not empty and lies in the cells from X0 to X1, so one of those
// cells, k, has lo < edges[k + 1] and edges[k] < hi: cellsOf lists it. Conversely a listed cell
// inside the rectangle gives the test. Along y alike; the counts are whole numbers.
//
// Why area() is within error(): every cell's area is a sum of terms >= 0 (each a product of two
// differences, rounded: within 3 units of the last place of the true overlap's area), the running
// sums add terms >= 0 only (first along y, then along x), and area() combines four of them: each
// result is off by at most (cells + rectangles + a few) units of the last place of the total,
// and overlapArea's sum in any order by at most (rectangles + 3) of them. error() takes twice
// that, over twice the total.
void CoverGrid::build(const std::vector<double>& xs, const std::vector<double>& ys,
                      const std::vector<ScreenRect>& rects) {
    nx_ = xs.size();
    ny_ = ys.size();
    area_.assign(nx_ * ny_, 0.0);
    touches_.assign(nx_ * ny_, 0);
    // Cell (i, j) summed at (i + 1, j + 1): the running sums then need no other array.
    std::vector<std::pair<std::size_t, double>> alongX, alongY;
    for (const ScreenRect& r : rects) {
        cellsOf(xs, r.x, r.x + r.width, alongX);
        if (alongX.empty()) continue;
        cellsOf(ys, r.y, r.y + r.height, alongY);
        for (const auto& [i, w] : alongX) {
            for (const auto& [j, h] : alongY) {
                area_[(i + 1) * ny_ + j + 1] += w * h;
                touches_[(i + 1) * ny_ + j + 1] += 1;
            }
        }
    }
    for (std::size_t i = 0; i < nx_; ++i) {
        for (std::size_t j = 1; j < ny_; ++j) {
            area_[i * ny_ + j] += area_[i * ny_ + j - 1];
            touches_[i * ny_ + j] += touches_[i * ny_ + j - 1];
        }
    }
    for (std::size_t i = 1; i < nx_; ++i) {
        for (std::size_t j = 0; j < ny_; ++j) {
            area_[i * ny_ + j] += area_[(i - 1) * ny_ + j];
            touches_[i * ny_ + j] += touches_[(i - 1) * ny_ + j];
        }
    }
    const double total = nx_ * ny_ > 0 ? area_.back() : 0.0;
    const double units = 8.0 * static_cast<double>(nx_ + ny_ + rects.size()) + 64.0;
    error_ = units * DBL_EPSILON * 2.0 * total;
}
