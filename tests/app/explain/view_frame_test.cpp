// The centre-of-mass frame (view_frame.h) without GL: the lecture's numbers in lecture_example_1
// (u = 2, w1 = 4 and w2 = -2 before the collision, -4 and 2 after, as on the slide "Change your
// frame of reference!"), the arrows the scene renderer builds, the camera following the centre
// of mass, the --frame flag and the lesson key (its bad values: tests/lesson/lesson_test.cpp).
#include "app.h"
#include "lesson_session.h"
#include "options.h"
#include "scene_geometry.h"
#include "scene_library.h"
#include "view_frame.h"

#include <gtest/gtest.h>

#include <string>

namespace {

// The perfect method resolves at the exact instant of impact: only rounding differs.
constexpr double kExact = 1e-12;

App lectureExample() {
    App app;
    EXPECT_TRUE(loadScene(app, resolveScenePath("lecture_example_1", SANDBOX_SCENES_DIR)))
        << app.ui.messages.error;
    return app;
}

Vec2 seen(const App& app, int block) {
    return app.sim.world().blocks[static_cast<std::size_t>(block)].velocity -
           frameVelocity(app.sim.world(), app.view.frame);
}

std::string label(const App& app, int block) {
    return frameVelocityLabel(app.sim.labels[static_cast<std::size_t>(block)].name,
                              seen(app, block), app.view.frame);
}

void stepUntilCollision(App& app) {
    for (int i = 0; i < 120 && app.sim.run.totals.collisions == 0; ++i) stepSimulation(app);
    ASSERT_EQ(app.sim.run.totals.collisions, 1);
}

} // namespace

TEST(ViewFrame, LectureExampleOneReadsTheSlidesNumbers) {
    App app = lectureExample();
    setViewFrame(app.view, ViewFrame::CentreOfMass);
    // u = (1·6 + 2·0)/(1 + 2) = 2 m/s.
    EXPECT_NEAR(frameVelocity(app.sim.world(), app.view.frame).x, 2.0, kExact);
    EXPECT_NEAR(seen(app, 0).x, 4.0, kExact);
    EXPECT_NEAR(seen(app, 1).x, -2.0, kExact);
    EXPECT_EQ(label(app, 0), "w1 = 4 m/s");
    EXPECT_EQ(label(app, 1), "w2 = -2 m/s");
    stepUntilCollision(app);
    // w_i' = -C·w_i with C = 1; u unchanged (momentum kept).
    EXPECT_NEAR(frameVelocity(app.sim.world(), app.view.frame).x, 2.0, kExact);
    EXPECT_NEAR(seen(app, 0).x, -4.0, kExact);
    EXPECT_NEAR(seen(app, 1).x, 2.0, kExact);
    EXPECT_EQ(label(app, 0), "w1 = -4 m/s");
    EXPECT_EQ(label(app, 1), "w2 = 2 m/s");
    // The world's frame: the velocities themselves.
    setViewFrame(app.view, ViewFrame::World);
    EXPECT_EQ(label(app, 0), "v1 = -2 m/s");
    EXPECT_EQ(label(app, 1), "v2 = 4 m/s");
}

TEST(ViewFrame, LabelsNameTheSymbolAndTheVectorOffTheAxis) {
    EXPECT_EQ(frameVelocityLabel("A (2 kg)", {1.5, 0.0}, ViewFrame::CentreOfMass), "wA = 1.5 m/s");
    EXPECT_EQ(frameVelocityLabel("bullet", {1.0, 2.0}, ViewFrame::CentreOfMass), "w = (1, 2) m/s");
    EXPECT_EQ(frameVelocityLabel("", {0.0, -3.0}, ViewFrame::World), "v = (0, -3) m/s");
    // Rounding noise across the axis reads as motion along it.
    EXPECT_EQ(frameVelocityLabel("m1", {4.0, 1e-15}, ViewFrame::CentreOfMass), "w1 = 4 m/s");
}

TEST(ViewFrame, NoDynamicBlockMeansNoMotion) {
    World w;
    Block wall;
    wall.kind = BodyKind::Static;
    wall.mass = kInfiniteMass;
    wall.position = {5.0, 5.0};
    wall.size = {1.0, 1.0};
    w.blocks.push_back(wall);
    EXPECT_FALSE(centreOfMass(w).valid);
    EXPECT_EQ(frameVelocity(w, ViewFrame::CentreOfMass), Vec2{});
    FrameCamera follow;
    EXPECT_EQ(followShift(follow, w, ViewFrame::CentreOfMass, true), Vec2{});
}

