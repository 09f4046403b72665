// Classroom presentation logic without GL: the docked layout (no window over the world, none off
// screen), numbers as students read them, block names with the current mass, save naming.
#include "app.h"
#include "classroom.h"
#include "dock_layout.h"
#include "equation_check.h"
#include "inspector_format.h"
#include "palette.h"
#include "save_naming.h"
#include "scene_geometry.h"
#include "scene_library.h"
#include "test_fixtures.h"
#include "text_format.h"
#include "timeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace {

// Every overlay window, with the wishes the app gives them (overlay table).
std::vector<DockRequest> everyWindow() {
    return {{"Plots", DockSide::Right, 240, 3, 400},
            {"Collision inspector", DockSide::Right, 200, 2, 430},
            {"Speed versus accuracy", DockSide::Right, 260, 2, 400},
            {"Timeline", DockSide::Bottom, 330, 1, 100},
            {"Methods side by side", DockSide::Bottom, 480, 2, 150},
            {"Momenta", DockSide::Bottom, 200, 1, 200}};
}

void expectSound(const Layout& l, double w, double h) {
    const ScreenRect screen{0, 0, w, h};
    EXPECT_TRUE(rectInside(l.scene, screen));
    EXPECT_GT(l.scene.width, w * 0.3);
    EXPECT_GT(l.scene.height, h * 0.5);
    if (l.panel.width > 0) {
        EXPECT_TRUE(rectInside(l.panel, screen));
        EXPECT_FALSE(rectsOverlap(l.panel, l.scene));
    }
    for (std::size_t i = 0; i < l.windows.size(); ++i) {
        const ScreenRect& r = l.windows[i].rect;
        EXPECT_TRUE(rectInside(r, screen)) << l.windows[i].name;
        EXPECT_GT(r.width, 50.0) << l.windows[i].name;
        EXPECT_GT(r.height, 50.0) << l.windows[i].name;
        EXPECT_FALSE(rectsOverlap(r, l.scene)) << l.windows[i].name;
        if (l.panel.width > 0) {
            EXPECT_FALSE(rectsOverlap(r, l.panel)) << l.windows[i].name;
        }
        for (std::size_t j = i + 1; j < l.windows.size(); ++j) {
            EXPECT_FALSE(rectsOverlap(r, l.windows[j].rect))
                << l.windows[i].name << " / " << l.windows[j].name;
        }
        // Whole pixels, so neighbours never overlap by rounding.
        EXPECT_EQ(r.x, std::round(r.x));
        EXPECT_EQ(r.width, std::round(r.width));
    }
}

TEST(DockLayout, EveryWindowAtTheFourClassroomSizes) {
    for (const auto& size : {std::pair<double, double>{1280, 720}, {1920, 1080}}) {
        for (float scale : {1.0f, 1.5f}) {
            LayoutInput in;
            in.displayWidth = size.first;
            in.displayHeight = size.second;
            in.uiScale = scale;
            in.panelWidth = std::min(350.0 * scale, size.first * 0.45);
            in.windows = everyWindow();
            const Layout l = computeLayout(in);
            SCOPED_TRACE(std::to_string(size.first) + "x" + std::to_string(scale));
            // Each window docked, or folded behind a tab (1280x720 at UI 1.5: DockTabs).
            std::size_t folded = 0;
            for (const DockTabs& t : l.tabs) folded += t.names.size() - 1;
            ASSERT_EQ(l.windows.size() + folded, in.windows.size());
            expectSound(l, size.first, size.second);
            EXPECT_DOUBLE_EQ(l.scene.x, l.panel.width); // the scene starts where the panel ends
        }
    }
}

// Issue 23: the plots take room from the panel, not from the scene: under the panel, in its
// column, three plots of 14% of the height each (151 px at 1080p) whatever the UI scale; without a
// panel column they go to the right column as before.
TEST(DockLayout, PanelSideWindowsTakeRoomFromThePanelNotTheScene) {
    for (float scale : {1.0f, 1.5f}) {
        LayoutInput in;
        in.displayWidth = 1920;
        in.displayHeight = 1080;
        in.uiScale = scale;
        in.panelWidth = 350.0 * scale;
        in.topInset = 257; // a lesson's caption
        in.windows = {{"Collision inspector", DockSide::Right, 200, 2, 430}};
        const Layout without = computeLayout(in);
        in.windows.push_back({"Plots", DockSide::Panel, 115, 3, 400, 0.42});
        const Layout l = computeLayout(in);
        SCOPED_TRACE(scale);
        expectSound(l, 1920, 1080);
        EXPECT_EQ(l.scene.x, without.scene.x);
        EXPECT_EQ(l.scene.width, without.scene.width);
        EXPECT_EQ(l.scene.height, without.scene.height);
        const ScreenRect* plots = l.find("Plots");
        ASSERT_NE(plots, nullptr);
        EXPECT_EQ(plots->x, 0.0);
        EXPECT_EQ(plots->width, l.panel.width);
        EXPECT_EQ(plots->y + plots->height, 1080.0); // at the bottom of the column
        EXPECT_LE(l.panel.y + l.panel.height, plots->y);
        // The caption bar spans the panel's column too (issue 39): the column is what is below
        // it, and the plots take at most kMaxPanelDockShare of that (their share still of 1080).
        const double below = 1080.0 - in.topInset;
        const double wanted = 115 * scale + 0.42 * 1080, gap = kDockGap * scale;
        const double shrink = std::min(1.0, below * kMaxPanelDockShare / (wanted + gap));
        EXPECT_NEAR(plots->height, wanted * shrink, 2.0);
        EXPECT_GE(l.panel.y, in.topInset);
        EXPECT_GE(l.panel.height, below * (1 - kMaxPanelDockShare) - 1);
    }
    // No panel column (hidden): the right column.
    LayoutInput bare;
    bare.displayWidth = 1920;
    bare.displayHeight = 1080;
    bare.windows = {{"Plots", DockSide::Panel, 115, 3, 400, 0.42}};
    const Layout l = computeLayout(bare);
    ASSERT_NE(l.find("Plots"), nullptr);
    EXPECT_EQ(l.find("Plots")->x + l.find("Plots")->width, 1920.0);
    EXPECT_EQ(l.find("Plots")->height, 1080.0);
    expectSound(l, 1920, 1080);
}

TEST(DockLayout, ATopInsetKeepsTheSceneAndTheColumnBelowIt) {
    LayoutInput in;
    in.panelWidth = 350.0;
    in.topInset = 100.0; // a lesson's caption
    in.windows = everyWindow();
    const Layout l = computeLayout(in);
    expectSound(l, 1280, 720);
    EXPECT_DOUBLE_EQ(l.scene.y, 100.0);
    EXPECT_DOUBLE_EQ(l.find("Plots")->y, 100.0);
}

TEST(DockLayout, NoWindowsNoPanelGivesTheSceneEverything) {
    LayoutInput in;
    in.panelWidth = 0.0;
    const Layout l = computeLayout(in);
    EXPECT_DOUBLE_EQ(l.scene.x, 0.0);
    EXPECT_DOUBLE_EQ(l.scene.width, 1280.0);
    EXPECT_DOUBLE_EQ(l.scene.height, 720.0);
    EXPECT_TRUE(l.windows.empty());
    EXPECT_EQ(l.find("Plots"), nullptr);
}

