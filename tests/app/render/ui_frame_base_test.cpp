// The plan of a frame's first paint (no GL): which colour the frame's clear paints (the scene's
// background, its arena, or windows' backgrounds), and the others painted where they are seen.
// Every pixel must end as it would have: the plan never skips a fill where anything was drawn
// before it.
#include "ui_frame_base.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace {

constexpr ImU32 kWindow = 0xFF241D1Bu, kTitle = 0xFF7A4A29u;

long long rectArea(const UiPixelRect& r) {
    return static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
}

// How many of `rects` hold the pixel whose top-left corner is (x, y).
int coverage(const std::vector<UiPixelRect>& rects, int x, int y) {
    int n = 0;
    for (const UiPixelRect& r : rects) n += r.x0 <= x && x < r.x1 && r.y0 <= y && y < r.y1;
    return n;
}

UiPaint fill(UiPixelRect inside, ImU32 color) {
    return {{inside.x0 - 1, inside.y0 - 1, inside.x1 + 1, inside.y1 + 1}, inside, color};
}

UiPaint draw(UiPixelRect bounds) {
    return {bounds, {}, 0};
}

} // namespace

TEST(RectsOutside, TilesExactlyThePixelsOutsideTheHoles) {
    const std::vector<UiPixelRect> holes{{0, 10, 30, 80}, {70, 0, 100, 60}, {20, 50, 50, 70}};
    const std::vector<UiPixelRect> rest = rectsOutside(holes, 100, 80);
    for (int y = 0; y < 80; ++y) {
        for (int x = 0; x < 100; ++x) {
            const bool inHole = coverage(holes, x, y) > 0;
            ASSERT_EQ(coverage(rest, x, y), inHole ? 0 : 1) << "pixel " << x << "," << y;
        }
    }
}

TEST(RectsOutside, MergesBandsAndClipsHolesToTheFrame) {
    // A hole down the left side (reaching past the frame) leaves one rectangle on the right.
    const std::vector<UiPixelRect> rest = rectsOutside({{-5, -5, 40, 200}}, 100, 80);
    ASSERT_EQ(rest.size(), 1u);
    EXPECT_EQ(rest[0].x0, 40);
    EXPECT_EQ(rest[0].y0, 0);
    EXPECT_EQ(rest[0].x1, 100);
    EXPECT_EQ(rest[0].y1, 80);
    EXPECT_EQ(rectsOutside({}, 100, 80).size(), 1u);
    EXPECT_TRUE(rectsOutside({{0, 0, 100, 80}}, 100, 80).empty());
}

TEST(FrameBase, DockedWindowsComeFromTheClearAndTheRestIsPainted) {
    // A 1000 x 600 frame: panels left and right (background, title bar), the scene between.
    const std::vector<UiPaint> paints{draw({400, 100, 600, 120}), // a label over the scene
                                      fill({0, 20, 300, 600}, kWindow),
                                      fill({0, 0, 300, 20}, kTitle),
                                      draw({10, 30, 290, 500}), // the panel's text
                                      fill({700, 20, 1000, 600}, kWindow),
                                      fill({700, 0, 1000, 20}, kTitle)};
    const UiFrameBase plan = planFrameBase(paints, {320, 50, 680, 550}, {}, 1000, 600);
    ASSERT_TRUE(plan.planned);
    EXPECT_EQ(plan.clear, kWindow);
    ASSERT_EQ(plan.skip.size(), paints.size());
    EXPECT_FALSE(plan.skip[0]);
    EXPECT_TRUE(plan.skip[1]);
    EXPECT_FALSE(plan.skip[2]); // another colour: cleared as ever
    EXPECT_TRUE(plan.skip[4]);
    // The background is painted exactly outside the fills.
    long long painted = 0;
    for (const UiPixelRect& r : plan.background) painted += rectArea(r);
    EXPECT_EQ(painted, 400LL * 600);
    EXPECT_EQ(coverage(plan.background, 500, 300), 1);
    EXPECT_EQ(coverage(plan.background, 100, 300), 0);
    EXPECT_EQ(coverage(plan.background, 100, 5), 0);
}

TEST(FrameBase, NeverSkipsAFillWhereSomethingWasDrawnBefore) {
    const std::vector<UiPaint> paints{
        draw({250, 100, 320, 120}), // a label reaching under the left panel
        fill({0, 0, 300, 600}, kWindow), fill({600, 0, 1000, 600}, kWindow),
        fill({750, 100, 950, 300}, kWindow)}; // a window over the right panel
    const UiFrameBase plan = planFrameBase(paints, {320, 50, 590, 550}, {}, 1000, 600);
    ASSERT_TRUE(plan.planned);
    EXPECT_FALSE(plan.skip[1]); // under the label
    EXPECT_TRUE(plan.skip[2]);
    EXPECT_FALSE(plan.skip[3]); // over a fill drawn before it
    // The scene reaching under the right panel: nothing left clean to skip.
    const UiFrameBase underScene = planFrameBase(paints, {320, 50, 720, 550}, {}, 1000, 600);
    EXPECT_FALSE(underScene.planned);
}

