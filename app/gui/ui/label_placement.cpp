// Where the scene's texts go (label_placement.h).
#include "label_placement.h"

#include "overlay_window.h"
#include "placement.h"
#include "scene_geometry.h"

#include <algorithm>
#include <cmath>

namespace {

// Calls visit(p, text) for the part of `placed` that meets `region`, in order (the blocks, then
// the texts): all that a search whose rectangles lie in `region` can touch, so that its sums are
// the same over fewer rectangles (a gas of 1,000 blocks had every label's search add up every
// block: a sixth of the frame).
template <typename Visit>
void eachMeeting(const Taken& placed, const ScreenRect& region, const BlockStrips* blocks,
                 Visit visit) {
    const auto meets = [&region](const ScreenRect& p) {
        return p.x < region.x + region.width && region.x < p.x + p.width &&
               p.y < region.y + region.height && region.y < p.y + p.height;
    };
    if (blocks != nullptr && blocks->rows.size() == placed.blocks.size() &&
        blocks->columns.size() == placed.blocks.size()) {
        // Through the blocks' strips: those in the region's rows and columns only, in order
        // (rect_strips.h).
        blocks->rows.forEachAlso(blocks->columns, region.y, region.y + region.height, region.x,
                                 region.x + region.width, [&](const ScreenRect& p) {
                                     if (meets(p)) visit(p, false);
                                     return true;
                                 });
    } else {
        for (const ScreenRect& p : placed.blocks)
            if (meets(p)) visit(p, false);
    }
    for (const ScreenRect& p : placed.texts)
        if (meets(p)) visit(p, true);
}

// That part into `out`, cleared first: a buffer each search keeps, so that no label allocates.
void meeting(const Taken& placed, const ScreenRect& region, Taken& out,
             const BlockStrips* blocks = nullptr) {
    out.blocks.clear();
    out.texts.clear();
    eachMeeting(placed, region, blocks, [&out](const ScreenRect& p, bool text) {
        (text ? out.texts : out.blocks).push_back(p);
    });
}

// A rectangle of a band (band) as coveredAt works it out against a text of the band: its sides,
// and its overlap with the band's rows, the same for every text of the band (worked out once).
struct Side {
    double left, right, h;
};
struct Band {
    std::vector<Side> blocks, texts;
};

// The rows a search tries (spotAmong): kRows above and kRows below.
constexpr int kRows = 6;
constexpr int kTries = 2 * kRows;
constexpr int kPlaces = 7; // the places tried sideways in each

// The bands of a search's rows, each the part of what it looks at that a text with its top at
// the row and `height` tall meets in rows, in order (any x): coveredAt's vertical overlap worked
// out as coveredAt does, so that its sums over the band are the sums over all (what the band
// leaves out adds nothing), over a tenth of it. Filled in one pass over the rectangles (add),
// each going into the bands of the rows it meets only (the rows lie one over the other: a block
// meets one or two of the dozen); rows at the same height share one band.
class Bands {
  public:
    // Row r's top: tops[r], r < kTries.
    void start(const float (&tops)[kTries], float height) {
        count_ = 0;
        for (int r = 0; r < kTries; ++r) {
            const ScreenRect row = spanning(0.0, tops[r], 0.0, tops[r] + height);
            const double top = row.y, bottom = row.y + row.height;
            int b = 0;
            while (b < count_ && !(top_[b] == top && bottom_[b] == bottom)) ++b;
            if (b == count_) {
                top_[b] = top, bottom_[b] = bottom;
                band_[b].blocks.clear();
                band_[b].texts.clear();
                ++count_;
            }
            of_[r] = b;
        }
        // In order of their tops (then bottoms); where the bottoms come in that order too (the
        // rows are equally tall: always, but for NaN and overflow), the bands a rectangle meets
        // follow one another in it. (A dozen at most: sorted by insertion.)
        const auto before = [this](int a, int b) {
            return top_[a] < top_[b] || (top_[a] == top_[b] && bottom_[a] < bottom_[b]);
        };
        int order[kTries];
        for (int b = 0; b < count_; ++b) {
            int k = b;
            for (; k > 0 && before(b, order[k - 1]); --k) order[k] = order[k - 1];
            order[k] = b;
        }
        ordered_ = true;
        for (int k = 0; k < kTries; ++k) {
            // The places after the last are never counted (add: no finite edge reaches them).
            sortedTop_[k] = k < count_ ? top_[order[k]] : INFINITY;
            sortedBottom_[k] = k < count_ ? bottom_[order[k]] : INFINITY;
            sorted_[k] = k < count_ ? order[k] : 0;
            if (k < count_)
                ordered_ = ordered_ && std::isfinite(sortedTop_[k]) &&
                           std::isfinite(sortedBottom_[k]) &&
                           (k == 0 || sortedBottom_[k - 1] <= sortedBottom_[k]);
        }
    }

