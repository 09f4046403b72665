// What the overlay windows share: a semi-transparent, movable, resizable window placed at first
// use relative to the scene's viewport (so it lands sensibly at 720p and on a projector), and
// placed again when the UI scale or the viewport's size changes.
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

// Where a window goes at first use: a corner of the scene viewport (anchor 0..1 in x and y,
// e.g. (1, 0) top-right) and its size as a fraction of the viewport, capped in pixels at UI
// scale 1 (scaled by the UI scale).
struct OverlayPlacement {
    float anchorX = 1.0f, anchorY = 0.0f;
    float widthFraction = 0.4f, heightFraction = 0.5f;
    float maxWidth = 480.0f, maxHeight = 480.0f;
};

// Begins a semi-transparent overlay window (ImGui::End() must follow, as with Begin).
bool beginOverlayWindow(const App& app, const char* title, bool* open,
                        const OverlayPlacement& place);

// One text line with a dim label and a value, for compact readouts.
void dimText(const char* text);