TEST(FrameBase, NoPlanWhenTheRestWouldCostMore) {
    // One narrow panel: painting the scene's background over the rest costs more than its fill.
    const std::vector<UiPaint> paints{fill({0, 0, 300, 600}, kWindow)};
    const UiFrameBase plan = planFrameBase(paints, {320, 50, 980, 550}, {}, 1000, 600);
    EXPECT_FALSE(plan.planned);
    EXPECT_TRUE(plan.background.empty());
    EXPECT_TRUE(plan.arena.empty());
}

TEST(FrameBase, TheArenaTakesTheClearWhenItCoversMost) {
    // The default view: a panel on the left, the arena filling most of the rest. The arena
    // comes from the clear, the band around it is painted the background, the panel its own.
    const std::vector<UiPaint> paints{fill({0, 0, 300, 600}, kWindow), draw({320, 0, 400, 40})};
    const UiFrameBase plan =
        planFrameBase(paints, {320, 50, 980, 550}, {330, 50, 980, 550}, 1000, 600);
    ASSERT_TRUE(plan.planned);
    EXPECT_EQ(plan.clearTo, UiFrameClear::Arena);
    EXPECT_FALSE(plan.skip[0]);
    EXPECT_TRUE(plan.arena.empty());
    long long painted = 0;
    for (const UiPixelRect& r : plan.background) painted += rectArea(r);
    EXPECT_EQ(painted, 700LL * 600 - 650LL * 500);
    EXPECT_EQ(coverage(plan.background, 305, 300), 1);
    EXPECT_EQ(coverage(plan.background, 990, 560), 1);
    EXPECT_EQ(coverage(plan.background, 500, 300), 0);
    EXPECT_EQ(coverage(plan.background, 100, 300), 0);
}

TEST(FrameBase, WindowsTakeTheClearAndTheArenaIsPaintedWhereItIsSeen) {
    // Wide panels and a small arena: the panels come from the clear; the arena is painted but
    // where a window lies over it (that window clears its own pixels).
    const std::vector<UiPaint> paints{fill({0, 0, 600, 600}, kWindow),
                                      fill({800, 100, 900, 200}, kWindow)}; // over the arena
    const UiFrameBase plan =
        planFrameBase(paints, {650, 50, 950, 550}, {650, 50, 950, 550}, 1000, 600);
    ASSERT_TRUE(plan.planned);
    EXPECT_EQ(plan.clearTo, UiFrameClear::Fills);
    EXPECT_EQ(plan.clear, kWindow);
    EXPECT_TRUE(plan.skip[0]);
    EXPECT_FALSE(plan.skip[1]); // over the scene
    long long arena = 0;
    for (const UiPixelRect& r : plan.arena) arena += rectArea(r);
    EXPECT_EQ(arena, 300LL * 500 - 100 * 100);
    EXPECT_EQ(coverage(plan.arena, 700, 300), 1);
    EXPECT_EQ(coverage(plan.arena, 850, 150), 0);
    EXPECT_EQ(coverage(plan.background, 620, 300), 1);
    EXPECT_EQ(coverage(plan.background, 700, 300), 0);
}

TEST(FrameBase, TheBackgroundKeepsTheClearWhenItCoversMost) {
    // A small arena, a small window over it: the clear stays the background's; the arena is
    // painted but under the window.
    const std::vector<UiPaint> paints{fill({700, 100, 800, 200}, kWindow)};
    const UiFrameBase plan =
        planFrameBase(paints, {300, 0, 1000, 300}, {300, 0, 1000, 300}, 1000, 600);
    ASSERT_TRUE(plan.planned);
    EXPECT_EQ(plan.clearTo, UiFrameClear::Background);
    EXPECT_FALSE(plan.skip[0]);
    EXPECT_TRUE(plan.background.empty());
    long long arena = 0;
    for (const UiPixelRect& r : plan.arena) arena += rectArea(r);
    EXPECT_EQ(arena, 700LL * 300 - 100 * 100);
    // An arena past the frame's edges is painted within it.
    const UiFrameBase past = planFrameBase({}, {}, {-50, -50, 300, 100}, 1000, 600);
    ASSERT_TRUE(past.planned);
    ASSERT_EQ(past.arena.size(), 1u);
    EXPECT_EQ(past.arena[0].x0, 0);
    EXPECT_EQ(past.arena[0].y0, 0);
    EXPECT_EQ(past.arena[0].x1, 300);
    EXPECT_EQ(past.arena[0].y1, 100);
}

