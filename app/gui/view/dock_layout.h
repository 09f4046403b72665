// The docked layout: where the controls panel, the overlay windows and the scene go on screen.
// The panel is a column on the left; docked overlay windows stack in a column on the right, side
// by side in a strip along the bottom (right of the panel, under the column), or at the bottom of
// the panel's column (taking room from the panel, none from the scene); the scene takes the
// rectangle that is left, and the camera fits the world into it, so no docked window ever covers
// the world. Pure logic (no GL,
// no ImGui): given the display size, the UI scale, the panel and the visible windows with their
// wishes, it returns rectangles in screen pixels (whole pixels, inside the display, disjoint).
#pragma once

#include "camera.h"

#include <string>
#include <vector>

// Panel: under the controls panel, in its column (the plots: evidence that costs the scene
// nothing); in the right column when there is no panel column (hidden, or a narrow screen's sheet).
enum class DockSide { Right, Bottom, Panel };

// Where a window docks, as the overlay table (overlays.h) states it: the fields of DockRequest
// without the name.
struct DockWish {
    DockSide side = DockSide::Right;
    double minExtent = 120.0;
    double weight = 1.0;
    double crossExtent = 360.0;
    double heightShare = 0.0;
};

// What a window asks of the layout. Sizes are pixels at UI scale 1 (scaled by the UI scale).
struct DockRequest {
    std::string name;
    DockSide side = DockSide::Right;
    // Along the region's stack (a height in the right column, a width in the bottom strip): the
    // least the window needs, and its weight in sharing what is left once every window has that.
    double minExtent = 120.0;
    double weight = 1.0;
    // Across the region (the column's width, the strip's height): what the window would like.
    double crossExtent = 360.0;
    // Panel side and right column: the window's least height is minExtent (scaled) plus this
    // share of the display's height (content that must be a size on screen whatever the UI
    // scale: plots of 140 px at 1080p). The windows under the panel take at most
    // kMaxPanelDockShare of the height.
    double heightShare = 0.0;
    // When the region's windows fold into tabs (computeLayout), the one with the highest `front`
    // is shown (the one asked for last); on a tie, the first.
    int front = 0;
};

// Narrow screens (a phone held upright): below kSheetBelowPx wide (px at UI scale 1) the panel
// is a sheet along the bottom, the screen's width: closed, one row of buttons kSheetBarPx high
// (44 px touch buttons and the window's padding); open, kSheetOpenShare of the height. Docked
// windows then share a strip above it, and the scene keeps the rest. A touch screen below
// kTouchSheetBelowPx high (a tablet held sideways, 1024x768) gets the sheet too: beside a
// panel column of finger-sized rows, a lesson's caption and its windows would leave the scene a
// fifth of the screen and scroll the panel's Play away.
constexpr double kSheetBelowPx = 600.0;
constexpr double kTouchSheetBelowPx = 800.0;
constexpr double kSheetBarPx = 64.0;
constexpr double kSheetOpenShare = 0.55;
// Above a closed sheet, the windows' strip leaves the scene at least this share of the screen's
// height (a phone held upright: the scene keeps 40% of the screen at a step's moment).
constexpr double kMinSheetSceneShare = 0.40;
bool sheetLayout(double displayWidth, float uiScale, double displayHeight = 0.0,
                 bool touch = false);

struct LayoutInput {
    double displayWidth = 1280.0;
    double displayHeight = 720.0;
    float uiScale = 1.0f;
    double panelWidth = 0.0;  // 0: no panel (hidden, or present mode)
    double panelHeight = 0.0; // > 0: the panel is a sheet this high along the bottom
    // px kept free across the whole width at the top (a lesson's caption bar): the panel, the
    // windows and the scene share what is below it.
    double topInset = 0.0;
    // The height the windows' heightShare is of (0: displayHeight): the image's, also below a
    // caption bar (a plot is 13% of the screen's height wherever it is).
    double shareHeight = 0.0;
    // > 0: the bottom strip of windows at most this high (above a sheet: the scene keeps
    // kMinSheetSceneShare of the screen).
    double maxStripHeight = 0.0;
    // A region (the right column, the bottom strip, the strip above a phone's sheet) whose
    // windows do not fit side by side, each at least kLeastDockShrink of its least extent, folds
    // them into tabs (on a touch screen too: a phone's three windows side by side are each a
    // third of 390 CSS px, their texts cut to a word).
    bool tabs = true;
    std::vector<DockRequest> windows;
};

struct DockedWindow {
    std::string name;
    ScreenRect rect;
};

// Windows folded into tabs: one shown at the region's rectangle (in Layout::windows), with a tab
// bar of every name along its top; the others are one click on their tab away.
struct DockTabs {
    ScreenRect rect;
    std::vector<std::string> names; // in the order the windows were requested
    std::string shown;
};

