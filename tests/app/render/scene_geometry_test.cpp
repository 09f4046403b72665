// The scene renderer's geometry rules (no GL): what a crowded scene costs a software rasteriser
// is bounded (trail length and segments, headless momentum arrows, point sprites), and a small
// scene keeps every detail.
#include "scene_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

// A gas of `columns` x `rows` blocks of 0.2 m in the default 20 m x 12 m world; its velocities
// point in a fixed pattern of directions at 2 m/s.
World gas(int columns, int rows) {
    World w;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            Block b;
            b.position = {0.5 + 0.48 * c, 0.5 + 0.44 * r};
            b.size = {0.2, 0.2};
            b.mass = 1.0;
            const double angle = 0.7 * (r * columns + c);
            b.velocity = {2.0 * std::cos(angle), 2.0 * std::sin(angle)};
            w.blocks.push_back(b);
        }
    }
    return w;
}

struct Fixture {
    World world;
    Camera camera;
    Trails trails;
    SceneView view;

    explicit Fixture(World w) : world(std::move(w)) {
        camera.setViewport({0.0, 0.0, 1280.0, 720.0});
        camera.fit(world.bounds, 20.0);
        // 1.5 s of trail: each block circles 0.2 m around its place at 2 m/s (10 rad/s), and
        // ends where it started.
        std::vector<Vec2> home;
        for (const Block& b : world.blocks) home.push_back(b.position);
        for (int frame = 90; frame >= 0; --frame) {
            const double angle = 10.0 * frame / 60.0;
            for (std::size_t i = 0; i < home.size(); ++i)
                world.blocks[i].position =
                    home[i] + Vec2{0.2 * std::sin(angle), 0.2 * (1.0 - std::cos(angle))};
            trails.record(world);
        }
        view.world = &world;
        view.camera = &camera;
        view.trails = &trails;
        view.vectors = true;
    }
};

double segmentPixels(const ShapeBatch& batch, const Camera& camera) {
    double total = 0.0;
    const auto& v = batch.segmentVertices();
    for (std::size_t k = 0; k + 1 < v.size(); k += 2) {
        total += std::hypot(v[k + 1].x - v[k].x, v[k + 1].y - v[k].y);
    }
    return total * camera.pixelsPerMetre();
}

TEST(SceneGeometry, ACrowdedSceneStaysWithinItsBudgets) {
    Fixture f(gas(40, 25)); // 1,000 blocks
    SceneGeometry g;
    g.build(f.view, 64.0);
    // Trails: at most the pixel budget (the chords of a circle are shorter than its arcs, which
    // the budget counts), and the segment budget plus at most one per block (rounding of the
    // stride).
    EXPECT_GT(g.under.segmentVertices().size(), 0u);
    EXPECT_LE(segmentPixels(g.under, f.camera), kTrailPixelBudget);
    EXPECT_GT(segmentPixels(g.under, f.camera), 0.5 * kTrailPixelBudget); // cut, not dropped
    EXPECT_LE(g.under.segmentVertices().size() / 2, std::size_t(kTrailSegmentBudget) + 1000);
    // Momentum arrows: shafts only; velocity arrows: a shaft and a head each.
    EXPECT_TRUE(g.momenta.vertices().empty());
    EXPECT_EQ(g.momenta.segmentVertices().size(), 2u * 1000);
    EXPECT_EQ(g.over.segmentVertices().size(), 2u * 1000);
    EXPECT_EQ(g.over.vertices().size(), 3u * 1000);
    // Every block is small and inside the view: all points; the four walls are quads.
    EXPECT_EQ(g.blocks[kPlain][kPoint].size(), 1000u);
    EXPECT_TRUE(g.blocks[kPlain][kQuad].empty());
    EXPECT_EQ(g.blocks[kPatterned][kQuad].size(), 4u);
    // Without point sprites (a driver that has none), the same blocks are quads.
    g.build(f.view, 1.0);
    EXPECT_EQ(g.blocks[kPlain][kQuad].size(), 1000u);
}

