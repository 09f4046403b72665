// The status badge over the scene's top left corner: the method, the time and the collision count
// (or, in present mode, the scene's caption), PAUSED or SLOW MOTION, the frame of reference when
// it is not the world's, and the "P to play" hint at the start.
#include "app_frame.h"

#include "number_text.h"
#include "screen_text.h"
#include "text_format.h"
#include "ui_style.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace {

// A text on a rounded plate; returns its width with the padding. `extent` grows to hold it.
float plate(ImDrawList* dl, ImVec2 at, const char* text, ImU32 bg, ImU32 fg, float pad,
            ScreenRect& extent) {
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 lo(at.x - pad * 0.5f, at.y - pad * 0.25f),
        hi(at.x + size.x + pad * 0.5f, at.y + size.y + pad * 0.25f);
    dl->AddRectFilled(lo, hi, bg, 4.0f);
    dl->AddText(at, fg, text);
    if (extent.width <= 0.0) {
        extent = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
    } else {
        const double x1 = std::max<double>(extent.x + extent.width, hi.x);
        const double y1 = std::max<double>(extent.y + extent.height, hi.y);
        extent.x = std::min<double>(extent.x, lo.x);
        extent.y = std::min<double>(extent.y, lo.y);
        extent.width = x1 - extent.x;
        extent.height = y1 - extent.y;
    }
    return size.x + pad * 1.5f;
}

// Plates side by side from `at`, on to a row below where the next would pass `right` (the
// scene's right edge: a narrow scene at UI scale 1.5 cut "3141 co" and "1 collisio"); a plate
// wider than a whole row in lines (the start hint at 1280x720, UI 1.5, ran under the inspector
// docked beside the scene).
struct PlateRow {
    ImDrawList* dl;
    ImVec2 at;
    float left, right, pad;
    ScreenRect* extent;
    void add(const char* text, ImU32 bg, ImU32 fg) {
        const float room = right - left - pad * 0.5f;
        std::string shown = text;
        if (ImGui::CalcTextSize(text).x > room)
            shown = wrapAtSeparators(text, "   ·   ", room, [](const std::string& line) {
                return static_cast<double>(ImGui::CalcTextSize(line.c_str()).x);
            });
        const ImVec2 size = ImGui::CalcTextSize(shown.c_str());
        if (at.x > left && at.x + size.x + pad * 0.5f > right) {
            at.x = left;
            at.y += ImGui::GetFontSize() + pad;
        }
        at.x += plate(dl, at, shown.c_str(), bg, fg, pad, *extent);
        if (size.y > ImGui::GetFontSize() * 1.5f) { // in lines: what follows goes below it
            at.x = left;
            at.y += size.y + pad;
        }
    }
};

// `text` cut to `width` pixels with "..." at the end (whole UTF-8 characters).
std::string fitted(const std::string& text, float width) {
    if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
    std::string s = text;
    while (!s.empty()) {
        do {
            s.pop_back();
        } while (!s.empty() && (static_cast<unsigned char>(s.back()) & 0xC0) == 0x80);
        if (!s.empty() && (static_cast<unsigned char>(s.back()) & 0x80)) s.pop_back();
        if (ImGui::CalcTextSize((s + "...").c_str()).x <= width) return s + "...";
    }
    return "";
}

} // namespace

