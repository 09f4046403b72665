#include "palette.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

std::uint32_t toByte(float v) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

// Colour-blind-friendly, saturated enough to read on the dark arena and on a projector.
constexpr std::array<Color, 10> kPalette{{
    {0.90f, 0.36f, 0.33f, 1.0f}, // red
    {0.30f, 0.62f, 0.95f, 1.0f}, // blue
    {0.99f, 0.75f, 0.25f, 1.0f}, // amber
    {0.40f, 0.78f, 0.45f, 1.0f}, // green
    {0.72f, 0.50f, 0.92f, 1.0f}, // violet
    {0.98f, 0.56f, 0.20f, 1.0f}, // orange
    {0.30f, 0.80f, 0.80f, 1.0f}, // teal
    {0.95f, 0.50f, 0.72f, 1.0f}, // pink
    {0.70f, 0.78f, 0.35f, 1.0f}, // olive
    {0.55f, 0.65f, 0.98f, 1.0f}, // periwinkle
}};

// One per Method, in the engine's order (a new method is a row here).
constexpr Color kMethodColors[] = {
    {0.45f, 0.95f, 0.55f, 1.0f}, // perfect
    {1.0f, 0.55f, 0.25f, 1.0f},  // move-and-correct
    {0.80f, 0.50f, 1.0f, 1.0f},  // turn-based
};
static_assert(sizeof kMethodColors / sizeof kMethodColors[0] ==
                  static_cast<std::size_t>(Method::Count),
              "one colour per method");

} // namespace

std::uint32_t Color::packed() const {
    return (toByte(a) << 24) | (toByte(b) << 16) | (toByte(g) << 8) | toByte(r);
}

Color Color::mix(const Color& other, float t) const {
    return {r + (other.r - r) * t, g + (other.g - g) * t, b + (other.b - b) * t,
            a + (other.a - a) * t};
}

bool parseHexColor(const std::string& text, Color& out) {
    const std::size_t start = (!text.empty() && text[0] == '#') ? 1 : 0;
    if (text.size() != start + 6) return false;
    int bytes[3];
    for (int i = 0; i < 3; ++i) {
        const int hi = hexDigit(text[start + 2 * i]);
        const int lo = hexDigit(text[start + 2 * i + 1]);
        if (hi < 0 || lo < 0) return false;
        bytes[i] = hi * 16 + lo;
    }
    out = {bytes[0] / 255.0f, bytes[1] / 255.0f, bytes[2] / 255.0f, 1.0f};
    return true;
}

std::string toHexColor(const Color& color) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<unsigned>(toByte(color.r)),
                  static_cast<unsigned>(toByte(color.g)), static_cast<unsigned>(toByte(color.b)));
    return buf;
}

Color blockColor(int index, const std::string& sceneColor) {
    Color c;
    if (parseHexColor(sceneColor, c)) return c;
    const std::size_t n = kPalette.size();
    return kPalette[static_cast<std::size_t>(index < 0 ? 0 : index) % n];
}

Color staticBlockColor() {
    return {0.50f, 0.53f, 0.60f, 1.0f};
}
Color kinematicBlockColor() {
    return {0.62f, 0.58f, 0.48f, 1.0f};
}

Color studentTraceColor() {
    return {1.0f, 0.35f, 0.85f, 1.0f}; // magenta: none of the methods' green, orange, violet
}

Color methodColor(Method method) {
    const auto i = static_cast<std::size_t>(method);
    return i < static_cast<std::size_t>(Method::Count) ? kMethodColors[i] : Color{1.0f, 1.0f, 1.0f};
}

namespace {

double linearChannel(float c) {
    const double v = static_cast<double>(c);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double luminance(const Color& c) {
    return 0.2126 * linearChannel(c.r) + 0.7152 * linearChannel(c.g) + 0.0722 * linearChannel(c.b);
}

} // namespace

double contrastRatio(const Color& a, const Color& b) {
    const double la = luminance(a), lb = luminance(b);
    return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Color outlineFor(const Color& fill, const Color& background) {
    if (contrastRatio(fill, background) >= kMinBlockContrast) return scene_colors::kOutline;
    return luminance(background) < 0.4 ? Color{0.92f, 0.93f, 0.96f, 1.0f}
                                       : Color{0.05f, 0.05f, 0.08f, 1.0f};
}

const SceneTheme& sceneTheme(bool light) {
    static const SceneTheme dark{scene_colors::kBackground, scene_colors::kArena,
                                 scene_colors::kGridMinor,  scene_colors::kGridMajor,
                                 scene_colors::kWall,       scene_colors::kLabel,
                                 {0.0f, 0.0f, 0.0f, 0.78f}, {0.667f, 0.698f, 0.765f, 0.78f},
                                 scene_colors::kVelocity};
    static const SceneTheme bright{
        {0.86f, 0.87f, 0.89f, 1.0f}, {0.975f, 0.975f, 0.965f, 1.0f}, {0.0f, 0.0f, 0.0f, 0.07f},
        {0.0f, 0.0f, 0.0f, 0.18f},   {0.45f, 0.47f, 0.52f, 1.0f},    {0.06f, 0.06f, 0.09f, 1.0f},
        {1.0f, 1.0f, 1.0f, 0.80f},   {0.25f, 0.27f, 0.32f, 1.0f},    {0.0f, 0.42f, 0.78f, 1.0f}};
    return light ? bright : dark;
}