TEST(DockLayout, RightColumnOnlyLeavesTheFullHeightAndStacksByWeight) {
    LayoutInput in;
    in.panelWidth = 350.0;
    in.windows = {{"a", DockSide::Right, 100, 3, 360}, {"b", DockSide::Right, 100, 1, 360}};
    const Layout l = computeLayout(in);
    expectSound(l, 1280, 720);
    EXPECT_DOUBLE_EQ(l.scene.height, 720.0);
    const ScreenRect* a = l.find("a");
    const ScreenRect* b = l.find("b");
    ASSERT_TRUE(a && b);
    EXPECT_LT(a->y, b->y);                                   // stacked top to bottom
    EXPECT_GT(a->height, b->height);                         // weight 3 against 1
    EXPECT_DOUBLE_EQ(b->y + b->height, 720.0);               // down to the bottom edge
    EXPECT_DOUBLE_EQ(a->x + a->width, 1280.0);               // against the right edge
    EXPECT_DOUBLE_EQ(l.scene.x + l.scene.width + 4.0, a->x); // the column starts after a gap
}

TEST(DockLayout, BottomStripOnlySpansFromThePanelToTheEdge) {
    LayoutInput in;
    in.panelWidth = 350.0;
    in.windows = {{"t", DockSide::Bottom, 200, 1, 80}};
    const Layout l = computeLayout(in);
    expectSound(l, 1280, 720);
    const ScreenRect* t = l.find("t");
    ASSERT_TRUE(t);
    EXPECT_DOUBLE_EQ(l.scene.width, 1280.0 - 350.0);
    EXPECT_DOUBLE_EQ(t->x + t->width, 1280.0);
    EXPECT_GE(t->y, l.scene.y + l.scene.height);
    EXPECT_NEAR(t->height, 720 * kMinStripShare - 4.0,
                1.0); // 110 px is less than the minimum share
}

TEST(DockLayout, MinimumsThatDoNotFitShrinkAlikeAndStayInside) {
    LayoutInput in;
    in.displayWidth = 640;
    in.displayHeight = 360;
    in.uiScale = 2.0f;
    in.panelWidth = 280;
    for (int i = 0; i < 6; ++i) in.windows.push_back({"w" + std::to_string(i), DockSide::Right});
    in.tabs = false; // (else they fold into tabs)
    const Layout l = computeLayout(in);
    ASSERT_EQ(l.windows.size(), 6u);
    const ScreenRect screen{0, 0, 640, 360};
    for (const DockedWindow& w : l.windows) {
        EXPECT_TRUE(rectInside(w.rect, screen)) << w.name;
        EXPECT_FALSE(rectsOverlap(w.rect, l.scene)) << w.name;
    }
}

// Issue 39: every overlay on at 1280x800, UI 1.5 leaves the bottom strip's four windows 110-270
// px wide; a region whose windows do not fit side by side (each at least kLeastDockShrink of its
// least extent) shows one of them, the one brought to the front last, with the others' tabs.
TEST(DockLayout, WindowsThatDoNotFitFoldIntoTabs) {
    const auto input = [](double w, double h, float scale) {
        LayoutInput in;
        in.displayWidth = w;
        in.displayHeight = h;
        in.uiScale = scale;
        in.panelWidth = std::min(350.0 * scale, w * 0.45);
        in.windows = everyWindow();
        return in;
    };
    // They fit at 1920x1080: nothing folds.
    EXPECT_TRUE(computeLayout(input(1920, 1080, 1.0f)).tabs.empty());
    LayoutInput in = input(1280, 800, 1.5f);
    in.windows[4].front = 2; // methods side by side asked for last
    in.windows[3].front = 1;
    const Layout l = computeLayout(in);
    expectSound(l, 1280, 800);
    ASSERT_EQ(l.tabs.size(), 2u);
    const DockTabs& right = l.tabs[0];
    const DockTabs& bottom = l.tabs[1];
    EXPECT_EQ(right.names,
              (std::vector<std::string>{"Plots", "Collision inspector", "Speed versus accuracy"}));
    EXPECT_EQ(right.shown, "Plots"); // none brought to the front: the first
    EXPECT_EQ(bottom.names,
              (std::vector<std::string>{"Timeline", "Methods side by side", "Momenta"}));
    EXPECT_EQ(bottom.shown, "Methods side by side");
    ASSERT_EQ(l.windows.size(), 2u);
    for (const DockTabs& t : l.tabs) {
        const ScreenRect* shown = l.find(t.shown);
        ASSERT_NE(shown, nullptr) << t.shown;
        EXPECT_EQ(shown->x, t.rect.x);
        EXPECT_EQ(shown->width, t.rect.width);
        EXPECT_EQ(l.tabsOf(t.shown), &t);
        for (const std::string& name : t.names) {
            if (name != t.shown) {
                EXPECT_EQ(l.find(name), nullptr) << name;
            }
        }
    }
    // The shown window has its whole region: the strip from the panel to the right edge.
    EXPECT_EQ(bottom.rect.x, l.panel.width + std::round(kDockGap * 1.5));
    EXPECT_EQ(bottom.rect.x + bottom.rect.width, 1280.0);
    // Under a caption bar the tabs move down with their windows.
    in.topInset = 100;
    const Layout below = computeLayout(in);
    ASSERT_EQ(below.tabs.size(), 2u);
    EXPECT_EQ(below.tabs[0].rect.y, 100.0);
    ASSERT_NE(below.find("Plots"), nullptr);
    EXPECT_EQ(below.find("Plots")->y, below.tabs[0].rect.y);
    EXPECT_EQ(below.find("Plots")->height, below.tabs[0].rect.height);
    // Tabs off: the windows shrink as before.
    in.tabs = false;
    EXPECT_TRUE(computeLayout(in).tabs.empty());
    in.tabs = true;
    // Above a phone's sheet (390x844 at ratio 3, UI scale 3: 1170x2532 px) the strip's windows
    // fold too, one shown across the whole width and none over the sheet or the scene.
    LayoutInput phone = input(1170, 2532, 3.0f);
    phone.panelWidth = 0.0;
    phone.panelHeight = 64.0 * 3.0;
    phone.windows.resize(3); // a lesson step's three windows
    const Layout p = computeLayout(phone);
    ASSERT_TRUE(p.sheet);
    ASSERT_EQ(p.tabs.size(), 1u);
    EXPECT_EQ(p.tabs[0].names.size(), 3u);
    ASSERT_EQ(p.windows.size(), 1u);
    EXPECT_EQ(p.windows[0].rect.x, 0.0);
    EXPECT_EQ(p.windows[0].rect.width, 1170.0);
    EXPECT_LE(p.windows[0].rect.y + p.windows[0].rect.height, p.panel.y);
    EXPECT_FALSE(rectsOverlap(p.windows[0].rect, p.scene));
    EXPECT_TRUE(p.hidden.empty());
    // The sheet open (55% of the height) under a lesson's caption (a third): no room for the
    // strip; its windows are hidden (not drawn over the sheet), the scene keeps its share.
    phone.panelHeight = 2532 * kSheetOpenShare;
    phone.topInset = 2532 / 3.0;
    const Layout open = computeLayout(phone);
    EXPECT_TRUE(open.windows.empty());
    EXPECT_TRUE(open.tabs.empty());
    EXPECT_EQ(open.hidden,
              (std::vector<std::string>{"Plots", "Collision inspector", "Speed versus accuracy"}));
    EXPECT_TRUE(open.hides("Plots"));
    EXPECT_FALSE(rectsOverlap(open.scene, open.panel));
}

