// The collision inspector: the last collisions (bodies, axis, time of impact) and, for the one
// picked (the newest by default), the lecture's formula with its numbers filled in, momentum
// before and after, and the "pause on each collision" switch.
#include "app_frame.h"
#include "inspector_format.h"
#include "number_text.h"
#include "overlay_window.h"
#include "printable.h"
#include "report.h"
#include "ui_style.h"

#include <cstdio>
#include <string>

namespace {

std::string bodyName(const App& app, int index) {
    return index < 0 ? std::string(wallName(index)) : app.sim.blockDisplayName(index);
}

// Wrapped before an operator where the window is too narrow (nothing cut at its edge).
void formulaLine(const std::string& text, bool strong) {
    if (strong) ImGui::PushStyleColor(ImGuiCol_Text, uiThemed(ImVec4(1.0f, 0.93f, 0.55f, 1.0f)));
    textWrappedFormula(text);
    if (strong) ImGui::PopStyleColor();
}

// A student's trace (docs/compare.md): the reference's collision where the two part, the
// student's velocities beside it, and the diagnosis; above the collisions of the run.
void studentTraceSection(App& app) {
    const StudentTrace& st = app.studentTrace;
    if (!st.open()) return;
    const TraceComparison& c = *st.comparison;
    ImGui::PushStyleColor(ImGuiCol_Text,
                          uiThemed(ImGui::ColorConvertU32ToFloat4(studentTraceColor().packed())));
    textWrappedAtSpaces("Your trace: " + studentTraceSummary(st));
    ImGui::PopStyleColor();
    if (!c.same()) {
        const PartingCollision& p = c.parting;
        if (p.found) {
            const CollisionRecord& r = p.record;
            const CollisionFormula f =
                collisionFormula(r, bodyName(app, r.block), bodyName(app, r.other));
            dimText(p.inPartingFrame ? "The reference's collision in that frame:"
                                     : "The reference's collision nearest to it:");
            textWrappedFormula(f.title);
            formulaLine(f.u, true);
            formulaLine(f.v1After, true);
            formulaLine(f.v2After, true);
            if (p.yoursKnown && p.inPartingFrame) {
                const Vec2 y = p.yoursVelocity, ref = p.referenceVelocity;
                ImGui::PushStyleColor(ImGuiCol_Text, uiThemed(ImGui::ColorConvertU32ToFloat4(
                                                         studentTraceColor().packed())));
                textWrappedAtSpaces(app.sim.blockDisplayName(p.block) + " after it: yours v = (" +
                                    formatNumber(y.x) + ", " + formatNumber(y.y) +
                                    ") m/s, the reference's (" + formatNumber(ref.x) + ", " +
                                    formatNumber(ref.y) + ") m/s");
                ImGui::PopStyleColor();
            }
        }
        for (const std::string& line : diagnosisLines(c)) textWrappedAtSpaces(line);
        if (uiSmallButton("go to the first difference")) goToFirstDifference(app);
    }
    ImGui::Separator();
}

} // namespace

void drawInspectorOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::inspector);
    if (!overlay) return;
    studentTraceSection(app);
    // A small window shows the formula first, the switch under it.
    auto pauseSwitch = [&] {
        ImGui::Checkbox("pause on each collision", &app.sim.pauseOnCollision);
    };
    if (!overlay.compact()) pauseSwitch();
    const auto& recent = app.sim.telemetry.recent; // up to the scrubbed time while replaying
    if (recent.empty()) {
        dimText(app.sim.isReplaying() ? "No collision up to this point of the replay."
                                      : "No collision yet. Run the scene, or step with N.");
        if (overlay.compact()) pauseSwitch();
        return;
    }
    const int count = static_cast<int>(recent.size());
    int& picked = app.ui.inspectorPicked; // 0: the newest collision, 1: the one before, ...
    if (picked >= count) picked = 0;
    const CollisionRecord& r = recent[static_cast<std::size_t>(count - 1 - picked)];
    const CollisionFormula f = collisionFormula(r, bodyName(app, r.block), bodyName(app, r.other));

    // The list of the last collisions, newest first.
    // "t = %.3f s" (number_text.h: without printf) in "%s t = %.3f s: %s / %s (%c)".
    std::string time = "t = ";
    number_text::appendFixed(time, r.time, 3);
    time += " s";
    char preview[160];
    std::snprintf(preview, sizeof preview, "%s %s: %s / %s (%c)",
                  picked != 0             ? ""
                  : app.sim.isReplaying() ? "last so far,"
                                          : "newest,",
                  time.c_str(), bodyName(app, r.block).c_str(), bodyName(app, r.other).c_str(),
                  r.axis == 0 ? 'x' : 'y');
    // Where the combo is too narrow for it, without the names (the formula's title under it
    // names them).
    const ImGuiStyle& st = ImGui::GetStyle();
    const float previewRoom =
        ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() - 2.0f * st.FramePadding.x;
    if (ImGui::CalcTextSize(preview).x > previewRoom)
        std::snprintf(preview, sizeof preview, "%s (%c)", time.c_str(), r.axis == 0 ? 'x' : 'y');
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##collisions", preview)) {
        for (int k = 0; k < count; ++k) {
            const CollisionRecord& c = recent[static_cast<std::size_t>(count - 1 - k)];
            char row[160];
            std::snprintf(row, sizeof row, "t = %.3f s  %s / %s  (%c, toi %.2f)%s##%d", c.time,
                          bodyName(app, c.block).c_str(), bodyName(app, c.other).c_str(),
                          c.axis == 0 ? 'x' : 'y', c.toi, c.rest ? "  rest" : "", k);
            if (ImGui::Selectable(row, k == picked)) picked = k;
        }
        ImGui::EndCombo();
    }
    ImGui::Separator();
    textWrappedFormula(f.title);
    char toi[96];
    std::snprintf(toi, sizeof toi, "time of impact: t = %s of the frame (t = a/b)",
                  formatNumber(r.toi).c_str());
    // A small window: the test and the formula first, the time of impact and the givens after.
    if (!overlay.compact()) {
        dimText(toi);
        dimText(f.given.c_str());
    }
    // The relative-velocity test decides whether this is a collision at all.
    if (f.separating) {
        ImGui::PushStyleColor(ImGuiCol_Text, uiThemed(ImVec4(1.0f, 0.55f, 0.35f, 1.0f)));
        textWrappedFormula(f.relative);
        ImGui::PopStyleColor();
    } else {
        textWrappedFormula(f.relative);
    }
    ImGui::Spacing();
    formulaLine(f.u, true);
    formulaLine(f.v1After, true);
    formulaLine(f.v2After, true);
    if (overlay.compact()) {
        dimText(toi);
        dimText(f.given.c_str());
    }
    ImGui::Spacing();
    formulaLine(f.momentumBefore, false);
    formulaLine(f.momentumAfter, false);
    if (!f.friction.empty()) textWrappedFormula(f.friction);
    if (!f.note.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, uiThemed(ImVec4(0.62f, 0.66f, 0.74f, 1.0f)));
        textWrappedFormula(f.note);
        ImGui::PopStyleColor();
    }
    if (overlay.compact()) pauseSwitch();
    if (app.log.verbose && f.title != app.ui.inspectorLoggedTitle) {
        app.ui.inspectorLoggedTitle = f.title;
        std::printf("inspector %s\ninspector %s\ninspector %s\ninspector %s\n",
                    printable(f.title, kPrintablePath).c_str(), f.u.c_str(), f.v1After.c_str(),
                    f.v2After.c_str());
        std::fflush(stdout);
    }
}
