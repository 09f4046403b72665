// The rectangles of a list by strips of the screen (rect_strips.h).
#include "rect_strips.h"

#include <cmath>

// Why the strips find every rectangle that overlaps (along x here; y alike): a rectangle b with
// b.x < q1 and q0 < b.x + b.width (q0 and q1 the query's ends; overlapArea's positive width is
// such a case, a difference of doubles being positive exactly where the first is the larger) has
// its lower end below q1 and its upper end above q0, so, as strip() never decreases, its first
// strip is at most the query's last and the query's first at most its last: they share one. A
// NaN side makes std::min and std::max pick the other side: such a rectangle is in every strip.
void RectStrips::build(const std::vector<ScreenRect>& rects, Axis axis, double lo, double hi,
                       int strips) {
    rects_ = &rects;
    const bool usable = std::isfinite(lo) && std::isfinite(hi) && hi > lo && strips > 0;
    strips_ = usable ? strips : 1;
    lo_ = usable ? lo : 0.0;
    scale_ = usable ? strips / (hi - lo) : 0.0;
    count_ = rects.size();
    words_ = (rects.size() + 63) / 64;
    bits_.assign(static_cast<std::size_t>(strips_) * words_, 0);
    query_.assign(words_, 0);
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const ScreenRect& r = rects[i];
        const double from = axis == Axis::x ? r.x : r.y;
        const double to = axis == Axis::x ? r.x + r.width : r.y + r.height;
        const bool nan = from != from || to != to;
        const int s0 = nan ? 0 : strip(from < to ? from : to);
        const int s1 = nan ? strips_ - 1 : strip(from < to ? to : from);
        for (int s = s0; s <= s1; ++s)
            bits_[static_cast<std::size_t>(s) * words_ + i / 64] |= std::uint64_t{1} << (i % 64);
    }
}

int RectStrips::strip(double v) const {
    const double s = std::floor((v - lo_) * scale_);
    if (!(s > 0.0)) return 0; // and NaN (an infinite v where the strips are unusable)
    return s >= strips_ - 1 ? strips_ - 1 : static_cast<int>(s);
}