TEST(DockLayout, WorldRectOnScreenFollowsTheCamera) {
    Camera cam;
    cam.setViewport({350, 0, 600, 500});
    cam.fit(Bounds{{0, 0}, {20, 12}}, 36);
    const ScreenRect w = worldRectOnScreen(cam, Bounds{{0, 0}, {20, 12}});
    EXPECT_TRUE(rectInside(w, cam.viewport()));
    EXPECT_NEAR(w.width / w.height, 20.0 / 12.0, 1e-9);
    EXPECT_NEAR(w.x - 350, 36, 1e-9); // the width is the limit: 36 px margin left and right
}

TEST(DockLayout, LayoutJsonIsTheSpecsDocument) {
    const std::string json =
        layoutJson({350, 0, 600, 500}, {386, 70, 528, 316.8},
                   {{"Plots", {954, 0, 326, 300}}, {"a \"b\"\n", {0, 0, 1, 1}}});
    EXPECT_EQ(json, "{\"scene\": [350, 0, 600, 500], \"world\": [386, 70, 528, 316.8], "
                    "\"windows\": [{\"name\": \"Plots\", \"rect\": [954, 0, 326, 300]}, "
                    "{\"name\": \"a \\\"b\\\"\\u000a\", \"rect\": [0, 0, 1, 1]}], "
                    "\"blocks\": [], \"plots\": [], \"marks\": []}\n");
    EXPECT_EQ(layoutJson({0, 0, 1280, 720}, {36, 36, 10, 10}, {}, {{"m1", {100, 200, 50, 50}}},
                         {{"velocity", {900, 10, 300, 150}}}, {{"POI", {400, 300, 60, 60}}}),
              "{\"scene\": [0, 0, 1280, 720], \"world\": [36, 36, 10, 10], \"windows\": [], "
              "\"blocks\": [{\"name\": \"m1\", \"rect\": [100, 200, 50, 50]}], "
              "\"plots\": [{\"name\": \"velocity\", \"rect\": [900, 10, 300, 150]}], "
              "\"marks\": [{\"name\": \"POI\", \"rect\": [400, 300, 60, 60]}]}\n");
}

TEST(TextFormat, RoundingNoiseReadsAsZero) {
    EXPECT_EQ(formatNumber(6.56e-13), "0");  // "t = 6.56e-13 of the frame"
    EXPECT_EQ(formatNumber(-7.11e-15), "0"); // "a = 7.11e-15 m"
    EXPECT_EQ(formatNumber(-1e-12), "0");
    EXPECT_EQ(formatNumber(2e-9, 1e3), "0"); // noise relative to the scale of the quantity
    EXPECT_EQ(formatNumber(2e-9), "2e-09");  // above the noise of a quantity of scale 1
    EXPECT_TRUE(isRoundingNoise(1e-10));
    EXPECT_FALSE(isRoundingNoise(1e-6));
    EXPECT_FALSE(isRoundingNoise(INFINITY));
}

// A step's texts name a block by its name as a word of its own (the magnifier's rule).
TEST(TextFormat, SaysWordFindsANameOnlyAsAWholeWord) {
    EXPECT_TRUE(saysWord("m1 hits m2", "m2"));
    EXPECT_TRUE(saysWord("m1 = 1 kg", "m1"));
    EXPECT_TRUE(saysWord("(red, blue)", "blue"));
    EXPECT_FALSE(saysWord("m12 hits m21", "m1")); // inside longer words only
    EXPECT_TRUE(saysWord("m12 and m1", "m1"));    // a later whole word counts
    EXPECT_FALSE(saysWord("anything", ""));
}

TEST(TextFormat, ReadablePrecision) {
    EXPECT_EQ(formatNumber(2.0), "2");
    EXPECT_EQ(formatNumber(-2.0), "-2");
    EXPECT_EQ(formatNumber(0.625), "0.625");
    EXPECT_EQ(formatNumber(1.0 / 3.0), "0.333");
    EXPECT_EQ(formatNumber(-0.0), "0");
    EXPECT_EQ(formatNumber(0.000123), "0.000123");
    EXPECT_EQ(formatNumber(1.5e-5), "0.000015");
    EXPECT_EQ(formatNumber(1e6), "1000000");
    EXPECT_EQ(formatNumber(1.5e12), "1.5e+12");
    EXPECT_EQ(formatNumber(INFINITY), "inf");
    EXPECT_EQ(formatQuantity(0.625, "s"), "0.625 s");
    EXPECT_EQ(operand(-2.0), "(-2)");
    EXPECT_EQ(operand(4.0), "4");
}

TEST(TextFormat, NamesCarryTheCurrentMass) {
    EXPECT_EQ(baseBlockName("m1 = 1 kg"), "m1");
    EXPECT_EQ(baseBlockName("heavy (5 kg)"), "heavy");
    EXPECT_EQ(baseBlockName("bullet"), "bullet");
    EXPECT_EQ(baseBlockName("x = 3"), "x = 3"); // not a mass
    EXPECT_TRUE(nameStatesMass("m2 = 2 kg"));
    EXPECT_FALSE(nameStatesMass("giant"));
    // lecture3's step 7: "big ship, 4 kg" drew a second line "4 kg" under its name.
    EXPECT_TRUE(nameStatesMass("big ship, 4 kg"));
    EXPECT_EQ(baseBlockName("big ship, 4 kg"), "big ship");
    EXPECT_EQ(nameWithMass("big ship, 4 kg", 8.0), "big ship, 8 kg");
    EXPECT_EQ(nameWithMass("big ship, 4 kg", 4.0), "big ship, 4 kg");
    EXPECT_FALSE(nameStatesMass("red, blue")); // a comma alone states no mass
    // Step 8: "feather, 50 g" drew "0.05 kg" under its name; a name in grams stays in grams.
    EXPECT_TRUE(nameStatesMass("feather, 50 g"));
    EXPECT_EQ(nameWithMass("feather, 50 g", 0.05), "feather, 50 g");
    EXPECT_EQ(nameWithMass("feather, 50 g", 0.2), "feather, 200 g");
    EXPECT_FALSE(nameStatesMass("x = g")); // no number
    EXPECT_EQ(nameWithMass("m1 = 1 kg", 3.0), "m1 = 3 kg");
    EXPECT_EQ(nameWithMass("heavy (5 kg)", 0.5), "heavy (0.5 kg)");
    EXPECT_EQ(nameWithMass("m1 = 1 kg", INFINITY), "m1 = infinite mass");
    EXPECT_EQ(nameWithMass("giant", 3.0), "giant");
    EXPECT_EQ(formulaSymbol("m1 = 1 kg"), "1");
    EXPECT_EQ(formulaSymbol("A"), "A");
    EXPECT_EQ(formulaSymbol("bullet"), "");
}

TEST(InspectorNames, AWallHitNamesTheBlockThatHit) {
    const CollisionFormula f =
        collisionFormula(rightWallHit(1, 2.0), "m2 = 2 kg", wallName(kWallRight));
    EXPECT_EQ(f.title, "m2 = 2 kg  hits  right wall  along x at t = 1.5 s");
    EXPECT_EQ(f.given, "m2 = 2, v2 = 4, C = 0.5; the right wall does not move");
    EXPECT_EQ(f.v1After, "v2' = 0 - 0.5·(4 - 0) = -2");
    EXPECT_EQ(f.momentumBefore, "p2 before = 2·4 = 8 kg·m/s");
    EXPECT_TRUE(f.v2After.empty());
    const CollisionFormula g = collisionFormula(rightWallHit(1, 2.0), "bullet", "floor");
    EXPECT_EQ(g.v1After, "v' = 0 - 0.5·(4 - 0) = -2");
}

