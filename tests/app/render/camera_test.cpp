#include "camera.h"
#include "shape_batch.h"

#include <gtest/gtest.h>

namespace {

Camera makeCamera() {
    Camera c;
    c.setViewport({100.0, 0.0, 800.0, 600.0});
    c.setCentre({10.0, 6.0});
    c.setPixelsPerMetre(40.0);
    return c;
}

TEST(Camera, CentreOfWorldMapsToCentreOfViewport) {
    const Camera c = makeCamera();
    const Vec2 s = c.worldToScreen({10.0, 6.0});
    EXPECT_DOUBLE_EQ(s.x, 500.0);
    EXPECT_DOUBLE_EQ(s.y, 300.0);
}

TEST(Camera, YPointsUpInTheWorldAndDownOnScreen) {
    const Camera c = makeCamera();
    const Vec2 up = c.worldToScreen({10.0, 7.0});
    EXPECT_DOUBLE_EQ(up.y, 260.0);
    const Vec2 right = c.worldToScreen({11.0, 6.0});
    EXPECT_DOUBLE_EQ(right.x, 540.0);
}

TEST(Camera, ScreenToWorldInvertsWorldToScreen) {
    const Camera c = makeCamera();
    for (Vec2 p : {Vec2{0, 0}, Vec2{3.5, -2.25}, Vec2{19.75, 11.5}}) {
        EXPECT_TRUE(approxEqual(c.screenToWorld(c.worldToScreen(p)), p, 1e-12));
    }
}

TEST(Camera, FitShowsTheWholeBoundsCentred) {
    Camera c;
    c.setViewport({0.0, 0.0, 1000.0, 500.0});
    Bounds b;
    b.min = {0.0, 0.0};
    b.max = {20.0, 12.0};
    c.fit(b, 10.0);
    // Height limits: (500 - 20) / 12 = 40 px/m.
    EXPECT_DOUBLE_EQ(c.pixelsPerMetre(), 40.0);
    const Vec2 lo = c.worldToScreen(b.min);
    const Vec2 hi = c.worldToScreen(b.max);
    EXPECT_GE(lo.x, 0.0);
    EXPECT_LE(hi.x, 1000.0);
    EXPECT_DOUBLE_EQ(lo.y, 490.0);
    EXPECT_DOUBLE_EQ(hi.y, 10.0);
}

TEST(Camera, ZoomKeepsThePointUnderTheCursor) {
    Camera c = makeCamera();
    const Vec2 cursor{250.0, 420.0};
    const Vec2 before = c.screenToWorld(cursor);
    c.zoomAbout(cursor, 1.7);
    EXPECT_DOUBLE_EQ(c.pixelsPerMetre(), 68.0);
    EXPECT_TRUE(approxEqual(c.screenToWorld(cursor), before, 1e-12));
}

TEST(Camera, ZoomIsClampedAndIgnoresBadFactors) {
    Camera c = makeCamera();
    c.zoomAbout({0, 0}, 1e9);
    EXPECT_DOUBLE_EQ(c.pixelsPerMetre(), Camera::kMaxPixelsPerMetre);
    c.zoomAbout({0, 0}, 0.0);
    c.zoomAbout({0, 0}, -2.0);
    EXPECT_DOUBLE_EQ(c.pixelsPerMetre(), Camera::kMaxPixelsPerMetre);
    c.setPixelsPerMetre(std::nan(""));
    EXPECT_DOUBLE_EQ(c.pixelsPerMetre(), Camera::kMaxPixelsPerMetre);
}

TEST(Camera, PanMovesTheWorldWithTheCursor) {
    Camera c = makeCamera();
    const Vec2 grabbed = c.screenToWorld({300.0, 200.0});
    c.panPixels({40.0, -80.0});
    EXPECT_TRUE(approxEqual(c.worldToScreen(grabbed), Vec2{340.0, 120.0}, 1e-9));
}

TEST(Camera, ClipTransformAgreesWithScreenMapping) {
    const Camera c = makeCamera();
    const double w = 1000.0, h = 600.0;
    const ClipTransform t = c.clipTransform(w, h);
    for (Vec2 p : {Vec2{0, 0}, Vec2{10, 6}, Vec2{17.5, 2.5}}) {
        const Vec2 s = c.worldToScreen(p);
        EXPECT_NEAR(p.x * t.scaleX + t.offsetX, s.x / w * 2.0 - 1.0, 1e-5);
        EXPECT_NEAR(p.y * t.scaleY + t.offsetY, 1.0 - s.y / h * 2.0, 1e-5);
    }
}

TEST(Camera, GridSpacingGrowsWhenZoomedOut) {
    EXPECT_DOUBLE_EQ(gridSpacing(50.0, 12.0), 1.0);
    EXPECT_DOUBLE_EQ(gridSpacing(10.0, 12.0), 2.0);
    EXPECT_DOUBLE_EQ(gridSpacing(4.0, 12.0), 5.0);
    EXPECT_DOUBLE_EQ(gridSpacing(1.0, 12.0), 20.0);
}

} // namespace

TEST(ShapeBatch, LineArrowIsOneSegmentAndAHeadTriangle) {
    ShapeBatch batch;
    const Color c{1.0f, 0.5f, 0.25f, 1.0f};
    batch.lineArrow({0, 0}, {10, 0}, 2.0, c);
    // The shaft: one GL line from the tail to the head's base, 2 m before the tip.
    ASSERT_EQ(batch.segmentVertices().size(), 2u);
    EXPECT_EQ(batch.segmentVertices()[0].x, 0.0f);
    EXPECT_EQ(batch.segmentVertices()[1].x, 8.0f);
    // The head: one triangle, its tip at the arrow's end, its base 2 * 0.55 m wide.
    ASSERT_EQ(batch.vertices().size(), 3u);
    EXPECT_EQ(batch.vertices()[0].x, 10.0f);
    EXPECT_FLOAT_EQ(batch.vertices()[1].y - batch.vertices()[2].y, 2.2f);
    // Too short to see (under 5% of the head): nothing at all.
    batch.clear();
    batch.lineArrow({0, 0}, {0.05, 0}, 2.0, c);
    EXPECT_TRUE(batch.vertices().empty());
    EXPECT_TRUE(batch.segmentVertices().empty());
}

TEST(ShapeBatch, SmallSquareishBlocksInsideTheViewAreDrawnAsPoints) {
    const ScreenRect screen{0.0, 0.0, 1280.0, 720.0};
    EXPECT_TRUE(drawsAsPointSprite(12.0, 12.0, {640.0, 360.0}, screen, 64.0));
    EXPECT_TRUE(drawsAsPointSprite(20.0, 10.0, {640.0, 360.0}, screen, 64.0));  // 2:1 is fine
    EXPECT_FALSE(drawsAsPointSprite(40.0, 4.0, {640.0, 360.0}, screen, 64.0));  // a thin bar
    EXPECT_FALSE(drawsAsPointSprite(63.0, 63.0, {640.0, 360.0}, screen, 64.0)); // too big
    EXPECT_FALSE(drawsAsPointSprite(12.0, 12.0, {640.0, 360.0}, screen, 1.0));  // no big points
    // Near an edge (within half the side and 2 px): a quad, so it is clipped, not dropped.
    EXPECT_TRUE(drawsAsPointSprite(12.0, 12.0, {8.0, 360.0}, screen, 64.0));
    EXPECT_FALSE(drawsAsPointSprite(12.0, 12.0, {7.9, 360.0}, screen, 64.0));
    EXPECT_FALSE(drawsAsPointSprite(12.0, 12.0, {640.0, 715.0}, screen, 64.0));
}
