#include "chart.h"

#include "printable.h"
#include "safe_file.h"

#include <stb_image_write.h>
#include <stb_truetype.h> // libstb.so holds the implementation: no STB_TRUETYPE_IMPLEMENTATION

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <utility>

namespace {

struct Rgb {
    std::uint8_t r, g, b;
};

constexpr double kFloor = 1e-16;
constexpr float kTextPx = 14.0f;  // body text height (px)
constexpr float kTitlePx = 24.0f; // titles

// The next code point of UTF-8 text at `i` (advanced past it); a malformed byte reads as '?'.
int nextCodePoint(const std::string& s, size_t& i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(i++);
    int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    if (extra < 0) return '?';
    int cp = extra == 0 ? b : b & (0x3f >> extra);
    for (; extra > 0; --extra) {
        if (i >= s.size() || (byte(i) >> 6) != 2) return '?';
        cp = (cp << 6) | (byte(i++) & 0x3f);
    }
    return cp;
}

// The chart's typeface: DejaVu Sans from Debian's fonts-dejavu-core (the file CMake found,
// SANDBOX_CHART_FONT; the environment variable of that name overrides it), read when the first
// chart is drawn and rasterised by stb_truetype, glyph by glyph.
class Font {
  public:
    // Reads the font file; false with a message naming the file and the package when it is
    // missing or not a font.
    bool load(std::string* error) {
        const char* override = std::getenv("SANDBOX_CHART_FONT");
        const std::string path = override && *override ? override : SANDBOX_CHART_FONT;
        if (ready_ && path == path_) return true;
        ready_ = false;
        glyphs_.clear();
        path_ = path;
        std::ifstream file(path, std::ios::binary);
        data_.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
        const auto* bytes = reinterpret_cast<const unsigned char*>(data_.data());
        const int offset = data_.size() < 12 ? -1 : stbtt_GetFontOffsetForIndex(bytes, 0);
        if (offset < 0 || !stbtt_InitFont(&info_, bytes, offset)) {
            if (error)
                *error = "cannot read the chart's font " + printable(path, kPrintablePath) +
                         " (a TrueType file; Debian package fonts-dejavu-core)";
            return false;
        }
        ready_ = true;
        return true;
    }

    struct Glyph {
        std::vector<std::uint8_t> alpha; // w x h coverage, row by row
        int w = 0, h = 0, x = 0, y = 0;  // offset of the top-left from the pen on the baseline
        float advance = 0.0f;            // px
        bool made = false;
    };
    const Glyph& glyph(int codePoint, float px) {
        Glyph& g = glyphs_[{codePoint, px}];
        if (g.made) return g;
        g.made = true;
        const float scale = stbtt_ScaleForPixelHeight(&info_, px);
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(&info_, codePoint, &advance, &bearing);
        g.advance = advance * scale;
        unsigned char* bitmap =
            stbtt_GetCodepointBitmap(&info_, scale, scale, codePoint, &g.w, &g.h, &g.x, &g.y);
        if (bitmap) g.alpha.assign(bitmap, bitmap + static_cast<size_t>(g.w) * g.h);
        stbtt_FreeBitmap(bitmap, nullptr);
        return g;
    }
    float ascent(float px) const {
        int ascent = 0, descent = 0, gap = 0;
        stbtt_GetFontVMetrics(&info_, &ascent, &descent, &gap);
        return ascent * stbtt_ScaleForPixelHeight(&info_, px);
    }
    float kerning(int a, int b, float px) const {
        return stbtt_GetCodepointKernAdvance(&info_, a, b) * stbtt_ScaleForPixelHeight(&info_, px);
    }

