#include "imgui_ext.h"

#include <imgui_internal.h>

#include <algorithm>
#include <cfloat>

// Every function below reads or writes what Dear ImGui 1.86 keeps to itself or has since
// replaced (io.KeysDown and io.KeyMap became io.AddKeyEvent in 1.87; ImGuiWindowFlags_NavFlattened
// moved to the child flags in 1.90; draw lists' layout and the navigation's state change between
// versions). Another version: check each function against it, then change this number.
static_assert(IMGUI_VERSION_NUM == 18600,
              "imgui_ext.cpp is written against Dear ImGui 1.86 (IMGUI_VERSION_NUM 18600)");

namespace imgui_ext {

void mapKeys() {
    ImGuiIO& io = ImGui::GetIO();
    // As ImGui's GLFW backend maps them (the offscreen renderer has no backend: 1.86 asserts
    // without Space). PageUp and PageDown stay unmapped: ImGui's navigation would move its focus
    // with them, and they are the lesson's keys whatever has the keyboard.
    const int map[][2] = {
        {ImGuiKey_Tab, keys::kTab},          {ImGuiKey_LeftArrow, keys::kLeft},
        {ImGuiKey_RightArrow, keys::kRight}, {ImGuiKey_UpArrow, keys::kUp},
        {ImGuiKey_DownArrow, keys::kDown},   {ImGuiKey_Home, keys::kHome},
        {ImGuiKey_End, keys::kEnd},          {ImGuiKey_Delete, keys::kDelete},
        {ImGuiKey_Space, keys::kSpace},      {ImGuiKey_Enter, keys::kEnter},
        {ImGuiKey_Escape, keys::kEscape},    {ImGuiKey_KeyPadEnter, keys::kKeypadEnter}};
    for (const auto& k : map) io.KeyMap[k[0]] = k[1];
    io.KeyMap[ImGuiKey_PageUp] = io.KeyMap[ImGuiKey_PageDown] = -1;
}

namespace {

constexpr int kKeyCount = IM_ARRAYSIZE(ImGuiIO::KeysDown);

bool validKey(int key) {
    return key >= 0 && key < kKeyCount;
}

} // namespace

bool keyDown(int key) {
    return validKey(key) && ImGui::GetIO().KeysDown[key];
}

void holdKeyTaps(const std::vector<KeyPress>& queued, std::vector<int>& held,
                 const std::function<bool(int key)>& isDown) {
    ImGuiIO& io = ImGui::GetIO();
    for (int key : held)
        if (validKey(key)) io.KeysDown[key] = isDown(key);
    held.clear();
    for (const KeyPress& k : queued) {
        if (!validKey(k.key) || io.KeysDown[k.key]) continue;
        io.KeysDown[k.key] = true;
        held.push_back(k.key);
    }
}

void setPointer(bool onScreen, ImVec2 pos, bool down, bool ctrl) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = onScreen ? pos : ImVec2(-FLT_MAX, -FLT_MAX);
    for (bool& button : io.MouseDown) button = false;
    io.MouseDown[0] = down;
    io.KeyCtrl = ctrl || keyDown(keys::kLeftControl) || keyDown(keys::kRightControl);
}

void focusCurrentWindowForKeyboard() {
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    ImGui::FocusWindow(window);
    ImGui::NavInitWindow(window, true);
    ImGuiContext& g = *ImGui::GetCurrentContext();
    g.NavDisableHighlight = false;
    g.NavDisableMouseHover = true;
}

void stopTyping() {
    if (ImGui::GetIO().WantTextInput) ImGui::ClearActiveID();
}

bool typingAfterFrame() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    return g.IO.WantTextInput || g.WantTextInputNextFrame == 1;
}

void endFrameLeftOpen() {
    if (!ImGui::GetCurrentContext()->WithinFrameScope) return;
    ImGui::ErrorCheckEndFrameRecover(nullptr);
    ImGui::EndFrame();
}

KeyboardFocus keyboardFocus() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiIO& io = ImGui::GetIO();
    KeyboardFocus f;
    f.id = g.NavId;
    f.ringShown = io.NavActive && io.NavVisible;
    if (g.NavWindow) {
        // NavRectRel is relative to the window's content start, which moves with its scrolling.
        const ImRect r = ImGui::WindowRectRelToAbs(g.NavWindow, g.NavWindow->NavRectRel[0]);
        f.min = r.Min;
        f.max = r.Max;
    }
    return f;
}

ImGuiWindowFlags flattenedNavigation() {
    return ImGuiWindowFlags_NavFlattened;
}

ScrollTarget scrollTargetUnderPointer() {
    ImGuiWindow* window = GImGui->HoveredWindow;
    while (window && (window->Flags & ImGuiWindowFlags_ChildWindow) && window->ScrollMax.y <= 0.0f)
        window = window->ParentWindow;
    return {window};
}

