// The plots overlay: velocity of the watched block (vx, vy), total momentum (px, py), and the
// kinetic, potential and total energy against time, in a scrolling window with a marker at each
// collision; all drawn with the one plot widget.
#include "app_frame.h"
#include "csv_export.h"
#include "overlay_window.h"
#include "plot_widget.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <vector>

namespace {

std::vector<double> markersIn(const std::deque<double>& times) {
    return std::vector<double>(times.begin(), times.end());
}

// Series `channel` of `ts` within [window.lo, window.hi] and [from, to].
PlotSeries series(const char* label, ImU32 color, const TimeSeries& ts, int channel,
                  PlotRange window, double from, double to) {
    PlotSeries s;
    s.label = label;
    s.color = color;
    for (std::size_t i = ts.firstAtOrAfter(std::max(window.lo, from)); i < ts.size(); ++i) {
        const double t = ts.time(i);
        if (t > std::min(window.hi, to) + 1e-12) break;
        s.x.push_back(t);
        s.y.push_back(ts.value(i, channel));
    }
    return s;
}

// A series up to `now` and, while the timeline replays, its recorded future, faded and without
// a legend entry.
void addSeries(std::vector<PlotSeries>& out, const char* label, ImU32 color, const TimeSeries& ts,
               int channel, PlotRange window, double now, bool replaying) {
    out.push_back(series(label, color, ts, channel, window, -INFINITY, now));
    if (!replaying) return;
    const ImU32 faded = (color & ~IM_COL32_A_MASK) | IM_COL32(0, 0, 0, 70);
    out.push_back(series("", faded, ts, channel, window, now, INFINITY));
}

// One button per plot: its whole recorded series (the last 60 s) as CSV (csv_export.h).
void exportButtons(App& app) {
    const Telemetry& tm = app.telemetry;
    ImGui::TextDisabled("CSV:");
    ImGui::SameLine();
    if (ImGui::SmallButton("velocity")) {
        const std::string name =
            tm.watched >= 0 ? blockDisplayName(app, tm.watched) + " " : std::string();
        exportCsv(app, "velocity",
                  timeSeriesTable(tm.velocity, {name + "vx (m/s)", name + "vy (m/s)"}));
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("momentum"))
        exportCsv(app, "momentum", timeSeriesTable(tm.momentum, {"px (kg*m/s)", "py (kg*m/s)"}));
    ImGui::SameLine();
    if (ImGui::SmallButton("energy")) {
        exportCsv(app, "energy",
                  timeSeriesTable(tm.energy, {"kinetic (J)", "potential (J)", "total (J)"}));
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Each writes its plot's series as a CSV file");
}

} // namespace

void drawPlotsOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::plots);
    if (!overlay) return;
    const Telemetry& tm = app.telemetry;
    // While the timeline replays, the plots show the recorded run around the scrubbed time, with
    // a "now" line there; live, the last seconds up to now.
    const double now = app.world.time;
    const bool replaying = isReplaying(app);
    const double newest =
        tm.energy.size() > 0 ? std::max(now, tm.energy.time(tm.energy.size() - 1)) : now;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    ImGui::SliderFloat("time window", &app.ui.plotSpanSeconds, 2.0f, 60.0f, "%.0f s",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    exportButtons(app);
    // Until the window fills, the axis grows with the run (at least 2 s), then it scrolls.
    const double span = std::clamp(newest * 1.05, 2.0, static_cast<double>(app.ui.plotSpanSeconds));
    const PlotRange window = timelineWindow(now, replaying ? newest : now, span);
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float h = (ImGui::GetContentRegionAvail().y - 2.0f * spacing) / 3.0f;
    using namespace overlay_colors;

    PlotOptions o;
    o.x = window;
    o.xUnit = "s";
    o.height = h;
    o.includeZero = true;
    if (replaying) o.cursor = now;
    std::string title =
        "v of " + (tm.watched >= 0 ? blockDisplayName(app, tm.watched) : std::string("(no block)"));
    o.title = title.c_str();
    o.yUnit = "m/s";
    std::vector<PlotSeries> s;
    addSeries(s, "vx", kX, tm.velocity, 0, window, now, replaying);
    addSeries(s, "vy", kY, tm.velocity, 1, window, now, replaying);
    drawPlot("##velocity", o, s, markersIn(tm.watchedCollisionTimes));
    o.title = "total momentum";
    o.yUnit = "kg·m/s";
    s.clear();
    addSeries(s, "px", kX, tm.momentum, 0, window, now, replaying);
    addSeries(s, "py", kY, tm.momentum, 1, window, now, replaying);
    drawPlot("##momentum", o, s, markersIn(tm.collisionTimes));
    o.title = "energy";
    o.yUnit = "J";
    s.clear();
    addSeries(s, "kinetic", kKinetic, tm.energy, 0, window, now, replaying);
    addSeries(s, "potential", kPotential, tm.energy, 1, window, now, replaying);
    addSeries(s, "total", kTotal, tm.energy, 2, window, now, replaying);
    drawPlot("##energy", o, s, markersIn(tm.collisionTimes));
}
