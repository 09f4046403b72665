// Where the scene's texts go (scene_view.cpp, the overlays' labels, the magnifier): the
// rectangles taken on screen (the blocks, the overlays' marks and every text drawn so far) and the
// searches for a free spot beside them. Labels never lie about whom they name (issue 39): a label
// sits on its block or beside it, off the other blocks, marks and texts.
#pragma once

#include "app.h"
#include "rect_strips.h"

#include <imgui.h>

using Taken = UiState::TakenOnScreen;

// The blocks taken on screen by rows and by columns (blockStrips).
struct BlockStrips {
    RectStrips rows, columns;
};

// Over this many blocks a scene is crowded: only the selected block's name goes beside its block
// when it does not fit on it, and only a few arrows carry their value.
constexpr int kCrowdedScene = 20; // blocks

// The rectangle from (x0, y0) to (x1, y1), px.
ScreenRect spanning(double x0, double y0, double x1, double y1);

// `text` at `at` over a 1 px shadow, readable over blocks and grid alike.
void shadowText(ImDrawList* dl, ImVec2 at, ImU32 color, const char* text,
                ImU32 shadow = IM_COL32(0, 0, 0, 200));

// What a text at (x, y) (top-left) of `size`, widened by `gap` on either side, covers of what is
// taken: the area in common with the blocks, and ten times that with the texts (over a block, a
// label hides less than over another label); infinite outside `view`. 0: a free spot.
double coveredAt(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 size,
                 float gap);

// The top-left of a label of `size` meant for x with its top at `above` or `below`: moved up or
// down in steps of a line (trying above first) until it lies in `view` and overlaps none of
// `placed` (labels already drawn and blocks); where no row is free, the same rows half its width
// to the right, then to the left, and further. Where nothing is free, the spot in `view`
// covering the least (a block rather than its label), else (x, above).
// `blocks`, where given, is blockStrips(placed, ...) (placed.blocks unchanged since): the same
// spot, found faster.
ImVec2 freeSpot(const Taken& placed, const ScreenRect& view, float x, float above, float below,
                ImVec2 size, float line, const BlockStrips* blocks = nullptr);

// The spot for a text of size `ts` at (x, y): there, or moved down a line at a time (at most
// six) until it overlaps nothing in `placed`; where the rows down leave `view`, up instead; where
// no row is free, a free spot sideways (freeSpot: lecture3 step 27's values were written over the
// blocks of a pile), else the row covering the least.
ImVec2 freeRow(const Taken& placed, const ScreenRect& view, float x, float y, ImVec2 ts,
               const BlockStrips* blocks = nullptr);

// placed.blocks by rows and by columns of `view` (rect_strips.h), for the searches of a loop
// that takes texts only (the arrows' values): each search then looks at the blocks near it (in
// both its rows and its columns), not at a thousand. placed.blocks must not change while it is
// used (one taken since is noticed: the searches then look at every block).
BlockStrips blockStrips(const Taken& placed, const ScreenRect& view);

// Takes the blocks' rectangles on screen (placed.blocks[i] is block i's), then the overlays'
// marks drawn later (the point of impact's boxes, the centre of mass): no label goes over them.
void takeBlocks(const App& app, Taken& placed);

// The top of a label of `size` at x inside block `own`'s rectangle (placed.blocks[own]) that
// overlaps no other block: `top` (centred) where that is clear, else the clear row nearest it in
// the block; NAN where no row of the block is clear.
float clearRowInside(const Taken& placed, std::size_t own, float x, float top, ImVec2 size);
