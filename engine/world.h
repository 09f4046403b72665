// The world model of docs/physics.md: axis-aligned blocks with mass, closed bounds, gravity, one
// bounciness, and the lecture's three simulation methods. Plain data in arrays addressed by index.
#pragma once

#include "stats.h"
#include "vec2.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

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

// Dynamic blocks have a finite mass and feel gravity. Static blocks never move. Kinematic blocks
// move at their own constant velocity, ignore gravity, and reverse the velocity component on
// hitting a wall or a static block (a moving platform). Static and kinematic have infinite mass.
enum class BodyKind : std::uint8_t { Dynamic, Static, Kinematic };

constexpr double kInfiniteMass = std::numeric_limits<double>::infinity();

struct Block {
    Vec2 position;     // m, centre
    Vec2 size;         // m, full width and height
    Vec2 velocity;     // m/s
    double mass = 1.0; // kg; kInfiniteMass for static and kinematic blocks
    Vec2 force;        // N, a constant force on a dynamic block (a thruster): a = F/m
    BodyKind kind = BodyKind::Dynamic;

    bool isDynamic() const { return kind == BodyKind::Dynamic; }
    Vec2 halfSize() const { return size * 0.5; }
};

// The world's closed bounds: four walls of infinite mass.
struct Bounds {
    Vec2 min{0.0, 0.0};   // m, lower-left corner
    Vec2 max{20.0, 12.0}; // m, upper-right corner
};

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

    bool has(Mistake m) const { return (mistakes >> static_cast<int>(m)) & 1u; }
    void set(Mistake m, bool on) {
        const auto bit = static_cast<std::uint8_t>(1u << static_cast<int>(m));
        mistakes = static_cast<std::uint8_t>(on ? mistakes | bit : mistakes & ~bit);
    }
};

WorldSettings defaultWorldSettings();

struct StepScratch;

// Owns the buffers the methods reuse between steps (scratch.h), made at the first step. A copy
// starts without any (and a copied-to world keeps its own): two worlds never share them.
class ScratchCache {
  public:
    ScratchCache();
    ~ScratchCache();
    ScratchCache(const ScratchCache&);
    ScratchCache& operator=(const ScratchCache&);
    ScratchCache(ScratchCache&&) noexcept;
    ScratchCache& operator=(ScratchCache&&) noexcept;
    StepScratch& get();

  private:
    std::unique_ptr<StepScratch> scratch_;
};

struct World {
    WorldSettings settings = defaultWorldSettings();
    Bounds bounds;
    std::vector<Block> blocks;
    double time = 0.0;       // s of simulated time
    std::uint64_t frame = 0; // frames stepped
    ScratchCache scratch;    // the methods' buffers (a cache: no result depends on it)

    // Advances one frame of settings.dt in settings.substeps substeps, each the chosen method with
    // the forces applied as the integrator says (semi-implicit Euler before the method, explicit
    // Euler after it, the exact integrator within it: see World::step); then the statistics. When
    // `log` is given, every resolved collision is appended to it.
    StepStats step(std::vector<CollisionRecord>* log = nullptr);
};

// The acceleration of a dynamic block over a step of h seconds (m/s^2, lecture "Newton's 2nd
// law": a = F/m): gravity, its own force F/m and the world's drag -k·A·|v|·v/m, the drag's capped
// at |v|/h (a drag can stop a block within a step, never reverse it: without the cap explicit
// steps with k·A·|v|·h/m > 2 would grow without bound). The one place forces are summed.
Vec2 accelerationOf(const WorldSettings& settings, const Block& block, double h);

// Each dynamic block's share of the totals below.
inline Vec2 momentumOf(const Block& b) {
    return b.mass * b.velocity;
}
inline double kineticEnergyOf(const Block& b) {
    return 0.5 * b.mass * lengthSquared(b.velocity);
}
inline double potentialEnergyOf(const World& world, const Block& b) {
    return -b.mass * dot(world.settings.gravity, b.position - world.bounds.min);
}

// Totals over the dynamic blocks (kinematic and static blocks have infinite mass: left out).
Vec2 totalMomentum(const World& world);     // kg·m/s, Σ m·v
double kineticEnergy(const World& world);   // J, Σ m·|v|²/2
double potentialEnergy(const World& world); // J, Σ -m·g·(p - bounds.min)
// Largest overlap (m, the smaller of the two axis overlaps) among all pairs of blocks, walls
// included (a block sticking out of the bounds); 0 when nothing overlaps. Static pairs ignored.
double maxOverlap(const World& world);
// A 64-bit FNV-1a hash of the bits of every block's position and velocity and the time: equal
// hashes mean bit-identical states (the determinism test).
std::uint64_t stateHash(const World& world);
