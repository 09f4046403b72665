#include "palette.h"

#include <algorithm>
#include <array>
#include <cmath>

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

// The blocks' palette, chosen with the marks below (palette_test.cpp): every pair stays at least
// kMinMarkDifference apart for normal vision and the three dichromacies. Ordered so that
// neighbours in a scene's list differ in lightness, the cue every reader keeps.
constexpr std::array<NamedColor, 8> kPalette{{
    {"red", {0.631f, 0.176f, 0.165f, 1.0f}},    // #a12d2a
    {"blue", {0.310f, 0.475f, 0.871f, 1.0f}},   // #4f79de
    {"yellow", {0.988f, 0.882f, 0.314f, 1.0f}}, // #fce150
    {"purple", {0.318f, 0.129f, 0.545f, 1.0f}}, // #51218b
    {"teal", {0.137f, 0.812f, 0.867f, 1.0f}},   // #23cfdd
    {"orange", {0.776f, 0.490f, 0.016f, 1.0f}}, // #c67d04
    {"green", {0.643f, 0.694f, 0.600f, 1.0f}},  // #a4b199
    {"grey", {0.435f, 0.435f, 0.455f, 1.0f}},   // #6f6f74
}};

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

Color Color::over(const Color& backdrop) const {
    return backdrop.withAlpha(1.0f).mix(withAlpha(1.0f), a);
}

const std::array<NamedColor, 8>& blockPalette() {
    return kPalette;
}

Color blockColor(int index, const std::string& sceneColor) {
    Color c;
    if (parseHexColor(sceneColor, c)) return c;
    const std::size_t n = kPalette.size();
    return kPalette[static_cast<std::size_t>(index < 0 ? 0 : index) % n].color;
}

Color staticBlockColor() {
    return {0.50f, 0.53f, 0.60f, 1.0f};
}
Color kinematicBlockColor() {
    return {0.62f, 0.58f, 0.48f, 1.0f};
}

// Not yet one of the marks (markGroups): compare's colour, kept as it came.
Color studentTraceColor() {
    return {1.0f, 0.35f, 0.85f, 1.0f}; // magenta: none of the methods' green, orange, violet
}

double linearChannel(float c) {
    const double v = static_cast<double>(c);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

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
    static const SceneTheme dark{scene_colors::kBackground,
                                 scene_colors::kArena,
                                 scene_colors::kGridMinor,
                                 scene_colors::kGridMajor,
                                 scene_colors::kWall,
                                 scene_colors::kLabel,
                                 {0.0f, 0.0f, 0.0f, 0.78f},
                                 {0.667f, 0.698f, 0.765f, 0.78f},
                                 markColor(Mark::Velocity, false),
                                 markColor(Mark::Momentum, false),
                                 markColor(Mark::Force, false)};
    static const SceneTheme bright{{0.86f, 0.87f, 0.89f, 1.0f},     {0.975f, 0.975f, 0.965f, 1.0f},
                                   {0.0f, 0.0f, 0.0f, 0.07f},       {0.0f, 0.0f, 0.0f, 0.18f},
                                   {0.45f, 0.47f, 0.52f, 1.0f},     {0.06f, 0.06f, 0.09f, 1.0f},
                                   {1.0f, 1.0f, 1.0f, 0.80f},       {0.25f, 0.27f, 0.32f, 1.0f},
                                   markColor(Mark::Velocity, true), markColor(Mark::Momentum, true),
                                   markColor(Mark::Force, true)};
    return light ? bright : dark;
}

namespace {

// "#rrggbb" as a colour, for the table below (checked by the palette test: every entry parses).
Color hex(const char* text, float alpha = 1.0f) {
    Color c;
    parseHexColor(text, c);
    return c.withAlpha(alpha);
}

} // namespace

