// Speed versus accuracy in the app: the current scene's cost per step under each method (a copy
// of the world stepped a few frames per method) and the tradeoff chart (error against cost,
// log-log, from runTradeoff with quick = true) drawn with the plot widget. The sweep runs on a
// background thread; the frame loop only polls it.
#include "app_frame.h"
#include "overlay_window.h"
#include "plot_widget.h"
#include "side_by_side.h"
#include "tradeoff.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <future>
#include <map>
#include <set>
#include <string>

Color methodGhostColor(Method method);

namespace {

constexpr int kCostFrames = 30;

struct CostState {
    std::string measuredScene; // scenePath of the last measurement
    std::array<double, 3> msPerStep{{-1.0, -1.0, -1.0}};
    std::future<std::vector<TradeoffRow>> job;
    bool running = false;
    std::vector<TradeoffRow> rows;
    std::string error;
    int scene = 0;
};

CostState& state() {
    static CostState s;
    return s;
}

void measure(const App& app, CostState& s) {
    for (int m = 0; m < 3; ++m) {
        World w = app.world;
        w.settings.method = static_cast<Method>(m);
        double total = 0.0;
        for (int i = 0; i < kCostFrames; ++i) total += w.step().stepMs;
        s.msPerStep[static_cast<std::size_t>(m)] = total / kCostFrames;
    }
    s.measuredScene = app.scenePath;
}

ImU32 engineColor(const std::string& engine) {
    Method m;
    if (parseMethod(engine.c_str(), m)) return methodGhostColor(m).packed();
    if (engine == "chipmunk") return IM_COL32(120, 200, 230, 255);
    return IM_COL32(200, 200, 210, 255); // box2d
}

void pollJob(CostState& s) {
    if (!s.running) return;
    if (s.job.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    s.running = false;
    try {
        s.rows = s.job.get();
        s.error.clear();
    } catch (const std::exception& e) {
        s.error = e.what();
    }
}

void tradeoffChart(CostState& s) {
    std::vector<std::string> scenes;
    for (const TradeoffRow& r : s.rows) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
            scenes.push_back(r.scene);
        }
    }
    if (scenes.empty()) return;
    s.scene = std::clamp(s.scene, 0, static_cast<int>(scenes.size()) - 1);
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 12.0f);
    if (ImGui::BeginCombo("scene", scenes[static_cast<std::size_t>(s.scene)].c_str())) {
        for (int i = 0; i < static_cast<int>(scenes.size()); ++i) {
            if (ImGui::Selectable(scenes[static_cast<std::size_t>(i)].c_str(), i == s.scene)) {
                s.scene = i;
            }
        }
        ImGui::EndCombo();
    }
    const std::string& scene = scenes[static_cast<std::size_t>(s.scene)];
    std::map<std::string, PlotSeries> byEngine;
    std::string unit;
    std::vector<const TradeoffRow*> rows;
    for (const TradeoffRow& r : s.rows) {
        if (r.scene == scene) rows.push_back(&r);
    }
    std::sort(rows.begin(), rows.end(), [](const TradeoffRow* a, const TradeoffRow* b) {
        return a->msPerSimulatedSecond < b->msPerSimulatedSecond;
    });
    for (const TradeoffRow* r : rows) {
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
    drawPlot("##tradeoff", o, series);
}

} // namespace

void drawCostOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::cost);
    if (!overlay) return;
    CostState& s = state();
    pollJob(s);
    if (s.measuredScene != app.scenePath) measure(app, s);
    ImGui::Text("Cost per step of this scene (%zu blocks):", app.world.blocks.size());
    if (ImGui::BeginTable("cost", 2, ImGuiTableFlags_SizingStretchProp)) {
        for (int m = 0; m < 3; ++m) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const Color c = methodGhostColor(static_cast<Method>(m));
            ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1.0f), "%s",
                               methodName(static_cast<Method>(m)));
            ImGui::TableNextColumn();
            ImGui::Text("%.3f ms/step", s.msPerStep[static_cast<std::size_t>(m)]);
        }
        ImGui::EndTable();
    }
    if (ImGui::SmallButton("Measure again")) measure(app, s);
    ImGui::SameLine();
    dimText("(a copy, 30 frames per method)");
    ImGui::Separator();
    if (s.running) {
        ImGui::TextColored(ImVec4(0.55f, 0.85f, 0.6f, 1.0f), "Sweep running in the background...");
    } else if (ImGui::Button("Run the tradeoff sweep (quick)")) {
        TradeoffOptions options;
        options.scenesDir = app.scenesDir;
        options.quick = true;
        s.job = std::async(std::launch::async, runTradeoff, options);
        s.running = true;
    }
    if (!s.error.empty()) ImGui::TextWrapped("Sweep failed: %s", s.error.c_str());
    if (s.rows.empty()) {
        if (!s.running) dimText("Sweeps method x dt x substeps over scenes with known answers.");
    } else {
        tradeoffChart(s);
    }
}

// For the offscreen renderer: runs the sweep now, so a screenshot shows the chart.
void runCostSweepNow(const App& app) {
    CostState& s = state();
    TradeoffOptions options;
    options.scenesDir = app.scenesDir;
    options.quick = true;
    try {
        s.rows = runTradeoff(options);
    } catch (const std::exception& e) {
        s.error = e.what();
    }
}