    // Puts `p` (a block, or a text) into the bands of the rows it meets: a positive overlap,
    // h = min(bottom, pb) - max(top, py) > 0 (coveredAt's). It needs bottom > py and pb > top (all
    // finite): in order, the bands after those with bottom <= py and before those with top >= pb,
    // each kind counted (where the tops and the bottoms come in order, each is a run from the
    // first). Other edges are tried against every band.
    void add(const ScreenRect& p, bool text) {
        const double py = p.y, pb = p.y + p.height;
        const auto keep = [&](int b, double top, double bottom) {
            const double h = std::min(bottom, pb) - std::max(top, py);
            if (h > 0.0)
                (text ? band_[b].texts : band_[b].blocks).push_back({p.x, p.x + p.width, h});
        };
        if (!ordered_ || !std::isfinite(py) || !std::isfinite(pb)) {
            for (int b = 0; b < count_; ++b) keep(b, top_[b], bottom_[b]);
            return;
        }
        int first = 0, end = 0;
        for (int k = 0; k < kTries; ++k) {
            first += sortedBottom_[k] <= py;
            end += sortedTop_[k] < pb;
        }
        for (int k = first; k < end; ++k) keep(sorted_[k], sortedTop_[k], sortedBottom_[k]);
    }

    const Band& of(int row) const { return band_[of_[row]]; }

