#include "chart.h"

#include <imgui.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

namespace {

struct Rgb {
    std::uint8_t r, g, b;
};

constexpr double kFloor = 1e-16;
const Rgb kPalette[] = {{208, 64, 64},  {64, 112, 208}, {64, 160, 80},  {144, 80, 192},
                        {224, 138, 48}, {48, 160, 160}, {120, 120, 120}};

// An RGB image with the few drawing operations a chart needs.
class Canvas {
  public:
    Canvas(int width, int height) : w_(width), h_(height), pixels_(width * height * 3, 255) {
        ImFontAtlas& atlas = fontAtlas();
        font_ = atlas.Fonts.empty() ? atlas.AddFontDefault() : atlas.Fonts[0];
        atlas.GetTexDataAsAlpha8(&fontPixels_, &fontWidth_, &fontHeight_);
    }

    void blend(int x, int y, Rgb c, float alpha) {
        if (x < 0 || y < 0 || x >= w_ || y >= h_ || alpha <= 0.0f) return;
        std::uint8_t* p = &pixels_[(static_cast<size_t>(y) * w_ + x) * 3];
        p[0] = static_cast<std::uint8_t>(p[0] + (c.r - p[0]) * alpha);
        p[1] = static_cast<std::uint8_t>(p[1] + (c.g - p[1]) * alpha);
        p[2] = static_cast<std::uint8_t>(p[2] + (c.b - p[2]) * alpha);
    }
    void fillRect(int x0, int y0, int x1, int y1, Rgb c) {
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) blend(x, y, c, 1.0f);
    }
    void disc(double cx, double cy, double radius, Rgb c) {
        for (int y = static_cast<int>(cy - radius - 1); y <= cy + radius + 1; ++y) {
            for (int x = static_cast<int>(cx - radius - 1); x <= cx + radius + 1; ++x) {
                const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
                blend(x, y, c, static_cast<float>(std::clamp(radius + 0.5 - d, 0.0, 1.0)));
            }
        }
    }
    // A line of the given width, drawn as overlapping discs (anti-aliased at the edges).
    void line(double x0, double y0, double x1, double y1, double width, Rgb c) {
        const double len = std::hypot(x1 - x0, y1 - y0);
        const int steps = std::max(1, static_cast<int>(len / 0.5));
        for (int i = 0; i <= steps; ++i) {
            const double t = static_cast<double>(i) / steps;
            disc(x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, width / 2, c);
        }
    }
    // Text with its top-left at (x, y), glyphs scaled by an integer factor.
    int text(int x, int y, const std::string& s, Rgb c, int scale = 1) {
        float pen = static_cast<float>(x);
        for (char ch : s) {
            const ImFontGlyph* g =
                font_->FindGlyph(static_cast<ImWchar>(static_cast<unsigned char>(ch)));
            if (!g) continue;
            const int gx0 = static_cast<int>(g->U0 * fontWidth_),
                      gy0 = static_cast<int>(g->V0 * fontHeight_);
            const int gw = static_cast<int>((g->U1 - g->U0) * fontWidth_ + 0.5f);
            const int gh = static_cast<int>((g->V1 - g->V0) * fontHeight_ + 0.5f);
            for (int v = 0; v < gh * scale; ++v)
                for (int u = 0; u < gw * scale; ++u) {
                    const float a =
                        fontPixels_[(gy0 + v / scale) * fontWidth_ + gx0 + u / scale] / 255.0f;
                    blend(static_cast<int>(pen + g->X0 * scale) + u,
                          y + static_cast<int>(g->Y0 * scale) + v, c, a);
                }
            pen += g->AdvanceX * scale;
        }
        return static_cast<int>(pen) - x;
    }
    int textWidth(const std::string& s, int scale = 1) const {
        return static_cast<int>(font_->CalcTextSizeA(font_->FontSize, 1e9f, 0.0f, s.c_str()).x) *
               scale;
    }
    bool save(const std::string& path) const {
        return stbi_write_png(path.c_str(), w_, h_, 3, pixels_.data(), w_ * 3) != 0;
    }

  private:
    static ImFontAtlas& fontAtlas() {
        static ImFontAtlas atlas; // built once; needs no ImGui context
        return atlas;
    }
    int w_, h_;
    std::vector<std::uint8_t> pixels_;
    ImFont* font_ = nullptr;
    unsigned char* fontPixels_ = nullptr;
    int fontWidth_ = 0, fontHeight_ = 0;
};

std::string decadeLabel(int exponent) {
    if (exponent == 0) return "1";
    if (exponent == 1) return "10";
    return "1e" + std::to_string(exponent);
}

