// How the UI renderer splits an ImGui draw command: into runs of solid triangles (every vertex
// at the font atlas's white texel: window backgrounds, frames, buttons, filled shapes) and runs
// of textured ones (glyphs, ImGui's anti-aliased lines). Solid runs are drawn without sampling
// the texture, which on llvmpipe is about a quarter of a UI pixel's cost; a solid triangle drawn
// with the texture looks the same (white texel x colour), so a small solid run between textured
// ones joins them rather than paying for two more draw calls. No GL here: tested in tests/app.
#pragma once

#include <imgui.h>

#include <vector>

struct UiDrawRun {
    unsigned firstIndex = 0; // into the draw list's index buffer
    unsigned indexCount = 0; // a multiple of 3
    bool solid = false;      // every vertex at the white texel: no texture needed
};

// Appends to `runs` the runs of the `indexCount` indices from `indices` (vertex numbers into
// `vertices`, from the command's VtxOffset), in drawing order; `firstIndex` counts from
// `indexBase`. Solid runs whose triangles cover fewer than `minSolidPixels` in all become part of
// the textured runs around them; neighbouring runs of the same kind are merged.
void splitIntoRuns(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned indexBase,
                   unsigned indexCount, ImVec2 whiteUv, float minSolidPixels,
                   std::vector<UiDrawRun>& runs);