void scrollBy(ScrollTarget target, float dy) {
    auto* window = static_cast<ImGuiWindow*>(target.window);
    if (window) ImGui::SetScrollY(window, window->Scroll.y + dy);
}

DrawMark markDrawing() {
    ImDrawList* list = ImGui::GetWindowDrawList();
    return {list, list->CmdBuffer.Size - 1, list->IdxBuffer.Size};
}

bool stillDrawing(const DrawMark& mark) {
    return mark.list && ImGui::GetWindowDrawList() == mark.list && mark.command >= 0 &&
           mark.command < mark.list->CmdBuffer.Size;
}

namespace {

// The draw commands since `mark` in the current window's list, the first one split where the
// mark is (what was drawn before it, the window's frame, stays as it was); false when the
// current window draws elsewhere.
bool commandsSince(const DrawMark& mark) {
    if (!stillDrawing(mark)) return false;
    ImVector<ImDrawCmd>& cmds = mark.list->CmdBuffer;
    ImDrawCmd& first = cmds[mark.command];
    const auto start = static_cast<unsigned>(mark.index);
    if (first.IdxOffset < start && first.IdxOffset + first.ElemCount > start) {
        ImDrawCmd rest = first;
        rest.IdxOffset = start;
        rest.ElemCount = first.IdxOffset + first.ElemCount - start;
        first.ElemCount = start - first.IdxOffset;
        cmds.insert(cmds.begin() + mark.command + 1, rest);
    }
    return true;
}

} // namespace

void drawnSince(const DrawMark& mark, ImU32 skip, MergedSpans& into) {
    if (!commandsSince(mark)) return;
    const ImDrawList& list = *mark.list;
    const auto start = static_cast<unsigned>(mark.index);
    skip &= ~IM_COL32_A_MASK;
    for (int c = mark.command; c < list.CmdBuffer.Size; ++c) {
        const ImDrawCmd& cmd = list.CmdBuffer[c];
        if (cmd.UserCallback || cmd.IdxOffset < start) continue;
        for (unsigned k = 0; k + 3 <= cmd.ElemCount; k += 3) {
            Span s{FLT_MAX, -FLT_MAX};
            bool skipped = false;
            for (unsigned v = 0; v < 3; ++v) {
                const ImDrawIdx i = list.IdxBuffer[static_cast<int>(cmd.IdxOffset + k + v)];
                const ImDrawVert& vert = list.VtxBuffer[static_cast<int>(cmd.VtxOffset + i)];
                s.y0 = std::min(s.y0, vert.pos.y);
                s.y1 = std::max(s.y1, vert.pos.y);
                skipped = skipped || (vert.col & ~IM_COL32_A_MASK) == skip;
            }
            if (!skipped) into.add(s);
        }
    }
}

void clipDrawnSince(const DrawMark& mark, float top, float bottom) {
    if (!commandsSince(mark)) return;
    ImVector<ImDrawCmd>& cmds = mark.list->CmdBuffer;
    const auto start = static_cast<unsigned>(mark.index);
    for (int c = mark.command; c < cmds.Size; ++c) {
        ImDrawCmd& cmd = cmds[c];
        if (cmd.IdxOffset < start) continue;
        cmd.ClipRect.y = std::max(cmd.ClipRect.y, top);
        cmd.ClipRect.w = std::min(cmd.ClipRect.w, bottom);
    }
}

void takeHover(ImVec2 min, ImVec2 max) {
    const ImRect rect(min, max);
    const ImGuiID id = ImGui::GetCurrentWindow()->GetID("##hover taken");
    ImGui::ItemAdd(rect, id, nullptr, ImGuiItemFlags_NoNav);
    ImGui::ItemHoverable(rect, id);
}

std::string drawListOwner(const ImDrawList& list) {
    return list._OwnerName ? list._OwnerName : "";
}

int drawListVertices(const ImDrawList& list) {
    return list.VtxBuffer.Size;
}

std::vector<SidewaysScroll> sidewaysScrolls() {
    std::vector<SidewaysScroll> out;
    for (const ImGuiWindow* w : GImGui->Windows) {
        // Half a pixel: ImGui's sizes are floats that round to the same pixel.
        if (!w->Active || w->Hidden || w->ScrollMax.x < 0.5f) continue;
        const std::string root = w->RootWindow ? w->RootWindow->Name : w->Name;
        out.push_back({root.substr(0, root.find("##")), w->Pos,
                       ImVec2(w->Pos.x + w->Size.x, w->Pos.y + w->Size.y), w->ScrollMax.x});
    }
    return out;
}