void drawPanel(Canvas& canvas, const ChartPanel& panel, int x0, int y0, int w, int h,
               const std::map<std::string, Rgb>& colours) {
    const Rgb ink{40, 40, 40}, grid{225, 225, 225};
    canvas.text(x0 + 70, y0 + 8, panel.title, ink, 2);
    const int left = x0 + 70, right = x0 + w - 20, top = y0 + 58, bottom = y0 + h - 50;

    // Data range in decades.
    double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
    for (const ChartSeries& s : panel.series)
        for (const Vec2& p : s.points) {
            if (p.x <= 0.0) continue;
            const double y = std::max(p.y, kFloor);
            minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
            minY = std::min(minY, y), maxY = std::max(maxY, y);
        }
    if (minX > maxX) return;
    const int ex0 = static_cast<int>(std::floor(std::log10(minX))),
              ex1 = static_cast<int>(std::ceil(std::log10(maxX) + 1e-9));
    const int ey0 = static_cast<int>(std::floor(std::log10(minY))),
              ey1 = static_cast<int>(std::ceil(std::log10(maxY) + 1e-9));
    const int spanX = std::max(1, ex1 - ex0), spanY = std::max(1, ey1 - ey0);
    auto px = [&](double x) { return left + (std::log10(x) - ex0) / spanX * (right - left); };
    auto py = [&](double y) {
        return bottom - (std::log10(std::max(y, kFloor)) - ey0) / spanY * (bottom - top);
    };

    // Grid and tick labels at every decade (every other one when crowded).
    const int stepY = spanY > 10 ? 2 : 1;
    for (int e = ex0; e <= ex0 + spanX; ++e) {
        const double x = px(std::pow(10.0, e));
        canvas.line(x, top, x, bottom, 1, grid);
        const std::string label = decadeLabel(e);
        canvas.text(static_cast<int>(x) - canvas.textWidth(label) / 2, bottom + 6, label, ink);
    }
    for (int e = ey0; e <= ey0 + spanY; e += stepY) {
        const double y = py(std::pow(10.0, e));
        canvas.line(left, y, right, y, 1, grid);
        const std::string label = decadeLabel(e);
        canvas.text(left - 8 - canvas.textWidth(label), static_cast<int>(y) - 6, label, ink);
    }
    canvas.line(left, bottom, right, bottom, 1.5, ink);
    canvas.line(left, top, left, bottom, 1.5, ink);
    canvas.text(left + (right - left) / 2 - canvas.textWidth(panel.xLabel) / 2, bottom + 24,
                panel.xLabel, ink);
    canvas.text(left, top - 18, panel.yLabel, {90, 90, 90});

    for (const ChartSeries& s : panel.series) {
        const Rgb c = colours.at(s.name);
        for (size_t i = 0; i < s.points.size(); ++i) {
            const Vec2& p = s.points[i];
            if (p.x <= 0.0) continue;
            canvas.disc(px(p.x), py(p.y), 3.5, c);
            if (i > 0 && s.points[i - 1].x > 0.0)
                canvas.line(px(s.points[i - 1].x), py(s.points[i - 1].y), px(p.x), py(p.y), 2, c);
        }
    }
}

} // namespace

bool writeLogLogChart(const std::string& path, const std::vector<ChartPanel>& panels,
                      const std::string& title, std::string* error) {
    const int columns = 3, panelW = 560, panelH = 400, header = 70;
    const int rows = std::max(1, static_cast<int>((panels.size() + columns - 1) / columns));
    Canvas canvas(columns * panelW, header + rows * panelH);

    std::map<std::string, Rgb> colours;
    for (const ChartPanel& p : panels)
        for (const ChartSeries& s : p.series)
            if (!colours.count(s.name))
                colours[s.name] = kPalette[colours.size() % std::size(kPalette)];

    const Rgb ink{30, 30, 30};
    canvas.text(20, 14, title, ink, 2);
    int lx = 20;
    for (const auto& [name, c] : colours) { // legend
        canvas.fillRect(lx, 50, lx + 14, 62, c);
        lx += 20 + canvas.text(lx + 20, 49, name, ink) + 20;
    }
    canvas.text(lx + 20, 49, "(errors below 1e-16 drawn on the floor)", {110, 110, 110});
    for (size_t i = 0; i < panels.size(); ++i)
        drawPanel(canvas, panels[i], static_cast<int>(i % columns) * panelW,
                  header + static_cast<int>(i / columns) * panelH, panelW, panelH, colours);
    if (!canvas.save(path)) {
        if (error) *error = "cannot write " + path;
        return false;
    }
    return true;
}
