// The world's settings: WorldSettings and, below it, its rows of the settings table
// (settings_rows.h types a row: scene key, limits, words, sandbox-cli flag, panel widget;
// settings_table.h reads them). A new setting is its member and its row here, the engine code
// that uses it, a test and the docs.
#pragma once

#include "input_limits.h"
#include "settings_rows.h"
#include "vec2.h"

#include <cstdint>

// The lecture's three simulation methods (lecture, "Physics Engine Setup").
enum class Method : std::uint8_t { Perfect, MoveAndCorrect, TurnBased, Count };

// "perfect", "move-and-correct", "turn-based": the names used in scene files and on the CLI.
const char* methodName(Method method);
// Parses a method name; returns false (and leaves `method` alone) for an unknown name.
bool parseMethod(const char* name, Method& method);

// How a collision changes the velocities (lecture, "Demo: bouncing squares; with/without
// Newton"): the momentum formula, or each body reversing its own component as off a wall.
enum class Resolve : std::uint8_t { Momentum, Reflect, Count };
// How a step advances velocities and positions (lecture, "Integration", "It is just an
// approximation of the true movement! (Piecewise linear instead of parabola)").
enum class Integrator : std::uint8_t { SemiImplicitEuler, ExplicitEuler, Exact, Count };
// The Tips slides' mistakes, each off by default; WorldSettings::mistakes holds a set of them.
enum class Mistake : std::uint8_t { Discrete, MoveBack, FirstFound, NoApproachTest, Count };

// The names used in scene files and on the CLI: "momentum" | "reflect"; "semi-implicit-euler" |
// "explicit-euler" | "exact"; "discrete" | "move-back" | "first-found" | "no-approach-test".
// The parsers return false (and leave the value alone) for an unknown name.
const char* resolveName(Resolve resolve);
bool parseResolve(const char* name, Resolve& resolve);
const char* integratorName(Integrator integrator);
bool parseIntegrator(const char* name, Integrator& integrator);
const char* mistakeName(Mistake mistake);
bool parseMistake(const char* name, Mistake& mistake);
// The lecture slide each mistake illustrates (for docs, the panel and the stability matrix).
const char* mistakeSlide(Mistake mistake);

struct WorldSettings {
    Vec2 gravity{0.0, -9.81};        // m/s^2
    double bounciness = 1.0;         // C in [0, 1], coefficient of restitution (dimensionless)
    double dt = 1.0 / 60.0;          // s per frame
    int substeps = 1;                // steps per frame, each of dt / substeps seconds
    Method method = Method::Perfect; // simulation method
    // m/s: a contact closing slower than restSpeed + 2·|g|·h (h the substep length) is resolved
    // as perfectly inelastic, together with everything resting on it (the rest rule, so resting
    // stacks neither jitter nor make unbounded numbers of events).
    double restSpeed = 1e-6;
    int eventCap = 20000;       // perfect method: collision events per substep at most
    bool measureOverlap = true; // compute StepStats::maxPenetration (costs one broad phase)
    Resolve resolve = Resolve::Momentum; // the lecture's formula, or "without Newton"
    Integrator integrator = Integrator::SemiImplicitEuler;
    std::uint8_t mistakes = 0; // bit (1 << Mistake) set: that mistake is made (all off: correct)
    double drag = 0.0;         // k in kg/m^3: quadratic drag force -k·A·|v|·v, A = w·h (m^2)
    double friction = 0.0;     // μ >= 0: Coulomb friction at every contact (friction.cpp)

    bool has(Mistake m) const { return (mistakes >> static_cast<int>(m)) & 1u; }
    void set(Mistake m, bool on) {
        const auto bit = static_cast<std::uint8_t>(1u << static_cast<int>(m));
        mistakes = static_cast<std::uint8_t>(on ? mistakes | bit : mistakes & ~bit);
    }
};

WorldSettings defaultWorldSettings();

// ---- The rows: key, member, limits, how people read it, sandbox-cli's flag, the panel ----

// Method, resolve and integrator as Choice rows: choice<E, &WorldSettings::m, name>().
namespace settings_table {
template <typename E, E WorldSettings::*M, const char* (*Name)(E)> constexpr Member choice() {
    return Member(
        [](const WorldSettings& s) { return static_cast<int>(s.*M); },
        [](WorldSettings& s, int i) { s.*M = static_cast<E>(i); },
        Names{static_cast<int>(E::Count), [](int i) { return Name(static_cast<E>(i)); }, nullptr});
}
} // namespace settings_table

