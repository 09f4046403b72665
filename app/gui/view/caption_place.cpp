// Where a caption goes over the scene: placeCaption (dock_layout.h).
//
// The spot is the candidate with the least (texts covered, area covered, tier, y, x), the sums
// taken over the lists in their order. Over a thousand blocks (a gas with the point-of-impact
// overlay) the plate overlaps nearly every rectangle of its rows, so that summing the rows for
// each of some 500 candidates cost a quarter of the browser's frame (issue 42). There the sums
// are first estimated for every candidate at once from a grid of the candidates' edges
// (cover_grid.h: within a known bound, and exact about covering nothing), and the exact sums are
// taken for the few candidates that the estimates leave in the running: the same spot, found with
// the same sums.
#include "dock_layout.h"

#include "cover_grid.h"
#include "rect_strips.h"

#include <algorithm>
#include <cmath>

namespace {

double overlapArea(const ScreenRect& a, const ScreenRect& b) {
    const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

// The candidates' corners (not yet kept to the scene nor rounded) and the range they must lie in.
struct Corners {
    double x0, x1, y0, y1;
    std::vector<double> xs, ys;
};

Corners corners(double width, double height, const ScreenRect& scene, const ScreenRect& world,
                const std::vector<ScreenRect>& avoid, double inset,
                const std::vector<ScreenRect>& texts) {
    Corners c;
    c.x0 = scene.x + inset, c.x1 = scene.x + scene.width - inset - width;
    c.y0 = scene.y + inset, c.y1 = scene.y + scene.height - inset - height;
    // Along the scene's and the world's edges, and a grid between them.
    c.xs = {c.x0, world.x + inset, world.x + world.width - inset - width, c.x1,
            world.x - inset - width};
    c.ys = {c.y0, world.y + inset, world.y + world.height - inset - height, c.y1,
            world.y - inset - height};
    constexpr int kSteps = 16;
    for (int i = 0; i <= kSteps; ++i) {
        c.xs.push_back(c.x0 + (c.x1 - c.x0) * i / kSteps);
        c.ys.push_back(c.y0 + (c.y1 - c.y0) * i / kSteps);
    }
    // And beside each text and each rectangle to avoid, where there are few (the grid's steps
    // of a 16th missed the 125 px between the status badge and the labels above the blocks that
    // a 108 px plate fits: step 5 of lecture3 at 1280x800, UI 1.5). A thousand blocks keep to
    // the grid.
    constexpr std::size_t kFewEdges = 32;
    for (const std::vector<ScreenRect>* list : {&texts, &avoid}) {
        if (list->size() > kFewEdges) continue;
        for (const ScreenRect& r : *list) {
            c.xs.push_back(r.x + r.width), c.xs.push_back(r.x - width);
            c.ys.push_back(r.y + r.height), c.ys.push_back(r.y - height);
        }
    }
    return c;
}

// A rectangle of the list as overlapArea works it out against a candidate with its top at a
// band's top: its sides, and its overlap with the band's rows (the same for the whole band).
struct InBand {
    double left, right, h;
};

void keepInBand(const ScreenRect& a, double top, double height, std::vector<InBand>& to) {
    if (overlapArea({a.x, top, a.width, height}, a) > 0.0)
        to.push_back(
            {a.x, a.x + a.width, std::min(top + height, a.y + a.height) - std::max(top, a.y)});
}

// overlapArea(r, a) of a candidate r of the band, from `left` to `right`.
double area(double left, double right, const InBand& a) {
    const double w = std::min(right, a.right) - std::max(left, a.left);
    return w > 0.0 && a.h > 0.0 ? w * a.h : 0.0;
}

// Every candidate's sums over the lists through their rows (rect_strips.h): the search for any
// input (a NaN, an empty plate), and for few rectangles.
ScreenRect scanAll(const Corners& c, double width, double height, const ScreenRect& scene,
                   const ScreenRect& world, const std::vector<ScreenRect>& avoid, double inset,
                   const std::vector<ScreenRect>& texts) {
    const ScreenRect inner{world.x + inset, world.y + inset, world.width - 2.0 * inset,
                           world.height - 2.0 * inset};
    ScreenRect best{c.x0, c.y0, width, height};
    // (texts covered, area covered, tier, y, x): the smallest wins.
    double bestHidden = INFINITY, bestCovered = INFINITY, bestTier = INFINITY, bestY = INFINITY,
           bestX = INFINITY;
    // The rectangles a candidate at `top` can overlap: those in its band of rows, in their
    // order (the others add nothing to the sums, which come out bit for bit the same).
    constexpr int kRows = 32;
    RectStrips avoidRows, textRows;
    avoidRows.build(avoid, RectStrips::Axis::y, scene.y, scene.y + scene.height, kRows);
    textRows.build(texts, RectStrips::Axis::y, scene.y, scene.y + scene.height, kRows);
    std::vector<InBand> avoidInBand, textsInBand;
    const auto inBand = [height](double top, const RectStrips& from, std::vector<InBand>& to) {
        to.clear();
        from.forEach(top, top + height, [&](const ScreenRect& a) {
            keepInBand(a, top, height, to);
            return true;
        });
    };
    for (double y : c.ys) {
        if (y < c.y0 - 1e-9 || y > c.y1 + 1e-9) continue;
        inBand(std::round(y), avoidRows, avoidInBand);
        inBand(std::round(y), textRows, textsInBand);
        for (double x : c.xs) {
            if (x < c.x0 - 1e-9 || x > c.x1 + 1e-9) continue;
            const ScreenRect r{std::round(x), std::round(y), width, height};
            const double left = r.x, right = r.x + r.width;
            double hidden = 0.0;
            for (const InBand& t : textsInBand) hidden += area(left, right, t);
            if (hidden > bestHidden) continue;
            // The sums only grow (every area is >= 0): once past the best, the candidate loses
            // whatever the rest adds (the sum is the same as the whole loop's up to there).
            double covered = 0.0;
            for (const InBand& a : avoidInBand) {
                covered += area(left, right, a);
                if (hidden == bestHidden && covered > bestCovered) break;
            }
            const double tier = !rectsOverlap(r, world) ? 0.0 : rectInside(r, inner) ? 1.0 : 2.0;
            const bool better =
                hidden < bestHidden ||
                (hidden == bestHidden &&
                 (covered < bestCovered ||
                  (covered == bestCovered &&
                   (tier < bestTier ||
                    (tier == bestTier && (r.y < bestY || (r.y == bestY && r.x < bestX)))))));
            if (!better) continue;
            best = r;
            bestHidden = hidden, bestCovered = covered, bestTier = tier, bestY = r.y, bestX = r.x;
        }
    }
    return best;
}

// The corners kept to [lo, hi] (1e-9 px to spare) and rounded, each value once, in their order:
// a candidate met again is the same rectangle, which never beats itself.
std::vector<double> roundedOnce(const std::vector<double>& from, double lo, double hi) {
    std::vector<double> out;
    for (double v : from) {
        if (v < lo - 1e-9 || v > hi + 1e-9) continue;
        const double r = std::round(v);
        if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
    }
    return out;
}

// The sorted edges of rectangles at `starts`, `size` long, each value once.
std::vector<double> edgesOf(const std::vector<double>& starts, double size) {
    std::vector<double> edges;
    for (double v : starts) edges.push_back(v), edges.push_back(v + size);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

std::size_t edgeIndex(const std::vector<double>& edges, double v) {
    return static_cast<std::size_t>(std::lower_bound(edges.begin(), edges.end(), v) -
                                    edges.begin());
}

// A sum through a grid: it lies from lo to hi; none: it is 0, exactly (nothing is covered).
struct Estimate {
    double lo = 0.0, hi = 0.0;
    bool none = true;
};

Estimate estimate(const CoverGrid& grid, std::size_t i0, std::size_t j0, std::size_t i1,
                  std::size_t j1) {
    if (grid.touches(i0, j0, i1, j1) == 0) return {};
    const double sum = grid.area(i0, j0, i1, j1);
    return {sum - grid.error(), sum + grid.error(), false};
}

// A candidate through the grids: where it is, its estimates and, once taken, its exact sums.
struct Candidate {
    std::size_t row;                    // its corner in the rows (ys)
    double x, y;                        // its top-left corner
    Estimate texts, blocks;             // its sums over the texts and over the rectangles to avoid
    double hidden = NAN, covered = NAN; // the sums, as scanAll takes them
};

// placeCaption for finite input, a plate of positive size, many rectangles (see the top).
ScreenRect throughGrid(const Corners& c, double width, double height, const ScreenRect& world,
                       const std::vector<ScreenRect>& avoid, double inset,
                       const std::vector<ScreenRect>& texts) {
    const std::vector<double> xs = roundedOnce(c.xs, c.x0, c.x1);
    const std::vector<double> ys = roundedOnce(c.ys, c.y0, c.y1);
    if (xs.empty() || ys.empty()) return {c.x0, c.y0, width, height};
    const std::vector<double> edgesX = edgesOf(xs, width), edgesY = edgesOf(ys, height);
    CoverGrid avoidGrid, textGrid;
    avoidGrid.build(edgesX, edgesY, avoid);
    textGrid.build(edgesX, edgesY, texts);
    std::vector<Candidate> all;
    all.reserve(xs.size() * ys.size());
    // Each corner's edges in the grid, looked up once.
    std::vector<std::size_t> left(xs.size()), right(xs.size());
    for (std::size_t c = 0; c < xs.size(); ++c)
        left[c] = edgeIndex(edgesX, xs[c]), right[c] = edgeIndex(edgesX, xs[c] + width);
    for (std::size_t row = 0; row < ys.size(); ++row) {
        const std::size_t j0 = edgeIndex(edgesY, ys[row]), j1 = edgeIndex(edgesY, ys[row] + height);
        for (std::size_t c = 0; c < xs.size(); ++c) {
            all.push_back({row, xs[c], ys[row], estimate(textGrid, left[c], j0, right[c], j1),
                           estimate(avoidGrid, left[c], j0, right[c], j1)});
        }
    }
    // The rows' bands, taken when a candidate of the row needs its exact sums.
    std::vector<std::vector<InBand>> avoidBands(ys.size()), textBands(ys.size());
    std::vector<char> banded(ys.size(), 0);
    const auto exact = [&](const Candidate& k, bool ofTexts) {
        if ((ofTexts ? k.texts : k.blocks).none) return 0.0;
        if (!banded[k.row]) {
            for (const ScreenRect& a : avoid) keepInBand(a, k.y, height, avoidBands[k.row]);
            for (const ScreenRect& t : texts) keepInBand(t, k.y, height, textBands[k.row]);
            banded[k.row] = 1;
        }
        double sum = 0.0;
        for (const InBand& a : ofTexts ? textBands[k.row] : avoidBands[k.row])
            sum += area(k.x, k.x + width, a);
        return sum;
    };
    // The least sum over the texts: among the candidates whose lower bound is no more than the
    // least upper bound (the others cover more than that), by their exact sums.
    double most = INFINITY;
    for (const Candidate& k : all) most = std::min(most, k.texts.hi);
    double least = INFINITY;
    for (Candidate& k : all) {
        if (k.texts.lo > most) continue;
        k.hidden = exact(k, true);
        least = std::min(least, k.hidden);
    }
    // Among those hiding that least, the least area, alike; then the tier, the top, the left.
    double mostCovered = INFINITY;
    for (const Candidate& k : all)
        if (k.hidden == least) mostCovered = std::min(mostCovered, k.blocks.hi);
    const ScreenRect inner{world.x + inset, world.y + inset, world.width - 2.0 * inset,
                           world.height - 2.0 * inset};
    ScreenRect best{c.x0, c.y0, width, height};
    double bestCovered = INFINITY, bestTier = INFINITY;
    bool found = false;
    for (Candidate& k : all) {
        if (!(k.hidden == least) || k.blocks.lo > mostCovered) continue;
        k.covered = exact(k, false);
        const ScreenRect r{k.x, k.y, width, height};
        const double tier = !rectsOverlap(r, world) ? 0.0 : rectInside(r, inner) ? 1.0 : 2.0;
        const bool better =
            k.covered < bestCovered ||
            (k.covered == bestCovered &&
             (tier < bestTier ||
              (tier == bestTier && (r.y < best.y || (r.y == best.y && r.x < best.x)))));
        if (!found || better) {
            best = r;
            bestCovered = k.covered, bestTier = tier, found = true;
        }
    }
    return best;
}

// True when every number is finite and no more than a billion in size (no sum overflows).
bool ordinary(double v) {
    return std::abs(v) <= 1e9;
}
bool ordinary(const ScreenRect& r) {
    return ordinary(r.x) && ordinary(r.y) && ordinary(r.width) && ordinary(r.height);
}
bool ordinary(const std::vector<ScreenRect>& list) {
    return std::all_of(list.begin(), list.end(), [](const ScreenRect& r) { return ordinary(r); });
}

} // namespace

ScreenRect placeCaption(double width, double height, const ScreenRect& scene,
                        const ScreenRect& world, const std::vector<ScreenRect>& avoid, double inset,
                        const std::vector<ScreenRect>& texts) {
    const Corners c = corners(width, height, scene, world, avoid, inset, texts);
    // Over few rectangles the rows are quick, and the grid's edges many (beside each of them).
    constexpr std::size_t kMany = 64;
    const bool grid = avoid.size() + texts.size() > kMany && width > 0.0 && height > 0.0 &&
                      ordinary(width) && ordinary(height) && ordinary(inset) && ordinary(scene) &&
                      ordinary(world) && ordinary(avoid) && ordinary(texts);
    return grid ? throughGrid(c, width, height, world, avoid, inset, texts)
                : scanAll(c, width, height, scene, world, avoid, inset, texts);
}
