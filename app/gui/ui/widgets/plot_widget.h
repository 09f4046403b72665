// One small plot widget on ImDrawList (ImPlot is not packaged in Debian), used by every plot of
// the app: the velocity, momentum and energy plots and the speed-versus-accuracy chart. Several
// series, axes with tick labels, a legend, vertical markers (collisions), optional log axes, and
// the values under the cursor. Tick and range logic is in plot_logic.h.
#pragma once

#include "camera.h" // ScreenRect
#include "plot_logic.h"

#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

struct PlotSeries {
    std::string label;                          // "" : no legend entry (the faded part of a series)
    ImU32 color = IM_COL32(255, 255, 255, 255); // as drawn (the caller's theme's colour)
    Dash dash = Dash::Solid;
    std::vector<double> x, y;
    bool points = false; // draw a dot at every sample (sparse data: the tradeoff chart)
    // A wide translucent band under the other lines (drawn first), for a series another may
    // equal: the total energy, which is the kinetic energy without gravity, shows around it.
    bool band = false;
};

struct PlotOptions {
    const char* title = ""; // drawn at the top left, inside the plot
    const char* xUnit = ""; // after the last x tick label
    const char* yUnit = ""; // above the y axis
    PlotRange x{0.0, 1.0};  // x range (linear values even when logX: the widget takes logs)
    bool autoX = false;     // fit x to the data instead
    bool logX = false, logY = false;
    bool includeZero = false; // keep y = 0 in view
    float height = 0.0f;      // px; 0: the rest of the window
    double cursor = NAN; // x of a vertical "now" line (the timeline's scrubbed time); NAN: none
};

// Draws the plot at the cursor, full width. `markers` are x values drawn as vertical lines.
// Returns the widget's rectangle on screen (title, axes and legend included).
ScreenRect drawPlot(const char* id, const PlotOptions& options,
                    const std::vector<PlotSeries>& series, const std::vector<double>& markers = {});
