// What the browser tests measure of a frame (tests/web/phone_lesson_test.py): every control drawn,
// with its window and its rectangle, and every text drawn. The controls come from Dear ImGui's
// item hooks (IMGUI_ENABLE_TEST_ENGINE, defined for the browser build's ImGui only,
// cmake/web.cmake): each interactive item (a button, a slider, a checkbox, a window's close button,
// ...) is added with its rectangle and, for most, named. The hooks record nothing until a test
// first asks (sandbox_web_controls), so the page pays a flag's test per item.
#include "screen_text.h"

#include <emscripten.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <string>
#include <vector>

namespace {

struct Control {
    ImGuiID id = 0;
    std::string label;
    std::string window; // the root window's name
    ImGuiWindow* root = nullptr;
    ImRect rect;
    bool visible = false; // some of it inside its window's clipping rectangle
};

struct Probe {
    bool hooked = false;
    std::vector<Control> building; // this frame's, so far
    std::vector<Control> last;     // the last whole frame's
    float scrollbar = 0.0f; // the narrowest scrollbar shown in the last whole frame (0: none)
    float buildingScrollbar = 0.0f;
};
Probe gProbe;

// At each frame's start: the frame before is whole.
void frameStarts(ImGuiContext* ctx, ImGuiContextHook*) {
    // The scrollbars the frame before showed (a window's, not an item: ImGui adds none for it).
    float narrowest = 0.0f;
    for (ImGuiWindow* w : ctx->Windows) {
        if (!w->WasActive || w->Hidden) continue;
        for (const bool shown : {w->ScrollbarX, w->ScrollbarY})
            if (shown && (narrowest == 0.0f || ctx->Style.ScrollbarSize < narrowest))
                narrowest = ctx->Style.ScrollbarSize;
    }
    // The controls of windows shown (ImGui begins its fallback window "Debug##Default" every
    // frame, with a title bar, and hides it unless something is drawn into it).
    gProbe.last.clear();
    for (Control& c : gProbe.building)
        if (c.root && c.root->Active && !c.root->Hidden) gProbe.last.push_back(std::move(c));
    gProbe.building.clear();
    gProbe.scrollbar = narrowest;
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

// The part of an ImGui label shown ("Play##bar" shows "Play"; "##id" shows nothing).
std::string shownPart(const char* label) {
    if (!label) return "";
    const std::string s(label);
    return s.substr(0, s.find("##"));
}

} // namespace

void ImGuiTestEngineHook_ItemAdd(ImGuiContext* ctx, const ImRect& bb, ImGuiID id) {
    ImGuiWindow* window = ctx->CurrentWindow;
    if (!window) return;
    Control c;
    c.id = id;
    c.root = window->RootWindow ? window->RootWindow : window;
    c.window = c.root->Name;
    c.rect = bb;
    c.visible = bb.Overlaps(window->ClipRect) && bb.GetWidth() > 0.0f && bb.GetHeight() > 0.0f;
    gProbe.building.push_back(std::move(c));
}

void ImGuiTestEngineHook_ItemInfo(ImGuiContext*, ImGuiID id, const char* label,
                                  ImGuiItemStatusFlags) {
    for (auto it = gProbe.building.rbegin(); it != gProbe.building.rend(); ++it)
        if (it->id == id) {
            it->label = shownPart(label);
            return;
        }
}

void ImGuiTestEngineHook_Log(ImGuiContext*, const char*, ...) {}

const char* ImGuiTestEngine_FindItemDebugLabel(ImGuiContext*, ImGuiID) {
    return nullptr;
}

// Called by the browser tests: the last whole frame's controls in framebuffer pixels,
//   {"controls": [{"label": "Play", "window": "Controls", "rect": [x, y, w, h], "visible": true},
//    ...], "scrollbar": 12}
// (scrollbar: the width of the narrowest scrollbar shown, 0 for none). The first call turns the
// hooks on: its list is empty until a frame has been drawn since.
extern "C" EMSCRIPTEN_KEEPALIVE const char* sandbox_web_controls() {
    static std::string text;
    ImGuiContext* ctx = ImGui::GetCurrentContext();
    if (!ctx) return "{}";
    if (!gProbe.hooked) {
        ImGuiContextHook hook;
        hook.Type = ImGuiContextHookType_NewFramePre;
        hook.Callback = frameStarts;
        ImGui::AddContextHook(ctx, &hook);
        ctx->TestEngineHookItems = true;
        gProbe.hooked = true;
    }
    text = "{\"controls\":[";
    bool first = true;
    for (const Control& c : gProbe.last) {
        char rect[128];
        std::snprintf(rect, sizeof rect, "[%.3f,%.3f,%.3f,%.3f]", static_cast<double>(c.rect.Min.x),
                      static_cast<double>(c.rect.Min.y), static_cast<double>(c.rect.GetWidth()),
                      static_cast<double>(c.rect.GetHeight()));
        text += std::string(first ? "" : ",") + "{\"label\":" + quoted(c.label) +
                ",\"window\":" + quoted(c.window) + ",\"rect\":" + rect +
                ",\"visible\":" + (c.visible ? "true" : "false") + "}";
        first = false;
    }
    text += "],\"scrollbar\":" + std::to_string(gProbe.scrollbar) + "}";
    return text.c_str();
}

// Called by the browser tests: every text drawn in the last frame (screen_text.h's document, in
// framebuffer pixels).
extern "C" EMSCRIPTEN_KEEPALIVE const char* sandbox_web_texts() {
    static std::string text;
    const ImDrawData* data = ImGui::GetDrawData();
    if (!data) return "{\"texts\":[]}";
    text = screenTextJson(readScreenText(*data, *ImGui::GetIO().Fonts));
    return text.c_str();
}
