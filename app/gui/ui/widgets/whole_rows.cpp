#include "whole_rows.h"

#include "imgui_ext.h"

#include <imgui.h>

#include <algorithm>
#include <map>
#include <vector>

namespace {

// What a region hid in the frame before: its strips, while it stays where it was.
struct Hidden {
    int frame = -1;
    ImVec2 pos, scroll;
    float top = 0.0f, bottom = 0.0f; // the clip rectangle's edges kept (screen px)
    float clipTop = 0.0f, clipBottom = 0.0f;
};
// By the region's draw list (a window keeps its own from frame to frame).
std::map<const ImDrawList*, Hidden> gHidden;
// The texts kept together (WholeRows::keepTogether) in the regions being drawn, by draw list.
std::map<const ImDrawList*, std::vector<imgui_ext::Span>> gTogether;

ImVec2 scrollOfWindow() {
    return ImVec2(ImGui::GetScrollX(), ImGui::GetScrollY());
}

} // namespace

WholeRows::WholeRows() : mark_(imgui_ext::markDrawing()) {
    // Right after Begin: the window's clip rectangle, inside its frame and scroll bars.
    ImDrawList* list = ImGui::GetWindowDrawList();
    gTogether[list].clear(); // from here on its texts kept together are noted
    clipTop_ = list->GetClipRectMin().y;
    clipBottom_ = list->GetClipRectMax().y;
    // The mouse over a strip hidden in the frame before reaches nothing under it.
    const auto it = gHidden.find(list);
    if (it == gHidden.end()) return;
    const Hidden& h = it->second;
    const ImVec2 pos = ImGui::GetWindowPos(), scroll = scrollOfWindow();
    if (h.frame != ImGui::GetFrameCount() - 1 || h.pos.x != pos.x || h.pos.y != pos.y ||
        h.scroll.x != scroll.x || h.scroll.y != scroll.y)
        return;
    const float left = list->GetClipRectMin().x, right = list->GetClipRectMax().x;
    const float strips[2][2] = {{h.clipTop, h.top}, {h.bottom, h.clipBottom}};
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    for (const auto& strip : strips) {
        if (strip[1] > strip[0] && mouse.x >= left && mouse.x < right && mouse.y >= strip[0] &&
            mouse.y < strip[1])
            imgui_ext::takeHover(ImVec2(left, strip[0]), ImVec2(right, strip[1]));
    }
}

void WholeRows::keepTogether(ImVec2 min, ImVec2 max) {
    // Noted only where a region that shows whole rows is being drawn.
    const auto it = gTogether.find(ImGui::GetWindowDrawList());
    if (it != gTogether.end()) it->second.push_back(imgui_ext::Span{min.y, max.y});
}

std::vector<imgui_ext::Span> WholeRows::rowsOf(std::vector<imgui_ext::Span> spans, float tall) {
    imgui_ext::MergedSpans merged{tall};
    for (const imgui_ext::Span& s : spans) merged.add(s);
    return rowsOf(std::move(merged));
}

std::vector<imgui_ext::Span> WholeRows::rowsOf(imgui_ext::MergedSpans merged) {
    const float kSlack = merged.slack;
    // The tall ones left out, and spans drawn one after the other that meet taken as one, as they
    // came (a line of text is a hundred triangles of nearly one span): the rows come out the same
    // (the span from [y0, y1 + kSlack] of two that meet is their union, so the spans' union and
    // the rows, its parts, are unchanged), and the sort below has a span a row or so, not a
    // triangle (half a millisecond a frame in the browser, for the panel's text).
    std::vector<imgui_ext::Span>& spans = merged.spans;
    std::sort(spans.begin(), spans.end(),
              [](const imgui_ext::Span& a, const imgui_ext::Span& b) { return a.y0 < b.y0; });
    // Rows: spans merged where they overlap or touch (a rounded frame is drawn as a fan of
    // triangles that meet at a corner's height).
    std::vector<imgui_ext::Span> rows;
    for (const imgui_ext::Span& s : spans) {
        if (!rows.empty() && s.y0 <= rows.back().y1 + kSlack)
            rows.back().y1 = std::max(rows.back().y1, s.y1);
        else
            rows.push_back(s);
    }
    return rows;
}

void WholeRows::end() {
    std::vector<imgui_ext::Span> together;
    if (const auto it = gTogether.find(mark_.list); it != gTogether.end()) {
        together = std::move(it->second);
        gTogether.erase(it);
    }
    if (!imgui_ext::stillDrawing(mark_)) return; // ended in another window
    const float top = clipTop_, bottom = clipBottom_;
    // Every triangle drawn, as the span of heights it covers, and the texts kept together; a tall
    // one (a background) is no row, nor the keyboard's focus ring (its colour is no control's):
    // it reaches into the gaps between rows and would join the focused row to the next, hiding
    // it with a row cut under it. Taken in as they come (rowsOf's spans, without a list of every
    // triangle's first).
    imgui_ext::MergedSpans spans{0.5f * (bottom - top)};
    imgui_ext::drawnSince(mark_, ImGui::GetColorU32(ImGuiCol_NavHighlight), spans);
    for (const imgui_ext::Span& s : together) spans.add(s);
    const std::vector<imgui_ext::Span> rows = WholeRows::rowsOf(std::move(spans));
    constexpr float kEdge = 1.0f; // px
    float keptTop = top, keptBottom = bottom;
    for (const imgui_ext::Span& r : rows) {
        // Cut: more than a pixel over the edge (ImGui's keyboard navigation takes a row a pixel
        // over as in view and does not scroll to it; a pixel of a frame's edge cuts no text).
        if (r.y0 < top - kEdge && r.y1 > top) keptTop = std::max(keptTop, r.y1);
        if (r.y0 < bottom && r.y1 > bottom + kEdge) keptBottom = std::min(keptBottom, r.y0);
    }
    if (keptTop >= keptBottom) { // a row taller than the region: leave it cut
        gHidden.erase(mark_.list);
        return;
    }
    if (keptTop > top || keptBottom < bottom) imgui_ext::clipDrawnSince(mark_, keptTop, keptBottom);
    Hidden& h = gHidden[mark_.list];
    h.frame = ImGui::GetFrameCount();
    h.pos = ImGui::GetWindowPos();
    h.scroll = scrollOfWindow();
    h.top = keptTop;
    h.bottom = keptBottom;
    h.clipTop = top;
    h.clipBottom = bottom;
}
