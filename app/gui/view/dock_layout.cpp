#include "dock_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {

// A rectangle from edges rounded to whole pixels, so neighbours share an edge exactly.
ScreenRect fromEdges(double x0, double y0, double x1, double y1) {
    const double l = std::round(x0), t = std::round(y0);
    const double r = std::max(l, std::round(x1)), b = std::max(t, std::round(y1));
    return {l, t, r - l, b - t};
}

// The least extent of a window along its stack: its minimum at the UI scale, and in a column
// its share of the display's height (`displayH`; 0 along the strip, where extents are widths).
double leastExtent(const DockRequest& r, double scale, double displayH) {
    return std::max(0.0, r.minExtent) * scale + std::max(0.0, r.heightShare) * displayH;
}

// Splits `length` pixels among `items` along a stack: each gets its least extent (all shrunk
// alike when they do not fit), then what is left by weight. Returns the extents.
std::vector<double> share(const std::vector<const DockRequest*>& items, double length, double gap,
                          double scale, double displayH) {
    std::vector<double> out(items.size(), 0.0);
    if (items.empty()) return out;
    const double usable = std::max(0.0, length - gap * static_cast<double>(items.size() - 1));
    double mins = 0.0, weights = 0.0;
    for (const DockRequest* r : items) {
        mins += leastExtent(*r, scale, displayH);
        weights += std::max(0.0, r->weight);
    }
    const double shrink = mins > usable && mins > 0.0 ? usable / mins : 1.0;
    const double left = std::max(0.0, usable - mins * shrink);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const double w = std::max(0.0, items[i]->weight);
        const double extra =
            weights > 0.0 ? left * w / weights : left / static_cast<double>(items.size());
        out[i] = leastExtent(*items[i], scale, displayH) * shrink + extra;
    }
    return out;
}

// True when `items` side by side along `length` each get at least kLeastDockShrink of their
// least extent.
bool fitSideBySide(const std::vector<const DockRequest*>& items, double length, double gap,
                   double scale, double displayH) {
    if (items.size() < 2) return true;
    double mins = 0.0;
    for (const DockRequest* r : items) mins += leastExtent(*r, scale, displayH);
    return mins * kLeastDockShrink <= length - gap * static_cast<double>(items.size() - 1);
}

// The region's windows folded into tabs: the one shown (the highest `front`) stays in `items`
// alone, to be given the whole region; the tabs go into `out` (their rectangle set with it).
void foldIntoTabs(std::vector<const DockRequest*>& items, std::vector<DockTabs>& out) {
    DockTabs tabs;
    const DockRequest* shown = items.front();
    for (const DockRequest* r : items) {
        tabs.names.push_back(r->name);
        if (r->front > shown->front) shown = r;
    }
    tabs.shown = shown->name;
    out.push_back(std::move(tabs));
    items = {shown};
}

double wanted(const std::vector<const DockRequest*>& items, double scale) {
    double w = 0.0;
    for (const DockRequest* r : items) w = std::max(w, r->crossExtent * scale);
    return w;
}

} // namespace

const ScreenRect* Layout::find(const std::string& name) const {
    for (const DockedWindow& w : windows) {
        if (w.name == name) return &w.rect;
    }
    return nullptr;
}

const DockTabs* Layout::tabsOf(const std::string& name) const {
    for (const DockTabs& t : tabs)
        if (std::find(t.names.begin(), t.names.end(), name) != t.names.end()) return &t;
    return nullptr;
}

bool Layout::hides(const std::string& name) const {
    return std::find(hidden.begin(), hidden.end(), name) != hidden.end();
}

bool sheetLayout(double displayWidth, float uiScale, double displayHeight, bool touch) {
    const double s = static_cast<double>(uiScale > 0.0f ? uiScale : 1.0f);
    return displayWidth < kSheetBelowPx * s || (touch && displayHeight < kTouchSheetBelowPx * s);
}

namespace {

void shiftDown(ScreenRect& r, double dy) {
    r.y += dy;
}

} // namespace

