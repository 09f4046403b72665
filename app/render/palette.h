// Colours of the scene: the block palette, "#rrggbb" parsing, and the fixed scene colours.
#pragma once

#include "world.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

struct Color {
    float r = 0.0f, g = 0.0f, b = 0.0f, a = 1.0f;

    // 0xAABBGGRR, the layout ImGui's ImU32 colours use.
    std::uint32_t packed() const;
    Color withAlpha(float alpha) const { return {r, g, b, alpha}; }
    // Mixes towards `other` by `t` in [0, 1].
    Color mix(const Color& other, float t) const;
    // This colour drawn with its alpha over an opaque `backdrop`: what the eye gets (opaque).
    Color over(const Color& backdrop) const;
};

// Parses "#rrggbb" (or "rrggbb"), case-insensitive. Returns false for anything else.
bool parseHexColor(const std::string& text, Color& out);
// "#rrggbb" for a colour (alpha ignored).
std::string toHexColor(const Color& color);

// The blocks' palette: eight colours that stay apart for every reader (see markGroups below),
// each with the name a scene uses for its block ("red", ...). Shipped scenes take their colours
// from it.
struct NamedColor {
    const char* name;
    Color color;
};
const std::array<NamedColor, 8>& blockPalette();
// The colour of block `index`: its scene colour when it has a valid one, otherwise a fixed
// palette entry chosen by index (so a block keeps its colour across runs).
Color blockColor(int index, const std::string& sceneColor);
// The colour of a static or kinematic block without a scene colour.
Color staticBlockColor();
Color kinematicBlockColor();
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
    Color velocity;   // velocity arrows
    Color momentum;   // momentum arrows (wide, translucent, under the velocity arrows)
    Color force;      // force arrows
};
const SceneTheme& sceneTheme(bool light);

// An sRGB channel (0..1) as linear light (IEC 61966-2-1).
double linearChannel(float c);
// WCAG contrast ratio of two colours (1 to 21; alpha ignored).
double contrastRatio(const Color& a, const Color& b);
// Below this contrast with the arena, a block gets a contrasting outline.
constexpr double kMinBlockContrast = 2.0;
// The outline that makes a block of `fill` stand out from `background`: the usual dark outline,
// or a light one (dark on a light background) when the fill is close to the background.
Color outlineFor(const Color& fill, const Color& background);

// Colours that carry meaning besides the blocks', one table (palette.cpp) with each mark's
// colour in the dark and the light theme. Chosen so that every group of marks drawn together
// (markGroups) stays apart, mark from mark and mark from what it is drawn on, by at least
// kMinMarkDifference in CIEDE2000 for normal vision and under simulated protanopia,
// deuteranopia and tritanopia (tests/app/render/palette_test.cpp computes it). Plot series also
// differ by their dash pattern (PlotSeries::dash), the arrows by their shape.
enum class Mark {
    PlotX,                // the x component in the plots (vx, px)
    PlotY,                // the y component (vy, py)
    Kinetic,              // kinetic energy (and the velocity-space circle of constant energy)
    Potential,            // potential energy
    Total,                // total energy (and the total momentum of the momenta diagram)
    MethodPerfect,        // each method's rows and ghosts (methods side by side, cost)
    MethodMoveAndCorrect, //
    MethodTurnBased,      //
    PoiOld,               // point of impact: the block where the frame began
    PoiNew,               // where the frame would have put it (overlapping)
    PoiContact,           // the point of impact
    PoiMovedBack,         // moved back along one axis (the crooked result)
    Reflection,           // velocity space: the line of reflection
    VelocityPath,         // velocity space: the path of the state
    Velocity,             // arrows over the scene
    Momentum,             //
    Force,                //
    CentreOfMass,         // the centre of mass's mark and arrow
    Count
};
struct MarkColors {
    Mark mark;
    const char* name; // for the test's messages
    Color dark, light;
};
const std::array<MarkColors, static_cast<std::size_t>(Mark::Count)>& markTable();
Color markColor(Mark mark, bool light);
Mark methodMark(Method method);

// What marks are drawn on: the scene's arena, a panel or window, the inside of a plot.
enum class Backdrop { Arena, Window, Plot };
// The opaque colour of a backdrop (the plot's area composed over its window).
Color backdropColor(Backdrop backdrop, bool light);
// The UI windows' background (ImGui's WindowBg, ui_style.cpp) and the plots' area drawn over it
// (translucent: plot_widget.cpp and the overlays' pictures).
Color windowBackground(bool light);
Color plotAreaColor(bool light);
// Marks drawn together, which a reader must tell apart (and each from the backdrop).
struct MarkGroup {
    const char* name;
    Backdrop backdrop;
    std::vector<Mark> marks;
};
const std::vector<MarkGroup>& markGroups();
constexpr double kMinMarkDifference = 20.0; // CIEDE2000

namespace scene_colors {
constexpr Color kBackground{0.075f, 0.082f, 0.106f, 1.0f}; // outside the bounds
constexpr Color kArena{0.118f, 0.129f, 0.165f, 1.0f};      // inside the bounds
constexpr Color kGridMinor{1.0f, 1.0f, 1.0f, 0.06f};
constexpr Color kGridMajor{1.0f, 1.0f, 1.0f, 0.14f};
constexpr Color kWall{0.42f, 0.45f, 0.52f, 1.0f};
constexpr Color kOutline{0.04f, 0.04f, 0.06f, 1.0f};
constexpr Color kSelection{1.0f, 0.86f, 0.25f, 1.0f};
constexpr Color kFling{1.0f, 0.55f, 0.2f, 1.0f};
constexpr Color kLabel{1.0f, 1.0f, 1.0f, 0.95f};
} // namespace scene_colors
