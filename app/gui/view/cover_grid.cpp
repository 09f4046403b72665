// How much of a list of rectangles a rectangle covers (cover_grid.h).
#include "cover_grid.h"

#include <algorithm>
#include <cfloat>

namespace {

// The cells of one axis: how many of its edges (sorted) lie at or before a value, found in a few
// steps (a search per rectangle and axis: a binary search's comparisons are as good as random for
// the branch predictor). A table says how many edges lie in the buckets before each of a few
// equal steps from the first edge to the last; the edges are then walked from there.
class Axis {
  public:
    explicit Axis(const std::vector<double>& edges) : edges_(edges) {
        const std::size_t buckets = 4 * edges.size();
        const double span = edges.back() - edges.front();
        first_ = edges.front();
        scale_ = span > 0.0 ? static_cast<double>(buckets) / span : 0.0;
        last_ = buckets - 1;
        before_.assign(buckets + 1, 0);
        for (double e : edges) ++before_[bucket(e) + 1];
        for (std::size_t b = 1; b <= buckets; ++b) before_[b] += before_[b - 1];
    }

    // std::upper_bound's index. Why the walk finds it: bucket() never decreases as v grows, so an
    // edge in an earlier bucket than v's is below v: all before_[bucket(v)] of them are.
    std::size_t countUpTo(double v) const {
        std::size_t k = before_[bucket(v)];
        while (k < edges_.size() && edges_[k] <= v) ++k;
        return k;
    }

    // The cells that the span from `lo` to `hi` shares positive length with, and that length:
    // (cell, length) into `out` (from its start; how many is returned). Cell k runs from
    // edges[k] to edges[k + 1].
    std::size_t cellsOf(double lo, double hi,
                        std::vector<std::pair<std::size_t, double>>& out) const {
        if (!(lo < hi)) return 0; // (and a NaN side: overlapArea finds no positive area with it)
        const std::size_t first = countUpTo(lo);
        std::size_t count = 0;
        for (std::size_t k = first == 0 ? 0 : first - 1; k + 1 < edges_.size() && edges_[k] < hi;
             ++k) {
            const double length = std::min(edges_[k + 1], hi) - std::max(edges_[k], lo);
            if (length > 0.0) out[count++] = {k, length};
        }
        return count;
    }

  private:
    std::size_t bucket(double v) const {
        const double f = (v - first_) * scale_;
        if (!(f > 0.0)) return 0;
        return f < static_cast<double>(last_) ? static_cast<std::size_t>(f) : last_;
    }

    const std::vector<double>& edges_;
    double first_ = 0.0, scale_ = 0.0;
    std::size_t last_ = 0;
    std::vector<std::size_t> before_; // edges in the buckets before bucket b, at b
};

} // namespace

// Why touches() is exact: a rectangle from X0 to X1 (grid edges) shares positive length along x
// with a span (lo, hi) exactly when lo < X1 and X0 < hi (overlapArea's test: a difference of
// doubles is positive exactly where the first is the larger); then the open interval between
// max(lo, X0) and min(hi, X1) is not empty and lies in the cells from X0 to X1, so one of those
// cells, k, has lo < edges[k + 1] and edges[k] < hi: cellsOf lists it. Conversely a listed cell
// inside the rectangle gives the test. Along y alike; the counts are whole numbers.
//
// Why area() is within error(): every cell's area is a sum of terms >= 0 (each a product of two
// differences, rounded: within 3 units u of roundoff, u = DBL_EPSILON / 2, of the true overlap's
// area), the running sums add terms >= 0 only (first along y, then along x), and area() combines
// four of them: it is off the true area by at most 4 (rectangles + edges + 3) + 6 units u of the
// total, and overlapArea's sum in any order by at most rectangles + 3 of them: together under
// 5 (rectangles + edges) + 20. error() takes 32 (rectangles + edges) + 256 units u of the total
// as summed (itself within a few units of the true total).
void CoverGrid::build(const std::vector<double>& xs, const std::vector<double>& ys,
                      const std::vector<ScreenRect>& rects) {
    nx_ = xs.size();
    ny_ = ys.size();
    area_.assign(nx_ * ny_, 0.0);
    touches_.assign(nx_ * ny_, 0);
    // Cell (i, j) summed at (i + 1, j + 1): the running sums then need no other array.
    const Axis alongXs(xs), alongYs(ys);
    std::vector<std::pair<std::size_t, double>> alongX(nx_), alongY(ny_);
    for (const ScreenRect& r : rects) {
        const std::size_t cx = alongXs.cellsOf(r.x, r.x + r.width, alongX);
        if (cx == 0) continue;
        const std::size_t cy = alongYs.cellsOf(r.y, r.y + r.height, alongY);
        for (std::size_t a = 0; a < cx; ++a) {
            const auto [i, w] = alongX[a];
            for (std::size_t b = 0; b < cy; ++b) {
                const auto [j, h] = alongY[b];
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
    const double units = 32.0 * static_cast<double>(nx_ + ny_ + rects.size()) + 256.0;
    error_ = units * (DBL_EPSILON / 2.0) * total;
}
