// The indexes of rectangles the searches for a free spot look through (issue 42): the strips
// (rect_strips.h) and the grid of candidates' edges (cover_grid.h), against looking at every
// rectangle.
#include "cover_grid.h"
#include "label_placement.h"
#include "rect_strips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>

namespace {

// overlapArea's area in common (dock_layout.cpp, label_placement.cpp).
double areaInCommon(const ScreenRect& a, const ScreenRect& b) {
    const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

TEST(RectStrips, FindEveryRectangleOverlappingInOrder) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> at(-100.0, 900.0), size(-5.0, 120.0);
    for (int trial = 0; trial < 300; ++trial) {
        std::vector<ScreenRect> rects;
        const int n = static_cast<int>(random() % 300);
        for (int i = 0; i < n; ++i)
            rects.push_back({std::round(at(random)), std::round(at(random)),
                             std::round(size(random)), std::round(size(random))});
        if (trial % 10 == 0 && n > 0) rects[0].x = NAN; // in every strip
        const auto axis = trial % 2 == 0 ? RectStrips::Axis::x : RectStrips::Axis::y;
        RectStrips strips;
        strips.build(rects, axis, 0.0, 800.0, 1 + trial % 40);
        ASSERT_EQ(strips.size(), rects.size());
        for (int q = 0; q < 20; ++q) {
            const double from = std::round(at(random)), to = from + std::round(size(random));
            std::vector<const ScreenRect*> visited;
            strips.forEach(from, to, [&](const ScreenRect& r) {
                visited.push_back(&r);
                return true;
            });
            // In the list's order, each once.
            EXPECT_TRUE(std::is_sorted(visited.begin(), visited.end()));
            EXPECT_EQ(std::adjacent_find(visited.begin(), visited.end()), visited.end());
            // Every rectangle overlapping the span is among them.
            for (const ScreenRect& r : rects) {
                const double lo = axis == RectStrips::Axis::x ? r.x : r.y;
                const double hi = axis == RectStrips::Axis::x ? r.x + r.width : r.y + r.height;
                const bool overlaps = std::min(to, hi) - std::max(from, lo) > 0.0 || lo != lo;
                const bool found = std::find(visited.begin(), visited.end(), &r) != visited.end();
                EXPECT_TRUE(found || !overlaps) << "trial " << trial << ": [" << lo << ", " << hi
                                                << "] against [" << from << ", " << to << "]";
            }
        }
    }
}

// Rows and columns together: forEachAlso visits, in the list's order, just the rectangles that
// both the rows' forEach and the columns' visit (every one meeting the region among them).
TEST(RectStrips, RowsAndColumnsTogetherVisitThoseOfBoth) {
    std::mt19937 random(17);
    std::uniform_real_distribution<double> at(-100.0, 900.0), size(-5.0, 120.0);
    for (int trial = 0; trial < 100; ++trial) {
        std::vector<ScreenRect> rects;
        const int n = static_cast<int>(random() % 400);
        for (int i = 0; i < n; ++i)
            rects.push_back({at(random), at(random), size(random), size(random)});
        if (trial % 10 == 0 && n > 1) rects[1].y = NAN; // in every row
        RectStrips rows, columns;
        rows.build(rects, RectStrips::Axis::y, 0.0, 700.0, 1 + trial % 33);
        columns.build(rects, RectStrips::Axis::x, 0.0, 800.0, 1 + trial % 29);
        for (int q = 0; q < 20; ++q) {
            const ScreenRect region{at(random), at(random), size(random) * 3.0, size(random) * 2.0};
            std::vector<const ScreenRect*> inRows, inColumns, both;
            rows.forEach(region.y, region.y + region.height, [&](const ScreenRect& r) {
                inRows.push_back(&r);
                return true;
            });
            columns.forEach(region.x, region.x + region.width, [&](const ScreenRect& r) {
                inColumns.push_back(&r);
                return true;
            });
            std::vector<const ScreenRect*> want;
            std::set_intersection(inRows.begin(), inRows.end(), inColumns.begin(), inColumns.end(),
                                  std::back_inserter(want));
            rows.forEachAlso(columns, region.y, region.y + region.height, region.x,
                             region.x + region.width, [&](const ScreenRect& r) {
                                 both.push_back(&r);
                                 return true;
                             });
            EXPECT_EQ(both, want) << "trial " << trial << " query " << q;
            for (const ScreenRect& r : rects) {
                const bool meets = r.x < region.x + region.width && region.x < r.x + r.width &&
                                   r.y < region.y + region.height && region.y < r.y + r.height;
                EXPECT_TRUE(!meets || std::find(both.begin(), both.end(), &r) != both.end());
            }
        }
    }
}

// Stopping: forEach visits no more once visit returns false.
TEST(RectStrips, StopsWhenTold) {
    const std::vector<ScreenRect> rects = {{0, 0, 10, 10}, {5, 0, 10, 10}, {8, 0, 10, 10}};
    RectStrips strips;
    strips.build(rects, RectStrips::Axis::x, 0.0, 100.0, 10);
    int visited = 0;
    strips.forEach(0.0, 20.0, [&](const ScreenRect&) { return ++visited < 2; });
    EXPECT_EQ(visited, 2);
}

// The grid's sums: whether a rectangle covers anything, exactly; how much, within error().
TEST(CoverGrid, TouchesExactlyAndAreaWithinItsError) {
    std::mt19937 random(31);
    std::uniform_real_distribution<double> at(-50.0, 650.0), size(-3.0, 90.0);
    for (int trial = 0; trial < 60; ++trial) {
        std::vector<ScreenRect> rects;
        const int n = static_cast<int>(random() % 400);
        for (int i = 0; i < n; ++i) {
            const bool whole = trial % 2 == 0; // edges meeting the grid's exactly
            const auto v = [&](double d) { return whole ? std::round(d / 10.0) * 10.0 : d; };
            rects.push_back({v(at(random)), v(at(random)), v(size(random)), v(size(random))});
        }
        std::vector<double> xs, ys;
        for (int i = 0; i < 2 + static_cast<int>(random() % 30); ++i)
            xs.push_back(std::round(at(random) / 10.0) * 10.0 + (trial % 3 == 0 ? 0.25 : 0.0));
        for (int i = 0; i < 2 + static_cast<int>(random() % 30); ++i)
            ys.push_back(std::round(at(random) / 10.0) * 10.0);
        for (std::vector<double>* e : {&xs, &ys}) {
            std::sort(e->begin(), e->end());
            e->erase(std::unique(e->begin(), e->end()), e->end());
        }
        if (xs.size() < 2 || ys.size() < 2) continue;
        CoverGrid grid;
        grid.build(xs, ys, rects);
        for (int q = 0; q < 50; ++q) {
            std::size_t i0 = random() % xs.size(), i1 = random() % xs.size();
            std::size_t j0 = random() % ys.size(), j1 = random() % ys.size();
            if (i0 > i1) std::swap(i0, i1);
            if (j0 > j1) std::swap(j0, j1);
            const ScreenRect r = spanning(xs[i0], ys[j0], xs[i1], ys[j1]);
            double sum = 0.0;
            int touching = 0;
            for (const ScreenRect& a : rects) {
                const double area = areaInCommon(r, a);
                sum += area;
                touching += area > 0.0 ? 1 : 0;
            }
            EXPECT_EQ(grid.touches(i0, j0, i1, j1) == 0, touching == 0) << "trial " << trial;
            EXPECT_LE(std::abs(grid.area(i0, j0, i1, j1) - sum), grid.error()) << "trial " << trial;
            EXPECT_LT(grid.error(), 1e-4); // px²: a bound that tells sums apart
        }
    }
}

} // namespace
