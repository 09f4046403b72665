// How the UI renderer splits an ImGui draw command: into runs of solid triangles (every vertex
// at the font atlas's white texel: window backgrounds, frames, buttons, filled shapes) and runs
// of textured ones (glyphs, ImGui's anti-aliased lines). Solid runs are drawn without sampling
// the texture, which on llvmpipe is about a quarter of a UI pixel's cost; a solid triangle drawn
// with the texture looks the same (white texel x colour), so a small solid run between textured
// ones joins them rather than paying for two more draw calls. No GL here: tested in tests/app.
#pragma once

#include <imgui.h>

#include <vector>

// Framebuffer pixels [x0, x1) x [y0, y1), rows counted from the top.
struct UiPixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct UiDrawRun {
    unsigned firstIndex = 0; // into the draw list's index buffer
    unsigned indexCount = 0; // a multiple of 3
    bool solid = false;      // every vertex at the white texel: no texture needed
    // An opaque fill (solid, one colour with alpha 255, one convex fan: a window's background,
    // a frame): the pixels it surely covers, which a clear to `color` paints as the triangles
    // would (the triangles then draw only the rest); empty otherwise.
    UiPixelRect inside;
    ImU32 color = 0;
};

// Appends to `runs` the runs of the `indexCount` indices from `indices` (vertex numbers into
// `vertices`, from the command's VtxOffset), in drawing order; `firstIndex` counts from
// `indexBase`. Solid runs whose triangles cover fewer than `minSolidPixels` in all become part of
// the textured runs around them; neighbouring runs of the same kind are merged.
void splitIntoRuns(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned indexBase,
                   unsigned indexCount, ImVec2 whiteUv, float minSolidPixels,
                   std::vector<UiDrawRun>& runs);

// Splits every solid run of `runs` (from splitIntoRuns, with the same `vertices` and `indices`,
// `indexBase`) around its opaque fills whose sure pixels number at least `minPixels`, and gives
// those their `inside`. ImGui fills a rectangle or a convex shape with a fan of triangles
// (v, v+k+1, v+k+2), every vertex one colour; the sure pixels are those whose centres lie more
// than a twentieth of a pixel inside the fan's widest rectangle of full width (a rounded window
// loses its corners' rows). Positions map to framebuffer pixels as (pos - origin) * scale.
void findOpaqueFills(const ImDrawVert* vertices, const ImDrawIdx* indices, unsigned indexBase,
                     ImVec2 origin, ImVec2 scale, int minPixels, std::vector<UiDrawRun>& runs);