// Gravity, bounciness and the method are the lecture's ("Physics Engine Setup"); dt and substeps
// the frame; resolve, integrator, mistakes and drag issue 16's lecture options; friction (issue
// 25) the lecture's Application (0 runs no friction code at all: every result as without it).
inline constexpr settings_table::WorldKey kWorldKeys[] = {
    {{&WorldSettings::gravity},
     "gravity",
     limits::kGravity,
     {"gravity", "g", "Gravity (x, y) in m/s² (Ctrl+click to type a value)"},
     {"--gravity", "GX,GY", "Gravity GX,GY", 5},
     {settings_table::Section::Simulation, 3, "gravity", -20.0f, 20.0f, "%.2f", false, "9.81",
      "Gravity 9.81 m/s² down"}},
    {{&WorldSettings::bounciness},
     "bounciness",
     limits::kBounciness,
     {"bounciness", "C", "Coefficient of restitution: 1 elastic, 0 perfectly inelastic"},
     {"--bounciness", "C", "Bounciness C", 4},
     {settings_table::Section::Simulation, 2, "bounciness C", 0.0f, 1.0f, "%.2f"}},
    {settings_table::choice<Method, &WorldSettings::method, methodName>(),
     "method",
     {},
     {"method", "",
      "perfect: events in time order, no overlap\nmove-and-correct: move, then push "
      "apart\nturn-based: one body at a time"},
     {"--method", "M", "Simulation method: perfect, move-and-correct or turn-based", 1},
     {settings_table::Section::Simulation, 1, "method"}},
    {{&WorldSettings::dt},
     "dt",
     limits::kDt,
     {"frame rate", "", "Simulation frames per simulated second: dt = 1 / rate", true,
      limits::kFrameRate},
     {"--dt", "S", "Seconds per frame", 2},
     {settings_table::Section::Simulation, 4, "frame rate", 5.0f, 240.0f, "%.0f Hz"}},
    {{&WorldSettings::substeps},
     "substeps",
     limits::kSubsteps,
     {"substeps"},
     {"--substeps", "K", "Substeps per frame", 3},
     {settings_table::Section::Simulation, 5, "substeps", 1.0f, 32.0f, "%d"}},
    {settings_table::choice<Resolve, &WorldSettings::resolve, resolveName>(),
     "resolve",
     {},
     {"resolve", "",
      "momentum: with Newton, the lecture's formula u = (m1·v1 + m2·v2)/(m1 + m2), "
      "v' = u - C·(v - u)\nreflect: without Newton, each body reverses its own component as "
      "off a wall, v' = -C·v (momentum is not kept)\n(slide \"Demo: bouncing squares; "
      "with/without Newton\")"},
     {"--resolve", "R",
      "Collision resolve: momentum (the lecture's formula) or reflect (without Newton: each "
      "body reverses its own velocity, v' = -C*v)"},
     {settings_table::Section::Physics, 1, "resolve"}},
    {settings_table::choice<Integrator, &WorldSettings::integrator, integratorName>(),
     "integrator",
     {},
     {"integrator", "",
      "semi-implicit-euler: v += a·h, then x += v·h (the lecture's)\nexplicit-euler: x moves "
      "with the old v\nexact: x += v·h + a·h²/2, the parabola (slide \"It is just an "
      "approximation of the true movement!\")"},
     {"--integrator", "I",
      "Integrator: semi-implicit-euler, explicit-euler or exact (constant acceleration "
      "integrated exactly)"},
     {settings_table::Section::Physics, 2, "integrator"}},
    {{&WorldSettings::mistakes,
      settings_table::Names{static_cast<int>(Mistake::Count),
                            [](int i) { return mistakeName(static_cast<Mistake>(i)); },
                            [](int i) { return mistakeSlide(static_cast<Mistake>(i)); }}},
     "mistakes",
     {},
     {"mistakes"},
     {"--mistake", "NAME",
      "Make one of the lecture's mistakes (repeatable, added to the scene's): discrete, "
      "move-back, first-found, no-approach-test; none clears the scene's"},
     {settings_table::Section::Physics, 5, "Mistakes (the Tips slides' bugs)"}},
    {{&WorldSettings::drag},
     "drag",
     limits::kDrag,
     {"drag", "k",
      "Quadratic drag: force -k·A·|v|·v, A = w·h; terminal speed sqrt(m·g/(k·A)). Air 1.2, "
      "water 1000 (slide \"Viscosity/drag: a feather falls slower than a stone\"; Ctrl+click "
      "to type)"},
     {},
     {settings_table::Section::Physics, 3, "drag k", 0.0f, 1000.0f, "%.3g kg/m³", true}},
    {{&WorldSettings::friction},
     "friction",
     limits::kFriction,
     // µ is U+00B5 (the micro sign): the panel's font has Latin-1, not Greek.
     {"friction", "µ",
      "Coulomb friction at every contact: along the face the relative velocity changes by at "
      "most µ times the change across it, toward zero, never past it; a block sliding on the "
      "floor stops after v0/(µ·g) s and v0²/(2·µ·g) m. A pair uses sqrt(µ1·µ2) (Box2D's rule; a "
      "block's own \"friction\" overrides the world's). 0: none (slide \"Application: "
      "Platformer\": moving platforms, friction, pushing objects)"},
     {"--friction", "MU",
      "Coulomb friction coefficient mu at every contact (0: none; a block's own \"friction\" "
      "still overrides it)"},
     {settings_table::Section::Physics, 4, "friction µ", 0.0f, 2.0f, "%.2f"}},
    // The engine's own: no scene key (world.h says what they do).
    {{&WorldSettings::restSpeed}, "rest_speed", {}, {}, {}, {}, false},
    {{&WorldSettings::eventCap}, "event_cap", {}, {}, {}, {}, false},
    {{&WorldSettings::measureOverlap}, "measure_overlap", {}, {}, {}, {}, false},
};