TEST(InspectorNames, SymbolsFollowTheNamesInEitherOrder) {
    CollisionRecord r; // block 1 (2 kg at -2 m/s) meets block 0 (1 kg at 4 m/s), C = 0
    r.block = 1, r.other = 0;
    r.m1 = 2.0, r.m2 = 1.0, r.v1 = -2.0, r.v2 = 4.0, r.u = 0.0, r.C = 0.0;
    const CollisionFormula f = collisionFormula(r, "m2 = 2 kg", "m1 = 1 kg");
    EXPECT_EQ(f.given, "m2 = 2, m1 = 1, v2 = -2, v1 = 4, C = 0");
    EXPECT_EQ(f.u, "u = (2·(-2) + 1·4)/(2 + 1) = 0");
    const CollisionFormula g = collisionFormula(r, "left", "right");
    EXPECT_EQ(g.given, "m1 = 2, m2 = 1, v1 = -2, v2 = 4, C = 0");
}

// Issue 18: the inspector states the lecture's relative-velocity test ("Tips – Collision
// Resolve": resolve only when the relative velocity along the axis closes).
TEST(InspectorFormat, StatesTheRelativeVelocityTest) {
    CollisionRecord r;
    r.block = 0;
    r.other = 1;
    r.m1 = 1.0, r.m2 = 1.0, r.C = 0.5, r.u = 3.5;
    r.v1 = 3.0, r.v2 = 4.0; // red follows the faster blue: separating, resolved by the mistake
    r.v1After = 3.75, r.v2After = 3.25;
    r.firstBelow = true;
    CollisionFormula f = collisionFormula(r, "red", "blue");
    EXPECT_EQ(f.relative, "rel. vel. along x = v1 - v2 = 3 - 4 = -1 < 0: separating, not a "
                          "collision (resolved anyway: the mistake no-approach-test)");
    EXPECT_TRUE(f.separating);
    r.v1 = 3.75, r.v2 = 3.25; // the next frame: red really hits blue
    f = collisionFormula(r, "red", "blue");
    EXPECT_EQ(f.relative, "rel. vel. along x = v1 - v2 = 3.75 - 3.25 = 0.5 > 0: approaching, "
                          "resolved");
    EXPECT_FALSE(f.separating);
    // The first body on the upper side: the test reads v2 - v1 (lecture example 1 seen from m2).
    r.v1 = 0.0, r.v2 = 6.0;
    r.firstBelow = false;
    f = collisionFormula(r, "m2 = 2 kg", "m1 = 1 kg");
    EXPECT_EQ(f.relative, "rel. vel. along x = v1 - v2 = 6 - 0 = 6 > 0: approaching, resolved");
    // Walls: the right wall is above the block, the floor below it.
    EXPECT_EQ(collisionFormula(rightWallHit(1, 2.0), "m2 = 2 kg", "right wall").relative,
              "rel. vel. along x = v2 - 0 = 4 - 0 = 4 > 0: approaching, resolved");
    CollisionRecord drop = rightWallHit(1, 2.0);
    drop.other = kWallBottom, drop.axis = 1, drop.v1 = -5.0;
    EXPECT_EQ(collisionFormula(drop, "ball", "floor").relative,
              "rel. vel. along y = 0 - v = 0 - (-5) = 5 > 0: approaching, resolved");
}

// The point-of-impact caption never covers a block: it goes to the scene's margin when there is
// room, else into the world where no block is, the top first.
TEST(CaptionPlacement, NeverCoversABlock) {
    const ScreenRect scene{400, 100, 1000, 800};
    const ScreenRect world{420, 120, 960, 760}; // the world fills the scene, a 20 px margin
    const std::vector<ScreenRect> blocks = {{430, 130, 300, 200}, {900, 600, 200, 200}};
    const ScreenRect r = placeCaption(400, 120, scene, world, blocks, 10);
    for (const ScreenRect& b : blocks) EXPECT_FALSE(rectsOverlap(r, b));
    EXPECT_TRUE(rectInside(r, scene));
    EXPECT_TRUE(rectInside(r, {world.x + 10, world.y + 10, world.width - 20, world.height - 20}));
    EXPECT_EQ(r.y, 130); // the top: right of the first block
    EXPECT_GE(r.x, 730);
    // A wide margin above the world: the caption goes there, off the world.
    const ScreenRect low{420, 400, 960, 480};
    const ScreenRect m = placeCaption(400, 120, scene, low, blocks, 10);
    EXPECT_FALSE(rectsOverlap(m, low));
    EXPECT_TRUE(rectInside(m, scene));
    // No free spot at all: the least covered one, still inside the scene.
    const ScreenRect full = placeCaption(400, 120, scene, world, {scene}, 10);
    EXPECT_TRUE(rectInside(full, scene));
    // Blocks everywhere (a jammed box): it hides no label, though the top left corner (half in
    // the margin) would cover the least of the blocks.
    const std::vector<ScreenRect> labels = {
        {425, 125, 60, 30}, {600, 500, 60, 40}, {1300, 860, 40, 16}};
    EXPECT_TRUE(rectsOverlap(placeCaption(400, 120, scene, world, {world}, 10), labels[0]));
    const ScreenRect packed = placeCaption(400, 120, scene, world, {world}, 10, labels);
    for (const ScreenRect& l : labels) EXPECT_FALSE(rectsOverlap(packed, l)) << packed.y;
}

TEST(SaveNaming, OffersANameFromTheSceneAndNeverAnExistingFile) {
    EXPECT_EQ(sceneFileStem("Lecture example 1"), "lecture_example_1");
    EXPECT_EQ(sceneFileStem("High mass ratio (counting pi)"), "high_mass_ratio_counting_pi");
    EXPECT_EQ(sceneFileStem("!!!"), "scene");
    std::set<std::string> taken = {"/home/u/lecture_example_1.json",
                                   "/home/u/lecture_example_1-2.json"};
    const auto exists = [&taken](const std::string& p) { return taken.count(p) > 0; };
    EXPECT_EQ(suggestSavePath("Lecture example 1", "/home/u", exists),
              "/home/u/lecture_example_1-3.json");
    EXPECT_EQ(suggestSavePath("Two blocks", "/home/u/", exists), "/home/u/two_blocks.json");
}

TEST(SaveNaming, PathsAreAbsolute) {
    EXPECT_EQ(absoluteScenePath("my_scene", "/home/u"), "/home/u/my_scene.json");
    EXPECT_EQ(absoluteScenePath("../x/a.json", "/home/u/work"), "/home/u/x/a.json");
    EXPECT_EQ(absoluteScenePath("/tmp/b.json", "/home/u"), "/tmp/b.json");
    EXPECT_EQ(absoluteScenePath("", "/home/u"), "");
}

