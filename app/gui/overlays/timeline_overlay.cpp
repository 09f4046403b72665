// The timeline: scrub back through the recorded history (WorldHistory) with a slider, step a
// frame back or forward, and return to the newest frame. Playing or stepping from an earlier
// frame replays from there (the same states, bit for bit, unless something is changed).
#include "app_frame.h"
#include "number_text.h"
#include "overlay_window.h"
#include "slider.h"
#include "ui_style.h"

#include <cstdio>

namespace {

// A student's trace (docs/compare.md): its first difference marked on the slider just drawn (a
// tick in the trace's colour), and a button that goes there.
void markFirstDifference(App& app, std::uint64_t first, std::uint64_t last) {
    const std::int64_t at = app.studentTrace.firstDifference();
    if (at < 0) return;
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    const auto frame = static_cast<std::uint64_t>(at);
    if (frame >= first && frame <= last && last > first) {
        const float x = lo.x + (hi.x - lo.x) * static_cast<float>(frame - first) /
                                   static_cast<float>(last - first);
        ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x - 1.5f, lo.y), ImVec2(x + 1.5f, hi.y),
                                                  uiThemed(studentTraceColor().packed()));
    }
    char text[96];
    std::snprintf(text, sizeof text, "first difference: frame %lld", static_cast<long long>(at));
    if (uiSmallButton(text)) goToFirstDifference(app);
}

} // namespace

void drawTimelineOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::timeline);
    if (!overlay) return;
    const WorldHistory& h = app.sim.history;
    if (h.empty()) {
        dimText("Nothing recorded yet: run or step the scene.");
        return;
    }
    const auto first = h.firstFrame(), last = h.lastFrame();
    int frame = static_cast<int>(app.sim.world().frame);
    auto go = [&](long long f) {
        if (f < static_cast<long long>(first)) f = static_cast<long long>(first);
        if (f > static_cast<long long>(last)) f = static_cast<long long>(last);
        app.sim.paused = true;
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
    dimText(app.sim.isReplaying() ? "REPLAY" : "live");
    ImGui::SetNextItemWidth(-1.0f); // the slider on its own line: it must show frame and time
    // "frame %%d   t = %.2f s" (number_text.h: the time without printf)
    std::string label = "frame %d   t = ";
    number_text::appendFixed(label, app.sim.world().time, 2);
    label += " s";
    if (uiSliderInt("##frame", &frame, static_cast<int>(first), static_cast<int>(last),
                    label.c_str(), ImGuiSliderFlags_AlwaysClamp)) {
        go(frame);
    }
    markFirstDifference(app, first, last);
    // Memory in MB of 2^20 bytes, each against its cap (README, "Memory in long runs").
    const auto mb = [](std::size_t bytes) {
        return static_cast<double>(bytes) / (1024.0 * 1024.0);
    };
    char info[256];
    std::snprintf(
        info, sizeof info,
        "%.1f s recorded, %zu keyframes, %.1f MB of %.0f; trails %.1f MB of %.0f; plots %.1f MB%s",
        h.recordedSeconds(), h.keyframeCount(), mb(h.bytes()), mb(h.maxBytes()),
        mb(app.sim.run.trails.bytes()), mb(app.sim.run.trails.maxBytes()),
        mb(app.sim.telemetry.bytes()),
        app.sim.isReplaying() ? ". Play or step to go on from here; an edit starts a new future."
                              : "");
    ImGui::PushTextWrapPos(0.0f);
    dimText(info);
    ImGui::PopTextWrapPos();
}
