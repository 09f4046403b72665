// What the overlays share: the draw functions the table in overlays.h names, drawn in its order,
// and their window: docked where the frame's layout (app.view.layout) puts it, around the scene and
// never over the world, and opaque enough to read. Dragging a docked window by its title bar
// pulls it out to float (movable, resizable); its "dock" button puts it back. In present mode no
// window is drawn.
#pragma once

#include "app.h"
#include "whole_rows.h"

#include <imgui.h>

#include <optional>
#include <string>
#include <vector>

// Begins the window of row `id` (ImGui::End() must follow, as with Begin), with the row's title,
// docked at its rectangle in app.view.layout, or floating when pulled out; its close button clears
// the row's flag. The one placement function: every overlay window goes through it (through
// OverlayWindow).
bool beginOverlayWindow(App& app, OverlayId id);
// Notes the current window (between Begin and End) in app.view.shownWindows, for --layout-json,
// and a mouse button pressed in it (app.ui.clickedWindow: the keyboard goes to it from another
// window); when the keyboard focus was asked for it (app.ui.keyboardFocus), moves ImGui's
// navigation there, its focus ring on the window's first control.
void recordShownWindow(App& app, const char* name);
// F6: the window after the one that has the keyboard (app.ui.keyboardWindow), in the last frame's
// drawing order of the windows with controls (the overlay windows, the panel, Help, a dialog);
// the panel when the scene has it (else the first); "" when none is shown.
std::string nextWindowForKeyboard(const App& app);
// Where the camera shows the world's point `p` (m) on screen (px), as ImGui draws it.
ImVec2 toScreen(const App& app, Vec2 p);
// The point of impact's boxes on screen (old, POI, moved back, new; px) when its overlay shows
// them this frame, else none: the scene's labels, drawn before the overlays, go around them.
std::vector<ScreenRect> poiBoxesOnScreen(const App& app);
// The centre of mass's marker and its arrow on screen (px) when its overlay is on, else none
// (com_overlay.cpp).
std::vector<ScreenRect> comMarkerOnScreen(const App& app);
// Where an overlay's label of `size` px wanted at `at` (its top-left) goes over the scene: there,
// or moved up or down by lines (then sideways) until it lies in the scene's view and overlaps
// nothing taken on screen this frame (the blocks, their labels, the axis numbers, the arrows'
// values: app.ui.takenOnScreen); the spot is then taken too (scene_view.cpp).
ImVec2 placeSceneLabel(App& app, ImVec2 at, ImVec2 size);
// The first of `tries` (top-left corners, in order of preference: a mark's label beside each of
// its sides) where the label lies in the view and overlaps nothing taken on screen; where none
// is free, placeSceneLabel from the first. The spot is then taken.
ImVec2 placeSceneLabelAtOneOf(App& app, const std::vector<ImVec2>& tries, ImVec2 size);
// The font of the scene's labels: the UI's label font, slide-sized in a lesson and in present
// mode (uiSlideLabelFont). SceneLabelFont pushes it while it lives (overlays drawn over the
// scene).
struct ImFont;
ImFont* sceneLabelFont(const App& app);
struct SceneLabelFont {
    explicit SceneLabelFont(const App& app);
    ~SceneLabelFont();
    SceneLabelFont(const SceneLabelFont&) = delete;
    SceneLabelFont& operator=(const SceneLabelFont&) = delete;
};

// A box of the world (centre and size, m) that a caption over the scene must not cover.
struct WorldBox {
    Vec2 centre;
    Vec2 size;
};
// One line of a caption over the scene, in its colour (the dark theme's; uiThemed deepens it;
// or, `themed`, already the theme's: a mark's, uiMarkColor), and, where the scene is too narrow
// for the line, its brief form ("" keeps the line as it is).
struct CaptionLine {
    std::string text;
    ImU32 color;
    bool themed = false;
    std::string brief = "";
};
// Where a caption of `width` x `height` px goes over the scene (placeCaption): covering no
// block (grown by its labels), none of `boxes` (grown by one and a half lines), nor the status
// badge, the axis numbers and the labels taken on screen so far (app.ui.takenOnScreen).
ImVec2 sceneCaptionPlace(const App& app, float width, float height,
                         const std::vector<WorldBox>& boxes);
// Lines of text on a plate over the scene, where sceneCaptionPlace finds room (the point of
// impact's numbers, the student's trace), never wider than the scene: where the lines are wider,
// their brief forms, wrapped (wrapFormula) to the scene's width where even those are. Where the
// plate would hide a text drawn so far (a label), the brief or wrapped forms, then narrower ones,
// if one finds a spot hiding none (else the one hiding the least). The plate is then taken on
// screen (app.ui.takenOnScreen): the labels drawn after it go around it.
void drawSceneCaption(App& app, const std::vector<CaptionLine>& lines,
                      const std::vector<WorldBox>& boxes);

// The window of an overlay row (overlays.h: its title and placement), closed by its close button
// through the row's flag. Ends the window when it goes out of scope; false while collapsed:
//     OverlayWindow overlay(app, OverlayId::plots);
//     if (!overlay) return;
class OverlayWindow {
  public:
    OverlayWindow(App& app, OverlayId id);
    ~OverlayWindow();
    OverlayWindow(const OverlayWindow&) = delete;
    OverlayWindow& operator=(const OverlayWindow&) = delete;
    explicit operator bool() const { return open_; }
    // Docked and small (compactWindow): drawn in the compact font; show what matters first.
    bool compact() const { return font_; }

  private:
    bool begun_ = false;
    bool open_ = false;
    bool font_ = false; // the compact font pushed
    // The window shows whole rows: a line its edge would cut scrolls into view whole.
    std::optional<WholeRows> wholeRows_;
};

// The draw functions the table names (one file each in overlays/).
#define SANDBOX_OVERLAY_DRAW_DECL(member, name, label, tooltip, on, title, place, draw)            \
    void draw(App& app);
SANDBOX_OVERLAYS(SANDBOX_OVERLAY_DRAW_DECL)
#undef SANDBOX_OVERLAY_DRAW_DECL

// The frame's part: each shown overlay's draw function, in the table's order.
void drawOverlays(App& app);

// One text line with a dim label and a value, for compact readouts.
void dimText(const char* text);