TEST(SaveNaming, TheDescriptionSaysWhichSettingsChanged) {
    WorldSettings original;
    original.gravity = Vec2{0, 0};
    WorldSettings now = original;
    EXPECT_FALSE(settingsDiffer(original, now));
    EXPECT_EQ(savedDescription("A block, no gravity.", original, now), "A block, no gravity.");
    now.gravity = Vec2{0, -9.81};
    now.method = Method::TurnBased;
    EXPECT_TRUE(settingsDiffer(original, now));
    EXPECT_EQ(savedDescription("A block, no gravity.", original, now),
              "A block, no gravity. Saved with changed settings: gravity (0, -9.81) m/s², method "
              "turn-based.");
    now = original;
    now.dt = 1.0 / 120.0;
    EXPECT_EQ(changedSettingsNote(original, now),
              "Saved with changed settings: frame rate 120 Hz.");
}

TEST(Arrows, ShortArrowsToScaleLongOnesCompressedWithTheirHeadsOnScreen) {
    EXPECT_DOUBLE_EQ(displayedArrowPx(50, 100), 50);
    EXPECT_GT(displayedArrowPx(300, 100), 100);
    EXPECT_LE(displayedArrowPx(1e9, 100), 200);
    Camera cam;
    cam.setViewport({350, 0, 930, 720});
    cam.fit(Bounds{{0, 0}, {20, 12}}, 36);
    // A 1 m/s arrow is drawn to scale.
    const ArrowOnScreen slow = arrowOnScreen(cam, {10, 6}, Vec2{1, 0} * kVelocityArrowScale);
    EXPECT_TRUE(slow.toScale);
    EXPECT_NEAR(slow.tip.x, 10.25, 1e-12);
    // bullet_wall: 300 m/s from x = 1 would end 75 m away; its head stays in the viewport.
    const ArrowOnScreen fast = arrowOnScreen(cam, {1, 6}, Vec2{300, 0} * kVelocityArrowScale);
    EXPECT_FALSE(fast.toScale);
    EXPECT_TRUE(cam.viewport().contains(cam.worldToScreen(fast.tip)));
    EXPECT_GT(fast.tip.x, 1.0);
    EXPECT_NEAR(fast.tip.y, 6.0, 1e-12); // same direction
    // high_mass_ratio: the giant's momentum 1e6 kg·m/s to the left stays inside on the left.
    const ArrowOnScreen giant = arrowOnScreen(cam, {10, 6}, Vec2{-1e6, 0} * kMomentumArrowScale);
    EXPECT_FALSE(giant.toScale);
    EXPECT_TRUE(cam.viewport().contains(cam.worldToScreen(giant.tip)));
}

// Issue 23: an arrow too long for the view ends at the arena's wall or the view's edge, whichever
// comes first (lecture3 step 6: the heavy block's momentum went through the floor and off the
// screen), so its head and the value written there are in sight.
TEST(Arrows, AnOverLongArrowEndsInsideTheArenaAndTheView) {
    Camera cam;
    cam.setViewport({350, 135, 1570, 945});
    const Bounds arena{{0, 0}, {20, 12}};
    cam.fit(arena, 36);
    // 20 kg falling at 9.81 m/s from y = 5: 196.2 kg·m/s, 29 m of arrow to scale.
    const Vec2 p = Vec2{0, -196.2} * kMomentumArrowScale;
    const ArrowOnScreen bare = arrowOnScreen(cam, {13, 5}, p);
    EXPECT_LT(bare.tip.y, arena.min.y); // without the arena: through the floor
    const ArrowOnScreen a = arrowOnScreen(cam, {13, 5}, p, &arena);
    EXPECT_FALSE(a.toScale);
    EXPECT_GE(a.tip.y, arena.min.y);
    EXPECT_LT(a.tip.y, 1.0); // it does reach down to the floor
    EXPECT_DOUBLE_EQ(a.tip.x, 13.0);
    EXPECT_TRUE(cam.viewport().contains(cam.worldToScreen(a.tip)));
    // A view that shows only part of the arena (a lesson's camera): the view's edge comes first.
    Camera close;
    close.setViewport({350, 135, 1570, 945});
    close.fit(Bounds{{0, 3}, {18, 12}}, 36);
    const ArrowOnScreen fast = arrowOnScreen(close, {16, 6}, Vec2{300, 0} * 0.25, &arena);
    EXPECT_FALSE(fast.toScale);
    EXPECT_TRUE(close.viewport().contains(close.worldToScreen(fast.tip)));
    EXPECT_LE(fast.tip.x, arena.max.x);
    // Short arrows are untouched.
    EXPECT_TRUE(arrowOnScreen(cam, {10, 6}, Vec2{1, 0} * kVelocityArrowScale, &arena).toScale);
}

TEST(BlockContrast, ADarkBlockOnTheDarkArenaGetsALightOutline) {
    Color bullet;
    ASSERT_TRUE(parseHexColor("#202020", bullet)); // bullet_wall's bullet
    EXPECT_LT(contrastRatio(bullet, scene_colors::kArena), kMinBlockContrast);
    const Color o = outlineFor(bullet, scene_colors::kArena);
    EXPECT_GE(contrastRatio(o, scene_colors::kArena), 7.0);
    Color red;
    ASSERT_TRUE(parseHexColor("#d04040", red));
    EXPECT_GE(contrastRatio(red, scene_colors::kArena), kMinBlockContrast);
    EXPECT_EQ(outlineFor(red, scene_colors::kArena).packed(), scene_colors::kOutline.packed());
    // On a light arena a light block gets a dark outline.
    const Color lightArena{0.95f, 0.95f, 0.93f, 1.0f};
    const Color pale{0.9f, 0.9f, 0.88f, 1.0f};
    EXPECT_GE(contrastRatio(outlineFor(pale, lightArena), lightArena), 7.0);
    EXPECT_DOUBLE_EQ(contrastRatio(red, red), 1.0);
}

TEST(ScenePicker, ShippedScenesInTheLecturesOrderWithTheirTitles) {
    const auto list = listScenes(SANDBOX_SCENES_DIR);
    ASSERT_GE(list.size(), 15u);
    EXPECT_EQ(list[0].title, "Bouncing squares");
    auto at = [&list](const std::string& file) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            if (std::filesystem::path(list[i].path).filename() == file) return i;
        }
        return list.size();
    };
    EXPECT_LT(at("lecture_example_1.json"), at("lecture_example_2.json"));
    EXPECT_LT(at("point_of_impact.json"), at("lecture_example_1.json"));
    EXPECT_LT(at("lecture_example_2.json"), at("bullet_wall.json"));
    EXPECT_LT(at("bullet_wall.json"), at("gas_500.json"));
    for (const SceneEntry& e : list) {
        const SceneResult r = loadSceneFile(e.path);
        ASSERT_TRUE(r.scene) << e.path;
        EXPECT_EQ(e.title, r.scene->name);
    }
    // Every scene the order file names exists (a renamed scene must be renamed there too).
    std::ifstream order(std::filesystem::path(SANDBOX_SCENES_DIR) / kSceneOrderFile);
    int named = 0;
    for (std::string line; std::getline(order, line);) {
        if (line.empty() || line[0] == '#') continue;
        EXPECT_LT(at(line), list.size()) << line;
        ++named;
    }
    EXPECT_GE(named, 15);
}

