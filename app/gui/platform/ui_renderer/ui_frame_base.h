// The frame's first paint, planned from ImGui's draw data (desktop GL; llvmpipe): on a software
// rasteriser an opaque fill costs as much as any drawn pixel, even as a scissored clear (Mesa
// draws a quad for it), while a clear of the whole framebuffer costs next to nothing. Three
// colours lie under everything else: the scene's background, its arena (inside the world's
// bounds, painted before the scene draws) and the windows' backgrounds (painted over the scene).
// The whole frame is cleared to the one that covers the most pixels still seen, and only the
// others are painted: the background outside the arena and the fills, the arena outside the
// fills (a fill clears its own pixels over whatever is there), and the fills not of the clear's
// colour or with something drawn under them before their turn. The same pixels as painting
// everything. No GL here: tested in tests/app.
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

// The colour the whole frame is cleared to first.
enum class UiFrameClear { Background, Fills, Arena };

struct UiFrameBase {
    // false: as ever: the frame cleared to the scene's background, all the arena painted, every
    // fill painted.
    bool planned = false;
    UiFrameClear clearTo = UiFrameClear::Background;
    ImU32 clear = 0; // the fills' colour (clearTo Fills)
    // Then these are painted the scene's background (every pixel outside the fills and the
    // arena), unless it is the clear's colour,
    std::vector<UiPixelRect> background;
    // and these the arena's (its pixels outside the fills), unless it is the clear's colour.
    std::vector<UiPixelRect> arena;
    std::vector<bool> skip; // per paint: a fill whose clear is skipped (its pixels hold `clear`)
};

// The plan for `paints` on a width x height framebuffer when the scene may draw within
// `sceneDrawn` and its arena is `arena` (painted before the scene draws): the clear goes to the
// colour that covers most pixels among the background's (outside the fills and the arena), the
// arena's (outside the fills) and, of one colour, the fills that nothing touches before them
// (neither the scene nor an earlier paint); only fills of that colour are skipped.
UiFrameBase planFrameBase(const std::vector<UiPaint>& paints, UiPixelRect sceneDrawn,
                          UiPixelRect arena, int width, int height);

// The pixels of `area` outside every rectangle of `holes`, as rectangles that do not overlap
// (bands from the top, each band's runs merged with the same runs below).
std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& holes, UiPixelRect area);
// The same within [0, width) x [0, height).
std::vector<UiPixelRect> rectsOutside(const std::vector<UiPixelRect>& holes, int width, int height);