TEST(FrameBase, NothingToPlanOnAnEmptyFrame) {
    EXPECT_FALSE(planFrameBase({}, {}, {}, 1000, 600).planned);
    EXPECT_FALSE(planFrameBase({fill({0, 0, 900, 600}, kWindow)}, {}, {}, 0, 0).planned);
    EXPECT_FALSE(planFrameBase({}, {}, {1100, 0, 1200, 600}, 1000, 600).planned); // off screen
}

namespace {

// A small framebuffer of colour numbers for painting a frame both ways. An opaque fill sets its
// pixels to its colour's number; anything else stands for blended drawing: each pixel it touches
// becomes a mix of what was there and the draw, so whatever lay under it shows in the result.
struct Canvas {
    int width, height;
    std::vector<std::uint64_t> pixels;
    Canvas(int w, int h, std::uint64_t clear)
        : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, clear) {}
    void paint(const UiPixelRect& r, std::uint64_t value, bool blend,
               const UiPixelRect& except = {}) {
        for (int y = std::max(0, r.y0); y < std::min(height, r.y1); ++y) {
            for (int x = std::max(0, r.x0); x < std::min(width, r.x1); ++x) {
                if (except.x0 <= x && x < except.x1 && except.y0 <= y && y < except.y1) continue;
                std::uint64_t& p = pixels[static_cast<std::size_t>(y) * width + x];
                p = blend ? p * 1000003u + value : value;
            }
        }
    }
};

constexpr std::uint64_t kBackground = 1, kArena = 2;

// The frame as drawn: the scene's background, its arena, what it draws, then every paint (a fill's
// sure pixels cleared to its colour, its triangles drawn around them).
Canvas drawnAsBefore(int w, int h, const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                     UiPixelRect sceneCovered) {
    Canvas c(w, h, kBackground);
    c.paint(sceneCovered, kArena, false);
    c.paint(sceneDrawn, 7, true);
    for (std::size_t i = 0; i < paints.size(); ++i) {
        if (!paints[i].inside.empty()) c.paint(paints[i].inside, paints[i].color, false);
        c.paint(paints[i].bounds, 100 + i, true, paints[i].inside);
    }
    return c;
}

// The same frame as planned: the clear, the background and the arena where planned (all the
// arena when not), the scene, then the paints without the clears the plan skips.
Canvas drawnAsPlanned(int w, int h, const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                      UiPixelRect sceneCovered, const UiFrameBase& plan) {
    Canvas c(w, h,
             !plan.planned || plan.clearTo == UiFrameClear::Background ? kBackground
             : plan.clearTo == UiFrameClear::Arena                     ? kArena
                                                                       : plan.clear);
    for (const UiPixelRect& r : plan.background) c.paint(r, kBackground, false);
    for (const UiPixelRect& r : plan.arena) c.paint(r, kArena, false);
    if (!plan.planned) c.paint(sceneCovered, kArena, false);
    c.paint(sceneDrawn, 7, true);
    for (std::size_t i = 0; i < paints.size(); ++i) {
        if (!paints[i].inside.empty() && !plan.skip[i])
            c.paint(paints[i].inside, paints[i].color, false);
        c.paint(paints[i].bounds, 100 + i, true, paints[i].inside);
    }
    return c;
}

bool holds(const UiPixelRect& r, int x, int y) {
    return r.x0 <= x && x < r.x1 && r.y0 <= y && y < r.y1;
}

// Counted pixel by pixel, with no help from the plan: the pixels the frame's clear saves from
// being painted (those painted when everything is, less those the plan paints), and the largest
// of the three colours' shares it could have saved: the background's (outside every fill and the
// arena), the arena's (outside every fill), and one colour's fills that nothing (the scene, the
// arena, an earlier paint) touched before them.
struct Shares {
    long long saved = 0, largest = 0;
};