TEST(SceneGeometry, ASmallSceneKeepsWholeTrailsAndArrowHeads) {
    Fixture f(gas(4, 2)); // 8 blocks
    SceneGeometry g;
    g.build(f.view, 64.0);
    // Every stored point of every trail (one every other frame: 46 points, 45 segments each),
    // momentum arrows with heads.
    ASSERT_EQ(f.trails.length(), 46);
    EXPECT_EQ(g.under.segmentVertices().size(), 2u * 8 * 45);
    EXPECT_EQ(g.momenta.vertices().size(), 3u * 8);
    // The trail fades from 0.75 at the block to 0.75 / 46 at its oldest point.
    EXPECT_FLOAT_EQ(g.under.segmentVertices().front().a, 0.75f);
    EXPECT_FLOAT_EQ(g.under.segmentVertices()[2 * 45 - 1].a, 0.75f / 46.0f);
}

// The box the scene draws in (the frame's base is planned around it): it holds every block,
// sprite margin included, every arrow and trail with its line's width, and nothing far beyond.
TEST(SceneGeometry, TheDrawnBoxHoldsEverythingDrawn) {
    Fixture f(gas(4, 2));
    SceneGeometry g;
    g.build(f.view, 64.0);
    const ClipTransform t = f.camera.clipTransform(1280.0, 720.0);
    const PixelBox box = drawnBox(g, t, 1280, 720, 7.0, 2.0);
    ASSERT_FALSE(box.empty());
    // The walls (quads just outside the 20 m x 12 m bounds) are drawn: their pixels are inside.
    const Vec2 lo = f.camera.worldToScreen(f.world.bounds.min);
    const Vec2 hi = f.camera.worldToScreen(f.world.bounds.max);
    const double wall = 10.0; // px, scene_geometry.cpp
    EXPECT_LE(box.x0, std::min(lo.x, hi.x) - wall);
    EXPECT_GE(box.x1, std::max(lo.x, hi.x) + wall);
    EXPECT_LE(box.y0, std::min(lo.y, hi.y) - wall);
    EXPECT_GE(box.y1, std::max(lo.y, hi.y) + wall);
    // ...and not much more: the margin asked for, a pixel for rounding.
    EXPECT_GE(box.x0, std::min(lo.x, hi.x) - wall - 4.0);
    EXPECT_LE(box.y1, std::max(lo.y, hi.y) + wall + 4.0);
    // A block far outside the walls, drawn as a quad, widens it; one beyond the frame is cut.
    g.blocks[kPlain][kQuad].push_back({{30.0f, 6.0f, 0.5f, 0.5f}, {}, {}, {1.5f, 0.0f}});
    const PixelBox wider = drawnBox(g, t, 1280, 720, 7.0, 2.0);
    const Vec2 far = f.camera.worldToScreen({30.5, 6.0});
    EXPECT_GE(wider.x1, std::min(1280.0, far.x));
    EXPECT_LE(wider.x1, 1280);
    // A trail segment's line width counts on every side.
    SceneGeometry lines;
    lines.under.segment({10.0, 6.0}, {10.0, 6.0}, Color{});
    const PixelBox dot = drawnBox(lines, t, 1280, 720, 7.0, 0.0);
    const Vec2 c = f.camera.worldToScreen({10.0, 6.0});
    EXPECT_LE(dot.x0, c.x - 3.5);
    EXPECT_GE(dot.x1, c.x + 3.5);
    EXPECT_LE(dot.x1 - dot.x0, 9);
    // Nothing drawn: an empty box.
    EXPECT_TRUE(drawnBox(SceneGeometry{}, t, 1280, 720, 7.0, 2.0).empty());
}