TEST(Classroom, EscapeClosesTheTopmostThingAndNeverQuits) {
    EXPECT_EQ(escapeEffect(true, true, true, true), EscapeEffect::CloseDialog);
    EXPECT_EQ(escapeEffect(false, true, false, true), EscapeEffect::CloseHelp);
    EXPECT_EQ(escapeEffect(false, true, true, false), EscapeEffect::LeavePresent);
    EXPECT_EQ(escapeEffect(false, false, false, true), EscapeEffect::LeaveFullscreen);
    EXPECT_EQ(escapeEffect(false, false, false, false), EscapeEffect::Nothing);
}

TEST(Classroom, UnsavedEditsAreBlockEditsOrChangedSettings) {
    WorldSettings scene;
    EXPECT_FALSE(hasUnsavedEdits(false, scene, scene));
    EXPECT_TRUE(hasUnsavedEdits(true, scene, scene));
    WorldSettings now = scene;
    now.method = Method::TurnBased;
    EXPECT_TRUE(hasUnsavedEdits(false, scene, now));
    now = scene;
    now.restSpeed = 1.0; // not a setting the user edits
    EXPECT_FALSE(hasUnsavedEdits(false, scene, now));
}

TEST(Classroom, PresentCaptionSaysWhatTheSceneIsTheMethodAndTheTime) {
    EXPECT_EQ(firstSentence("One. Two. Three"), "One.");
    EXPECT_EQ(firstSentence("No stop"), "No stop");
    EXPECT_EQ(presentCaption("Lecture example 1", "A hits B. Then more.", Method::Perfect, 0.625),
              "Lecture example 1: A hits B.   ·   perfect   ·   t = 0.62 s");
    EXPECT_EQ(presentCaption("Lecture example 1", "A hits B.", Method::TurnBased, 2, false),
              "Lecture example 1   ·   turn-based   ·   t = 2.00 s");
}

TEST(Classroom, PausedAtTheStartSaysPToPlay) {
    EXPECT_EQ(startHint(true, 0.0, false, false), "P to play");
    EXPECT_NE(startHint(true, 0.0, true, false).find("F1"), std::string::npos);
    EXPECT_EQ(startHint(false, 0.0, true, false), "");
    EXPECT_EQ(startHint(true, 1.0, false, false), "");
    // On a touch screen the hint names the buttons, never a key.
    for (bool first : {false, true}) {
        const std::string touch = startHint(true, 0.0, first, true);
        EXPECT_NE(touch.find("Play"), std::string::npos) << touch;
        EXPECT_EQ(touch.find("P to"), std::string::npos) << touch;
        EXPECT_EQ(touch.find("F1"), std::string::npos) << touch;
    }
}

TEST(Classroom, TypedValuesAreCheckedAgainstTheInputLimits) {
    // Gravity typed as 1e30 (the slider says +-20): refused, the field keeps its value.
    const TypedValue g = checkTypedValue("gravity", 1e30, -9.81, limits::kGravity);
    EXPECT_FALSE(g.ok);
    EXPECT_EQ(g.value, -9.81);
    EXPECT_EQ(g.message, "gravity: must be from -1e9 to 1e9 m/s^2, not 1e30");
    // Beyond the slider but within the limits: taken.
    const TypedValue g50 = checkTypedValue("gravity", -50.0, -9.81, limits::kGravity);
    EXPECT_TRUE(g50.ok);
    EXPECT_EQ(g50.value, -50.0);
    EXPECT_TRUE(g50.message.empty());
    // Each field of the panel against its row of the one table.
    EXPECT_EQ(checkTypedValue("bounciness C", 1.5, 1.0, limits::kBounciness).message,
              "bounciness C: must be from 0 to 1, not 1.5");
    EXPECT_EQ(checkTypedValue("frame rate", 2e6, 60.0, limits::kFrameRate).message,
              "frame rate: must be from 1 to 1e6 Hz, not 2e6");
    EXPECT_TRUE(checkTypedValue("frame rate", 1000.0, 60.0, limits::kFrameRate).ok);
    EXPECT_EQ(checkTypedValue("substeps", 0, 1, limits::kSubsteps).message,
              "substeps: must be a whole number from 1 to 1000, not 0");
    EXPECT_EQ(checkTypedValue("time scale", 0.0, 1.0, limits::kTimeScale).message,
              "time scale: must be from 0.01 to 100, not 0");
    EXPECT_EQ(checkTypedValue("mass", 0.0, 2.0, limits::kMass).message,
              "mass: must be from 1e-15 to 1e15 kg, not 0");
    EXPECT_TRUE(checkTypedValue("mass", 1e6, 2.0, limits::kMass).ok); // high_mass_ratio's giant
    EXPECT_EQ(checkTypedValue("size", 0.0, 1.0, limits::kSize).message,
              "size: must be from 1e-6 to 1e9 m, not 0");
    EXPECT_EQ(checkTypedValue("velocity", -2e9, 3.0, limits::kSpeed).message,
              "velocity: must be from -1e9 to 1e9 m/s, not -2e9");
    const TypedValue nan = checkTypedValue("bounciness C", NAN, 0.5, limits::kBounciness);
    EXPECT_FALSE(nan.ok);
    EXPECT_EQ(nan.value, 0.5);
    const TypedValue inf = checkTypedValue("mass", INFINITY, 2.0, limits::kMass);
    EXPECT_FALSE(inf.ok);
    EXPECT_EQ(inf.value, 2.0);
}

TEST(Classroom, TheTypedValueWarningClearsWhenAGoodValueComes) {
    TypedWarning w;
    EXPECT_FALSE(w.note("mass", checkTypedValue("mass", 0.0, 2.0, limits::kMass)));
    EXPECT_EQ(w.field, "mass");
    EXPECT_EQ(w.message, "mass: must be from 1e-15 to 1e15 kg, not 0");
    // A good value of another field leaves it; a good mass clears it.
    EXPECT_TRUE(w.note("velocity", checkTypedValue("velocity", 3.0, 0.0, limits::kSpeed)));
    EXPECT_EQ(w.field, "mass");
    EXPECT_TRUE(w.note("mass", checkTypedValue("mass", 0.5, 2.0, limits::kMass)));
    EXPECT_TRUE(w.message.empty());
    EXPECT_TRUE(w.field.empty());
    // A new refusal replaces the warning (one at a time, under its field).
    w.note("substeps", checkTypedValue("substeps", 2000, 1, limits::kSubsteps));
    w.note("frame rate", checkTypedValue("frame rate", 0.5, 60, limits::kFrameRate));
    EXPECT_EQ(w.field, "frame rate");
}

TEST(Classroom, ANewSceneClearsTheTypedValueWarning) {
    const SceneResult stack =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/resting_stack.json");
    ASSERT_TRUE(stack.scene);
    App app;
    app.ui.typedWarning.note("mass", checkTypedValue("mass", 0.0, 2.0, limits::kMass));
    setScene(app, *stack.scene, "resting_stack.json");
    EXPECT_TRUE(app.ui.typedWarning.message.empty());
}

TEST(Classroom, RestingStackHasAReferenceHeight) {
    const SceneResult stack =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/resting_stack.json");
    ASSERT_TRUE(stack.scene);
    const auto top = restingStackTop(*stack.scene);
    ASSERT_TRUE(top);
    EXPECT_DOUBLE_EQ(*top, 5.0); // five 1 m blocks on the floor
    const SceneResult moving =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/lecture_example_1.json");
    ASSERT_TRUE(moving.scene);
    EXPECT_FALSE(restingStackTop(*moving.scene)); // no gravity, moving blocks
    Scene floating = *stack.scene;
    floating.blocks[0].position.y += 0.5; // the stack no longer stands on the floor
    EXPECT_FALSE(restingStackTop(floating));
    // Blocks at rest on the floor and on a static shelf, none on another: no stack.
    const SceneResult platformer =
        loadSceneFile(std::string(SANDBOX_SCENES_DIR) + "/platformer.json");
    ASSERT_TRUE(platformer.scene);
    EXPECT_FALSE(restingStackTop(*platformer.scene));
}

