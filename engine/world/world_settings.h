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
    // Time the step (StepStats::stepMs, ms of wall-clock time): two clock reads per step, which in
    // the browser are calls out to JavaScript. Off, stepMs is 0 and nothing else changes (the
    // physics never reads it). Not a row of the table below: it says how a step reports, not what
    // it computes, so no comparison of settings (a scene's, the timeline's) sees it.
    bool measureTime = true;
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

// ---- The rows: key, member, limits, how people read it, sandbox-cli's flag (the panel's columns
// are the app's: app/gui/view/panel_rows.h) ----

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
     {"gravity", "g"},
     {"--gravity", "GX,GY", "Gravity GX,GY", 5}},
    {{&WorldSettings::bounciness},
     "bounciness",
     limits::kBounciness,
     {"bounciness", "C"},
     {"--bounciness", "C", "Bounciness C", 4}},
    {settings_table::choice<Method, &WorldSettings::method, methodName>(),
     "method",
     {},
     {"method"},
     {"--method", "M", "Simulation method: perfect, move-and-correct or turn-based", 1}},
    {{&WorldSettings::dt},
     "dt",
     limits::kDt,
     {"frame rate", "", true, limits::kFrameRate},
     {"--dt", "S", "Seconds per frame", 2}},
    {{&WorldSettings::substeps},
     "substeps",
     limits::kSubsteps,
     {"substeps"},
     {"--substeps", "K", "Substeps per frame", 3}},
    {settings_table::choice<Resolve, &WorldSettings::resolve, resolveName>(),
     "resolve",
     {},
     {"resolve"},
     {"--resolve", "R",
      "Collision resolve: momentum (the lecture's formula) or reflect (without Newton: each "
      "body reverses its own velocity, v' = -C*v)"}},
    {settings_table::choice<Integrator, &WorldSettings::integrator, integratorName>(),
     "integrator",
     {},
     {"integrator"},
     {"--integrator", "I",
      "Integrator: semi-implicit-euler, explicit-euler or exact (constant acceleration "
      "integrated exactly)"}},
    {{&WorldSettings::mistakes,
      settings_table::Names{static_cast<int>(Mistake::Count),
                            [](int i) { return mistakeName(static_cast<Mistake>(i)); },
                            [](int i) { return mistakeSlide(static_cast<Mistake>(i)); }}},
     "mistakes",
     {},
     {"mistakes"},
     {"--mistake", "NAME",
      "Make one of the lecture's mistakes (repeatable, added to the scene's): discrete, "
      "move-back, first-found, no-approach-test; none clears the scene's"}},
    {{&WorldSettings::drag}, "drag", limits::kDrag, {"drag", "k"}, {}},
    {{&WorldSettings::friction},
     "friction",
     limits::kFriction,
     // µ is U+00B5 (the micro sign): the panel's font has Latin-1, not Greek.
     {"friction", "µ"},
     {"--friction", "MU",
      "Coulomb friction coefficient mu at every contact (0: none; a block's own \"friction\" "
      "still overrides it)"}},
    // The engine's own: no scene key (world.h says what they do).
    {{&WorldSettings::restSpeed}, "rest_speed", {}, {}, {}, false},
    {{&WorldSettings::eventCap}, "event_cap", {}, {}, {}, false},
    {{&WorldSettings::measureOverlap}, "measure_overlap", {}, {}, {}, false},
};
