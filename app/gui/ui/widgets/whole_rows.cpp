#include "whole_rows.h"

#include <imgui.h>
#include <imgui_internal.h>

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
std::map<ImGuiID, Hidden> gHidden;

struct Span {
    float y0, y1;
};

} // namespace

WholeRows::WholeRows() {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    list_ = window->DrawList;
    cmdStart_ = list_->CmdBuffer.Size - 1;
    idxStart_ = list_->IdxBuffer.Size;
    id_ = window->ID;
    // The mouse over a strip hidden in the frame before reaches nothing under it.
    const auto it = gHidden.find(id_);
    if (it == gHidden.end()) return;
    const Hidden& h = it->second;
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    if (h.frame != g.FrameCount - 1 || h.pos.x != window->Pos.x || h.pos.y != window->Pos.y ||
        h.scroll.x != window->Scroll.x || h.scroll.y != window->Scroll.y)
        return;
    const ImRect& clip = window->InnerClipRect;
    const ImRect strips[2] = {{ImVec2(clip.Min.x, h.clipTop), ImVec2(clip.Max.x, h.top)},
                              {ImVec2(clip.Min.x, h.bottom), ImVec2(clip.Max.x, h.clipBottom)}};
    for (const ImRect& strip : strips) {
        if (strip.GetHeight() <= 0.0f || !strip.Contains(ImGui::GetIO().MousePos)) continue;
        const ImGuiID stripId = window->GetID("##hidden rows");
        ImGui::ItemAdd(strip, stripId, nullptr, ImGuiItemFlags_NoNav);
        ImGui::ItemHoverable(strip, stripId);
    }
}

void WholeRows::end() {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    if (window->DrawList != list_ || window->ID != id_) return;
    ImVector<ImDrawCmd>& cmds = list_->CmdBuffer;
    if (cmdStart_ < 0 || cmdStart_ >= cmds.Size) return;
    // The first command may hold what was drawn before the content (the window's frame): split.
    ImDrawCmd& first = cmds[cmdStart_];
    const unsigned start = static_cast<unsigned>(idxStart_);
    if (first.IdxOffset < start && first.IdxOffset + first.ElemCount > start) {
        ImDrawCmd rest = first;
        rest.IdxOffset = start;
        rest.ElemCount = first.IdxOffset + first.ElemCount - start;
        first.ElemCount = start - first.IdxOffset;
        cmds.insert(cmds.begin() + cmdStart_ + 1, rest);
    }
    const float top = window->InnerClipRect.Min.y, bottom = window->InnerClipRect.Max.y;
    // Every triangle drawn, as the span of heights it covers; a tall one (a background) is no row,
    // nor the keyboard's focus ring (its colour is no control's): it reaches into the gaps between
    // rows and would join the focused row to the next, hiding it with a row cut under it.
    const ImU32 ring = ImGui::GetColorU32(ImGuiCol_NavHighlight) & ~IM_COL32_A_MASK;
    std::vector<Span> spans;
    for (int c = cmdStart_; c < cmds.Size; ++c) {
        const ImDrawCmd& cmd = cmds[c];
        if (cmd.UserCallback || cmd.IdxOffset < start) continue;
        for (unsigned k = 0; k + 3 <= cmd.ElemCount; k += 3) {
            float y0 = 1e30f, y1 = -1e30f;
            bool focusRing = false;
            for (unsigned v = 0; v < 3; ++v) {
                const ImDrawIdx i = list_->IdxBuffer[static_cast<int>(cmd.IdxOffset + k + v)];
                const ImDrawVert& vert = list_->VtxBuffer[static_cast<int>(cmd.VtxOffset + i)];
                y0 = std::min(y0, vert.pos.y);
                y1 = std::max(y1, vert.pos.y);
                focusRing = focusRing || (vert.col & ~IM_COL32_A_MASK) == ring;
            }
            if (!focusRing && y1 - y0 < 0.5f * (bottom - top)) spans.push_back({y0, y1});
        }
    }
    std::sort(spans.begin(), spans.end(), [](const Span& a, const Span& b) { return a.y0 < b.y0; });
    // Rows: spans merged where they overlap or touch (a rounded frame is drawn as a fan of
    // triangles that meet at a corner's height).
    constexpr float kSlack = 0.5f, kEdge = 1.0f; // px
    std::vector<Span> rows;
    for (const Span& s : spans) {
        if (!rows.empty() && s.y0 <= rows.back().y1 + kSlack)
            rows.back().y1 = std::max(rows.back().y1, s.y1);
        else
            rows.push_back(s);
    }
    float keptTop = top, keptBottom = bottom;
    for (const Span& r : rows) {
        // Cut: more than a pixel over the edge (ImGui's keyboard navigation takes a row a pixel
        // over as in view and does not scroll to it; a pixel of a frame's edge cuts no text).
        if (r.y0 < top - kEdge && r.y1 > top) keptTop = std::max(keptTop, r.y1);
        if (r.y0 < bottom && r.y1 > bottom + kEdge) keptBottom = std::min(keptBottom, r.y0);
    }
    if (keptTop >= keptBottom) { // a row taller than the region: leave it cut
        gHidden.erase(id_);
        return;
    }
    if (keptTop > top || keptBottom < bottom) {
        for (int c = cmdStart_; c < cmds.Size; ++c) {
            ImDrawCmd& cmd = cmds[c];
            if (cmd.IdxOffset < start) continue;
            cmd.ClipRect.y = std::max(cmd.ClipRect.y, keptTop);
            cmd.ClipRect.w = std::min(cmd.ClipRect.w, keptBottom);
        }
    }
    Hidden& h = gHidden[id_];
    h.frame = ImGui::GetCurrentContext()->FrameCount;
    h.pos = window->Pos;
    h.scroll = window->Scroll;
    h.top = keptTop;
    h.bottom = keptBottom;
    h.clipTop = top;
    h.clipBottom = bottom;
}