  private:
    Band band_[kTries];
    double top_[kTries] = {}, bottom_[kTries] = {};
    double sortedTop_[kTries] = {}, sortedBottom_[kTries] = {}; // in order
    int sorted_[kTries] = {}, of_[kTries] = {};
    int count_ = 0;
    bool ordered_ = false;
};

// The blocks' overlap plus ten times the texts' (a hidden text costs more than a hidden block),
// in their order; it stops once the sum reaches `least` (no overlap is negative, so a spot that
// stops there cannot be the best).
template <class Rects, class Overlap>
double weightedCover(const Rects& blocks, const Rects& texts, Overlap overlap, double least) {
    double onBlocks = 0.0;
    for (const auto& p : blocks) {
        const double a = overlap(p);
        if (a == 0.0) continue;
        onBlocks += a;
        if (onBlocks >= least) return onBlocks;
    }
    double onTexts = 0.0;
    for (const auto& p : texts) {
        const double a = overlap(p);
        if (a == 0.0) continue;
        onTexts += a;
        const double sum = onBlocks + 10.0 * onTexts;
        if (sum >= least) return sum;
    }
    return onBlocks + 10.0 * onTexts;
}

// True when a text of `size` at (x, y) (top-left) does not lie in `view`: coveredAt's infinite
// cover.
bool outside(const ScreenRect& view, float x, float y, ImVec2 size) {
    return x < view.x || y < view.y || x + size.x > view.x + view.width ||
           y + size.y > view.y + view.height;
}

// coveredAt, but once what it has summed reaches `least` it stops there and returns that sum: the
// whole is no less (every area added is >= 0, and a sum of doubles never falls as a term >= 0 is
// added), so a search after the spot covering the least, which keeps a spot only where it covers
// less than `least`, keeps the same spots. Where it covers less, the whole sum, bit for bit.
double coveredUnder(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 size,
                    float gap, double least) {
    if (outside(view, x, y, size)) return INFINITY;
    const ScreenRect r = spanning(x - gap, y, x + size.x + gap, y + size.y);
    const auto overlap = [&r](const ScreenRect& p) {
        const double w = std::min(r.x + r.width, p.x + p.width) - std::max(r.x, p.x);
        const double h = std::min(r.y + r.height, p.y + p.height) - std::max(r.y, p.y);
        return w > 0.0 && h > 0.0 ? w * h : 0.0;
    };
    return weightedCover(placed.blocks, placed.texts, overlap, least);
}

// coveredUnder over a band of its text's rows (band(near, y, size.y, ...)): the same sums.
double coveredInBand(const Band& band, const ScreenRect& view, float x, float y, ImVec2 size,
                     float gap, double least) {
    if (outside(view, x, y, size)) return INFINITY;
    const ScreenRect r = spanning(x - gap, y, x + size.x + gap, y + size.y);
    const double left = r.x, right = r.x + r.width;
    const auto overlap = [left, right](const Side& p) {
        const double w = std::min(right, p.right) - std::max(left, p.left);
        return w > 0.0 && p.h > 0.0 ? w * p.h : 0.0;
    };
    return weightedCover(band.blocks, band.texts, overlap, least);
}

// True when every rectangle meeting `inner` meets `outer` (meeting's test): `inner` lies in
// `outer`, its edges as meeting works them out.
bool within(const ScreenRect& inner, const ScreenRect& outer) {
    return outer.x <= inner.x && inner.x + inner.width <= outer.x + outer.width &&
           outer.y <= inner.y && inner.y + inner.height <= outer.y + outer.height;
}

// The rectangle freeSpot's search at (x, above, below) for a label of `size` can touch: all of
// `placed` that its sums can meet.
ScreenRect spotRegion(float x, float above, float below, ImVec2 size, float line) {
    const float gap = line * 0.5f;
    const float shift = size.x * 0.5f + gap;
    const float reach =
        3.0f * shift + gap + 1.0f; // the farthest a candidate's sides go, and a pixel
    return spanning(x - reach, std::min(above - 5.0f * line, below) - 1.0f, x + size.x + reach,
                    std::max(above, below + 5.0f * line) + size.y + 1.0f);
}

// The rows of a search for a free spot (freeSpot) at (x, above, below) for a label of `size`:
// their tops, and their bands of `source` (`placed`, or a part of it, in order, holding all of it
// that meets spotRegion: the same bands from either).
void searchRows(const Taken& source, float x, float above, float below, ImVec2 size, float line,
                const BlockStrips* blocks, float (&tops)[kTries], Bands& rows) {
    for (int k = 0; k < kRows; ++k) {
        tops[2 * k] = above - k * line;
        tops[2 * k + 1] = below + k * line;
    }
    rows.start(tops, size.y);
    eachMeeting(source, spotRegion(x, above, below, size, line), blocks,
                [&rows](const ScreenRect& p, bool text) { rows.add(p, text); });
}

// The places sideways of a search at x: each of the 12 rows is tried at these, in this order.
void searchPlaces(float x, ImVec2 size, float line, float (&lefts)[kPlaces]) {
    const float gap = line * 0.5f; // labels closer than this read as one
    const float shift = size.x * 0.5f + gap;
    const float dxs[kPlaces] = {0.0f,          shift,        -shift,       2.0f * shift,
                                -2.0f * shift, 3.0f * shift, -3.0f * shift};
    for (int c = 0; c < kPlaces; ++c) lefts[c] = x + dxs[c];
}

// freeSpot through its rows (searchRows).
ImVec2 spotIn(const Bands& rows, const float (&tops)[kTries], const ScreenRect& view, float x,
              float above, ImVec2 size, float line) {
    const float gap = line * 0.5f;
    float lefts[kPlaces];
    searchPlaces(x, size, line, lefts);
    ImVec2 best(x, above);
    double least = INFINITY;
    for (const float left : lefts) {
        for (int r = 0; r < kTries; ++r) {
            const double covered = coveredInBand(rows.of(r), view, left, tops[r], size, gap, least);
            if (covered == 0.0) return ImVec2(left, tops[r]);
            if (covered < least) {
                least = covered;
                best = ImVec2(left, tops[r]);
            }
        }
    }
    return best;
}

// True when a spot that a search (searchRows: its rows, tops, and the region that it looked at)
// may give is free for freeRow's test: coveredAt(..., 4 px) == 0 over all that meets the spot
// grown by a pixel (5 px sideways). That sum is 0 where no term is (none is negative): where no
// rectangle meeting the tested one overlaps it (a positive overlap means meeting it, as meeting
// works it out), each of which meets the search's region where the tested rectangle lies in it,
// and overlaps in rows just where the band has it. Where a rectangle does not lie in the region:
// true.
bool someSpotFree(const Bands& rows, const float (&tops)[kTries], const ScreenRect& region,
                  const ScreenRect& view, float x, ImVec2 size, float line) {
    float lefts[kPlaces];
    searchPlaces(x, size, line, lefts);
    for (const float left : lefts) {
        for (int r = 0; r < kTries; ++r) {
            const float top = tops[r];
            if (outside(view, left, top, size)) continue; // coveredAt: INFINITY
            const ScreenRect tested =
                spanning(left - 4.0f, top, left + size.x + 4.0f, top + size.y);
            const ScreenRect grown =
                spanning(left - 5.0f, top - 1.0f, left + size.x + 5.0f, top + size.y + 1.0f);
            if (!within(tested, region) || !within(tested, grown)) return true;
            const double l = tested.x, rt = tested.x + tested.width;
            const auto overlaps = [l, rt](const std::vector<Side>& band) {
                for (const Side& p : band) {
                    const double w = std::min(rt, p.right) - std::max(l, p.left);
                    if (w > 0.0 && p.h > 0.0 && w * p.h != 0.0) return true;
                }
                return false;
            };
            if (!overlaps(rows.of(r).blocks) && !overlaps(rows.of(r).texts)) return true;
        }
    }
    return false;
}

// freeSpot over `source` (searchRows).
ImVec2 spotAmong(const Taken& source, const ScreenRect& view, float x, float above, float below,
                 ImVec2 size, float line, const BlockStrips* blocks) {
    float tops[kTries];
    static thread_local Bands rows;
    searchRows(source, x, above, below, size, line, blocks, tops, rows);
    return spotIn(rows, tops, view, x, above, size, line);
}

} // namespace

