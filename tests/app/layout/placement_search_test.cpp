// The searches for a free spot (label_placement.h, placeCaption in dock_layout.h), issue 42:
// faster, and the same to the last bit. Each is checked against the plain loops it replaced (kept
// here as they were, namespace before) on random screens: a thousand blocks and labels, spots
// crowded and free. The indexes they look through: rect_index_test.cpp.
#include "dock_layout.h"
#include "label_placement.h"
#include "rect_strips.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace {

namespace before {

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

double overlapArea(const ScreenRect& a, const ScreenRect& b) {
    const double w = std::min(a.x + a.width, b.x + b.width) - std::max(a.x, b.x);
    const double h = std::min(a.y + a.height, b.y + b.height) - std::max(a.y, b.y);
    return w > 0.0 && h > 0.0 ? w * h : 0.0;
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
                const double covered = before::coveredAt(rows[k][side], view, x + dx, y, size, gap);
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
            const double covered = before::coveredAt(near, view, x, row, ts, 4.0f);
            if (covered == 0.0) return ImVec2(x, row);
            if (covered < least) {
                least = covered;
                best = row;
            }
        }
    }
    const ImVec2 aside = before::freeSpot(placed, view, x, y, y, ts, ts.y);
    meeting(placed,
            spanning(aside.x - 5.0f, aside.y - 1.0f, aside.x + ts.x + 5.0f, aside.y + ts.y + 1.0f),
            near); // all that the test below can meet
    if (before::coveredAt(near, view, aside.x, aside.y, ts, 4.0f) == 0.0) return aside;
    return ImVec2(x, best); // none free: the row covering the least
}