const std::array<MarkColors, static_cast<std::size_t>(Mark::Count)>& markTable() {
    // Dark theme: light colours over the dark arena and windows; light theme: deep ones.
    static const std::array<MarkColors, static_cast<std::size_t>(Mark::Count)> table{{
        {Mark::PlotX, "plot x", hex("#5ac8ff"), hex("#347da2")},
        {Mark::PlotY, "plot y", hex("#eb6899"), hex("#992c55")},
        {Mark::Kinetic, "kinetic", hex("#c28a06"), hex("#a8803b")},
        {Mark::Potential, "potential", hex("#9afc97"), hex("#015104")},
        {Mark::Total, "total", hex("#f0f0f5"), hex("#161617")},
        {Mark::MethodPerfect, "perfect", hex("#7cfa94"), hex("#5dc168")},
        {Mark::MethodMoveAndCorrect, "move-and-correct", hex("#da6c1d"), hex("#9f5423")},
        {Mark::MethodTurnBased, "turn-based", hex("#cc80ff"), hex("#6c2b97")},
        {Mark::PoiOld, "POI old", hex("#c8cdd7"), hex("#373b47")},
        {Mark::PoiNew, "POI new", hex("#c12a2b"), hex("#720e12")},
        {Mark::PoiContact, "POI", hex("#99feb5"), hex("#6cce7e")},
        {Mark::PoiMovedBack, "moved back", hex("#e3910f"), hex("#9c6923")},
        {Mark::Reflection, "reflection", hex("#93969a"), hex("#393c43")},
        {Mark::VelocityPath, "velocity path", hex("#5ac7fd"), hex("#2e7599")},
        {Mark::Velocity, "velocity", hex("#7bdeff"), hex("#4188e9")},
        {Mark::Momentum, "momentum", hex("#c0660e", 0.55f), hex("#fea035", 0.55f)},
        {Mark::Force, "force", hex("#d233c5"), hex("#881c7e")},
        {Mark::CentreOfMass, "centre of mass", hex("#ffeb5a"), hex("#978a2b")},
    }};
    return table;
}

Color markColor(Mark mark, bool light) {
    const MarkColors& m = markTable()[static_cast<std::size_t>(mark)];
    return light ? m.light : m.dark;
}

Mark methodMark(Method method) {
    switch (method) {
    case Method::Perfect:
        return Mark::MethodPerfect;
    case Method::MoveAndCorrect:
        return Mark::MethodMoveAndCorrect;
    case Method::TurnBased:
    case Method::Count:
        break;
    }
    return Mark::MethodTurnBased;
}

// Opaque: at 0.97-0.98 the scene never showed through a panel to the eye, but the software
// rasteriser (llvmpipe, a laptop without a GPU) had to blend every pixel of it, a fifth of a
// 1080p frame's fragments; opaque, the UI renderer clears it instead (findOpaqueFills, issue 42).
Color windowBackground(bool light) {
    return light ? Color{0.96f, 0.96f, 0.95f, 1.0f} : Color{0.105f, 0.113f, 0.140f, 1.0f};
}

Color plotAreaColor(bool light) {
    return light ? Color{1.0f, 1.0f, 1.0f, 235.0f / 255.0f}
                 : Color{10.0f / 255.0f, 12.0f / 255.0f, 18.0f / 255.0f, 150.0f / 255.0f};
}

Color backdropColor(Backdrop backdrop, bool light) {
    switch (backdrop) {
    case Backdrop::Arena:
        return sceneTheme(light).arena;
    case Backdrop::Window:
        return windowBackground(light).withAlpha(1.0f);
    case Backdrop::Plot:
        return plotAreaColor(light).over(windowBackground(light));
    }
    return {};
}

const std::vector<MarkGroup>& markGroups() {
    static const std::vector<MarkGroup> groups{
        {"velocity and momentum plots", Backdrop::Plot, {Mark::PlotX, Mark::PlotY}},
        {"energy plot", Backdrop::Plot, {Mark::Kinetic, Mark::Potential, Mark::Total}},
        {"methods' rows",
         Backdrop::Window,
         {Mark::MethodPerfect, Mark::MethodMoveAndCorrect, Mark::MethodTurnBased}},
        {"methods' ghosts",
         Backdrop::Arena,
         {Mark::MethodPerfect, Mark::MethodMoveAndCorrect, Mark::MethodTurnBased}},
        {"point of impact",
         Backdrop::Arena,
         {Mark::PoiOld, Mark::PoiNew, Mark::PoiContact, Mark::PoiMovedBack}},
        {"velocity space",
         Backdrop::Plot,
         {Mark::Kinetic, Mark::Reflection, Mark::VelocityPath, Mark::Momentum}},
        {"arrows over the scene",
         Backdrop::Arena,
         {Mark::Velocity, Mark::Momentum, Mark::Force, Mark::CentreOfMass}},
    };
    return groups;
}