  private:
    bool ready_ = false;
    std::string path_;
    std::string data_; // the .ttf file: stb_truetype reads from it
    stbtt_fontinfo info_{};
    std::map<std::pair<int, float>, Glyph> glyphs_;
};

Font& chartFont() {
    static Font font; // loaded once: the charts of a run share it
    return font;
}
const Rgb kPalette[] = {{208, 64, 64},   {64, 112, 208}, {64, 160, 80},
                        {144, 80, 192},  {224, 138, 48}, {48, 160, 160},
                        {120, 120, 120}, {150, 100, 40}, {220, 110, 180}};

// An RGB image with the few drawing operations a chart needs.
class Canvas {
  public:
    // `font` must be loaded.
    Canvas(int width, int height, Font& font)
        : w_(width), h_(height), pixels_(width * height * 3, 255), font_(font) {}

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
    // Text with its top-left at (x, y) (the top of the font's ascent), `px` high; returns its
    // width in pixels.
    int text(int x, int y, const std::string& s, Rgb c, float px = kTextPx) {
        return layout(
            s, px,
            [&](const Font::Glyph& g, float pen) {
                const int gx = static_cast<int>(std::lround(pen)) + g.x;
                const int gy = y + static_cast<int>(std::lround(font_.ascent(px))) + g.y;
                for (int v = 0; v < g.h; ++v)
                    for (int u = 0; u < g.w; ++u)
                        blend(gx + u, gy + v, c,
                              g.alpha[static_cast<size_t>(v) * g.w + u] / 255.0f);
            },
            static_cast<float>(x));
    }
    int textWidth(const std::string& s, float px = kTextPx) {
        return layout(
            s, px, [](const Font::Glyph&, float) {}, 0.0f);
    }
    bool save(const std::string& path, std::string* error) const {
        return writePngFile(path, pixels_.data(), w_, h_, 3, error);
    }

  private:
    // Calls draw(glyph, pen) for each glyph of s from `start`, kerned; returns the width.
    template <class Draw> int layout(const std::string& s, float px, Draw&& draw, float start) {
        float pen = start;
        int previous = 0;
        for (size_t i = 0; i < s.size();) {
            const int cp = nextCodePoint(s, i);
            if (previous) pen += font_.kerning(previous, cp, px);
            const Font::Glyph& g = font_.glyph(cp, px);
            draw(g, pen);
            pen += g.advance;
            previous = cp;
        }
        return static_cast<int>(std::lround(pen - start));
    }

    int w_, h_;
    std::vector<std::uint8_t> pixels_;
    Font& font_;
};

std::string decadeLabel(int exponent) {
    if (exponent == 0) return "1";
    if (exponent == 1) return "10";
    return "1e" + std::to_string(exponent);
}

void drawPanel(Canvas& canvas, const ChartPanel& panel, int x0, int y0, int w, int h,
               const std::map<std::string, Rgb>& colours) {
    const Rgb ink{40, 40, 40}, grid{225, 225, 225};
    canvas.text(x0 + 70, y0 + 8, panel.title, ink, kTitlePx);
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

bool writePngFile(const std::string& path, const std::uint8_t* pixels, int width, int height,
                  int channels, std::string* error) {
    // Encoded in memory, then written through a SafeFile (the old file kept on failure).
    std::string png;
    const auto append = [](void* to, void* data, int size) {
        static_cast<std::string*>(to)->append(static_cast<const char*>(data),
                                              static_cast<std::size_t>(size));
    };
    if (stbi_write_png_to_func(append, &png, width, height, channels, pixels, width * channels) ==
        0) {
        if (error) *error = printable(path, kPrintablePath) + ": cannot encode the PNG";
        return false;
    }
    return writeFileSafely(path, png, error);
}

bool writeLogLogChart(const std::string& path, const std::vector<ChartPanel>& panels,
                      const std::string& title, std::string* error) {
    const int columns = 3, panelW = 560, panelH = 400, header = 70;
    const int rows = std::max(1, static_cast<int>((panels.size() + columns - 1) / columns));
    Font& font = chartFont();
    if (!font.load(error)) return false;
    Canvas canvas(columns * panelW, header + rows * panelH, font);

    std::map<std::string, Rgb> colours;
    for (const ChartPanel& p : panels)
        for (const ChartSeries& s : p.series)
            if (!colours.count(s.name))
                colours[s.name] = kPalette[colours.size() % std::size(kPalette)];

    const Rgb ink{30, 30, 30};
    canvas.text(20, 14, title, ink, kTitlePx);
    int lx = 20;
    for (const auto& [name, c] : colours) { // legend
        canvas.fillRect(lx, 50, lx + 14, 62, c);
        lx += 20 + canvas.text(lx + 20, 49, name, ink) + 20;
    }
    canvas.text(lx + 20, 49, "(errors below 1e-16 drawn on the floor)", {110, 110, 110});
    for (size_t i = 0; i < panels.size(); ++i)
        drawPanel(canvas, panels[i], static_cast<int>(i % columns) * panelW,
                  header + static_cast<int>(i / columns) * panelH, panelW, panelH, colours);
    return canvas.save(path, error);
}