ScreenRect placeCaption(double width, double height, const ScreenRect& scene,
                        const ScreenRect& world, const std::vector<ScreenRect>& avoid, double inset,
                        const std::vector<ScreenRect>& texts) { // as before issue 42's strips
    const double x0 = scene.x + inset, x1 = scene.x + scene.width - inset - width;
    const double y0 = scene.y + inset, y1 = scene.y + scene.height - inset - height;
    // Candidate corners: along the scene's and the world's edges, and a grid between them.
    std::vector<double> xs = {x0, world.x + inset, world.x + world.width - inset - width, x1,
                              world.x - inset - width};
    std::vector<double> ys = {y0, world.y + inset, world.y + world.height - inset - height, y1,
                              world.y - inset - height};
    constexpr int kSteps = 16;
    for (int i = 0; i <= kSteps; ++i) {
        xs.push_back(x0 + (x1 - x0) * i / kSteps);
        ys.push_back(y0 + (y1 - y0) * i / kSteps);
    }
    // And beside each text and each rectangle to avoid, where there are few (the grid's steps
    // of a 16th missed the 125 px between the status badge and the labels above the blocks that
    // a 108 px plate fits: step 5 of lecture3 at 1280x800, UI 1.5). A thousand blocks keep to
    // the grid.
    constexpr std::size_t kFewEdges = 32;
    for (const std::vector<ScreenRect>* list : {&texts, &avoid}) {
        if (list->size() > kFewEdges) continue;
        for (const ScreenRect& r : *list) {
            xs.push_back(r.x + r.width), xs.push_back(r.x - width);
            ys.push_back(r.y + r.height), ys.push_back(r.y - height);
        }
    }
    const ScreenRect inner{world.x + inset, world.y + inset, world.width - 2.0 * inset,
                           world.height - 2.0 * inset};
    ScreenRect best{x0, y0, width, height};
    // (texts covered, area covered, tier, y, x): the smallest wins.
    double bestHidden = INFINITY, bestCovered = INFINITY, bestTier = INFINITY, bestY = INFINITY,
           bestX = INFINITY;
    // The rectangles a candidate at `top` can overlap: those in its band of rows, in their
    // order (the others add nothing to the sums, which come out bit for bit the same). A
    // thousand blocks against every candidate cost a millisecond a caption.
    std::vector<ScreenRect> avoidInBand, textsInBand;
    const auto inBand = [height](double top, const std::vector<ScreenRect>& from,
                                 std::vector<ScreenRect>& to) {
        to.clear();
        for (const ScreenRect& a : from)
            if (overlapArea({a.x, top, a.width, height}, a) > 0.0) to.push_back(a);
    };
    for (double y : ys) {
        if (y < y0 - 1e-9 || y > y1 + 1e-9) continue;
        inBand(std::round(y), avoid, avoidInBand);
        inBand(std::round(y), texts, textsInBand);
        for (double x : xs) {
            if (x < x0 - 1e-9 || x > x1 + 1e-9) continue;
            const ScreenRect r{std::round(x), std::round(y), width, height};
            double hidden = 0.0;
            for (const ScreenRect& t : textsInBand) hidden += overlapArea(r, t);
            if (hidden > bestHidden) continue;
            // The sums only grow (every area is >= 0): once past the best, the candidate loses
            // whatever the rest adds (the sum is the same as the whole loop's up to there).
            double covered = 0.0;
            for (const ScreenRect& a : avoidInBand) {
                covered += overlapArea(r, a);
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

} // namespace before

// A random screen: `blocks` rectangles 4 to 60 px (some beyond the view), `texts` labels, on a
// view of 1280 x 720 from (0, 20).
struct Screen {
    ScreenRect view{0.0, 20.0, 1280.0, 720.0};
    Taken taken;
};

Screen randomScreen(std::mt19937& random, int blocks, int texts) {
    Screen s;
    std::uniform_real_distribution<double> x(-40.0, 1300.0), y(0.0, 760.0), size(4.0, 60.0);
    // Whole pixels and quarters, as the screen's are, so that edges meet exactly.
    const auto snap = [](double v) { return std::round(v * 4.0) / 4.0; };
    for (int i = 0; i < blocks; ++i)
        s.taken.blocks.push_back(
            {snap(x(random)), snap(y(random)), snap(size(random)), snap(size(random))});
    std::uniform_real_distribution<double> width(20.0, 160.0);
    for (int i = 0; i < texts; ++i)
        s.taken.texts.push_back({snap(x(random)), snap(y(random)), snap(width(random)), 13.0});
    return s;
}

// freeRow and freeSpot, with the blocks' rows and without, find the spots the plain loops found,
// on crowded screens (no spot free: every candidate is weighed) and sparse ones.
TEST(LabelPlacement, SpotsAreThoseOfThePlainSearch) {
    std::mt19937 random(11);
    int crowded = 0, free = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const int blocks = trial % 3 == 0 ? 1000 : static_cast<int>(random() % 200);
        Screen s = randomScreen(random, blocks, static_cast<int>(random() % 60));
        const BlockStrips rows = blockStrips(s.taken, s.view);
        std::uniform_real_distribution<float> x(-20.0f, 1280.0f), y(0.0f, 760.0f);
        for (int q = 0; q < 40; ++q) {
            const ImVec2 ts(static_cast<float>(20 + random() % 140),
                            13.0f + static_cast<float>(q % 3));
            const float qx = x(random), qy = y(random);
            const ImVec2 want = before::freeRow(s.taken, s.view, qx, qy, ts);
            const ImVec2 got = freeRow(s.taken, s.view, qx, qy, ts);
            const ImVec2 fast = freeRow(s.taken, s.view, qx, qy, ts, &rows);
            EXPECT_EQ(got.x, want.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(got.y, want.y) << "trial " << trial << " query " << q;
            EXPECT_EQ(fast.x, want.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(fast.y, want.y) << "trial " << trial << " query " << q;
            const float below = qy + static_cast<float>(random() % 40);
            const ImVec2 spot = before::freeSpot(s.taken, s.view, qx, qy, below, ts, ts.y);
            const ImVec2 spotFast = freeSpot(s.taken, s.view, qx, qy, below, ts, ts.y, &rows);
            EXPECT_EQ(spotFast.x, spot.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(spotFast.y, spot.y) << "trial " << trial << " query " << q;
            const bool isFree = before::coveredAt(s.taken, s.view, want.x, want.y, ts, 4.0f) == 0.0;
            (isFree ? free : crowded) += 1;
            EXPECT_EQ(coveredAt(s.taken, s.view, want.x, want.y, ts, 4.0f),
                      before::coveredAt(s.taken, s.view, want.x, want.y, ts, 4.0f));
            // The texts then go around it, as the arrows' values are taken one after another.
            if (q % 4 == 0) s.taken.texts.push_back({want.x, want.y, ts.x, ts.y});
        }
    }
    EXPECT_GT(crowded, 200); // both kinds of screen were searched
    EXPECT_GT(free, 200);
}

// freeSpot and freeRow find the plain loops' spots on screens made to trip a faster search:
// edges anywhere (a sum's last bits then differ with its order), blocks on a lattice (many tries
// covering the same), and labels of any width.
TEST(LabelPlacement, SpotsAreThoseOfThePlainSearchOnTrickyScreens) {
    std::mt19937 random(41);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int crowded = 0, free = 0;
    for (int trial = 0; trial < 40; ++trial) {
        Screen s;
        const bool lattice = trial % 2 == 0;
        const double side = 6.0 + unit(random) * 30.0;
        const int blocks = 200 + static_cast<int>(random() % 1000);
        for (int i = 0; i < blocks; ++i) {
            if (lattice) {
                const int across = static_cast<int>(1280.0 / (side * 1.5));
                s.taken.blocks.push_back({(i % across) * std::round(side * 1.5),
                                          20.0 + (i / across) * std::round(side * 1.5),
                                          std::round(side), std::round(side)});
            } else {
                s.taken.blocks.push_back({unit(random) * 1300.0 - 20.0, unit(random) * 760.0,
                                          2.0 + unit(random) * side, 2.0 + unit(random) * side});
            }
        }
        for (int i = 0; i < static_cast<int>(random() % 80); ++i)
            s.taken.texts.push_back({unit(random) * 1280.0, unit(random) * 740.0,
                                     20.0 + unit(random) * 120.0,
                                     13.0 + (lattice ? 0.0 : unit(random))});
        const BlockStrips rows = blockStrips(s.taken, s.view);
        std::uniform_real_distribution<float> x(-20.0f, 1280.0f), y(0.0f, 760.0f);
        for (int q = 0; q < 30; ++q) {
            const ImVec2 ts(20.0f + static_cast<float>(unit(random)) * 140.0f,
                            lattice ? 13.0f : 13.0f + static_cast<float>(unit(random)));
            const float qx = lattice ? std::round(x(random)) : x(random), qy = y(random);
            const float below = qy + static_cast<float>(random() % 40);
            const ImVec2 spot = before::freeSpot(s.taken, s.view, qx, qy, below, ts, ts.y);
            const ImVec2 got = freeSpot(s.taken, s.view, qx, qy, below, ts, ts.y);
            const ImVec2 fast = freeSpot(s.taken, s.view, qx, qy, below, ts, ts.y, &rows);
            EXPECT_EQ(got.x, spot.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(got.y, spot.y) << "trial " << trial << " query " << q;
            EXPECT_EQ(fast.x, spot.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(fast.y, spot.y) << "trial " << trial << " query " << q;
            const ImVec2 want = before::freeRow(s.taken, s.view, qx, qy, ts);
            const ImVec2 row = freeRow(s.taken, s.view, qx, qy, ts, &rows);
            EXPECT_EQ(row.x, want.x) << "trial " << trial << " query " << q;
            EXPECT_EQ(row.y, want.y) << "trial " << trial << " query " << q;
            const bool isFree =
                before::coveredAt(s.taken, s.view, spot.x, spot.y, ts, ts.y * 0.5f) == 0.0;
            (isFree ? free : crowded) += 1;
        }
    }
    EXPECT_GT(crowded, 100); // both kinds of spot were searched for
    EXPECT_GT(free, 100);
}

// Mirror images: blocks and texts placed in pairs mirrored about the middle of a label's first
// try, so that the tries to the right and to the left cover the same area but for the last bits
// of their sums (the mirrored edges are rounded, the sums taken in another order): freeSpot picks
// between such near twins as the plain loop does, by its sums to the bit (a search that picked by
// estimates within a bound of the sums, e.g. a grid's, failed here).
TEST(LabelPlacement, MirroredTwinsPickedByTheSumsToTheBit) {
    std::mt19937 random(43);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int pickedRight = 0, pickedLeft = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Screen s;
        const ImVec2 ts(30.0f + static_cast<float>(unit(random)) * 80.0f,
                        12.0f + static_cast<float>(unit(random)) * 4.0f);
        const float qx = 400.0f + static_cast<float>(unit(random)) * 300.0f;
        const float qy = 200.0f + static_cast<float>(unit(random)) * 300.0f;
        const double middle = static_cast<double>(qx) + ts.x * 0.5;
        std::vector<ScreenRect> right, left;
        const int n = 150 + static_cast<int>(random() % 300);
        for (int i = 0; i < n; ++i) {
            const ScreenRect r{middle + unit(random) * 4.0 * ts.x,
                               qy - 8.0 * ts.y + unit(random) * 16.0 * ts.y,
                               1.0 + unit(random) * ts.x, 1.0 + unit(random) * ts.y};
            right.push_back(r);
            left.push_back({2.0 * middle - (r.x + r.width), r.y, r.width, r.height});
        }
        std::shuffle(left.begin(), left.end(), random);
        // Over the middle column (the first tries), wider than a label: the twins cover less.
        s.taken.blocks.push_back({middle - ts.x * 0.75, qy - 8.0 * ts.y, ts.x * 1.5, 17.0 * ts.y});
        const bool asTexts = trial % 3 == 0;
        for (const std::vector<ScreenRect>* half : {&right, &left})
            for (const ScreenRect& r : *half)
                (asTexts && &r - half->data() < n / 3 ? s.taken.texts : s.taken.blocks)
                    .push_back(r);
        const BlockStrips rows = blockStrips(s.taken, s.view);
        const ImVec2 want = before::freeSpot(s.taken, s.view, qx, qy, qy, ts, ts.y);
        const ImVec2 got = freeSpot(s.taken, s.view, qx, qy, qy, ts, ts.y, &rows);
        EXPECT_EQ(got.x, want.x) << "trial " << trial;
        EXPECT_EQ(got.y, want.y) << "trial " << trial;
        (want.x > qx ? pickedRight : pickedLeft) += want.x != qx ? 1 : 0;
    }
    EXPECT_GT(pickedRight, 20); // the twins were weighed, either way
    EXPECT_GT(pickedLeft, 20);
}

// freeSpot and freeRow find the plain loops' spots on odd input, where the rows or the places
// sideways coincide or overlap and where a number is not finite: a line of no height (every row
// the same), labels of no width (every place sideways the same), labels taller than a line (rows
// overlapping), a line going up (rows in the other order), and NaN and infinite edges in the
// blocks, the texts and the query.
TEST(LabelPlacement, SpotsAreThoseOfThePlainSearchOnOddInput) {
    std::mt19937 random(47);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const float odd[] = {NAN, INFINITY, -INFINITY};
    int free = 0, crowded = 0;
    for (int trial = 0; trial < 120; ++trial) {
        Screen s = randomScreen(random, 50 + static_cast<int>(random() % 400),
                                static_cast<int>(random() % 40));
        if (trial % 4 == 1) { // a few edges not finite
            for (int i = 0; i < 6; ++i) {
                std::vector<ScreenRect>& list = i % 2 == 0 ? s.taken.blocks : s.taken.texts;
                if (list.empty()) continue;
                ScreenRect& r = list[random() % list.size()];
                double* sides[] = {&r.x, &r.y, &r.width, &r.height};
                *sides[random() % 4] = odd[random() % 3];
            }
        }
        const BlockStrips rows = blockStrips(s.taken, s.view);
        for (int q = 0; q < 20; ++q) {
            float qx = static_cast<float>(unit(random) * 1300.0 - 20.0);
            float qy = static_cast<float>(unit(random) * 760.0);
            ImVec2 ts(static_cast<float>(20.0 + unit(random) * 100.0), 13.0f);
            float line = ts.y;
            switch ((trial + q) % 6) {
            case 0:
                line = 0.0f;
                break; // every row the same
            case 1:
                ts.x = 0.0f, line = 0.0f;
                break; // every place the same too
            case 2:
                ts.y = 40.0f;
                break; // rows overlapping
            case 3:
                line = -ts.y;
                break; // rows going up
            case 4:
                (q % 2 == 0 ? qx : qy) = odd[random() % 3];
                break;
            default:
                break;
            }
            const float below = qy + static_cast<float>(random() % 40);
            const ImVec2 want = before::freeSpot(s.taken, s.view, qx, qy, below, ts, line);
            const ImVec2 got = freeSpot(s.taken, s.view, qx, qy, below, ts, line);
            const ImVec2 fast = freeSpot(s.taken, s.view, qx, qy, below, ts, line, &rows);
            const auto same = [](float a, float b) { return a == b || (a != a && b != b); };
            EXPECT_TRUE(same(got.x, want.x) && same(got.y, want.y))
                << "trial " << trial << " query " << q << ": " << got.x << ", " << got.y << " for "
                << want.x << ", " << want.y;
            EXPECT_TRUE(same(fast.x, want.x) && same(fast.y, want.y))
                << "trial " << trial << " query " << q;
            const ImVec2 wantRow = before::freeRow(s.taken, s.view, qx, qy, ts);
            const ImVec2 row = freeRow(s.taken, s.view, qx, qy, ts, &rows);
            EXPECT_TRUE(same(row.x, wantRow.x) && same(row.y, wantRow.y))
                << "trial " << trial << " query " << q;
            const bool isFree = before::coveredAt(s.taken, s.view, want.x, want.y, ts, 0.0f) == 0.0;
            (isFree ? free : crowded) += 1;
        }
    }
    EXPECT_GT(free, 100); // both kinds of spot were searched for
    EXPECT_GT(crowded, 100);
}

// placeCaption through the rows finds the plain loops' spot, over a thousand blocks and few.
TEST(PlaceCaption, SpotIsThatOfThePlainSearch) {
    std::mt19937 random(5);
    for (int trial = 0; trial < 80; ++trial) {
        const int blocks = trial % 2 == 0 ? 1000 : static_cast<int>(random() % 30);
        const Screen s = randomScreen(random, blocks, static_cast<int>(random() % 50));
        const ScreenRect world{100.0 + static_cast<double>(random() % 50), 60.0, 1000.0, 600.0};
        const double width = static_cast<double>(60 + random() % 500);
        const double height = static_cast<double>(20 + random() % 300);
        const ScreenRect want =
            before::placeCaption(width, height, s.view, world, s.taken.blocks, 10.0, s.taken.texts);
        const ScreenRect got =
            placeCaption(width, height, s.view, world, s.taken.blocks, 10.0, s.taken.texts);
        EXPECT_EQ(got.x, want.x) << "trial " << trial;
        EXPECT_EQ(got.y, want.y) << "trial " << trial;
        EXPECT_EQ(got.width, want.width);
        EXPECT_EQ(got.height, want.height);
    }
}

// placeCaption through the grid of its candidates' edges (cover_grid.h) finds the plain loops'
// spot on screens made to trip it: edges anywhere (not quarters: the sums' last bits differ with
// their order), blocks on a lattice (many candidates covering the same, to the last bit or
// nearly), a badge across the top and the axis numbers' bands (sums equal along a row), texts
// few (candidates beside each) and many, plates wider than the scene, and free spots.
TEST(PlaceCaption, SpotIsThatOfThePlainSearchOnTrickyScreens) {
    std::mt19937 random(23);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hidesNone = 0, hidesSome = 0;
    for (int trial = 0; trial < 160; ++trial) {
        const ScreenRect scene{static_cast<double>(random() % 300), 0.0,
                               400.0 + static_cast<double>(random() % 1500),
                               300.0 + static_cast<double>(random() % 800)};
        const ScreenRect world{scene.x + 30.0 + unit(random) * 60.0, 50.0 + unit(random) * 20.0,
                               scene.width - 100.0 - unit(random) * 40.0,
                               scene.height - 120.0 - unit(random) * 30.0};
        std::vector<ScreenRect> avoid = {
            {scene.x, scene.y, scene.width, 37.5},
            {world.x - 15.0, world.y + world.height, world.width + 60.0, 24.0},
            {world.x - 60.0, world.y - 15.0, 60.0, world.height + 30.0}};
        const int kind = trial % 4;
        const int blocks = kind == 3 ? 40 + static_cast<int>(random() % 40)
                                     : 100 + static_cast<int>(random() % 1200);
        const double side = 8.0 + unit(random) * 30.0;
        for (int i = 0; i < blocks; ++i) {
            if (kind == 0) { // a lattice of equal blocks, whole pixels
                const int across = 1 + static_cast<int>(world.width / (side * 1.5));
                avoid.push_back({std::round(world.x) + (i % across) * std::round(side * 1.5),
                                 std::round(world.y) + (i / across) * std::round(side * 1.5),
                                 std::round(side), std::round(side)});
            } else { // anywhere in the world, any size
                avoid.push_back({world.x + unit(random) * world.width,
                                 world.y + unit(random) * world.height, 2.0 + unit(random) * side,
                                 2.0 + unit(random) * side});
            }
        }
        std::vector<ScreenRect> texts;
        const int labels =
            trial % 3 == 0 ? static_cast<int>(random() % 30) : static_cast<int>(random() % 200);
        for (int i = 0; i < labels; ++i)
            texts.push_back({scene.x + unit(random) * scene.width,
                             scene.y + unit(random) * scene.height, 20.0 + unit(random) * 120.0,
                             kind == 1 ? 13.0 : 13.0 + unit(random)});
        const double inset = trial % 5 == 0 ? 15.0 : 10.0;
        const double width = trial % 17 == 0 ? scene.width + 5.0 : 40.0 + unit(random) * 500.0;
        const double height =
            trial % 7 == 0 ? 20.0 + std::round(unit(random) * 100.0) : 20.0 + unit(random) * 300.0;
        const ScreenRect want =
            before::placeCaption(width, height, scene, world, avoid, inset, texts);
        const ScreenRect got = placeCaption(width, height, scene, world, avoid, inset, texts);
        EXPECT_EQ(got.x, want.x) << "trial " << trial;
        EXPECT_EQ(got.y, want.y) << "trial " << trial;
        EXPECT_EQ(got.width, want.width) << "trial " << trial;
        EXPECT_EQ(got.height, want.height) << "trial " << trial;
        bool hides = false;
        for (const ScreenRect& t : texts) hides = hides || rectsOverlap(want, t);
        (hides ? hidesSome : hidesNone) += 1;
    }
    EXPECT_GT(hidesSome, 20); // both kinds of spot were searched for
    EXPECT_GT(hidesNone, 20);
}

} // namespace
