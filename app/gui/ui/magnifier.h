// The magnifier (issue 39, "the evidence is big enough everywhere"): where a lesson step names
// blocks (their names are words of its texts) that the camera draws under the size a class can
// see from the back (40 px on their short side; 28 px on a screen 1024 px wide or less), a second
// view of them, magnified by a round factor that it states ("×4"), bordered, in the scene's free
// space. The part of the world it shows is outlined in the scene. Its rectangle is taken (labels,
// values and axis numbers go around it); its blocks as drawn are app.view.shownMagnified
// (`--layout-json`'s "magnified") and the inset a mark ("magnifier ×4"). Its texts have the role
// "magnifier" (screen_text.h).
#pragma once

#include "label_placement.h"

struct ImDrawList;

// Draws the magnifiers of the frame (none outside a lesson, or when every named block is big
// enough) into `dl` and takes their rectangles in `placed` (blocks taken already: takeBlocks).
void drawMagnifier(App& app, ImDrawList* dl, Taken& placed);
