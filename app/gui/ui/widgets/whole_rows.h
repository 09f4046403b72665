// A scroll region that shows whole rows only. A region (a window or a child window that scrolls)
// whose edge cuts through a row of its content (a slider, a line of text, a checkbox and its
// label) hides that row instead: after the content is drawn, the rows are read from what was
// drawn (the vertical extents of everything drawn, merged where they overlap; the gaps between
// them are the row boundaries), and the region's clip rectangle is narrowed to the boundaries
// next to its edges. What is hidden is a strip less than a row high at the top or the bottom; the
// row it hid scrolls into view whole. The mouse does not reach the widgets of a hidden row:
// the strip they are hidden under takes the hover (from the frame before: a row's place is known
// once it is drawn).
#pragma once

#include "imgui_ext.h"

class WholeRows {
  public:
    // Call right after Begin or BeginChild of the region (the window being drawn).
    WholeRows();
    // Call right before End or EndChild: narrows what was drawn since the constructor.
    void end();
    // A text of several lines (a wrapped equation, a paragraph) drawn into the current window at
    // `min`-`max` (screen px): one row, hidden whole where an edge would cut it, rather than
    // shown without its last line ("p after = 0.01·(-300)" without "= -3 kg·m/s"). A text taller
    // than half the region stays lines, as a background is no row.
    static void keepTogether(ImVec2 min, ImVec2 max);

    // The rows of `spans` (heights drawn, screen px): those shorter than `tall`, merged where they
    // overlap or touch (within half a pixel), sorted from the top.
    static std::vector<imgui_ext::Span> rowsOf(std::vector<imgui_ext::Span> spans, float tall);
    // The same of spans already taken in (imgui_ext::MergedSpans, as rowsOf takes them).
    static std::vector<imgui_ext::Span> rowsOf(imgui_ext::MergedSpans spans);

  private:
    imgui_ext::DrawMark mark_;   // where the region's content starts in its window's draw list
    float clipTop_, clipBottom_; // the region's clip rectangle (screen px)
};
