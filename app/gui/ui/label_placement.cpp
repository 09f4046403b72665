// Where the scene's texts go (label_placement.h).
#include "label_placement.h"

#include "overlay_window.h"
#include "placement.h"
#include "scene_geometry.h"

#include <algorithm>
#include <cmath>

namespace {

// The part of `placed` that meets `region`, in order: all that a search whose rectangles lie in
// `region` can touch, so that its sums are the same over fewer rectangles (a gas of 1,000 blocks
// had every label's search add up every block: a sixth of the frame). Into `out`, cleared first:
// a buffer each search keeps, so that no label allocates.
void meeting(const Taken& placed, const ScreenRect& region, Taken& out,
             const RectStrips* blockRows = nullptr) {
    out.blocks.clear();
    out.texts.clear();
    const auto meets = [&region](const ScreenRect& p) {
        return p.x < region.x + region.width && region.x < p.x + p.width &&
               p.y < region.y + region.height && region.y < p.y + p.height;
    };
    if (blockRows != nullptr && blockRows->size() == placed.blocks.size()) {
        // Through the blocks' rows: those in the region's rows only, in order (rect_strips.h).
        blockRows->forEach(region.y, region.y + region.height, [&](const ScreenRect& p) {
            if (meets(p)) out.blocks.push_back(p);
            return true;
        });
    } else {
        for (const ScreenRect& p : placed.blocks)
            if (meets(p)) out.blocks.push_back(p);
    }
    for (const ScreenRect& p : placed.texts)
        if (meets(p)) out.texts.push_back(p);
}

// A rectangle of a band (band) as coveredAt works it out against a text of the band: its sides,
// and its overlap with the band's rows, the same for every text of the band (worked out once).
struct Side {
    double left, right, h;
};
struct Band {
    std::vector<Side> blocks, texts;
};

// The part of `near` that a text with its top at `y` and `height` tall meets in rows, in order
// (any x): coveredAt's vertical overlap worked out as coveredAt does, so that its sums over the
// band are the sums over `near` (what the band leaves out adds nothing), over a tenth of it.
void band(const Taken& near, float y, float height, Band& out) {
    out.blocks.clear();
    out.texts.clear();
    const ScreenRect r = spanning(0.0, y, 0.0, y + height);
    const auto keep = [&r](const std::vector<ScreenRect>& from, std::vector<Side>& to) {
        for (const ScreenRect& p : from) {
            const double h = std::min(r.y + r.height, p.y + p.height) - std::max(r.y, p.y);
            if (h > 0.0) to.push_back({p.x, p.x + p.width, h});
        }
    };
    keep(near.blocks, out.blocks);
    keep(near.texts, out.texts);
}

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

// coveredAt, but once what it has summed reaches `least` it stops there and returns that sum: the
// whole is no less (every area added is >= 0, and a sum of doubles never falls as a term >= 0 is
// added), so a search after the spot covering the least, which keeps a spot only where it covers
// less than `least`, keeps the same spots. Where it covers less, the whole sum, bit for bit.
double coveredUnder(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 size,
                    float gap, double least) {
    if (x < view.x || y < view.y || x + size.x > view.x + view.width ||
        y + size.y > view.y + view.height)
        return INFINITY;
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
    if (x < view.x || y < view.y || x + size.x > view.x + view.width ||
        y + size.y > view.y + view.height)
        return INFINITY;
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

// freeSpot over `source`: `placed`, or a part of it, in order, holding all of it that meets
// spotRegion (meeting then picks the same rectangles from either).
ImVec2 spotAmong(const Taken& source, const ScreenRect& view, float x, float above, float below,
                 ImVec2 size, float line, const RectStrips* blockRows) {
    const float gap = line * 0.5f; // labels closer than this read as one
    const float shift = size.x * 0.5f + gap;
    static thread_local Taken near;
    meeting(source, spotRegion(x, above, below, size, line), near, blockRows);
    // Each of the 12 rows is tried at up to 7 places sideways: its band of `near` is found on its
    // first try and kept.
    constexpr int kRows = 6;
    static thread_local Band rows[kRows][2];
    bool banded[kRows][2] = {};
    ImVec2 best(x, above);
    double least = INFINITY;
    for (const float dx :
         {0.0f, shift, -shift, 2.0f * shift, -2.0f * shift, 3.0f * shift, -3.0f * shift}) {
        for (int k = 0; k < kRows; ++k) {
            for (int side = 0; side < 2; ++side) {
                const float y = side == 0 ? above - k * line : below + k * line;
                if (!banded[k][side]) band(near, y, size.y, rows[k][side]);
                banded[k][side] = true;
                const double covered =
                    coveredInBand(rows[k][side], view, x + dx, y, size, gap, least);
                if (covered == 0.0) return ImVec2(x + dx, y);
                if (covered < least) {
                    least = covered;
                    best = ImVec2(x + dx, y);
                }
            }
        }
    }
    return best;
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
                ImVec2 size, float line, const RectStrips* blockRows) {
    return spotAmong(placed, view, x, above, below, size, line, blockRows);
}

RectStrips blockRows(const Taken& placed, const ScreenRect& view) {
    RectStrips rows;
    rows.build(placed.blocks, RectStrips::Axis::y, view.y, view.y + view.height, 32);
    return rows;
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
               const RectStrips* blockRows) {
    float best = y;
    double least = INFINITY;
    // What the rows below and above can meet, what the search sideways can (spotRegion, and
    // its spot's own test below): one pass over `placed` for the three, into `wide`, where each
    // lies in it (else that one's own pass over `placed`).
    const ScreenRect rows =
        spanning(x - 5.0f, y - 5.0f * ts.y - 1.0f, x + ts.x + 5.0f, y + 6.0f * ts.y + 1.0f);
    const ScreenRect sideways = spotRegion(x, y, y, ts, ts.y);
    const double pad = 5.0 + 1.0; // the spot's test's margin, and a pixel
    const ScreenRect all =
        spanning(std::min(rows.x, sideways.x) - pad, std::min(rows.y, sideways.y) - pad,
                 std::max(rows.x + rows.width, sideways.x + sideways.width) + pad,
                 std::max(rows.y + rows.height, sideways.y + sideways.height) + pad);
    static thread_local Taken wide, near;
    meeting(placed, all, wide, blockRows);
    const auto from = [&](const ScreenRect& region) -> const Taken& {
        return within(region, all) ? wide : placed;
    };
    const auto rowsOf = [&](const Taken& source) {
        return &source == &placed ? blockRows : nullptr;
    };
    meeting(from(rows), rows, near, rowsOf(from(rows)));
    for (const float direction : {1.0f, -1.0f}) {
        for (int k = 0; k < 6; ++k) {
            const float row = y + direction * static_cast<float>(k) * ts.y;
            const double covered = coveredUnder(near, view, x, row, ts, 4.0f, least);
            if (covered == 0.0) return ImVec2(x, row);
            if (covered < least) {
                least = covered;
                best = row;
            }
        }
    }
    const ImVec2 aside = spotAmong(from(sideways), view, x, y, y, ts, ts.y, rowsOf(from(sideways)));
    const ScreenRect spot =
        spanning(aside.x - 5.0f, aside.y - 1.0f, aside.x + ts.x + 5.0f, aside.y + ts.y + 1.0f);
    meeting(from(spot), spot, near, rowsOf(from(spot))); // all that the test below can meet
    if (coveredAt(near, view, aside.x, aside.y, ts, 4.0f) == 0.0) return aside;
    return ImVec2(x, best); // none free: the row covering the least
}
