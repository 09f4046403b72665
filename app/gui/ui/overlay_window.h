// What the overlays share: the draw functions the table in overlays.h names, drawn in its order,
// and their window: semi-transparent, movable, resizable, placed at first use relative to the
// scene's viewport (so it lands sensibly at 720p and on a projector), and placed again when the
// UI scale or the viewport's size changes.
#pragma once

#include "app_state.h"

#include <imgui.h>

// Colours of the plotted quantities (shared by the plots and the arrows' legends).
namespace overlay_colors {
constexpr ImU32 kX = IM_COL32(90, 200, 255, 255);
constexpr ImU32 kY = IM_COL32(255, 120, 170, 255);
constexpr ImU32 kKinetic = IM_COL32(255, 190, 70, 255);
constexpr ImU32 kPotential = IM_COL32(120, 220, 120, 255);
constexpr ImU32 kTotal = IM_COL32(240, 240, 245, 255);
constexpr ImU32 kMomentum = IM_COL32(255, 150, 60, 255);
constexpr ImU32 kCom = IM_COL32(255, 235, 90, 255);
} // namespace overlay_colors

// Begins the semi-transparent window of row `id` (ImGui::End() must follow, as with Begin), with
// the row's title, placed at first use by the row's placement (and again when the UI scale or
// the viewport's size changes); its close button clears the row's flag. The one placement
// function: every overlay window goes through it (through OverlayWindow).
bool beginOverlayWindow(App& app, OverlayId id);

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

  private:
    bool open_;
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
