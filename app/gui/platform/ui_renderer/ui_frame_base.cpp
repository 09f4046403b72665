#include "ui_frame_base.h"

#include <algorithm>
#include <map>

namespace {

bool rectsOverlap(const UiPixelRect& a, const UiPixelRect& b) {
    return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

UiPixelRect clipped(const UiPixelRect& r, const UiPixelRect& to) {
    return {std::max(r.x0, to.x0), std::max(r.y0, to.y0), std::min(r.x1, to.x1),
            std::min(r.y1, to.y1)};
}

long long pixelCount(const UiPixelRect& r) {
    return r.empty() ? 0 : static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
}

} // namespace

std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& given, UiPixelRect area) {
    if (area.empty()) return {};
    std::vector<UiPixelRect> holes; // those reaching into the area, clipped to it
    for (const UiPixelRect& h : given)
        if (rectsOverlap(h, area)) holes.push_back(clipped(h, area));
    std::vector<int> xs{area.x0, area.x1}, ys{area.y0, area.y1};
    for (const UiPixelRect& h : holes) {
        xs.push_back(h.x0);
        xs.push_back(h.x1);
        ys.push_back(h.y0);
        ys.push_back(h.y1);
    }
    for (std::vector<int>* v : {&xs, &ys}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    std::vector<UiPixelRect> out;
    std::vector<UiPixelRect> open; // the previous band's runs, still growing downwards
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
        const int y0 = ys[j], y1 = ys[j + 1];
        std::vector<UiPixelRect> runs; // this band's free runs
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            const UiPixelRect cell{xs[i], y0, xs[i + 1], y1};
            const bool covered = std::any_of(holes.begin(), holes.end(), [&](const UiPixelRect& h) {
                return h.x0 <= cell.x0 && cell.x1 <= h.x1 && h.y0 <= cell.y0 && cell.y1 <= h.y1;
            });
            if (covered) continue;
            if (!runs.empty() && runs.back().x1 == cell.x0)
                runs.back().x1 = cell.x1;
            else
                runs.push_back(cell);
        }
        std::vector<UiPixelRect> next;
        for (UiPixelRect r : runs) {
            const auto same = std::find_if(open.begin(), open.end(), [&](const UiPixelRect& o) {
                return o.x0 == r.x0 && o.x1 == r.x1 && o.y1 == r.y0;
            });
            if (same != open.end()) {
                r.y0 = same->y0;
                open.erase(same);
            }
            next.push_back(r);
        }
        out.insert(out.end(), open.begin(), open.end()); // runs that stop here
        open = next;
    }
    out.insert(out.end(), open.begin(), open.end());
    return out;
}

std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& holes, int width,
                                      int height) {
    return rectsOutside(holes, UiPixelRect{0, 0, width, height});
}

UiFrameBase planFrameBase(const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                          UiPixelRect arena, int width, int height) {
    UiFrameBase plan;
    plan.skip.assign(paints.size(), false);
    if (width <= 0 || height <= 0) return plan;
    // Only the frame's pixels count (a box may reach past it).
    const UiPixelRect frame{0, 0, width, height};
    const auto inFrame = [&](const UiPixelRect& r) { return clipped(r, frame); };
    arena = inFrame(arena);
    // The fills whose pixels nothing touched before them, by colour.
    std::vector<UiPixelRect> touched{inFrame(sceneDrawn), arena}; // the arena's own colour there
    std::vector<bool> clean(paints.size(), false);
    std::map<ImU32, long long> cleanArea;
    std::vector<UiPixelRect> fills;
    for (std::size_t i = 0; i < paints.size(); ++i) {
        const UiPaint& p = paints[i];
        const UiPixelRect inside = inFrame(p.inside);
        if (!inside.empty() &&
            std::none_of(touched.begin(), touched.end(),
                         [&](const UiPixelRect& t) { return rectsOverlap(t, inside); })) {
            clean[i] = true;
            cleanArea[p.color] += pixelCount(inside);
        }
        touched.push_back(inFrame(p.bounds));
        if (!inside.empty()) {
            touched.push_back(inside);
            fills.push_back(inside);
        }
    }
    // The pixels still seen of the background (outside every fill, each clearing its own pixels
    // over whatever is there, and the arena) and of the arena (outside the fills).
    std::vector<UiPixelRect> arenaSeen = rectsOutside(fills, arena);
    fills.push_back(arena);
    std::vector<UiPixelRect> rest = rectsOutside(fills, frame);
    const auto areaOf = [](const std::vector<UiPixelRect>& rects) {
        long long n = 0;
        for (const UiPixelRect& r : rects) n += pixelCount(r);
        return n;
    };
    // The clear to the largest: the background on a tie (as ever), then the arena.
    long long largest = areaOf(rest);
    if (const long long a = areaOf(arenaSeen); !arena.empty() && a > largest) {
        plan.clearTo = UiFrameClear::Arena;
        largest = a;
    }
    if (!cleanArea.empty()) {
        const auto best =
            std::max_element(cleanArea.begin(), cleanArea.end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
        if (best->second > largest) {
            plan.clearTo = UiFrameClear::Fills;
            plan.clear = best->first;
        }
    }
    if (plan.clearTo == UiFrameClear::Background && arena.empty()) return plan; // as ever
    plan.planned = true;
    if (plan.clearTo != UiFrameClear::Background) plan.background = std::move(rest);
    if (plan.clearTo != UiFrameClear::Arena) plan.arena = std::move(arenaSeen);
    if (plan.clearTo == UiFrameClear::Fills)
        for (std::size_t i = 0; i < paints.size(); ++i)
            plan.skip[i] = clean[i] && paints[i].color == plan.clear;
    return plan;
}
