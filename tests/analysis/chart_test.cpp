// The CPU-drawn log-log chart: its text comes from the TrueType font (stb_truetype, no ImGui),
// and a missing font is a clear error, not a crash or a chart without labels.
#include "chart.h"

#include <stb_image.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

std::vector<ChartPanel> onePanel() {
    ChartPanel panel;
    panel.title = "panel";
    panel.xLabel = "ms per simulated second";
    panel.yLabel = "error";
    panel.series.push_back({"perfect", {{0.1, 1e-3}, {1.0, 1e-6}}});
    return {panel};
}

// Dark pixels (all channels below 128) in the rectangle [x0, x1) x [y0, y1) of a PNG.
int darkPixels(const std::string& png, int x0, int y0, int x1, int y1) {
    int w = 0, h = 0, channels = 0;
    unsigned char* pixels = stbi_load(png.c_str(), &w, &h, &channels, 3);
    if (!pixels) return -1;
    int dark = 0;
    for (int y = y0; y < y1 && y < h; ++y)
        for (int x = x0; x < x1 && x < w; ++x) {
            const unsigned char* p = pixels + (static_cast<size_t>(y) * w + x) * 3;
            dark += p[0] < 128 && p[1] < 128 && p[2] < 128;
        }
    stbi_image_free(pixels);
    return dark;
}

// One file per test: ctest runs tests in parallel processes.
std::string pngPath(const char* test) {
    return (std::filesystem::temp_directory_path() / (std::string("chart_test_") + test + ".png"))
        .string();
}

TEST(Chart, TitleTextIsDrawn) {
    const std::string kPng = pngPath("title");
    std::string error;
    // The title's line (y 14 to 44 at 24 px) holds ink only where there is text.
    ASSERT_TRUE(writeLogLogChart(kPng, onePanel(), "", &error)) << error;
    EXPECT_EQ(darkPixels(kPng, 0, 14, 600, 44), 0);
    ASSERT_TRUE(writeLogLogChart(kPng, onePanel(), "Error against cost (log-log)", &error))
        << error;
    // 28 glyphs of 24 px: well over a few hundred dark pixels.
    EXPECT_GT(darkPixels(kPng, 0, 14, 600, 44), 300);
    std::remove(kPng.c_str());
}

TEST(Chart, MissingFontIsAClearError) {
    const std::string kPng = pngPath("missing_font");
    std::remove(kPng.c_str());
    ASSERT_EQ(setenv("SANDBOX_CHART_FONT", "/nonexistent/DejaVuSans.ttf", 1), 0);
    std::string error;
    EXPECT_FALSE(writeLogLogChart(kPng, onePanel(), "title", &error));
    EXPECT_NE(error.find("/nonexistent/DejaVuSans.ttf"), std::string::npos) << error;
    EXPECT_NE(error.find("fonts-dejavu-core"), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists(kPng));
    // Not a font either.
    ASSERT_EQ(setenv("SANDBOX_CHART_FONT", SANDBOX_SCENES_DIR "/pile.json", 1), 0);
    EXPECT_FALSE(writeLogLogChart(kPng, onePanel(), "title", &error));
    EXPECT_NE(error.find("pile.json"), std::string::npos) << error;
    // The installed font again.
    ASSERT_EQ(unsetenv("SANDBOX_CHART_FONT"), 0);
    EXPECT_TRUE(writeLogLogChart(kPng, onePanel(), "title", &error)) << error;
    std::remove(kPng.c_str());
}

} // namespace
