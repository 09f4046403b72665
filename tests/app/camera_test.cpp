#include "camera.h"

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
