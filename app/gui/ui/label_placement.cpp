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
void meeting(const Taken& placed, const ScreenRect& region, Taken& out) {
    out.blocks.clear();
    out.texts.clear();
    const auto keep = [&region](const std::vector<ScreenRect>& from, std::vector<ScreenRect>& to) {
        for (const ScreenRect& p : from)
            if (p.x < region.x + region.width && region.x < p.x + p.width &&
                p.y < region.y + region.height && region.y < p.y + p.height)
                to.push_back(p);
    };
    keep(placed.blocks, out.blocks);
    keep(placed.texts, out.texts);
}

// The part of `near` that a text with its top at `y` and `height` tall meets in rows, in order
// (any x): coveredAt's vertical overlap worked out as coveredAt does, so that its sums over the
// band are the sums over `near` (what the band leaves out adds nothing), over a tenth of it.
void band(const Taken& near, float y, float height, Taken& out) {
    out.blocks.clear();
    out.texts.clear();
    const ScreenRect r = spanning(0.0, y, 0.0, y + height);
    const auto keep = [&r](const std::vector<ScreenRect>& from, std::vector<ScreenRect>& to) {
        for (const ScreenRect& p : from)
            if (std::min(r.y + r.height, p.y + p.height) - std::max(r.y, p.y) > 0.0)
                to.push_back(p);
    };
    keep(near.blocks, out.blocks);
    keep(near.texts, out.texts);
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
    if (x < view.x || y < view.y || x + size.x > view.x + view.width ||
        y + size.y > view.y + view.height)
        return INFINITY;
    const ScreenRect r = spanning(x - gap, y, x + size.x + gap, y + size.y);
    const auto area = [&r](const std::vector<ScreenRect>& list) {
        double sum = 0.0;
        for (const ScreenRect& p : list) {
            const double w = std::min(r.x + r.width, p.x + p.width) - std::max(r.x, p.x);
            const double h = std::min(r.y + r.height, p.y + p.height) - std::max(r.y, p.y);
            if (w > 0.0 && h > 0.0) sum += w * h;
        }
        return sum;
    };
    return area(placed.blocks) + 10.0 * area(placed.texts);
}

ImVec2 freeSpot(const Taken& placed, const ScreenRect& view, float x, float above, float below,
                ImVec2 size, float line) {
    const float gap = line * 0.5f; // labels closer than this read as one
    const float shift = size.x * 0.5f + gap;
    const float reach =
        3.0f * shift + gap + 1.0f; // the farthest a candidate's sides go, and a pixel
    static thread_local Taken near;
    meeting(placed,
            spanning(x - reach, std::min(above - 5.0f * line, below) - 1.0f, x + size.x + reach,
                     std::max(above, below + 5.0f * line) + size.y + 1.0f),
            near);
    // Each of the 12 rows is tried at up to 7 places sideways: its band of `near` is found on its
    // first try and kept.
    constexpr int kRows = 6;
    static thread_local Taken rows[kRows][2];
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
                const double covered = coveredAt(rows[k][side], view, x + dx, y, size, gap);
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

ImVec2 freeRow(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 ts) {
    float best = y;
    double least = INFINITY;
    static thread_local Taken near;
    meeting(placed,
            spanning(x - 5.0f, y - 5.0f * ts.y - 1.0f, x + ts.x + 5.0f, y + 6.0f * ts.y + 1.0f),
            near);
    for (const float direction : {1.0f, -1.0f}) {
        for (int k = 0; k < 6; ++k) {
            const float row = y + direction * static_cast<float>(k) * ts.y;
            const double covered = coveredAt(near, view, x, row, ts, 4.0f);
            if (covered == 0.0) return ImVec2(x, row);
            if (covered < least) {
                least = covered;
                best = row;
            }
        }
    }
    const ImVec2 aside = freeSpot(placed, view, x, y, y, ts, ts.y);
    meeting(placed,
            spanning(aside.x - 5.0f, aside.y - 1.0f, aside.x + ts.x + 5.0f, aside.y + ts.y + 1.0f),
            near); // all that the test below can meet
    if (coveredAt(near, view, aside.x, aside.y, ts, 4.0f) == 0.0) return aside;
    return ImVec2(x, best); // none free: the row covering the least
}
