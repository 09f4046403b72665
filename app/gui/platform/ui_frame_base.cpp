#include "ui_frame_base.h"

#include <algorithm>
#include <map>

namespace {

bool rectsOverlap(const UiPixelRect& a, const UiPixelRect& b) {
    return !a.empty() && !b.empty() && a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

long long pixelCount(const UiPixelRect& r) {
    return r.empty() ? 0 : static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
}

} // namespace

std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& holes, int width,
                                      int height) {
    std::vector<int> xs{0, width}, ys{0, height};
    for (const UiPixelRect& h : holes) {
        if (h.empty()) continue;
        xs.push_back(std::clamp(h.x0, 0, width));
        xs.push_back(std::clamp(h.x1, 0, width));
        ys.push_back(std::clamp(h.y0, 0, height));
        ys.push_back(std::clamp(h.y1, 0, height));
    }
    for (std::vector<int>* v : {&xs, &ys}) {
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    std::vector<UiPixelRect> out;
    std::vector<UiPixelRect> open; // the previous band's runs, still growing downwards
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
        const int y0 = ys[j], y1 = ys[j + 1];
        if (y1 <= y0) continue;
        std::vector<UiPixelRect> runs; // this band's free runs
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            const UiPixelRect cell{xs[i], y0, xs[i + 1], y1};
            if (cell.empty()) continue;
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

UiFrameBase planFrameBase(const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                          UiPixelRect sceneCovered, int width, int height) {
    UiFrameBase plan;
    plan.skip.assign(paints.size(), false);
    if (width <= 0 || height <= 0) return plan;
    // The fills whose pixels nothing touched before them, by colour.
    std::vector<UiPixelRect> touched;
    if (!sceneDrawn.empty()) touched.push_back(sceneDrawn);
    if (!sceneCovered.empty()) touched.push_back(sceneCovered); // the arena's own colour there

    std::vector<bool> clean(paints.size(), false);
    std::map<ImU32, long long> cleanArea;
    for (std::size_t i = 0; i < paints.size(); ++i) {
        const UiPaint& p = paints[i];
        if (!p.inside.empty() &&
            std::none_of(touched.begin(), touched.end(),
                         [&](const UiPixelRect& t) { return rectsOverlap(t, p.inside); })) {
            clean[i] = true;
            cleanArea[p.color] += pixelCount(p.inside);
        }
        touched.push_back(p.bounds);
        if (!p.inside.empty()) touched.push_back(p.inside);
    }
    if (cleanArea.empty()) return plan;
    const auto best =
        std::max_element(cleanArea.begin(), cleanArea.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    // The background is painted outside every fill (a skipped one keeps the clear's colour, the
    // others clear their own pixels over whatever is there) and the scene's opaque part.
    std::vector<UiPixelRect> holes{sceneCovered};
    for (const UiPaint& p : paints)
        if (!p.inside.empty()) holes.push_back(p.inside);
    std::vector<UiPixelRect> rest = rectsOutside(holes, width, height);
    long long restArea = 0;
    for (const UiPixelRect& r : rest) restArea += pixelCount(r);
    if (best->second <= restArea) return plan; // painting the rest would cost more
    plan.planned = true;
    plan.clear = best->first;
    plan.background = std::move(rest);
    for (std::size_t i = 0; i < paints.size(); ++i)
        plan.skip[i] = clean[i] && paints[i].color == best->first;
    return plan;
}
