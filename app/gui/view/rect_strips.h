// The rectangles of a list by strips of the screen, rows or columns (issue 42): which of them a
// rectangle can overlap, found without looking at the others. A search for a free spot sums the
// areas that a candidate covers over a thousand rectangles (a gas of 1,000 blocks), most of them
// far from it; through the strips it visits those in its strips only, in the list's order, so
// that its sums add the same areas in the same order and skip zeros only: the same to the bit.
#pragma once

#include "camera.h"

#include <cstdint>
#include <vector>

class RectStrips {
  public:
    enum class Axis { x, y }; // columns along x, or rows along y
    // Files `rects` (kept by reference: unchanged while this is used) into `strips` strips of
    // equal size from lo to hi (px) along `axis`; one reaching past either end is in that end's.
    void build(const std::vector<ScreenRect>& rects, Axis axis, double lo, double hi, int strips);
    // How many rectangles were filed (the list's size when built).
    std::size_t size() const { return count_; }

    // Calls visit(rect) for every rectangle of the list that may share a positive length along
    // the axis with the span from `from` to `to` (every one with start < `to` and `from` < end,
    // its end worked out as start + size: all that overlapArea finds overlapping a rectangle
    // starting at `from` with start + size = `to` along the axis), in the list's order, each
    // once, until it returns false.
    template <typename Visit> void forEach(double from, double to, Visit visit) const {
        gather(from, to);
        visitGathered(visit);
    }
    // The same for the rectangles that both forEach(from, to) here and across.forEach(acrossFrom,
    // acrossTo) visit: `across` files the same list by strips of the other axis (a region's rows
    // and its columns: fewer to visit than in either).
    template <typename Visit>
    void forEachAlso(const RectStrips& across, double from, double to, double acrossFrom,
                     double acrossTo, Visit visit) const {
        gather(from, to);
        across.gather(acrossFrom, acrossTo);
        const std::size_t words = words_ < across.words_ ? words_ : across.words_;
        for (std::size_t w = 0; w < words_; ++w) query_[w] &= w < words ? across.query_[w] : 0;
        visitGathered(visit);
    }

  private:
    // The union of the strips from `from` to `to` into query_.
    void gather(double from, double to) const {
        // Either way round; a NaN end reaches both ends (overlapArea's std::min and std::max
        // pass over a NaN).
        const bool nan = from != from || to != to;
        const int s0 = nan ? 0 : strip(from < to ? from : to);
        const int s1 = nan ? strips_ - 1 : strip(from < to ? to : from);
        std::uint64_t* const query = query_.data();
        for (std::size_t w = 0; w < words_; ++w) query[w] = 0;
        for (int s = s0; s <= s1; ++s) {
            const std::uint64_t* const bits = bits_.data() + static_cast<std::size_t>(s) * words_;
            for (std::size_t w = 0; w < words_; ++w) query[w] |= bits[w];
        }
    }
    template <typename Visit> void visitGathered(Visit& visit) const {
        for (std::size_t w = 0; w < words_; ++w) {
            for (std::uint64_t word = query_[w]; word != 0; word &= word - 1) {
                const auto i = w * 64 + static_cast<std::size_t>(__builtin_ctzll(word));
                if (!visit((*rects_)[i])) return;
            }
        }
    }

    // The strip of v, not NaN (clamped to the ends): never decreasing as v grows.
    int strip(double v) const;

    const std::vector<ScreenRect>* rects_ = nullptr;
    double lo_ = 0.0, scale_ = 0.0;
    int strips_ = 1;
    std::size_t count_ = 0;
    std::size_t words_ = 0;                    // 64-bit words a strip's set of rectangles takes
    std::vector<std::uint64_t> bits_;          // strip s's set: words_ words from s * words_
    mutable std::vector<std::uint64_t> query_; // the union of a query's strips
};
