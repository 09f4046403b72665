#include "overlay_window.h"

#include <algorithm>

bool beginOverlayWindow(App& app, OverlayId id) {
    const OverlayInfo& info = overlayInfo(id);
    const OverlayPlacement& place = info.place;
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
    // When the UI scale or the scene's viewport changes (Ctrl+= on a projector, a resized or
    // full-screen window), the window is placed again for it: at the old pixel sizes it would
    // overlap the wider panel and clip its larger text.
    const UiState::PlacedFor now{s, vp.width, vp.height};
    UiState::PlacedFor& placed = app.ui.placedFor[static_cast<std::size_t>(id)];
    const ImGuiCond when = placed == now ? ImGuiCond_FirstUseEver : ImGuiCond_Always;
    placed = now;
    ImGui::SetNextWindowPos(ImVec2(x0 + (x1 - x0) * place.anchorX, y0 + (y1 - y0) * place.anchorY),
                            when);
    ImGui::SetNextWindowSize(ImVec2(w, h), when);
    ImGui::SetNextWindowBgAlpha(0.80f);
    return ImGui::Begin(info.title, &(app.show.*info.flag), ImGuiWindowFlags_NoSavedSettings);
}

OverlayWindow::OverlayWindow(App& app, OverlayId id) : open_(beginOverlayWindow(app, id)) {}

OverlayWindow::~OverlayWindow() {
    ImGui::End();
}

void drawnByTheSceneRenderer(App&) {}

void drawOverlays(App& app) {
    using Draw = void (*)(App&);
#define SANDBOX_OVERLAY_DRAW(member, name, label, tooltip, on, title, place, draw) draw,
    static constexpr Draw kDraw[] = {SANDBOX_OVERLAYS(SANDBOX_OVERLAY_DRAW)};
#undef SANDBOX_OVERLAY_DRAW
    static_assert(sizeof kDraw / sizeof kDraw[0] == kOverlayCount, "one draw function a row");
    for (std::size_t i = 0; i < kOverlayCount; ++i) {
        if (app.show.*kOverlays[i].flag) kDraw[i](app);
    }
}

void dimText(const char* text) {
    ImGui::TextColored(ImVec4(0.62f, 0.66f, 0.74f, 1.0f), "%s", text);
}
