// The frame's first paint, planned from ImGui's draw data (desktop GL; llvmpipe): on a software
// rasteriser a window's opaque background costs as much as any drawn pixel, even as a scissored
// clear (Mesa draws a quad for it), while a clear of the whole framebuffer costs next to nothing.
// So when the windows' backgrounds outweigh the rest, the whole frame is cleared to their colour,
// only the rest is painted the scene's background, and the windows whose pixels still hold that
// colour when their turn comes (nothing drawn there before them: not the scene, not a label, not
// another window) skip their clear. The same pixels either way. No GL here: tested in tests/app.
#pragma once

#include "ui_draw_runs.h"

#include <imgui.h>

#include <vector>

// What a draw paints, in drawing order: the pixels it may touch (`bounds`), and for an opaque
// fill (UiDrawRun::inside) the pixels it surely paints `color` (`inside`, within its scissor).
struct UiPaint {
    UiPixelRect bounds;
    UiPixelRect inside; // empty: not an opaque fill
    ImU32 color = 0;
};

struct UiFrameBase {
    bool planned = false; // false: the frame is cleared to the scene's background as before
    ImU32 clear = 0;      // the colour the whole frame is cleared to first
    // Then these are painted the scene's background: every pixel outside the fills and the
    // scene's opaque part.
    std::vector<UiPixelRect> background;
    std::vector<bool> skip; // per paint: a fill whose clear is skipped (its pixels hold `clear`)
};

// The plan for `paints` on a width x height framebuffer when the scene may draw within
// `sceneDrawn` (besides its background) and paints all of `sceneCovered` opaque (the arena): the
// fills that nothing earlier touches (nor the scene), of the colour that covers most pixels among
// them, are skipped, when they cover more pixels than the rest of the frame (outside every fill
// and `sceneCovered`), which is then painted the scene's background instead.
UiFrameBase planFrameBase(const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                          UiPixelRect sceneCovered, int width, int height);

// The pixels of [0, width) x [0, height) outside every rectangle of `holes`, as rectangles that
// do not overlap (bands from the top, each band's runs merged with the same runs below).
std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& holes, int width, int height);