World movingWorld() {
    World w;
    w.settings.gravity = Vec2{0, 0};
    Block b;
    b.position = {5, 5};
    b.size = {1, 1};
    b.velocity = {1, 0};
    b.mass = 1;
    w.blocks = {b};
    return w;
}

// Steps `w` `n` frames, recording each in `h` as the app does.
void steps(WorldHistory& h, World& w, int n) {
    for (int i = 0; i < n; ++i) {
        h.beforeStep(w);
        w.step();
        h.afterStep(w);
    }
}

TEST(HistoryForTheTimeline, RecordedSecondsUseTheFramesOwnTimes) {
    WorldHistory h;
    World w = movingWorld();
    steps(h, w, 60);
    EXPECT_NEAR(h.recordedSeconds(), 1.0, 1e-12);
    w.settings.dt = 1.0 / 30.0; // a frame-rate change: frames times the current dt would say 2 s
    steps(h, w, 30);
    EXPECT_NEAR(h.recordedSeconds(), 2.0, 1e-12); // 1 s at 60 Hz and 1 s at 30 Hz
}

TEST(HistoryForTheTimeline, AnEditDuringReplayStartsANewFuture) {
    WorldHistory h;
    World w = movingWorld();
    steps(h, w, 60);
    World back;
    ASSERT_TRUE(h.stateAt(20, back));
    back.blocks[0].position.y = 8.0; // dragged during replay
    h.editedAt(back);
    EXPECT_EQ(h.lastFrame(), 20u); // the old future is gone
    World newest;
    ASSERT_TRUE(h.stateAt(h.lastFrame(), newest));
    EXPECT_EQ(newest.blocks[0].position.y, 8.0); // >| keeps the edit
    steps(h, back, 1);
    EXPECT_EQ(h.lastFrame(), 21u);
    World again;
    ASSERT_TRUE(h.stateAt(20, again));
    EXPECT_EQ(again.blocks[0].position.y, 8.0); // scrubbing back shows the edited state
}

} // namespace

// Every overlay on at 1280x720 makes small windows: they switch to the compact font; at
// 1920x1080 (UI scale 1.5) and with few windows they keep the UI font.
TEST(CompactWindows, SmallDockedWindowsUseTheCompactFont) {
    EXPECT_TRUE(compactWindow(387, 198, 16));  // the plots, all overlays on at 1280x720
    EXPECT_TRUE(compactWindow(135, 181, 16));  // the momenta
    EXPECT_FALSE(compactWindow(387, 720, 16)); // the inspector alone
    EXPECT_FALSE(compactWindow(560, 470, 24)); // 1920x1080 at UI scale 1.5
    EXPECT_TRUE(compactWindow(560, 300, 24));
    EXPECT_LT(kCompactFontScale, 1.0);
}

namespace {
// One width unit per byte: a monospaced stand-in for the font.
double bytes(const std::string& line) {
    return static_cast<double>(line.size());
}
} // namespace

// Wrapped at spaces only: a number's '.' or a pair's ',' never starts a line (ImGui's TextWrapped
// put "58." and "152)" on two lines in the Momenta window); the text's newlines stay; a word
// wider than the line is cut between characters, never inside a UTF-8 sequence.
TEST(WrapAtSpaces, BreaksAtSpacesOnly) {
    EXPECT_EQ(wrapAtSpaces("total p = (-2.6, 58.152) kg·m/s", 16, bytes),
              "total p = (-2.6,\n58.152) kg·m/s");
    EXPECT_EQ(wrapAtSpaces("0.8 s recorded, 4 keyframes, 0.0 MB", 30, bytes),
              "0.8 s recorded, 4 keyframes,\n0.0 MB");
    EXPECT_EQ(wrapAtSpaces("short", 30, bytes), "short");
    EXPECT_EQ(wrapAtSpaces("", 30, bytes), "");
    EXPECT_EQ(wrapAtSpaces("one\ntwo three", 5, bytes), "one\ntwo\nthree");
    EXPECT_EQ(wrapAtSpaces("a /very/long/path.json", 8, bytes), "a\n/very/lo\nng/path.\njson");
    const std::string cut = wrapAtSpaces("ééééé", 4, bytes); // 2 bytes each
    EXPECT_EQ(cut, "éé\néé\né");
}

// Issue 39: the start hint wider than a narrow scene (1280x720, UI 1.5, the inspector docked
// beside it) breaks between its parts, the separator left out; a part wider than a line at spaces.
TEST(WrapAtSeparators, BreaksBetweenPartsThenAtSpaces) {
    const std::string hint = "P to play   ·   N one step   ·   F1 help (keys, overlays)";
    EXPECT_EQ(wrapAtSeparators(hint, "   ·   ", 100, bytes), hint);
    EXPECT_EQ(wrapAtSeparators(hint, "   ·   ", 30, bytes),
              "P to play   ·   N one step\nF1 help (keys, overlays)");
    EXPECT_EQ(wrapAtSeparators(hint, "   ·   ", 12, bytes),
              "P to play\nN one step\nF1 help\n(keys,\noverlays)");
    EXPECT_EQ(wrapAtSeparators("", "   ·   ", 12, bytes), "");
    EXPECT_EQ(wrapAtSeparators("a b c", "", 3, bytes), "a b\nc");
}

