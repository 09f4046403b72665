#include "world.h"

#include "methods.h"

#include "collision.h"
#include "scratch.h"

#include <algorithm>
#include <chrono>
#include <cstring>

const char* methodName(Method method) {
    switch (method) {
    case Method::Perfect:
        return "perfect";
    case Method::MoveAndCorrect:
        return "move-and-correct";
    case Method::TurnBased:
        return "turn-based";
    case Method::Count:
        break;
    }
    return "unknown";
}

bool parseMethod(const char* name, Method& method) {
    for (int i = 0; i < static_cast<int>(Method::Count); ++i) {
        if (std::strcmp(name, methodName(static_cast<Method>(i))) == 0) {
            method = static_cast<Method>(i);
            return true;
        }
    }
    return false;
}

WorldSettings defaultWorldSettings() {
    return WorldSettings{};
}

namespace {

// Semi-implicit Euler, first half (lecture, "Integration"): velocity += acceleration · h.
void applyGravity(World& world, double h) {
    const Vec2 dv = world.settings.gravity * h;
    for (Block& b : world.blocks)
        if (b.isDynamic()) b.velocity += dv;
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

// Each dynamic block's share of the totals (kinematic and static blocks: infinite mass, left out).
Vec2 momentumOf(const Block& b) {
    return b.mass * b.velocity;
}
double kineticEnergyOf(const Block& b) {
    return 0.5 * b.mass * lengthSquared(b.velocity);
}
double potentialEnergyOf(const World& world, const Block& b) {
    return -b.mass * dot(world.settings.gravity, b.position - world.bounds.min);
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
    const auto wallStart = std::chrono::steady_clock::now();
    StepStats stats;
    const int substeps = settings.substeps > 0 ? settings.substeps : 1;
    const double h = settings.dt / substeps;
    double maxPenetrationSeen = 0.0;
    StepScratch& buffers = scratch.get();

    for (int k = 0; k < substeps; ++k) {
        // 1. Forces: gravity changes the velocities of dynamic blocks.
        applyGravity(*this, h);
        // 2. Motion and collisions, by the chosen simulation method.
        SubstepContext ctx{*this, buffers, buffers.broadPhase, stats, log, h, time};
        advance(ctx, settings.method);
        time += ctx.advanced;
        stats.simulatedTime += ctx.advanced;
        maxPenetrationSeen = std::max(maxPenetrationSeen, ctx.maxPenetrationSeen);
        // 3. The event cap held time back: the frame ends at the last event.
        if (ctx.capHit) {
            ++stats.eventCapHits;
            break;
        }
    }
    ++frame;

    // 4. Statistics of the new state.
    addTotals(*this, stats);
    stats.maxPenetration =
        settings.measureOverlap
            ? std::max(maxPenetrationSeen, maxOverlapIn(*this, buffers.overlapGrid))
            : maxPenetrationSeen;
    const auto wallEnd = std::chrono::steady_clock::now();
    stats.stepMs = std::chrono::duration<double, std::milli>(wallEnd - wallStart).count();
    return stats;
}

Vec2 totalMomentum(const World& world) {
    Vec2 p;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) p += momentumOf(b);
    return p;
}

double kineticEnergy(const World& world) {
    double e = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) e += kineticEnergyOf(b);
    return e;
}

double potentialEnergy(const World& world) {
    double e = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) e += potentialEnergyOf(world, b);
    return e;
}

double maxOverlap(const World& world) {
    BroadPhase grid;
    return maxOverlapIn(world, grid);
}

std::uint64_t stateHash(const World& world) {
    std::uint64_t hash = 1469598103934665603ull; // FNV-1a offset basis
    auto mix = [&hash](double value) {
        std::uint64_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        for (int i = 0; i < 8; ++i) {
            hash ^= (bits >> (8 * i)) & 0xffu;
            hash *= 1099511628211ull; // FNV prime
        }
    };
    mix(world.time);
    for (const Block& b : world.blocks) {
        mix(b.position.x), mix(b.position.y), mix(b.velocity.x), mix(b.velocity.y);
    }
    return hash;
}
