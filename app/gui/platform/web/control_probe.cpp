// What the browser tests measure of a frame (tests/web/phone_lesson_test.py): every control drawn,
// with its window and its rectangle, and every text drawn. The controls are Dear ImGui's items as
// imgui_ext::itemsOfLastFrame reads them through ImGui's item hooks (IMGUI_ENABLE_TEST_ENGINE,
// defined for the browser build's ImGui only, cmake/web.cmake): each interactive item (a button,
// a slider, a checkbox, a window's close button, ...) with its rectangle and, for most, its
// label. The hooks record nothing until a test first asks (sandbox_web_controls).
#include "imgui_ext.h"
#include "screen_text.h"

#include <emscripten.h>
#include <imgui.h>

#include <cstdio>
#include <string>

namespace {

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
    }
    return out + "\"";
}

} // namespace

// Called by the browser tests: the last whole frame's controls in framebuffer pixels,
//   {"controls": [{"label": "Play", "window": "Controls", "rect": [x, y, w, h], "visible": true},
//    ...], "scrollbar": 12}
// (scrollbar: the width of the narrowest scrollbar shown, 0 for none). The first call turns the
// hooks on: its list is empty until a frame has been drawn since.
extern "C" EMSCRIPTEN_KEEPALIVE const char* sandbox_web_controls() {
    static std::string text;
    if (!ImGui::GetCurrentContext()) return "{}";
    const imgui_ext::ItemsOfAFrame& frame = imgui_ext::itemsOfLastFrame();
    text = "{\"controls\":[";
    bool first = true;
    for (const imgui_ext::ItemSeen& c : frame.items) {
        char rect[128];
        std::snprintf(rect, sizeof rect, "[%.3f,%.3f,%.3f,%.3f]", static_cast<double>(c.min.x),
                      static_cast<double>(c.min.y), static_cast<double>(c.max.x - c.min.x),
                      static_cast<double>(c.max.y - c.min.y));
        text += std::string(first ? "" : ",") + "{\"label\":" + quoted(c.label) +
                ",\"window\":" + quoted(c.window) + ",\"rect\":" + rect +
                ",\"visible\":" + (c.visible ? "true" : "false") + "}";
        first = false;
    }
    text += "],\"scrollbar\":" + std::to_string(frame.narrowestScrollbar) + "}";
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
