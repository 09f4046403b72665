// A small log-log chart rendered on the CPU to a PNG (no GL): panels of series of points, axes
// with decade ticks, a legend. Text in DejaVu Sans (fonts-dejavu-core), rasterised by
// stb_truetype. Used for the speed-versus-accuracy chart of `sandbox-cli tradeoff`.
#pragma once

#include "vec2.h"

#include <cstdint>
#include <string>
#include <vector>

struct ChartSeries {
    std::string name;
    std::vector<Vec2> points; // (x, y), both > 0 to be drawn; y <= 0 is drawn at the floor
};

struct ChartPanel {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    std::vector<ChartSeries> series;
};

// Writes the panels side by side (three per row) as a PNG. Values of y below 1e-16 (exact
// answers) are drawn on the floor of the panel. Series get the same colour in every panel by
// name. Returns false with a message in `error` when the file cannot be written or the font
// cannot be read.
bool writeLogLogChart(const std::string& path, const std::vector<ChartPanel>& panels,
                      const std::string& title, std::string* error);

// Writes 8-bit pixels (`channels` per pixel, top row first) as a PNG through a SafeFile
// (safe_file.h): encoded in memory, the old file kept on failure; false with `error` naming the
// file. The chart's and the app's screenshots' one PNG writer.
bool writePngFile(const std::string& path, const std::uint8_t* pixels, int width, int height,
                  int channels, std::string* error);