void forEachDrawnRect(const ImDrawList& list, ImTextureID texture,
                      const std::function<void(const DrawnRect&)>& rect,
                      const std::function<void()>& other) {
    for (const ImDrawCmd& cmd : list.CmdBuffer) {
        if (cmd.UserCallback || cmd.TextureId != texture) continue;
        other(); // a new command
        const ImDrawVert* vtx = list.VtxBuffer.Data + cmd.VtxOffset;
        const ImDrawIdx* idx = list.IdxBuffer.Data + cmd.IdxOffset;
        for (unsigned k = 0; k + 6 <= cmd.ElemCount;) {
            // ImGui draws a textured rectangle as two triangles, (a, a+1, a+2) and (a, a+2, a+3),
            // its corners clockwise from the top left.
            const ImDrawIdx* q = idx + k;
            const unsigned a = q[0];
            const ImDrawVert& p = vtx[a];
            const ImDrawVert& r = vtx[a + 2];
            const bool isRect = q[1] == a + 1 && q[2] == a + 2 && q[3] == a && q[4] == a + 2 &&
                                q[5] == a + 3 && vtx[a + 1].pos.y == p.pos.y &&
                                vtx[a + 3].pos.x == p.pos.x;
            // (a solid shape has every corner at the atlas's white texel)
            if (!isRect || p.uv.x == r.uv.x || p.uv.y == r.uv.y) {
                other();
                k += 3;
                continue;
            }
            rect({p.pos, r.pos, p.uv, r.uv, cmd.ClipRect, static_cast<int>(cmd.VtxOffset + a)});
            k += 6;
        }
    }
}

namespace {

// The items seen so far this frame and the last whole frame's.
struct ItemProbe {
    bool hooked = false;
    std::vector<ItemSeen> building;
    ItemsOfAFrame last;
    std::vector<ImGuiWindow*> roots; // building[i]'s root window
};
ItemProbe gItems;

} // namespace

const ItemsOfAFrame& itemsOfLastFrame() {
#ifdef __EMSCRIPTEN__
    ImGuiContext* ctx = ImGui::GetCurrentContext();
    if (ctx && !gItems.hooked) {
        // At each frame's start the frame before is whole: keep the items of windows shown (ImGui
        // begins its fallback window "Debug##Default" every frame and hides it when empty) and
        // the narrowest scrollbar a shown window had (a window's scrollbar is not an item).
        ImGuiContextHook hook;
        hook.Type = ImGuiContextHookType_NewFramePre;
        hook.Callback = [](ImGuiContext* c, ImGuiContextHook*) {
            float narrowest = 0.0f;
            for (ImGuiWindow* w : c->Windows) {
                if (!w->WasActive || w->Hidden) continue;
                for (const bool shown : {w->ScrollbarX, w->ScrollbarY})
                    if (shown && (narrowest == 0.0f || c->Style.ScrollbarSize < narrowest))
                        narrowest = c->Style.ScrollbarSize;
            }
            gItems.last.items.clear();
            for (std::size_t i = 0; i < gItems.building.size(); ++i) {
                ImGuiWindow* root = gItems.roots[i];
                if (root && root->Active && !root->Hidden)
                    gItems.last.items.push_back(std::move(gItems.building[i]));
            }
            gItems.building.clear();
            gItems.roots.clear();
            gItems.last.narrowestScrollbar = narrowest;
        };
        ImGui::AddContextHook(ctx, &hook);
        ctx->TestEngineHookItems = true;
        gItems.hooked = true;
    }
#endif
    return gItems.last;
}

} // namespace imgui_ext

#ifdef __EMSCRIPTEN__
// ImGui's test-engine item hooks, which the browser build's ImGui calls (IMGUI_ENABLE_TEST_ENGINE,
// cmake/web.cmake) once itemsOfLastFrame has turned them on.
void ImGuiTestEngineHook_ItemAdd(ImGuiContext* ctx, const ImRect& bb, ImGuiID id) {
    ImGuiWindow* window = ctx->CurrentWindow;
    if (!window) return;
    imgui_ext::ItemSeen item;
    item.id = id;
    ImGuiWindow* root = window->RootWindow ? window->RootWindow : window;
    item.window = root->Name;
    item.min = bb.Min;
    item.max = bb.Max;
    item.visible = bb.Overlaps(window->ClipRect) && bb.GetWidth() > 0.0f && bb.GetHeight() > 0.0f;
    imgui_ext::gItems.building.push_back(std::move(item));
    imgui_ext::gItems.roots.push_back(root);
}

void ImGuiTestEngineHook_ItemInfo(ImGuiContext*, ImGuiID id, const char* label,
                                  ImGuiItemStatusFlags) {
    auto& items = imgui_ext::gItems.building;
    for (auto it = items.rbegin(); it != items.rend(); ++it)
        if (it->id == id) {
            const std::string shown(label ? label : "");
            it->label = shown.substr(0, shown.find("##"));
            return;
        }
}

void ImGuiTestEngineHook_Log(ImGuiContext*, const char*, ...) {}

const char* ImGuiTestEngine_FindItemDebugLabel(ImGuiContext*, ImGuiID) {
    return nullptr;
}
#endif
