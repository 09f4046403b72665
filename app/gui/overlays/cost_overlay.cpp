// Speed versus accuracy in the app: the current scene's cost per step under each method and the
// tradeoff chart (error against cost, log-log, from the quick sweep) drawn with the plot widget.
// What is measured, and the background sweep, are App's CostMeasurement (session/cost.h).
#include "app_frame.h"
#include "number_text.h"
#include "overlay_window.h"
#include "plot_widget.h"
#include "ui_style.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>

namespace {

ImU32 engineColor(const std::string& engine) {
    Method m;
    if (parseMethod(engine.c_str(), m)) return uiMarkColor(methodMark(m));
    if (engine == "chipmunk") return uiThemed(IM_COL32(120, 200, 230, 255));
    return uiThemed(IM_COL32(200, 200, 210, 255)); // box2d
}

// The chart's rectangle on screen (none when there is nothing to chart yet).
std::optional<ScreenRect> tradeoffChart(CostMeasurement& cost) {
    const std::vector<std::string> scenes = tradeoffScenes(cost.rows());
    if (scenes.empty()) return std::nullopt;
    int& pick = cost.chartScene;
    pick = std::clamp(pick, 0, static_cast<int>(scenes.size()) - 1);
    // 12 ems, or what a narrow window leaves beside its label.
    const ImGuiStyle& st = ImGui::GetStyle();
    // (at least 1 px: ImGui reads a width under 0 as "up to the right edge less that")
    ImGui::SetNextItemWidth(
        std::max(1.0f, std::min(ImGui::GetFontSize() * 12.0f, ImGui::GetContentRegionAvail().x -
                                                                  ImGui::CalcTextSize("scene").x -
                                                                  st.ItemInnerSpacing.x)));
    if (ImGui::BeginCombo("scene", scenes[static_cast<std::size_t>(pick)].c_str())) {
        for (int i = 0; i < static_cast<int>(scenes.size()); ++i) {
            if (ImGui::Selectable(scenes[static_cast<std::size_t>(i)].c_str(), i == pick)) {
                pick = i;
            }
        }
        ImGui::EndCombo();
    }
    std::map<std::string, PlotSeries> byEngine;
    std::string unit;
    for (const TradeoffRow* r :
         tradeoffRowsOf(cost.rows(), scenes[static_cast<std::size_t>(pick)])) {
        PlotSeries& ps = byEngine[r->engine];
        ps.label = r->engine;
        ps.color = engineColor(r->engine);
        ps.points = true;
        ps.x.push_back(r->msPerSimulatedSecond);
        ps.y.push_back(std::max(r->error, 1e-16));
        unit = r->errorUnit;
    }
    std::vector<PlotSeries> series;
    for (auto& kv : byEngine) series.push_back(std::move(kv.second));
    // The error's unit on its own line, so the legend of five engines fits beside the title.
    dimText(("error: " + unit).c_str());
    PlotOptions o;
    o.title = "error vs cost";
    o.xUnit = "ms/sim s";
    o.autoX = true;
    o.logX = o.logY = true;
    return drawPlot("##tradeoff", o, series);
}

} // namespace

void drawCostOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::cost);
    if (!overlay) return;
    CostMeasurement& cost = app.sim.cost;
    cost.pollSweep();
    if (!cost.measured(app.sim.scenePath)) cost.measure(app.sim.world(), app.sim.scenePath);
    // Wrapped, and the unit in the heading: a narrow window (folded behind a tab at 1280x800,
    // UI 1.5) cuts nothing.
    textWrappedAtSpaces("Cost per step of this scene (" +
                        std::to_string(app.sim.world().blocks.size()) + " blocks), ms:");
    if (ImGui::BeginTable("cost", 2, ImGuiTableFlags_SizingStretchProp)) {
        for (int m = 0; m < static_cast<int>(Method::Count); ++m) {
            const Method method = static_cast<Method>(m);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(uiMarkColorVec(methodMark(method)), "%s", methodName(method));
            ImGui::TableNextColumn();
            char ms[64];
            number_text::printFixed(ms, sizeof ms, cost.msPerStep(method), 3); // "%.3f"
            ImGui::TextUnformatted(ms);
        }
        ImGui::EndTable();
    }
    if (uiSmallButton("Measure again")) cost.measure(app.sim.world(), app.sim.scenePath);
    // Beside the button where it fits on the line, else under it (a narrow window at 1024x768,
    // UI 1.25, wrapped it into a column of single words).
    const char* how = "(a copy, 30 frames per method)";
    if (ImGui::CalcTextSize(how).x + ImGui::GetStyle().ItemSpacing.x <=
        ImGui::GetContentRegionAvail().x - ImGui::GetItemRectSize().x)
        ImGui::SameLine();
    dimText(how);
    ImGui::Separator();
    if (cost.sweepRunning()) {
        ImGui::TextColored(uiThemed(ImVec4(0.55f, 0.85f, 0.6f, 1.0f)),
                           "Sweep running in the background...");
    } else if (const char* label = ImGui::CalcTextSize("Run the tradeoff sweep (quick)").x +
                                               2.0f * ImGui::GetStyle().FramePadding.x <=
                                           ImGui::GetContentRegionAvail().x
                                       ? "Run the tradeoff sweep (quick)"
                                       : "Run the quick sweep";
               ImGui::Button(label)) {
        cost.startSweep(quickTradeoffSweep(app.shipped.scenesDir));
    }
    if (!cost.error().empty()) textWrappedAtSpaces("Sweep failed: " + cost.error());
    if (cost.rows().empty()) {
        if (!cost.sweepRunning()) {
            dimText("Sweeps method x dt x substeps over scenes with known answers.");
        }
    } else {
        if (const std::optional<ScreenRect> chart = tradeoffChart(cost))
            app.view.shownPlots.push_back({"tradeoff", *chart});
    }
}
