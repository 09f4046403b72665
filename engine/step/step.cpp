// One frame of the world (World::step), top to bottom: per substep the forces by the
// integrator's rule, then the chosen method's motion and collisions; then the totals of the
// new state (docs/physics.md, "One frame"). Apart from world.cpp, so that the model the
// methods include (world.h) does not include them back.
#include "world.h"

#include "methods.h"

#include "collision.h"
#include "scratch.h"

#include <algorithm>
#include <chrono>

Vec2 accelerationOf(const WorldSettings& settings, const Block& block, double h) {
    // Drag (lecture, "Viscosity/drag: proportional to velocity^2 and area"): F = -k·A·|v|·v,
    // so a = -rate·v with rate = k·A·|v|/m (1/s), at most 1/h.
    const double area = block.size.x * block.size.y;
    double rate = settings.drag * area * length(block.velocity) / block.mass;
    if (h > 0.0 && rate * h > 1.0) rate = 1.0 / h;
    return settings.gravity + block.force / block.mass - rate * block.velocity;
}

namespace {

// Euler's velocity half (lecture, "Integration"): velocity += acceleration · h. Gravity alone
// (no force, no drag: the common case) adds the same g·h to every dynamic block.
void applyForces(World& world, double h) {
    const WorldSettings& s = world.settings;
    const Vec2 dv = s.gravity * h;
    for (Block& b : world.blocks) {
        if (!b.isDynamic()) continue;
        if (s.drag == 0.0 && b.force == Vec2{})
            b.velocity += dv;
        else
            b.velocity += accelerationOf(s, b, h) * h;
    }
}

// The exact integrator's constant acceleration of every block over one substep (drag taken at
// the substep's start and held: see docs/scene-format.md); 0 for static and kinematic blocks.
void accelerations(const World& world, double h, std::vector<Vec2>& out) {
    out.assign(world.blocks.size(), Vec2{});
    for (size_t i = 0; i < world.blocks.size(); ++i)
        if (world.blocks[i].isDynamic())
            out[i] = accelerationOf(world.settings, world.blocks[i], h);
}

// One switch picks the method (solver2d style).
void advance(SubstepContext& ctx, Method method) {
    switch (method) {
    case Method::Perfect:
        advancePerfect(ctx);
        break;
    case Method::MoveAndCorrect:
        advanceMoveAndCorrect(ctx);
        break;
    case Method::TurnBased:
        advanceTurnBased(ctx);
        break;
    case Method::Count:
        break;
    }
}

// totalMomentum, kineticEnergy and potentialEnergy in one pass over the blocks (the same sums in
// the same order, so the same bits).
void addTotals(const World& world, StepStats& stats) {
    Vec2 p;
    double kinetic = 0.0, potential = 0.0;
    for (const Block& b : world.blocks) {
        if (!b.isDynamic()) continue;
        p += momentumOf(b);
        kinetic += kineticEnergyOf(b);
        potential += potentialEnergyOf(world, b);
    }
    stats.momentum = p;
    stats.kineticEnergy = kinetic;
    stats.potentialEnergy = potential;
}

// maxOverlap, in the given grid.
double maxOverlapIn(const World& world, BroadPhase& grid) {
    grid.build(world.bounds, world.blocks, [&](int i) { return aabbOf(world.blocks[i]); });
    double deepest = 0.0;
    for (const Block& b : world.blocks)
        deepest = std::max(deepest, outsideDepth(aabbOf(b), world.bounds));
    grid.forEachOverlappingPair([&](int i, int j) {
        const Block& a = world.blocks[i];
        const Block& b = world.blocks[j];
        if (a.kind != BodyKind::Static || b.kind != BodyKind::Static) // static pairs may overlap
            deepest = std::max(deepest, penetration(aabbOf(a), aabbOf(b)));
    });
    return deepest;
}

} // namespace

ScratchCache::ScratchCache() = default;
ScratchCache::~ScratchCache() = default;
ScratchCache::ScratchCache(const ScratchCache&) {}
ScratchCache& ScratchCache::operator=(const ScratchCache&) {
    return *this;
}
ScratchCache::ScratchCache(ScratchCache&&) noexcept = default;
ScratchCache& ScratchCache::operator=(ScratchCache&&) noexcept = default;
StepScratch& ScratchCache::get() {
    if (!scratch_) scratch_ = std::make_unique<StepScratch>();
    return *scratch_;
}

StepStats World::step(std::vector<CollisionRecord>* log) {
    using Clock = std::chrono::steady_clock;
    const bool timed = settings.measureTime;
    const Clock::time_point wallStart = timed ? Clock::now() : Clock::time_point{};
    StepStats stats;
    const int substeps = settings.substeps > 0 ? settings.substeps : 1;
    const double h = settings.dt / substeps;
    double maxPenetrationSeen = 0.0;
    StepScratch& buffers = scratch.get();

    const Integrator integrator = settings.integrator; // read here only
    // Friction acts when some μ > 0 (friction.cpp); else no friction code runs.
    double maxFriction = settings.friction;
    for (const Block& b : blocks) maxFriction = std::max(maxFriction, b.friction);
    const bool friction = maxFriction > 0.0;
    for (int k = 0; k < substeps; ++k) {
        // 1. Forces (gravity, a block's own force, drag). Semi-implicit Euler changes the
        //    velocities first and then moves with the new ones (the lecture's order); explicit
        //    Euler moves with the old ones and changes them after (step 3); the exact integrator
        //    hands each block's acceleration to the method, which moves along the parabola
        //    x += v·h + a·h²/2, v += a·h and finds impacts as roots of the quadratic.
        if (integrator == Integrator::SemiImplicitEuler) applyForces(*this, h);
        SubstepContext ctx{*this, buffers, buffers.broadPhase, stats, log, h, time};
        ctx.friction = friction;
        ctx.maxFriction = maxFriction;
        if (integrator == Integrator::Exact) {
            accelerations(*this, h, buffers.acceleration);
            ctx.acceleration = &buffers.acceleration;
            buffers.forces = buffers.acceleration;
            ctx.forces = &buffers.forces;
            if (friction) {
                buffers.slides.assign(2 * blocks.size(), Slide{});
                ctx.slides = &buffers.slides;
            }
        }
        // 2. Motion and collisions, by the chosen simulation method.
        advance(ctx, settings.method);
        // 3. Explicit Euler: the velocities change after the move.
        if (integrator == Integrator::ExplicitEuler) applyForces(*this, ctx.advanced);
        time += ctx.advanced;
        stats.simulatedTime += ctx.advanced;
        maxPenetrationSeen = std::max(maxPenetrationSeen, ctx.maxPenetrationSeen);
        // 4. The event cap held time back: the frame ends at the last event.
        if (ctx.capHit) {
            ++stats.eventCapHits;
            break;
        }
    }
    ++frame;

    // 5. Statistics of the new state.
    addTotals(*this, stats);
    stats.maxPenetration =
        settings.measureOverlap
            ? std::max(maxPenetrationSeen, maxOverlapIn(*this, buffers.overlapGrid))
            : maxPenetrationSeen;
    stats.timed = timed;
    if (timed)
        stats.stepMs = std::chrono::duration<double, std::milli>(Clock::now() - wallStart).count();
    return stats;
}

double maxOverlap(const World& world) {
    BroadPhase grid;
    return maxOverlapIn(world, grid);
}
