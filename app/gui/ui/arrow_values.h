// The values the scene writes at arrows' heads (scene_view.cpp draws them after the labels):
// arrows too long to draw to scale (velocity, momentum) and force arrows carry their value, each in
// a free row beside the head, with the inspector's digits where it shows the block's last
// collision, so that a value and the inspector never write different digits for one quantity.
#pragma once

#include "label_placement.h"

#include <optional>

struct SceneView;

// Each takes texts only: `blocks`, placed.blocks by strips (blockStrips), is built by the first
// that writes a value and shared by the others (placed.blocks unchanged between them).
//
// Velocity arrows too long to draw to scale (compressed, cut at the view's edge) carry their
// speed; in the centre-of-mass frame every arrow does, in a scene of few blocks.
void drawArrowValues(const App& app, ImDrawList* dl, Taken& placed,
                     std::optional<BlockStrips>& blocks);
// Momentum arrows too long to draw to scale carry p = m·w at their head.
void drawMomentumValues(const App& app, ImDrawList* dl, Taken& placed,
                        std::optional<BlockStrips>& blocks);
// Force arrows carry "F = 2 N" at their head (to scale only up to the knee).
void drawForceValues(const App& app, const SceneView& view, ImDrawList* dl, Taken& placed,
                     std::optional<BlockStrips>& blocks);
