// Methods side by side: the other two methods' blocks drawn as coloured outlines (ghosts) over
// the live world (by the renderer, see appRender), and a table of each method's statistics:
// collisions, largest overlap, energy, momentum, and how far it has drifted from perfect.
#include "app_frame.h"
#include "overlay_window.h"
#include "ui_style.h"

#include <cstdio>

void drawSideBySideOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::sideBySide);
    if (!overlay) return;
    const MethodsSideBySide& m = app.sim.run.methods;
    if (!m.running) {
        textWrappedAtSpaces("Starts from the current state when the simulation runs (P or N).");
        return;
    }
    // Columns at the width of their contents (never cut): a narrow window scrolls sideways.
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit |
                                  ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollX;
    const ImGuiStyle& st = ImGui::GetStyle();
    const float rows =
        4.0f * (ImGui::GetTextLineHeight() + 2.0f * st.CellPadding.y) + st.ScrollbarSize + 2.0f;
    if (ImGui::BeginTable("methods", 6, flags, ImVec2(0.0f, rows))) {
        ImGui::TableSetupColumn("method");
        ImGui::TableSetupColumn("collisions");
        ImGui::TableSetupColumn("max overlap");
        ImGui::TableSetupColumn("energy");
        ImGui::TableSetupColumn("off perfect");
        ImGui::TableSetupColumn("ms/step");
        ImGui::TableHeadersRow();
        for (int k = 0; k < static_cast<int>(Method::Count); ++k) {
            const Method method = static_cast<Method>(k);
            const MethodRun& r = m.run(method);
            const bool live = method == app.sim.world().settings.method;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(uiMarkColorVec(methodMark(method)), "%s%s", methodName(method),
                               live ? " (live)" : "");
            ImGui::TableNextColumn();
            ImGui::Text("%lld", static_cast<long long>(r.totals.collisions));
            ImGui::TableNextColumn();
            ImGui::Text("%.3g m", r.totals.maxPenetration);
            ImGui::TableNextColumn();
            ImGui::Text("%.4g J", r.stats.kineticEnergy + r.stats.potentialEnergy);
            ImGui::TableNextColumn();
            ImGui::Text("%.3g m", m.divergence(method));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f", r.stats.stepMs);
        }
        ImGui::EndTable();
    }
    dimText("Outlines in the scene: the other methods' blocks.");
}
