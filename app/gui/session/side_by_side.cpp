#include "side_by_side.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace {

// The same bits (a -0 is not a 0, a NaN is itself).
bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}
bool sameBits(Vec2 a, Vec2 b) {
    return sameBits(a.x, b.x) && sameBits(a.y, b.y);
}

// Whether two worlds' states are the same bits: what World::step reads besides its settings.
// Every field of a block and of the world but its settings and scratch is compared: a field added
// to either changes its size here, so that it is added below too (on 64-bit targets).
static_assert(sizeof(void*) != 8 || sizeof(Block) == 88, "compare the new field of Block");
static_assert(sizeof(void*) != 8 || sizeof(World) == 160, "compare the new field of World");
bool sameState(const World& a, const World& b) {
    if (a.frame != b.frame || !sameBits(a.time, b.time) || !sameBits(a.bounds.min, b.bounds.min) ||
        !sameBits(a.bounds.max, b.bounds.max) || a.blocks.size() != b.blocks.size())
        return false;
    for (std::size_t i = 0; i < a.blocks.size(); ++i) {
        const Block& p = a.blocks[i];
        const Block& q = b.blocks[i];
        if (!sameBits(p.position, q.position) || !sameBits(p.velocity, q.velocity) ||
            !sameBits(p.size, q.size) || !sameBits(p.mass, q.mass) || !sameBits(p.force, q.force) ||
            p.kind != q.kind || !sameBits(p.friction, q.friction))
            return false;
    }
    return true;
}

} // namespace

void MethodsSideBySide::start(const World& world) {
    for (std::size_t m = 0; m < runs.size(); ++m) {
        runs[m] = MethodRun{};
        runs[m].world = world;
        runs[m].world.settings.method = static_cast<Method>(m);
    }
    running = true;
}

void MethodsSideBySide::step(const WorldSettings& live, int pushed, Vec2 thrust, Method followed) {
    if (!running) return;
    for (std::size_t m = 0; m < runs.size(); ++m) {
        MethodRun& r = runs[m];
        if (static_cast<Method>(m) == followed) continue; // follow() gives its step
        r.world.settings = live;
        r.world.settings.method = static_cast<Method>(m);
        const bool push = pushed >= 0 && static_cast<std::size_t>(pushed) < r.world.blocks.size() &&
                          r.world.blocks[static_cast<std::size_t>(pushed)].isDynamic();
        Vec2 own;
        if (push) {
            Block& b = r.world.blocks[static_cast<std::size_t>(pushed)];
            own = b.force;
            b.force = own + thrust;
        }
        r.stats = r.world.step();
        if (push) r.world.blocks[static_cast<std::size_t>(pushed)].force = own;
        addStep(r.totals, r.stats);
    }
}

Method MethodsSideBySide::following(const World& live) const {
    const Method m = live.settings.method;
    if (!running || m == Method::Count || !sameState(run(m).world, live)) return Method::Count;
    return m;
}

void MethodsSideBySide::follow(Method followed, const World& live, const StepStats& stats) {
    if (!running || followed == Method::Count) return;
    MethodRun& r = runs[static_cast<std::size_t>(followed)];
    r.world.settings = live.settings;
    r.world.bounds = live.bounds;
    r.world.blocks = live.blocks;
    r.world.time = live.time;
    r.world.frame = live.frame;
    r.stats = stats;
    addStep(r.totals, r.stats);
}

double MethodsSideBySide::divergence(Method method) const {
    const World& a = run(method).world;
    const World& p = run(Method::Perfect).world;
    double worst = 0.0;
    const std::size_t n = std::min(a.blocks.size(), p.blocks.size());
    for (std::size_t i = 0; i < n; ++i) {
        worst = std::max(worst, length(a.blocks[i].position - p.blocks[i].position));
    }
    return worst;
}
