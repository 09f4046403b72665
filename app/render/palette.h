// Colours of the scene: the block palette, "#rrggbb" parsing, and the fixed scene colours.
#pragma once

#include "world.h" // Method

#include <cstdint>
#include <string>

struct Color {
    float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;

    // 0xAABBGGRR, the layout ImGui's ImU32 colours use.
    std::uint32_t packed() const;
    Color withAlpha(float alpha) const { return {r, g, b, alpha}; }
    // Mixes towards `other` by `t` in [0, 1].
    Color mix(const Color& other, float t) const;
};

// Parses "#rrggbb" (or "rrggbb"), case-insensitive. Returns false for anything else.
bool parseHexColor(const std::string& text, Color& out);
// "#rrggbb" for a colour (alpha ignored).
std::string toHexColor(const Color& color);

// The colour of block `index`: its scene colour when it has a valid one, otherwise a fixed
// palette entry chosen by index (so a block keeps its colour across runs).
Color blockColor(int index, const std::string& sceneColor);
// The colour of a static or kinematic block without a scene colour.
Color staticBlockColor();
Color kinematicBlockColor();
// The colour of a method (one per Method, in the engine's order): its ghosts over the scene and
// its rows in the side-by-side and cost tables, its line in the tradeoff chart.
Color methodColor(Method method);
// The colour of a student's trace (docs/compare.md): their blocks' outlines over the scene (the
// ghost overlay), apart from every method's.
Color studentTraceColor();

// The scene's colours for a theme: dark (the default, for a dark room or a screen) or light (for
// a bright room, where a projector washes dark colours out).
struct SceneTheme {
    Color background; // outside the bounds
    Color arena;      // inside the bounds
    Color gridMinor, gridMajor;
    Color wall;
    Color text;       // labels drawn over the scene
    Color textShadow; // behind them
    Color axis;       // the axis numbers
    Color velocity;   // velocity arrows (the momentum arrows keep their orange)
};
const SceneTheme& sceneTheme(bool light);

// WCAG contrast ratio of two colours (1 to 21; alpha ignored).
double contrastRatio(const Color& a, const Color& b);
// Below this contrast with the arena, a block gets a contrasting outline.
constexpr double kMinBlockContrast = 2.0;
// The outline that makes a block of `fill` stand out from `background`: the usual dark outline,
// or a light one (dark on a light background) when the fill is close to the background.
Color outlineFor(const Color& fill, const Color& background);

namespace scene_colors {
constexpr Color kBackground{0.075f, 0.082f, 0.106f, 1.0f}; // outside the bounds
constexpr Color kArena{0.118f, 0.129f, 0.165f, 1.0f};      // inside the bounds
constexpr Color kGridMinor{1.0f, 1.0f, 1.0f, 0.06f};
constexpr Color kGridMajor{1.0f, 1.0f, 1.0f, 0.14f};
constexpr Color kWall{0.42f, 0.45f, 0.52f, 1.0f};
constexpr Color kOutline{0.04f, 0.04f, 0.06f, 1.0f};
constexpr Color kSelection{1.0f, 0.86f, 0.25f, 1.0f};
constexpr Color kVelocity{0.35f, 0.85f, 1.0f, 0.95f};
constexpr Color kMomentum{1.0f, 0.59f, 0.24f, 0.55f};
constexpr Color kFling{1.0f, 0.55f, 0.2f, 1.0f};
constexpr Color kForce{0.92f, 0.32f, 0.86f, 0.95f}; // force arrows (magenta: not v, not p)
constexpr Color kLabel{1.0f, 1.0f, 1.0f, 0.95f};
} // namespace scene_colors