// arrowOnScreen as it was before ArrowsOnScreen worked out the camera's part once a frame.
ArrowOnScreen plainArrowOnScreen(const Camera& camera, Vec2 from, Vec2 vector,
                                 const Bounds* arena) {
    ArrowOnScreen a;
    const double ppm = camera.pixelsPerMetre();
    const double lengthPx = length(vector) * ppm;
    if (!(lengthPx > 0.0) || !std::isfinite(lengthPx)) {
        a.tip = from;
        return a;
    }
    const ScreenRect& vp = camera.viewport();
    const double knee = kArrowKneeShare * std::min(vp.width, vp.height);
    double shown = displayedArrowPx(lengthPx, knee);
    const Vec2 s = camera.worldToScreen(from);
    const Vec2 dir{vector.x / length(vector), -vector.y / length(vector)};
    double limits[2][2] = {{vp.x, vp.x + vp.width}, {vp.y, vp.y + vp.height}};
    if (arena) {
        const Vec2 a = camera.worldToScreen(arena->min), b = camera.worldToScreen(arena->max);
        const double box[2][2] = {{std::min(a.x, b.x), std::max(a.x, b.x)},
                                  {std::min(a.y, b.y), std::max(a.y, b.y)}};
        for (int k = 0; k < 2; ++k) {
            limits[k][0] = std::max(limits[k][0], box[k][0]);
            limits[k][1] = std::min(limits[k][1], box[k][1]);
        }
    }
    const double start[2] = {s.x, s.y}, d[2] = {dir.x, dir.y};
    for (int k = 0; k < 2; ++k) {
        if (start[k] < limits[k][0] || start[k] > limits[k][1]) continue;
        if (d[k] > 1e-12) shown = std::min(shown, (limits[k][1] - 2.0 - start[k]) / d[k]);
        if (d[k] < -1e-12) shown = std::min(shown, (limits[k][0] + 2.0 - start[k]) / d[k]);
    }
    shown = std::max(0.0, shown);
    a.toScale = shown >= lengthPx - 1e-9;
    a.tip = from + vector * (shown / lengthPx);
    return a;
}

// The arrows of a frame through ArrowsOnScreen are those of the plain arrowOnScreen to the bit:
// short and long, cut by the view and by the arena, from inside and outside them, none and NaN.
TEST(SceneGeometry, ArrowsOfAFrameAreThoseOfThePlainArrow) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int cut = 0, toScale = 0;
    for (int trial = 0; trial < 40; ++trial) {
        Camera camera;
        camera.setViewport({unit(random) * 100.0, unit(random) * 50.0,
                            300.0 + unit(random) * 1600.0, 200.0 + unit(random) * 900.0});
        camera.fit({{0.0, 0.0}, {5.0 + unit(random) * 30.0, 3.0 + unit(random) * 20.0}}, 20.0);
        camera.setPixelsPerMetre(camera.pixelsPerMetre() * (0.5 + unit(random) * 2.0));
        const Bounds arena{{0.0, 0.0}, {10.0 + unit(random) * 20.0, 8.0 + unit(random) * 10.0}};
        const ArrowsOnScreen withArena(camera, &arena), without(camera);
        for (int i = 0; i < 200; ++i) {
            const Vec2 from{unit(random) * 40.0 - 5.0, unit(random) * 30.0 - 5.0};
            Vec2 vector{(unit(random) - 0.5) * 60.0, (unit(random) - 0.5) * 60.0};
            if (i % 50 == 0) vector = {};
            if (i % 50 == 1) vector = {NAN, 1.0};
            if (i % 7 == 0) vector = vector * 0.01;
            const ArrowOnScreen a = withArena(from, vector),
                                want = plainArrowOnScreen(camera, from, vector, &arena);
            const ArrowOnScreen b = without(from, vector),
                                alone = plainArrowOnScreen(camera, from, vector, nullptr);
            const auto same = [](double x, double y) { return x == y || (x != x && y != y); };
            EXPECT_TRUE(same(a.tip.x, want.tip.x) && same(a.tip.y, want.tip.y))
                << trial << " " << i;
            EXPECT_EQ(a.toScale, want.toScale) << trial << " " << i;
            EXPECT_TRUE(same(b.tip.x, alone.tip.x) && same(b.tip.y, alone.tip.y))
                << trial << " " << i;
            EXPECT_EQ(b.toScale, alone.toScale) << trial << " " << i;
            (want.toScale ? toScale : cut) += 1;
        }
    }
    EXPECT_GT(cut, 500); // both kinds were drawn
    EXPECT_GT(toScale, 500);
}

} // namespace