void shadowText(ImDrawList* dl, ImVec2 at, ImU32 color, const char* text, ImU32 shadow) {
    dl->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), shadow, text);
    dl->AddText(at, color, text);
}

ScreenRect spanning(double x0, double y0, double x1, double y1) {
    return {x0, y0, x1 - x0, y1 - y0};
}

double coveredAt(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 size,
                 float gap) {
    return coveredUnder(placed, view, x, y, size, gap, INFINITY);
}

ImVec2 freeSpot(const Taken& placed, const ScreenRect& view, float x, float above, float below,
                ImVec2 size, float line, const BlockStrips* blocks) {
    return spotAmong(placed, view, x, above, below, size, line, blocks);
}

BlockStrips blockStrips(const Taken& placed, const ScreenRect& view) {
    BlockStrips strips;
    strips.rows.build(placed.blocks, RectStrips::Axis::y, view.y, view.y + view.height, 32);
    strips.columns.build(placed.blocks, RectStrips::Axis::x, view.x, view.x + view.width, 32);
    return strips;
}

void takeBlocks(const App& app, Taken& placed) {
    placed.blocks.reserve(app.sim.world().blocks.size());
    for (const Block& b : app.sim.world().blocks) {
        const Vec2 lo = app.view.camera.worldToScreen(b.position - b.size * 0.5);
        const Vec2 hi = app.view.camera.worldToScreen(b.position + b.size * 0.5);
        placed.blocks.push_back(spanning(std::min(lo.x, hi.x), std::min(lo.y, hi.y),
                                         std::max(lo.x, hi.x), std::max(lo.y, hi.y)));
    }
    for (const ScreenRect& box : poiBoxesOnScreen(app)) placed.blocks.push_back(box);
    for (const ScreenRect& box : comMarkerOnScreen(app)) placed.blocks.push_back(box);
}

