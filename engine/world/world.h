// The world model of docs/physics.md: axis-aligned blocks with mass, closed bounds, gravity, one
// bounciness, and the lecture's three simulation methods. Plain data in arrays addressed by index.
#pragma once

#include "stats.h"
#include "vec2.h"
#include "world_settings.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

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
    double friction = -1.0; // μ of this block's faces (>= 0), or < 0: the world's (resolve.h)

    bool isDynamic() const { return kind == BodyKind::Dynamic; }
    Vec2 halfSize() const { return size * 0.5; }
};

// The world's closed bounds: four walls of infinite mass.
struct Bounds {
    Vec2 min{0.0, 0.0};   // m, lower-left corner
    Vec2 max{20.0, 12.0}; // m, upper-right corner
};

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