ScreenRect drawStatusBadge(const App& app, ImDrawList* dl) {
    ScreenRect extent{0.0, 0.0, 0.0, 0.0};
    // The screen-text contract's parts (screen_text.h): the badge is the status, present mode's
    // one line the caption.
    const TextRole role(dl, "status");
    const ScreenRect& vp = app.view.camera.viewport();
    const float pad = 8.0f * app.view.uiScale;
    const ImVec2 at(static_cast<float>(vp.x) + pad * 1.5f, static_cast<float>(vp.y) + pad);
    PlateRow row{dl, at, at.x, static_cast<float>(vp.x + vp.width) - pad, pad, &extent};
    const ImU32 plateBg = uiLightTheme() ? IM_COL32(235, 236, 240, 230) : IM_COL32(20, 22, 30, 200);
    const ImU32 plateFg = uiLightTheme() ? IM_COL32(20, 22, 30, 255) : IM_COL32(225, 230, 240, 255);
    if (app.view.presentMode && app.lesson.active()) {
        // A lesson's caption bar says it all (lesson_bar.cpp): nothing more over the scene.
    } else if (app.view.presentMode) {
        // The caption: what the scene is, the method and the time, on one line, slide-sized.
        const TextRole captionRole(dl, "caption");
        ImGui::PushFont(uiCaptionFont());
        const float room = static_cast<float>(vp.width) - pad * 4.0f;
        std::string caption = presentCaption(app.sim.scene.name, app.sim.scene.description,
                                             app.sim.world().settings.method, app.sim.world().time);
        if (ImGui::CalcTextSize(caption.c_str()).x > room) {
            const std::string tail = presentCaption("", "", app.sim.world().settings.method,
                                                    app.sim.world().time, false);
            const float tailWidth = ImGui::CalcTextSize(tail.c_str()).x;
            std::string what = app.sim.scene.name;
            if (!app.sim.scene.description.empty())
                what += ": " + firstSentence(app.sim.scene.description);
            caption = fitted(what, room - tailWidth) + tail;
        }
        row.at.x += plate(dl, row.at, caption.c_str(), plateBg, plateFg, pad, extent);
        ImGui::PopFont();
    } else {
        // One count of collisions (the lesson's and sandbox-cli's); the rest rule's resting
        // contacts apart, so a settled pile's count stands still. Those are counted as what
        // they are, each a merge by the rest rule (a block lying on the floor: one per substep),
        // not as that many things touching.
        const StepTotals& totals = app.sim.run.totals;
        // "%s   t = %.2f s" (number_text.h: without printf), then the counts.
        std::string methodTime =
            std::string(methodName(app.sim.world().settings.method)) + "   t = ";
        number_text::appendFixed(methodTime, app.sim.world().time, 2);
        methodTime += " s";
        char text[200];
        const int n = std::snprintf(text, sizeof text, "%s   %llu collision%s", methodTime.c_str(),
                                    static_cast<unsigned long long>(totals.collisions),
                                    totals.collisions == 1 ? "" : "s");
        if (totals.contacts > 0 && n > 0 && n < static_cast<int>(sizeof text)) {
            std::snprintf(
                text + n, sizeof text - static_cast<std::size_t>(n), "   %llu rest-rule merge%s",
                static_cast<unsigned long long>(totals.contacts), totals.contacts == 1 ? "" : "s");
        }
        // One plate where it fits the scene's width; else the method and time, the count and
        // the merges each on its own, wrapping.
        if (ImGui::CalcTextSize(text).x + pad * 2.0f <= row.right - row.left) {
            row.add(text, plateBg, plateFg);
        } else {
            char count[64];
            std::snprintf(count, sizeof count, "%s", methodTime.c_str());
            row.add(count, plateBg, plateFg);
            std::snprintf(count, sizeof count, "%llu collision%s",
                          static_cast<unsigned long long>(totals.collisions),
                          totals.collisions == 1 ? "" : "s");
            row.add(count, plateBg, plateFg);
            if (totals.contacts > 0) {
                std::snprintf(count, sizeof count, "%llu rest-rule merge%s",
                              static_cast<unsigned long long>(totals.contacts),
                              totals.contacts == 1 ? "" : "s");
                row.add(count, plateBg, plateFg);
            }
        }
    }
    const char* state = app.sim.paused       ? "PAUSED"
                        : app.sim.slowMotion ? "SLOW MOTION  5 fps"
                                             : nullptr;
    if (state && !app.view.presentMode) {
        const ImU32 bg = app.sim.paused ? IM_COL32(220, 150, 40, 235) : IM_COL32(60, 130, 220, 235);
        row.add(state, bg, IM_COL32(15, 15, 20, 255));
    }
    // The frame of reference, when it is not the world's (the walls drift: that is why).
    if (app.view.frame == ViewFrame::CentreOfMass && !app.view.presentMode) {
        const Vec2 u = frameVelocity(app.sim.world(), app.view.frame);
        const std::string text =
            "centre-of-mass frame, u = " +
            (isRoundingNoise(u.y, length(u))
                 ? formatQuantity(u.x, "m/s")
                 : "(" + formatNumber(u.x) + ", " + formatNumber(u.y) + ") m/s");
        row.add(text.c_str(), IM_COL32(255, 235, 90, 235), IM_COL32(15, 15, 20, 255));
    }
    // Paused at t = 0: how to start (the first time the app runs, with the first keys). On a touch
    // screen in a lesson the caption says it ("Tap Play"): a phone's badge has no room for both.
    const bool captionSays = app.ui.touchUi && app.lesson.active();
    const std::string hint = captionSays ? ""
                                         : startHint(app.sim.paused, app.sim.world().time,
                                                     app.ui.firstLaunch, app.ui.touchUi);
    if (!hint.empty()) {
        row.add(hint.c_str(), IM_COL32(60, 150, 90, 235), IM_COL32(10, 16, 12, 255));
    }
    return extent;
}
