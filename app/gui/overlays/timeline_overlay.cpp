// The timeline: scrub back through the recorded history (WorldHistory) with a slider, step a
// frame back or forward, and return to the newest frame. Playing or stepping from an earlier
// frame replays from there (the same states, bit for bit, unless something is changed).
#include "app_frame.h"
#include "overlay_window.h"

#include <cstdio>

void drawTimelineOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::timeline);
    if (!overlay) return;
    const WorldHistory& h = app.history;
    if (h.empty()) {
        dimText("Nothing recorded yet: run or step the scene.");
        return;
    }
    const auto first = h.firstFrame(), last = h.lastFrame();
    int frame = static_cast<int>(app.world.frame);
    auto go = [&](long long f) {
        if (f < static_cast<long long>(first)) f = static_cast<long long>(first);
        if (f > static_cast<long long>(last)) f = static_cast<long long>(last);
        app.paused = true;
        scrubTo(app, static_cast<std::uint64_t>(f));
    };
    if (ImGui::Button("|<")) go(static_cast<long long>(first));
    ImGui::SameLine();
    if (ImGui::Button("<")) go(frame - 1);
    ImGui::SameLine();
    if (ImGui::Button(">")) go(frame + 1);
    ImGui::SameLine();
    if (ImGui::Button(">|")) go(static_cast<long long>(last));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    char label[64];
    std::snprintf(label, sizeof label, "frame %%d   t = %.2f s", app.world.time);
    if (ImGui::SliderInt("##frame", &frame, static_cast<int>(first), static_cast<int>(last), label,
                         ImGuiSliderFlags_AlwaysClamp)) {
        go(frame);
    }
    char info[160];
    std::snprintf(info, sizeof info, "%s  %.1f s recorded, %zu keyframes, %.1f MB",
                  isReplaying(app) ? "REPLAY: play or step to continue from here." : "live.",
                  static_cast<double>(last - first) * app.world.settings.dt, h.keyframeCount(),
                  static_cast<double>(h.bytes()) / (1024.0 * 1024.0));
    dimText(info);
}
