// The plots overlay: velocity of the watched block (vx, vy), total momentum (px, py), and the
// kinetic, potential and total energy against time, in a scrolling window with a marker at each
// collision; all drawn with the one plot widget.
#include "app_frame.h"
#include "csv_export.h"
#include "overlay_window.h"
#include "plot_widget.h"
#include "slider.h"
#include "ui_style.h"

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
PlotSeries series(const char* label, ImU32 color, Dash dash, bool band, const TimeSeries& ts,
                  int channel, PlotRange window, double from, double to) {
    PlotSeries s;
    s.label = label;
    s.color = color;
    s.dash = dash;
    s.band = band;
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
void addSeries(std::vector<PlotSeries>& out, const char* label, ImU32 color, Dash dash, bool band,
               const TimeSeries& ts, int channel, PlotRange window, double now, bool replaying) {
    out.push_back(series(label, color, dash, band, ts, channel, window, -INFINITY, now));
    if (!replaying) return;
    const ImU32 faded = (color & ~IM_COL32_A_MASK) | IM_COL32(0, 0, 0, 70);
    out.push_back(series("", faded, dash, band, ts, channel, window, now, INFINITY));
}

// The three plots, in one table: what each draws and what its CSV button writes. The series of
// a plot differ by colour (palette.h's marks) and by dash pattern; the total energy is a band
// under the others, so the kinetic energy it equals without gravity shows inside it.
struct PlotChannel {
    const char* label; // in the legend
    Mark mark;
    Dash dash;
    const char* column; // its CSV column, with the unit
    bool band = false;  // PlotSeries::band
};
struct PlotRow {
    const char* name;  // the plot's ImGui id, its CSV button and its file's name
    const char* title; // over the plot ("v of m1" for the watched block's)
    const char* unit;
    TimeSeries Telemetry::*series;
    std::deque<double> Telemetry::*markers;
    std::vector<PlotChannel> channels;
    bool ofWatchedBlock; // the title and CSV columns name the watched block
};

const std::vector<PlotRow>& plotRows() {
    static const std::vector<PlotRow> rows{
        {"velocity",
         "v of",
         "m/s",
         &Telemetry::velocity,
         &Telemetry::watchedCollisionTimes,
         {{"vx", Mark::PlotX, Dash::Solid, "vx (m/s)"},
          {"vy", Mark::PlotY, Dash::Dashed, "vy (m/s)"}},
         true},
        {"momentum",
         "total momentum",
         "kg·m/s",
         &Telemetry::momentum,
         &Telemetry::collisionTimes,
         {{"px", Mark::PlotX, Dash::Solid, "px (kg*m/s)"},
          {"py", Mark::PlotY, Dash::Dashed, "py (kg*m/s)"}},
         false},
        {"energy",
         "energy",
         "J",
         &Telemetry::energy,
         &Telemetry::collisionTimes,
         {{"kinetic", Mark::Kinetic, Dash::Solid, "kinetic (J)"},
          {"potential", Mark::Potential, Dash::Dashed, "potential (J)"},
          {"total", Mark::Total, Dash::Solid, "total (J)", true}},
         false},
    };
    return rows;
}

std::string watchedName(const App& app) {
    const int watched = app.sim.telemetry.watched;
    return watched >= 0 ? app.sim.blockDisplayName(watched) : std::string("(no block)");
}

// One button per plot: its whole recorded series (the last 60 s) as CSV (csv_export.h).
void exportButtons(App& app) {
    ImGui::TextDisabled("CSV:");
    const ImGuiStyle& style = ImGui::GetStyle();
    for (const PlotRow& row : plotRows()) {
        // On the same line where it fits, else on the next (issue 39: at 1024x768 UI 1.5 the
        // panel's column is 460 px and "energy" was cut at its edge).
        const float width = ImGui::CalcTextSize(row.name).x + 2.0f * style.FramePadding.x;
        if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <=
            ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x)
            ImGui::SameLine();
        if (!uiSmallButton(row.name)) continue;
        const std::string prefix =
            row.ofWatchedBlock && app.sim.telemetry.watched >= 0 ? watchedName(app) + " " : "";
        std::vector<std::string> columns;
        for (const PlotChannel& c : row.channels) columns.push_back(prefix + c.column);
        exportCsv(app, row.name, timeSeriesTable(app.sim.telemetry.*row.series, columns));
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Each writes its plot's series as a CSV file");
}

} // namespace

void drawPlotsOverlay(App& app) {
    OverlayWindow overlay(app, OverlayId::plots);
    if (!overlay) return;
    const Telemetry& tm = app.sim.telemetry;
    // While the timeline replays, the plots show the recorded run around the scrubbed time, with
    // a "now" line there; live, the last seconds up to now.
    const double now = app.sim.world().time;
    const bool replaying = app.sim.isReplaying();
    const double newest =
        tm.energy.size() > 0 ? std::max(now, tm.energy.time(tm.energy.size() - 1)) : now;
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 7.0f);
    uiSliderFloat("time window", &app.ui.plotSpanSeconds, 2.0f, 60.0f, "%.0f s",
                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    exportButtons(app);
    // Until the window fills, the axis grows with the run (at least 2 s), then it scrolls.
    const double span = std::clamp(newest * 1.05, 2.0, static_cast<double>(app.ui.plotSpanSeconds));
    const PlotRange window = timelineWindow(now, replaying ? newest : now, span);
    const std::vector<PlotRow>& rows = plotRows();
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float h = (ImGui::GetContentRegionAvail().y - (rows.size() - 1) * spacing) /
                    static_cast<float>(rows.size());
    for (const PlotRow& row : rows) {
        PlotOptions o;
        o.x = window;
        o.xUnit = "s";
        o.height = h;
        o.includeZero = true;
        if (replaying) o.cursor = now;
        const std::string title =
            row.ofWatchedBlock ? std::string(row.title) + " " + watchedName(app) : row.title;
        o.title = title.c_str();
        o.yUnit = row.unit;
        std::vector<PlotSeries> series;
        for (std::size_t c = 0; c < row.channels.size(); ++c)
            addSeries(series, row.channels[c].label, uiMarkColor(row.channels[c].mark),
                      row.channels[c].dash, row.channels[c].band, tm.*row.series,
                      static_cast<int>(c), window, now, replaying);
        const std::string id = std::string("##") + row.name;
        app.view.shownPlots.push_back(
            {row.name, drawPlot(id.c_str(), o, series, markersIn(tm.*row.markers))});
    }
}