TEST(ViewFrame, ArrowsShowTheVelocityRelativeToTheCentreOfMass) {
    App app = lectureExample();
    app.view.camera.setViewport({0.0, 0.0, 1280.0, 720.0});
    app.view.camera.fit(app.sim.world().bounds, 20.0);
    SceneView view;
    view.world = &app.sim.world();
    view.camera = &app.view.camera;
    view.vectors = true;
    SceneGeometry g;
    g.build(view, 1.0);
    // The world's frame: m2 is at rest, so only m1 has a velocity arrow (+x).
    ASSERT_EQ(g.over.segmentVertices().size(), 2u);
    EXPECT_GT(g.over.segmentVertices()[1].x, g.over.segmentVertices()[0].x);
    view.frameVelocity = frameVelocity(app.sim.world(), ViewFrame::CentreOfMass);
    g.build(view, 1.0);
    // Centre of mass: w1 = +4 from m1, w2 = -2 from m2 (half as long, pointing left).
    const auto& v = g.over.segmentVertices();
    ASSERT_EQ(v.size(), 4u);
    EXPECT_FLOAT_EQ(v[0].x, 4.0f);
    EXPECT_GT(v[1].x, v[0].x);
    EXPECT_FLOAT_EQ(v[2].x, 8.75f);
    EXPECT_LT(v[3].x, v[2].x);
    // Momenta m·w: 1·4 and 2·(-2), equal and opposite (the sum is zero in this frame).
    const auto& p = g.momenta.segmentVertices();
    ASSERT_EQ(p.size(), 4u);
    EXPECT_NEAR(p[1].x - p[0].x, -(p[3].x - p[2].x), 1e-5);
}

TEST(ViewFrame, TheCameraMovesWithTheCentreOfMass) {
    App app = lectureExample();
    setViewFrame(app.view, ViewFrame::CentreOfMass);
    updateCamera(app, 1280.0, 720.0);
    const Vec2 comOnScreen = app.view.camera.worldToScreen(centreOfMass(app.sim.world()).position);
    const Vec2 wallOnScreen = app.view.camera.worldToScreen(app.sim.world().bounds.min);
    for (int i = 0; i < 60; ++i) {
        stepSimulation(app);
        updateCamera(app, 1280.0, 720.0);
    }
    // 1 s: the centre of mass stays put on screen (to float rounding of pixels), the walls
    // drift by -u·t = -2 m.
    const Vec2 comNow = app.view.camera.worldToScreen(centreOfMass(app.sim.world()).position);
    EXPECT_NEAR(comNow.x, comOnScreen.x, 1e-6);
    EXPECT_NEAR(comNow.y, comOnScreen.y, 1e-6);
    const double ppm = app.view.camera.pixelsPerMetre();
    EXPECT_NEAR(app.view.camera.worldToScreen(app.sim.world().bounds.min).x - wallOnScreen.x,
                -2.0 * app.sim.world().time * ppm, 1e-6);
    EXPECT_NEAR(app.sim.world().time, 1.0, 1e-9);

    // Stepping many frames before the next draw (offscreen --frames N) ends in the same view.
    App later = lectureExample();
    later.view.frame = ViewFrame::CentreOfMass; // as --frame does at the run's start
    for (int i = 0; i < 60; ++i) stepSimulation(later);
    updateCamera(later, 1280.0, 720.0);
    EXPECT_NEAR(later.view.camera.centre().x, app.view.camera.centre().x, 1e-9);

    // Panned away from the fit, the camera still follows (by the displacement since last frame).
    app.view.autoFit = false;
    app.view.camera.panPixels({100.0, 0.0});
    updateCamera(app, 1280.0, 720.0);
    const Vec2 panned = app.view.camera.worldToScreen(centreOfMass(app.sim.world()).position);
    for (int i = 0; i < 30; ++i) stepSimulation(app);
    updateCamera(app, 1280.0, 720.0);
    EXPECT_NEAR(app.view.camera.worldToScreen(centreOfMass(app.sim.world()).position).x, panned.x,
                1e-6);

    // Back in the world's frame, the fit shows the walls where they are.
    setViewFrame(app.view, ViewFrame::World);
    app.view.autoFit = true;
    updateCamera(app, 1280.0, 720.0);
    EXPECT_NEAR(app.view.camera.worldToScreen(app.sim.world().bounds.min).x, wallOnScreen.x, 1e-6);
}

TEST(ViewFrame, FlagAndLessonKeyChooseIt) {
    const char* com[] = {"sandbox", "--frame", "com"};
    const ParsedOptions ok = parseOptions(3, com);
    ASSERT_FALSE(ok.exit);
    ASSERT_TRUE(ok.options.frame.has_value());
    EXPECT_EQ(*ok.options.frame, ViewFrame::CentreOfMass);
    const char* bad[] = {"sandbox", "--frame", "moving"};
    EXPECT_EQ(parseOptions(3, bad).exitCode, 2);
    EXPECT_FALSE(parseOptions(1, com).options.frame.has_value());

    // lecture3's step 12 ("Change your frame of reference") is seen from the centre of mass,
    // and the answer shows the slide's w after the collision.
    App app;
    app.shipped.scenesDir = SANDBOX_SCENES_DIR;
    ASSERT_TRUE(openLesson(app, std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", 11))
        << app.ui.messages.error;
    ASSERT_EQ(app.lesson.step()->title, "Change your frame of reference");
    EXPECT_EQ(app.view.frame, ViewFrame::CentreOfMass);
    lessonShowPausePoint(app);
    EXPECT_NEAR(seen(app, 0).x, -4.0, kExact);
    EXPECT_NEAR(seen(app, 1).x, 2.0, kExact);
    applyLessonAction(app, Action::LessonNext); // the next step is seen from the world again
    EXPECT_EQ(app.view.frame, ViewFrame::World);
    applyLessonAction(app, Action::LessonPrevious);
    EXPECT_EQ(app.view.frame, ViewFrame::CentreOfMass);
    closeLesson(app);
    EXPECT_EQ(app.view.frame, ViewFrame::World);
}
