// The view: how the scene is seen and what is shown with it. The camera and what it fits (the
// world's bounds or a lesson step's rectangle), the frame of reference, the overlays shown, the
// UI's scale, theme and present mode, and this frame's layout of the panel, the overlay windows
// and the scene. Plain logic: no GL, no ImGui; the UI binds its widgets to it every frame.
#pragma once

#include "camera.h"
#include "dock_layout.h"
#include "overlays.h"
#include "scene.h"
#include "view_frame.h"
#include "world.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

// The UI scale's range (View section, --ui-scale, the settings file) and the scene labels' size
// relative to the UI font.
constexpr float kMinUiScale = 0.75f, kMaxUiScale = 3.0f;
constexpr float kMinLabelScale = 0.75f, kMaxLabelScale = 2.5f;

struct View {
    Camera camera;
    bool autoFit = true; // refit the camera when the viewport changes, until the user zooms/pans
    std::optional<Bounds> fitBounds; // what fitting shows (a lesson step's camera); none: bounds
    // The frame of reference (view_frame.h): in the centre of mass's the camera moves with u and
    // the arrows show w = v - u (View section, U, --frame com, a lesson step's "frame").
    ViewFrame frame = ViewFrame::World;
    FrameCamera frameCamera;
    Overlays show;
    // A lesson step's overlays that open at its moment (its "reveal"): their docked windows' room
    // is kept from the setup on (computeAppLayout, with a caption bar; not of those under the
    // panel, which take the panel's room), so the scene keeps its size at the answer.
    Overlays reserved = ShowSet::noOverlays();
    bool overlaysChosen = false; // --show given: scenes no longer pick the default overlays
    bool uiVisible = true;
    float uiScale = 1.0f;
    float labelScale = 1.0f; // size of the scene's labels relative to the UI font; persisted
    bool lightTheme = false; // View section; persisted
    // Present mode (Tab): the scene and a one-line caption only; every panel and window hidden,
    // and back as they were when it is left.
    bool presentMode = false;
    bool fullscreen = false; // the window is full screen (the window backend keeps it true)
    // This frame's layout: the panel, the docked overlay windows and the scene's rectangle.
    Layout layout;
    // Overlay windows pulled out of the layout to float (by title); put back with "Dock".
    std::vector<std::string> floatingWindows;
    // Overlay windows by title in the order they were last turned on or picked (the last: the
    // latest): where windows fold into tabs (DockTabs), the latest of them is shown.
    std::vector<std::string> frontWindows;
    Overlays shownBefore = ShowSet::noOverlays(); // the overlays on at the last layout
    // Every window drawn this frame with its rectangle (for --layout-json), in drawing order.
    std::vector<DockedWindow> shownWindows;
    // Every plot drawn this frame (its widget's whole rectangle, by name: "velocity"), likewise.
    std::vector<DockedWindow> shownPlots;
    // Every mark an overlay drew over the scene this frame (the point of impact's boxes: "old",
    // "new", "POI", "moved back"), its rectangle on screen, by the label it carries.
    std::vector<DockedWindow> shownMarks;
    // The blocks a magnifier drew this frame (magnifier.h), their part in its inset, by name.
    std::vector<DockedWindow> shownMagnified;
    double captionHeight = 0.0; // px a lesson's caption bar takes across the top
    bool sheetOpen = false;     // narrow screens: the panel's sheet is open (sheetLayout)
    bool touch = false;         // a touch screen (app.ui.touchUi): a short one gets the sheet too
};

// A lesson's caption bar takes at most this share of the screen's height (lesson_bar.cpp).
constexpr double kMaxCaptionShare = 0.30;
// Width of the controls panel in pixels for a UI scale and window width.
double panelWidth(float uiScale, double displayWidth);
// The panel fits beside the scene: its width at this UI scale (350 px at 1) is at most
// kMaxPanelShare of the display's width (beyond it, panelWidth squeezes it).
constexpr double kPanelPxAtScale1 = 350.0;
constexpr double kMaxPanelShare = 0.45;
bool panelFits(float uiScale, double displayWidth);

