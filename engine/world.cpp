#include "world.h"

#include "methods.h"

#include "collision.h"
#include "scratch.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <iterator>

namespace {

// One table of names per setting, read by the name functions and the parsers below.
constexpr const char* kMethodNames[] = {"perfect", "move-and-correct", "turn-based"};
constexpr const char* kResolveNames[] = {"momentum", "reflect"};
constexpr const char* kIntegratorNames[] = {"semi-implicit-euler", "explicit-euler", "exact"};
constexpr const char* kMistakeNames[] = {"discrete", "move-back", "first-found",
                                         "no-approach-test"};
constexpr const char* kMistakeSlides[] = {
    "Discrete can give errors with high velocities: tunneling",
    "BAD: no exact point of impact",
    "BAD: resolving wrong collision",
    "You'll find collisions that are not really collisions (check the relative velocity)",
};
static_assert(std::size(kMethodNames) == static_cast<size_t>(Method::Count));
static_assert(std::size(kResolveNames) == static_cast<size_t>(Resolve::Count));
static_assert(std::size(kIntegratorNames) == static_cast<size_t>(Integrator::Count));
static_assert(std::size(kMistakeNames) == static_cast<size_t>(Mistake::Count));
static_assert(std::size(kMistakeSlides) == static_cast<size_t>(Mistake::Count));

template <typename E, size_t N> const char* nameIn(const char* const (&names)[N], E value) {
    const auto i = static_cast<size_t>(value);
    return i < N ? names[i] : "unknown";
}
template <typename E, size_t N>
bool parseIn(const char* const (&names)[N], const char* name, E& value) {
    for (size_t i = 0; i < N; ++i) {
        if (std::strcmp(name, names[i]) == 0) {
            value = static_cast<E>(i);
            return true;
        }
    }
    return false;
}

} // namespace

const char* methodName(Method method) {
    return nameIn(kMethodNames, method);
}
bool parseMethod(const char* name, Method& method) {
    return parseIn(kMethodNames, name, method);
}
const char* resolveName(Resolve resolve) {
    return nameIn(kResolveNames, resolve);
}
bool parseResolve(const char* name, Resolve& resolve) {
    return parseIn(kResolveNames, name, resolve);
}
const char* integratorName(Integrator integrator) {
    return nameIn(kIntegratorNames, integrator);
}
bool parseIntegrator(const char* name, Integrator& integrator) {
    return parseIn(kIntegratorNames, name, integrator);
}
const char* mistakeName(Mistake mistake) {
    return nameIn(kMistakeNames, mistake);
}
bool parseMistake(const char* name, Mistake& mistake) {
    return parseIn(kMistakeNames, name, mistake);
}
const char* mistakeSlide(Mistake mistake) {
    return nameIn(kMistakeSlides, mistake);
}

Vec2 accelerationOf(const WorldSettings& settings, const Block& block, double h) {
    // Drag (lecture, "Viscosity/drag: proportional to velocity^2 and area"): F = -k·A·|v|·v,
    // so a = -rate·v with rate = k·A·|v|/m (1/s), at most 1/h.
    const double area = block.size.x * block.size.y;
    double rate = settings.drag * area * length(block.velocity) / block.mass;
    if (h > 0.0 && rate * h > 1.0) rate = 1.0 / h;
    return settings.gravity + block.force / block.mass - rate * block.velocity;
}

WorldSettings defaultWorldSettings() {
    return WorldSettings{};
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

    const Integrator integrator = settings.integrator; // read here only
    for (int k = 0; k < substeps; ++k) {
        // 1. Forces (gravity, a block's own force, drag). Semi-implicit Euler changes the
        //    velocities first and then moves with the new ones (the lecture's order); explicit
        //    Euler moves with the old ones and changes them after (step 3); the exact integrator
        //    hands each block's acceleration to the method, which moves along the parabola
        //    x += v·h + a·h²/2, v += a·h and finds impacts as roots of the quadratic.
        if (integrator == Integrator::SemiImplicitEuler) applyForces(*this, h);
        SubstepContext ctx{*this, buffers, buffers.broadPhase, stats, log, h, time};
        if (integrator == Integrator::Exact) {
            accelerations(*this, h, buffers.acceleration);
            ctx.acceleration = &buffers.acceleration;
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