Layout computeLayout(const LayoutInput& in) {
    const double W = std::max(1.0, in.displayWidth), H = std::max(1.0, in.displayHeight);
    if (in.topInset > 0.0) { // the caption bar across the top: the rest laid out below it
        const double top = std::round(std::clamp(in.topInset, 0.0, H - 1.0));
        LayoutInput below = in;
        below.displayHeight = H - top;
        below.topInset = 0.0;
        below.shareHeight = in.shareHeight > 0.0 ? in.shareHeight : H;
        Layout out = computeLayout(below);
        shiftDown(out.panel, top);
        shiftDown(out.scene, top);
        for (DockedWindow& w : out.windows) shiftDown(w.rect, top);
        for (DockTabs& t : out.tabs) shiftDown(t.rect, top);
        return out;
    }
    if (in.panelHeight > 0.0) { // a sheet: the rest is laid out above it, windows in the strip
        const double top = std::round(H - std::clamp(in.panelHeight, 1.0, H - 1.0));
        LayoutInput above = in;
        above.displayHeight = top;
        above.panelWidth = 0.0;
        above.panelHeight = 0.0;
        const double screenH = in.shareHeight > 0.0 ? in.shareHeight : H;
        // (1 px to spare: the share is a floor, whatever the rounding.)
        above.maxStripHeight = std::max(1.0, top - std::ceil(kMinSheetSceneShare * screenH) - 1.0);
        // Under a strip lower than the sheet's bar (the sheet open) nothing can be read: the
        // windows wait, not drawn, and the scene keeps the room.
        std::vector<std::string> hidden;
        if (above.maxStripHeight < kSheetBarPx * static_cast<double>(in.uiScale)) {
            for (const DockRequest& w : above.windows) hidden.push_back(w.name);
            above.windows.clear();
        }
        for (DockRequest& w : above.windows) {
            // A column's window laid along the strip: its least extent was a height; as a width
            // it is the width the window wants (a plot's axis, the inspector's equations), so
            // that three of them fold into tabs on a phone rather than each shown a third wide.
            if (w.side != DockSide::Bottom) w.minExtent = std::max(w.minExtent, w.crossExtent);
            w.side = DockSide::Bottom;
        }
        Layout out = computeLayout(above);
        out.panel = fromEdges(0.0, top, W, H);
        out.sheet = true;
        out.hidden = std::move(hidden);
        return out;
    }
    Layout out;
    const double s = in.uiScale > 0.0f ? static_cast<double>(in.uiScale) : 1.0;
    const double shareH = in.shareHeight > 0.0 ? in.shareHeight : H; // what heightShare is of
    const double panel = std::clamp(in.panelWidth, 0.0, W * 0.5);
    out.panel = panel > 0.0 ? fromEdges(0.0, 0.0, panel, H) : ScreenRect{0.0, 0.0, 0.0, H};
    const double areaX = out.panel.width, areaW = W - areaX;

    std::vector<const DockRequest*> right, bottom, under;
    for (const DockRequest& r : in.windows) {
        if (r.side == DockSide::Panel && panel > 0.0)
            under.push_back(&r);
        else
            (r.side == DockSide::Bottom ? bottom : right).push_back(&r);
    }
    const double gap = kDockGap * s;
    // Under the panel, in its column, stacked up from the bottom; the panel keeps the rest.
    if (!under.empty()) {
        std::vector<double> heights;
        double total = 0.0;
        for (const DockRequest* r : under) {
            heights.push_back(leastExtent(*r, s, shareH));
            total += heights.back() + gap;
        }
        const double shrink = std::min(1.0, H * kMaxPanelDockShare / total);
        double y = H - total * shrink;
        out.panel = fromEdges(0.0, 0.0, panel, y);
        for (std::size_t i = 0; i < under.size(); ++i) {
            const double y0 = y + gap * shrink;
            const double y1 = i + 1 == under.size() ? H : y0 + heights[i] * shrink;
            out.windows.push_back({under[i]->name, fromEdges(0.0, y0, panel, y1)});
            y = y1;
        }
    }
    const double columnW = right.empty()
                               ? 0.0
                               : std::min(std::max(wanted(right, s), areaW * kMinColumnShare),
                                          areaW * kMaxColumnShare);
    const double stripMost = in.maxStripHeight > 0.0
                                 ? std::min(H * kMaxStripShare, in.maxStripHeight)
                                 : H * kMaxStripShare;
    const double stripH =
        bottom.empty() ? 0.0 : std::min(std::max(wanted(bottom, s), H * kMinStripShare), stripMost);
    const double columnX = W - columnW, stripY = H - stripH;
    // The right column, above the strip, windows stacked top to bottom.
    const double columnH = bottom.empty() ? H : stripY;
    // Regions too small for their windows side by side: one window each, the rest behind tabs.
    const double stripX0 = areaX + (panel > 0.0 ? gap : 0.0);
    const bool foldRight = in.tabs && !fitSideBySide(right, columnH, gap, s, shareH);
    const bool foldBottom = in.tabs && !fitSideBySide(bottom, W - stripX0, gap, s, 0.0);
    if (foldRight) foldIntoTabs(right, out.tabs);
    if (foldBottom) foldIntoTabs(bottom, out.tabs);
    const std::vector<double> heights = share(right, columnH, gap, s, shareH);
    double y = 0.0;
    for (std::size_t i = 0; i < right.size(); ++i) {
        const double y1 = i + 1 == right.size() ? columnH : y + heights[i];
        out.windows.push_back({right[i]->name, fromEdges(columnX + gap, y, W, y1)});
        if (foldRight) out.tabs[0].rect = out.windows.back().rect;
        y = y1 + gap;
    }
    // The bottom strip, from the panel to the right edge (under the column), left to right.
    const std::vector<double> widths = share(bottom, W - stripX0, gap, s, 0.0);
    double x = stripX0;
    for (std::size_t i = 0; i < bottom.size(); ++i) {
        const double x1 = i + 1 == bottom.size() ? W : x + widths[i];
        out.windows.push_back({bottom[i]->name, fromEdges(x, stripY + gap, x1, H)});
        if (foldBottom) out.tabs.back().rect = out.windows.back().rect;
        x = x1 + gap;
    }
    out.scene = fromEdges(areaX, 0.0, std::max(areaX + 1.0, columnX), std::max(1.0, stripY));
    return out;
}