// Issue 23: the inspector's lines wrap before an operator, never after one, never inside a
// number, and never leave one word alone on the last line; the wrapped chain still reads as one
// (equation_check) and holds.
TEST(WrapFormula, BreaksBeforeOperatorsAndKeepsTheChainReadable) {
    const std::string p = "p before = 1·1.59369958 + 1000000·0.99999873 = 1000000.324 kg·m/s";
    const std::string wrapped = wrapFormula(p, 50, bytes);
    EXPECT_EQ(wrapped, "p before = 1·1.59369958 + 1000000·0.99999873\n  = 1000000.324 kg·m/s");
    EXPECT_TRUE(equationsHold(wrapped, kFormatNumberUnit));
    EXPECT_EQ(checkEquations(wrapped).checked, 1);
    for (double width : {12.0, 20.0, 30.0, 40.0, 60.0}) {
        const std::string w = wrapFormula(p, width, bytes);
        std::size_t start = 0;
        while (start <= w.size()) {
            const std::size_t end = std::min(w.find('\n', start), w.size());
            const std::string line = w.substr(start, end - start);
            const std::string last = line.substr(line.rfind(' ') + 1);
            // No line ends with an operator; every number is whole (its digits on one line).
            EXPECT_TRUE(last != "=" && last != "+") << width << ": " << w;
            start = end + 1;
        }
        // A product wider than a line breaks between its factors, never inside a number.
        for (const char* number : {"1.59369958", "0.99999873", "1000000.324"})
            EXPECT_NE(w.find(number), std::string::npos) << width << ": " << w;
        if (width >= 30.0) {
            EXPECT_NE(w.find("1000000·0.99999873"), std::string::npos) << w;
        }
        EXPECT_EQ(checkEquations(w).checked, 1) << w;
        EXPECT_TRUE(equationsHold(w, kFormatNumberUnit)) << w;
    }
    // A word wider than a line (the collision inspector's u of the high mass ratio in a docked
    // window at 1280x720, UI 1.5: cut at the window's edge before) breaks inside, at its quotient
    // first ("...)/(1"), at its products only where a piece is still too wide; units stay whole.
    const std::string u = "u = (1·1.5937 + 1000000·0.99999873006)/(1 + 1000000) = 0.99999932376";
    EXPECT_EQ(wrapFormula(u, 28, bytes),
              "u = (1·1.5937\n  + 1000000·0.99999873006)\n  /(1 + 1000000)\n  = 0.99999932376");
    EXPECT_EQ(wrapFormula(u, 20, bytes),
              "u = (1·1.5937\n  + 1000000\n  ·0.99999873006)\n  /(1 + 1000000)\n  = 0.99999932376");
    EXPECT_EQ(wrapFormula(u, 72, bytes), u);
    for (double width = 18.0; width <= 72.0; width += 1.0) { // "  ·0.99999873006)" is 18 bytes
        const std::string w = wrapFormula(u, width, bytes);
        std::size_t start = 0;
        while (start <= w.size()) {
            const std::size_t end = std::min(w.find('\n', start), w.size());
            EXPECT_LE(bytes(w.substr(start, end - start)), width) << width << ": " << w;
            start = end + 1;
        }
        for (const char* number : {"1.5937", "0.99999873006", "1000000", "0.99999932376"})
            EXPECT_NE(w.find(number), std::string::npos) << width << ": " << w;
        EXPECT_EQ(checkEquations(w).checked, 1) << w;
        EXPECT_TRUE(equationsHold(w, kFormatNumberUnit)) << w;
    }
    EXPECT_EQ(wrapFormula("p = 2 kg·m/s", 4, bytes), "p\n  = 2\nkg·m/s");
    // Prose: at spaces, between clauses first; the last word is not left alone.
    EXPECT_EQ(wrapFormula("without Newton (reflect): no u, each block reverses its own velocity",
                          60, bytes),
              "without Newton (reflect): no u,\neach block reverses its own velocity");
    EXPECT_EQ(wrapFormula("without Newton (reflect): no u, each block reverses its own velocity",
                          70, bytes),
              "without Newton (reflect): no u, each block reverses its own velocity");
    EXPECT_EQ(wrapFormula("a b c d e f g h i j k l m n o p q r s t u v w x y z lone", 52, bytes),
              "a b c d e f g h i j k l m n o p q r s t u v w x y\nz lone");
    EXPECT_EQ(
        wrapFormula("m1 = 1, m2 = 1000000, v1 = 1.5936995812, v2 = 0.9999987301, C = 1", 45, bytes),
        "m1 = 1, m2 = 1000000, v1 = 1.5936995812,\nv2 = 0.9999987301, C = 1");
    // Issue 39: a vector in parentheses is never split ("(6,\n0)" in the momenta window); a
    // longer aside in parentheses still wraps.
    for (double width = 6.0; width <= 30.0; width += 1.0)
        EXPECT_NE(wrapFormula("total p = (6, 0) kg·m/s", width, bytes).find("(6, 0)"),
                  std::string::npos)
            << width;
    // A vector that fits on a line alone but not after its "=" starts its own line rather than
    // overflow the window (gas_500's momenta at 1920x1080, UI 1.5).
    EXPECT_EQ(wrapFormula("total p = (20.052, -17.339) kg·m/s", 18, bytes),
              "total p =\n(20.052, -17.339)\nkg·m/s");
    EXPECT_EQ(wrapFormula("p = (123456, 654321)", 10, bytes), "p\n  = (123456,\n654321)");
    EXPECT_EQ(wrapFormula("a (long aside in parentheses) b", 14, bytes),
              "a (long aside\nin\nparentheses) b");
    EXPECT_EQ(wrapFormula("short = 1", 30, bytes), "short = 1");
    // A short relation is not split where it fits on a line (a phone's lesson caption broke
    // "Here C / = 1"); a longer chain still breaks before its operator.
    EXPECT_EQ(wrapFormula("Here C = 1", 8, bytes), "Here\nC = 1");
    EXPECT_EQ(wrapFormula("with C = 0.5 the blocks", 12, bytes), "with C = 0.5\nthe blocks");
    EXPECT_EQ(wrapFormula("Here C = 1", 4, bytes), "Here\nC\n  = 1");
    EXPECT_EQ(wrapFormula("v = 2 + 3 = 5", 9, bytes), "v = 2 + 3\n  = 5");
    EXPECT_EQ(wrapFormula("one\ntwo = 2", 30, bytes), "one\ntwo = 2");
    // An aside after a gap of spaces goes under its equation where the two do not fit on a line
    // (the collision inspector, 311 px wide at 1280x800 UI 1.5, ran it past its edge); the gap
    // stays where they fit.
    const std::string aside = "v2' = v2 = 0   (infinite mass: unchanged)";
    EXPECT_EQ(wrapFormula(aside, 30, bytes), "v2' = v2 = 0\n(infinite mass: unchanged)");
    EXPECT_EQ(wrapFormula(aside, 41, bytes), aside);
}

// Issue 25: the inspector shows the friction rule that acted, |dvt| <= mu·|dvn|, with numbers
// whose equation holds as printed (the product is that of the digits shown, exact in decimal).
TEST(InspectorFormat, ShowsTheFrictionRuleWithDigitsThatHold) {
    CollisionRecord r = rightWallHit(1, 2.0);
    EXPECT_EQ(collisionFormula(r, "m2 = 2 kg", "floor").friction, "") << "no friction: no line";
    r.axis = 1;
    r.mu = 0.5, r.dvn = 2.3, r.dvt = 0.5 * 2.3;
    EXPECT_EQ(collisionFormula(r, "m2 = 2 kg", "floor").friction,
              "friction along x: |dvt| = mu·|dvn| = 0.5·2.3 = 1.15 m/s (kinetic: still sliding)");
    r.dvt = 0.4; // it stopped sliding: less than the bound
    EXPECT_EQ(collisionFormula(r, "m2 = 2 kg", "floor").friction,
              "friction along x: |dvt| = 0.4 < mu·|dvn| = 0.5·2.3 = 1.15 m/s (stopped sliding)");
    // Digits that hold: mu 1/3 and |dvn| 3.0004 are shown as 0.333 and 3, so the bound is 0.999
    // (not 1.0001, their true product); a |dvt| of 0.9996 shows as 1 > 0.999: it is called kinetic.
    r.mu = 1.0 / 3.0, r.dvn = 3.0004, r.dvt = 0.9996;
    EXPECT_EQ(collisionFormula(r, "m2 = 2 kg", "floor").friction,
              "friction along x: |dvt| = mu·|dvn| = 0.333·3 = 0.999 m/s (kinetic: still sliding)");
    // A resting contact with the exact integrator: rates (m/s²).
    r.mu = 0.25, r.dvn = 9.81, r.dvt = 0.25 * 9.81, r.perSecond = true;
    EXPECT_EQ(collisionFormula(r, "m2 = 2 kg", "floor").friction,
              "friction along x (resting, per second): |dvt| = mu·|dvn| = 0.25·9.81 = 2.4525 m/s² "
              "(kinetic: still sliding)");
}