float clearRowInside(const Taken& placed, std::size_t own, float x, float top, ImVec2 size) {
    const ScreenRect& box = placed.blocks[own];
    const auto clear = [&](float y) {
        const ScreenRect r{x, y, size.x, size.y};
        for (std::size_t j = 0; j < placed.blocks.size(); ++j)
            if (j != own && rectsOverlap(r, placed.blocks[j])) return false;
        return true;
    };
    const float lowest = static_cast<float>(box.y + box.height) - size.y - 1.0f;
    const float highest = static_cast<float>(box.y) + 1.0f;
    for (float d = 0.0f; top - d >= highest || top + d <= lowest; d += 2.0f) {
        if (top - d >= highest && clear(top - d)) return top - d;
        if (top + d <= lowest && clear(top + d)) return top + d;
    }
    return NAN;
}

ImVec2 freeRow(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 ts,
               const BlockStrips* blocks) {
    // The rows down and up are those of the search sideways (freeSpot at x, y, a line apart):
    // their bands, found once, serve both (each row's sum over its band is its sum over all that
    // meets the rows' region, where the row's rectangle lies in both regions: the rectangles
    // overlapping it are in both, in order, and the others add nothing).
    const ScreenRect rows =
        spanning(x - 5.0f, y - 5.0f * ts.y - 1.0f, x + ts.x + 5.0f, y + 6.0f * ts.y + 1.0f);
    const ScreenRect sideways = spotRegion(x, y, y, ts, ts.y);
    float tops[kTries];
    static thread_local Bands bands;
    searchRows(placed, x, y, y, ts, ts.y, blocks, tops, bands);
    static thread_local Taken near;
    bool nearTaken = false;
    float best = y;
    double least = INFINITY;
    for (const float direction : {1.0f, -1.0f}) {
        for (int k = 0; k < kRows; ++k) {
            const float row = y + direction * static_cast<float>(k) * ts.y;
            const int r = 2 * k + (direction > 0.0f ? 1 : 0); // the same row of the search
            const ScreenRect tested = spanning(x - 4.0f, row, x + ts.x + 4.0f, row + ts.y);
            double covered = INFINITY;
            if (row == tops[r] && within(tested, sideways) && within(tested, rows)) {
                covered = coveredInBand(bands.of(r), view, x, row, ts, 4.0f, least);
            } else { // (NaN, or a row out of the regions: over all that meets the rows' region)
                if (!nearTaken) meeting(placed, rows, near, blocks);
                nearTaken = true;
                covered = coveredUnder(near, view, x, row, ts, 4.0f, least);
            }
            if (covered == 0.0) return ImVec2(x, row);
            if (covered < least) {
                least = covered;
                best = row;
            }
        }
    }
    // The search sideways gives a spot that the test below takes where it is free: where none of
    // its spots is, the row covering the least (the search need not weigh its spots).
    if (!someSpotFree(bands, tops, sideways, view, x, ts, ts.y)) return ImVec2(x, best);
    const ImVec2 aside = spotIn(bands, tops, view, x, y, ts, ts.y);
    const ScreenRect spot =
        spanning(aside.x - 5.0f, aside.y - 1.0f, aside.x + ts.x + 5.0f, aside.y + ts.y + 1.0f);
    meeting(placed, spot, near, blocks); // all that the test below can meet
    if (coveredAt(near, view, aside.x, aside.y, ts, 4.0f) == 0.0) return aside;
    return ImVec2(x, best); // none free: the row covering the least
}
