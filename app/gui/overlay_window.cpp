#include "overlay_window.h"

#include <algorithm>

bool beginOverlayWindow(const App& app, const char* title, bool* open,
                        const OverlayPlacement& place) {
    const ScreenRect& vp = app.camera.viewport();
    const float s = app.uiScale;
    const float margin = 8.0f * s;
    const float badge = 36.0f * s; // the method/time badge at the top of the viewport
    const float w =
        std::min(place.maxWidth * s, static_cast<float>(vp.width) * place.widthFraction);
    const float h =
        std::min(place.maxHeight * s, static_cast<float>(vp.height - badge) * place.heightFraction);
    const float x0 = static_cast<float>(vp.x) + margin;
    const float x1 = static_cast<float>(vp.x + vp.width) - margin - w;
    const float y0 = static_cast<float>(vp.y) + badge;
    const float y1 = static_cast<float>(vp.y + vp.height) - margin - h;
    ImGui::SetNextWindowPos(ImVec2(x0 + (x1 - x0) * place.anchorX, y0 + (y1 - y0) * place.anchorY),
                            ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(w, h), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.80f);
    return ImGui::Begin(title, open, ImGuiWindowFlags_NoSavedSettings);
}

void dimText(const char* text) {
    ImGui::TextColored(ImVec4(0.62f, 0.66f, 0.74f, 1.0f), "%s", text);
}