bool compactWindow(double width, double height, double fontPx) {
    return height < 14.0 * fontPx || width < 18.0 * fontPx;
}

bool rectsOverlap(const ScreenRect& a, const ScreenRect& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
           b.y < a.y + a.height;
}

bool rectInside(const ScreenRect& inner, const ScreenRect& outer) {
    return inner.x >= outer.x && inner.y >= outer.y &&
           inner.x + inner.width <= outer.x + outer.width &&
           inner.y + inner.height <= outer.y + outer.height;
}

ScreenRect worldRectOnScreen(const Camera& camera, const Bounds& bounds) {
    const Vec2 a = camera.worldToScreen(bounds.min), b = camera.worldToScreen(bounds.max);
    const double x0 = std::min(a.x, b.x), y0 = std::min(a.y, b.y);
    return {x0, y0, std::max(a.x, b.x) - x0, std::max(a.y, b.y) - y0};
}

std::string jsonRect(const ScreenRect& r) {
    char text[128];
    std::snprintf(text, sizeof text, "[%.10g, %.10g, %.10g, %.10g]", r.x, r.y, r.width, r.height);
    return text;
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (u < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", u);
            out += esc;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

namespace {

// [{"name": ..., "rect": [...]}, ...]
std::string namedRects(const std::vector<DockedWindow>& list) {
    std::string out = "[";
    for (std::size_t i = 0; i < list.size(); ++i) {
        out += (i ? ", " : "") + std::string("{\"name\": ") + jsonString(list[i].name) +
               ", \"rect\": " + jsonRect(list[i].rect) + "}";
    }
    return out + "]";
}

} // namespace

std::string
layoutJson(const ScreenRect& scene, const ScreenRect& world,
           const std::vector<DockedWindow>& windows, const std::vector<DockedWindow>& blocks,
           const std::vector<DockedWindow>& plots, const std::vector<DockedWindow>& marks,
           const std::vector<DockedWindow>& magnified, const std::vector<DockedWindow>& sideways,
           const std::vector<DockedWindow>& folded) {
    return "{\"scene\": " + jsonRect(scene) + ", \"world\": " + jsonRect(world) +
           ", \"windows\": " + namedRects(windows) + ", \"blocks\": " + namedRects(blocks) +
           ", \"plots\": " + namedRects(plots) + ", \"marks\": " + namedRects(marks) +
           (magnified.empty() ? "" : ", \"magnified\": " + namedRects(magnified)) +
           (sideways.empty() ? "" : ", \"sideways\": " + namedRects(sideways)) +
           (folded.empty() ? "" : ", \"folded\": " + namedRects(folded)) + "}\n";
}