struct Layout {
    ScreenRect panel;   // width 0 when there is none
    bool sheet = false; // the panel is a sheet along the bottom (sheetLayout)
    ScreenRect scene;   // what the scene view gets
    std::vector<DockedWindow> windows;
    std::vector<DockTabs> tabs;
    // Windows with no room: above a phone's open sheet the scene keeps its share and the strip
    // has none, so its windows are not drawn until the sheet closes.
    std::vector<std::string> hidden;
    // The rectangle of window `name`, or nullptr when it is not docked (or folded behind a tab).
    const ScreenRect* find(const std::string& name) const;
    // The tabs window `name` is folded into, or nullptr.
    const DockTabs* tabsOf(const std::string& name) const;
    bool hides(const std::string& name) const;
};

// Shares of the display the regions never go beyond, so the scene keeps at least about half of
// what the panel leaves in each direction.
constexpr double kMaxColumnShare = 0.42; // of the width right of the panel
constexpr double kMinColumnShare = 0.30;
constexpr double kMaxStripShare = 0.38; // of the height
constexpr double kMinStripShare = 0.15;
constexpr double kMaxPanelDockShare = 0.7; // of the height: the panel keeps the rest
// Every plot is at least this share of the display's height (140 px at 1080p: evidence seen from
// the back row), whatever the UI scale: the plot widget keeps to it (plot_widget.cpp) and the
// cost window's row in the overlay table asks for it as its heightShare.
constexpr double kMinPlotShare = 0.13;
// Windows side by side are drawn down to this share of their least extent (their contents allow
// it: every overlay on at 1280x800, UI 1, and at 1920x1080, UI 1.5, they get 80%); below it, the
// region's windows fold into tabs (DockTabs).
constexpr double kLeastDockShrink = 0.75;
// Pixels (at UI scale 1) between neighbouring windows.
constexpr double kDockGap = 4.0;

Layout computeLayout(const LayoutInput& input);

// A docked window this small for its font (under 14 lines high or 18 ems wide: every overlay on
// at 1280x720) draws its contents in a font kCompactFontScale of the UI font's size, so that more
// of them fit before text wraps or a table scrolls.
constexpr double kCompactFontScale = 0.85;
bool compactWindow(double width, double height, double fontPx);

// True when the two rectangles share positive area (touching edges do not count).
bool rectsOverlap(const ScreenRect& a, const ScreenRect& b);
// True when `inner` lies inside `outer` (edges may coincide).
bool rectInside(const ScreenRect& inner, const ScreenRect& outer);
// Where a caption of `width` x `height` px drawn over the scene goes (the point-of-impact
// overlay's numbers): inside `scene` (`inset` px from its edges), covering none of `avoid` (the
// blocks on screen, grown by their labels). Preferred, in this order: wholly in the scene's
// margin outside `world`, wholly inside `world` (`inset` from its walls), anywhere else; the top
// first, then the left. When every spot covers something, the one covering the least of
// `texts` (labels and numbers drawn there: covering one hides it), then the least area.
ScreenRect placeCaption(double width, double height, const ScreenRect& scene,
                        const ScreenRect& world, const std::vector<ScreenRect>& avoid, double inset,
                        const std::vector<ScreenRect>& texts = {});
// The world's bounds on screen through `camera` (top-left corner and size, y down).
ScreenRect worldRectOnScreen(const Camera& camera, const Bounds& bounds);

// The --layout-json document (docs/cli.md): rectangles as [x, y, w, h] in image pixels,
//   {"scene": [...], "world": [...], "windows": [{"name": "Plots", "rect": [...]}, ...],
//    "blocks": [{"name": "m1", "rect": [...]}, ...], "plots": [{"name": "velocity", ...}, ...],
//    "marks": [{"name": "moved back", "rect": [...]}, ...]}
// and, when a magnifier is drawn (magnifier.h), "magnified": the blocks as drawn in it, by name;
// when a window (or a part of one: a table) must be scrolled sideways to read it, "sideways": that
// part's rectangle by its window's name; when windows are folded into tabs (DockTabs), "folded":
// each window behind a tab, with the rectangle it is shown at when its tab is picked.
std::string layoutJson(
    const ScreenRect& scene, const ScreenRect& world, const std::vector<DockedWindow>& windows,
    const std::vector<DockedWindow>& blocks = {}, const std::vector<DockedWindow>& plots = {},
    const std::vector<DockedWindow>& marks = {}, const std::vector<DockedWindow>& magnified = {},
    const std::vector<DockedWindow>& sideways = {}, const std::vector<DockedWindow>& folded = {});
// JSON pieces of the documents the app writes: a string (quoted, escaped) and [x, y, w, h].
std::string jsonString(const std::string& s);
std::string jsonRect(const ScreenRect& r);