Shares sharesOf(int w, int h, const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                UiPixelRect arena, const UiFrameBase& plan) {
    Shares s;
    long long background = 0, arenaSeen = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool inFill = false;
            for (std::size_t i = 0; i < paints.size(); ++i) {
                const bool in = holds(paints[i].inside, x, y);
                inFill = inFill || in;
                s.saved += in && plan.skip[i]; // a fill painted as ever unless skipped
            }
            s.saved += !inFill && !holds(arena, x, y) ? 1 : 0; // the background's
            s.saved += !inFill && holds(arena, x, y) ? 1 : 0;  // the arena's
            s.saved -= coverage(plan.background, x, y) + coverage(plan.arena, x, y) +
                       (!plan.planned && holds(arena, x, y));
            background += !inFill && !holds(arena, x, y);
            arenaSeen += !inFill && holds(arena, x, y);
        }
    }
    s.largest = std::max(background, arenaSeen);
    // Clean fills (only the frame's pixels count).
    std::vector<bool> touched(static_cast<std::size_t>(w) * h, false);
    const auto mark = [&](const UiPixelRect& r, bool* wasTouched) {
        for (int y = std::max(0, r.y0); y < std::min(h, r.y1); ++y) {
            for (int x = std::max(0, r.x0); x < std::min(w, r.x1); ++x) {
                const std::size_t k = static_cast<std::size_t>(y) * w + x;
                if (wasTouched)
                    *wasTouched = *wasTouched || touched[k];
                else
                    touched[k] = true;
            }
        }
    };
    mark(sceneDrawn, nullptr);
    mark(arena, nullptr);
    std::vector<std::pair<ImU32, long long>> clean;
    for (const UiPaint& p : paints) {
        bool wasTouched = false;
        mark(p.inside, &wasTouched);
        long long n = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) n += holds(p.inside, x, y);
        if (n > 0 && !wasTouched) clean.push_back({p.color, n});
        mark(p.bounds, nullptr);
        mark(p.inside, nullptr);
    }
    for (const auto& [color, n] : clean) {
        long long sum = 0;
        for (const auto& [other, m] : clean) sum += other == color ? m : 0;
        s.largest = std::max(s.largest, sum);
    }
    return s;
}

} // namespace

// Thousands of random frames (windows, labels, fills over fills, the scene and its arena
// anywhere, boxes past the edges), each painted as before (everything) and as planned: every
// pixel ends the same. Exact: pixels are compared as colour numbers, each blended draw leaves its
// own mark. And the clear saves the most it can: the largest share, counted pixel by pixel.
TEST(FrameBase, RandomFramesEndPixelForPixelAsBefore) {
    std::mt19937 random(42);
    const auto roll = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
    int planned = 0, clearTo[3] = {0, 0, 0};
    for (int trial = 0; trial < 6000; ++trial) {
        const int w = 8 + roll(24), h = 6 + roll(18);
        const auto box = [&] {
            const int x0 = roll(w + 4) - 2, y0 = roll(h + 4) - 2;
            const bool big = roll(2) == 0; // windows, or labels and frames
            return UiPixelRect{x0, y0, x0 + (big ? w / 2 + roll(w) : roll(w / 2 + 1)),
                               y0 + (big ? h / 2 + roll(h) : roll(h / 2 + 1))};
        };
        std::vector<UiPaint> paints(static_cast<std::size_t>(1 + roll(10)));
        for (UiPaint& p : paints) {
            p.bounds = box();
            if (roll(3) > 0) { // a fill: its sure pixels inside its triangles' bounds
                p.inside = {p.bounds.x0 + roll(2), p.bounds.y0 + roll(2), p.bounds.x1 - roll(2),
                            p.bounds.y1 - roll(2)};
                p.color = 10 + static_cast<ImU32>(roll(3));
            }
        }
        const UiPixelRect sceneDrawn = roll(4) == 0 ? UiPixelRect{} : box();
        // No arena, one anywhere, or one over most of the frame (the default view).
        const int arenaKind = roll(3);
        const UiPixelRect sceneCovered =
            arenaKind == 0   ? UiPixelRect{}
            : arenaKind == 1 ? box()
                             : UiPixelRect{roll(w / 3) - 1, roll(h / 3) - 1, w + 1 - roll(w / 3),
                                           h + 1 - roll(h / 3)};
        const UiFrameBase plan = planFrameBase(paints, sceneDrawn, sceneCovered, w, h);
        ASSERT_EQ(plan.skip.size(), paints.size());
        ASSERT_EQ(drawnAsBefore(w, h, paints, sceneDrawn, sceneCovered).pixels,
                  drawnAsPlanned(w, h, paints, sceneDrawn, sceneCovered, plan).pixels)
            << "trial " << trial;
        const Shares shares = sharesOf(w, h, paints, sceneDrawn, sceneCovered, plan);
        ASSERT_EQ(shares.saved, shares.largest) << "trial " << trial;
        ++clearTo[static_cast<int>(plan.clearTo)];
        planned += plan.planned;
    }
    EXPECT_GT(planned, 100); // the planned frames were tried, not only the unplanned
    for (const int n : clearTo) EXPECT_GT(n, 100); // each colour took the clear in some
}