// The screens a lecture hall may have (issue 39), each at the UI scales 1, 1.25, 1.5 and 2 where
// the panel fits: what the lesson sweep checks (sandbox-offscreen --record-steps DIR
// --screens all writes each into DIR/name()).
struct ClassroomScreen {
    int width = 0, height = 0;
    float uiScale = 1.0f;
    std::string name() const; // "1280x800_ui1.5"
};
std::vector<ClassroomScreen> classroomScreens();
// This frame's layout: the panel (unless hidden), the shown overlay windows that are not floating
// docked around the scene (none in present mode), and the scene's rectangle; `captionBar`: a
// lesson's caption bar (captionHeight) takes the top of the scene.
Layout computeAppLayout(const View& view, bool captionBar, double displayWidth,
                        double displayHeight);
// The part of the window the scene is drawn into (computeAppLayout's scene).
ScreenRect sceneViewport(const View& view, bool captionBar, double displayWidth,
                         double displayHeight);
// Pixels (at UI scale 1) between the world's bounds and the scene's rectangle when the camera
// fits the world: room for the axis numbers and, at the top, the status badge or caption.
constexpr double kFitMarginPx = 36.0;
// The scene's labels (block names, axis numbers) take this share of the display's height at
// least (ui_style.h: 24 px at 1080, 48 px at 2160): the fit's margin keeps room for the axis
// numbers' row under the floor (scene_view.cpp's placeAxisNumbers, kAxisRowGapPx under it), which
// kFitMarginPx at a small UI scale on a tall display does not (3840x2160 at UI 1 lifted the row
// over the blocks resting on the floor).
constexpr double kSceneLabelShare = 0.022;
constexpr double kAxisRowGapPx = 14.0;
// The UI font at UI scale 1 (px); the scene's labels are at least this x UI scale x label scale.
constexpr double kBaseFontPx = 16.0;
// The scene's label font (px) on a display `displayHeight` px high (ui_style.cpp builds it).
double sceneLabelPx(float uiScale, float labelScale, double displayHeight);
double fitMarginPx(float uiScale, float labelScale, double displayHeight);
// On a narrow screen (sheetLayout) too the fit shows the whole world: a phone held upright sees
// every block of the scene first (the default scene's 0.6 m block is then about 10 CSS px wide
// at 390 CSS px; two fingers or the wheel zoom in, a drag on empty space pans).
// Lays out the frame (view.layout), gives the camera the scene's rectangle and refits `world`
// while view.autoFit holds; in the centre of mass's frame the camera follows it.
void updateCamera(View& view, const World& world, bool captionBar, double displayWidth,
                  double displayHeight);

// Velocity arrows are on by default for scenes with at most this many blocks (more is clutter).
constexpr std::size_t kVectorsByDefaultUpTo = 50;
inline bool vectorsByDefault(const Scene& scene) {
    return scene.blocks.size() <= kVectorsByDefaultUpTo;
}
// A scene was loaded: fit it again, and its arrows on by default when it has few blocks (unless
// --show chose the overlays).
void showNewScene(View& view, const Scene& scene);
// A run started from its first state (a load, R, a lesson step): the centre of mass's frame
// follows from there, however many frames are stepped before the next draw.
void followNewRun(View& view, const World& world);
// Sees the scene in `frame` from now on (the camera follows the centre of mass from where it is).
void setViewFrame(View& view, ViewFrame frame);
// Present mode on or off: every panel and window hidden, and back as they were.
void setPresentMode(View& view, bool on);
// Clamps the UI scale into its range.
void setUiScale(View& view, float scale);
// Sets the overlays from a --show list.
void applyShowSet(View& view, const ShowSet& show);
// Shows window `title` where it is folded behind a tab (its tab picked; its overlay turned on).
void bringToFront(View& view, const std::string& title);
// Is `title` an overlay window pulled out of the layout to float?
bool isFloating(const View& view, const std::string& title);
void setFloating(View& view, const std::string& title, bool floating);
