// The perfect method (lecture, "Perfect Simulation"):
//   while CurrentTime < TargetTime: t = earliest collision; move all bodies to t; resolve; repeat.
// Exact for linear motion: no overlap, no tunnelling. Implemented as event-driven molecular
// dynamics does it: a priority queue of predicted impacts, each block moved lazily (its position
// is valid at its own clock), and after a collision only the blocks whose velocity changed are
// re-predicted against their neighbours from the broad phase. Stale predictions are recognised by
// a per-block stamp that every change of velocity increments.
//
// Contacts at one instant. Bodies that touch when an impact arrives (a block squeezed between a
// heavy body and a wall, a Newton's cradle) collide many times at that one instant, and the
// sequence is carried out collision by collision, as the same scene with the gaps going to zero
// would be: at C = 1 it is finite whenever the touching bodies can give way on one side, and it
// keeps energy and momentum to rounding (a light block between a wall and a block M/m times
// heavier collides ceil(pi / atan(sqrt(m/M))) - 1 times, about pi·sqrt(M/m): G. Galperin,
// "Playing pool with pi", Regular and Chaotic Dynamics 8, 2003). Three rules end what never ends,
// each resolving the contact perfectly inelastic by the rest rule (Resolver::restCluster, which
// keeps momentum and merges what rests on the contact):
// - Collapse (C < 1): a pair (or a block and a wall) that has met more than kRepeatsAtInstant
//   times at one instant is taken to be in inelastic collapse: infinitely many collisions at that
//   instant whose velocities converge to a common one (McNamara and Young, "Inelastic collapse and
//   clumping in a one-dimensional granular medium", Phys. Fluids A 4, 1992), which the merge
//   gives at once.
// - Trap (any C): a pair that meets more than kRepeatsAtInstant times at one instant while its
//   block is caught along the axis between infinite masses on both sides (a row packed between
//   walls): the impulse runs back and forth without end, and the row cannot move.
// - Crush (any C; crush.h, shared with turn-based): a block bouncing between two infinite masses
//   that close in on it (a platform pushing it into a wall) collides ever faster, without end,
//   before they meet. After CrushRule::kSqueezeBounces alternating bounces in one substep it is
//   merged, and the platform reverses as on a wall.
// Past half the event cap, the second meeting of a pair at one instant already counts as a
// collapse or a trap, so jams settle sooner (a lattice of hundreds of touching blocks can still end
// its frames at the cap: see Jams.JammedBoxOf400BlocksAdvances).
//
// Paths: each block's swept box for the rest of the substep is registered in one PathIndex, which
// both the predictions and the rest rule read.
#include "collision.h"
#include "corner_grid.h"
#include "crush.h"
#include "methods.h"
#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace {

constexpr int kWallEvent = CrushRule::kWall; // Event::b for an impact with the bounds
constexpr int kRepeatsAtInstant = 8;         // meetings of one pair at one instant (collapse, trap)

using Event = PerfectScratch::Event;

// Earliest first; ties in a fixed order so runs are deterministic.
struct Later {
    bool operator()(const Event& x, const Event& y) const {
        if (x.time != y.time) return x.time > y.time;
        if (x.a != y.a) return x.a > y.a;
        return x.b > y.b;
    }
};

// The index of the paths: a CornerGrid (one entry per block, cheap to build for blocks of similar
// size), or the BroadPhase when the sizes are too mixed for it. Both answer every query with the
// same blocks, in different orders, on which nothing depends (each pair is predicted once per pair
// of stamps; the rest rule sorts its cluster).
class PathIndex final : public BlockFinder {
  public:
    PathIndex(CornerGrid& cornerGrid, BroadPhase& broadPhase)
        : cornerGrid_(cornerGrid), broadPhase_(broadPhase) {}

    // Registers every block i with the path pathOf(i), called once per block in index order.
    template <class PathOf>
    void build(const Bounds& bounds, const std::vector<Block>& blocks, PathOf&& pathOf) {
        useCornerGrid_ = cornerGrid_.build(bounds, blocks, pathOf);
        if (!useCornerGrid_)
            broadPhase_.build(bounds, blocks, [&](int i) { return cornerGrid_.box(i); });
    }
    const Aabb& path(int i) const {
        return useCornerGrid_ ? cornerGrid_.box(i) : broadPhase_.box(i);
    }
    void set(int i, const Aabb& path) {
        if (useCornerGrid_)
            cornerGrid_.set(i, path);
        else
            broadPhase_.set(i, path);
    }
    // visit(j) for every block j other than `self` whose path meets `box`.
    template <class Visit> void queryOthers(const Aabb& box, int self, Visit&& visit) const {
        if (useCornerGrid_)
            cornerGrid_.queryOthers(box, self, visit);
        else
            broadPhase_.queryOthers(box, self, visit);
    }
    // visit(i, j) for every pair of paths that meet (right after build()).
    template <class Visit> void forEachMeetingPair(Visit&& visit) const {
        if (useCornerGrid_)
            cornerGrid_.forEachMeetingPair(visit);
        else
            broadPhase_.forEachMeetingPair(visit);
    }
    void find(const Aabb& box, std::vector<int>& found) const override {
        queryOthers(box, -1, [&](int j) { found.push_back(j); });
    }

  private:
    CornerGrid& cornerGrid_;
    BroadPhase& broadPhase_;
    bool useCornerGrid_ = true;
};

class PerfectSolver {
  public:
    explicit PerfectSolver(SubstepContext& ctx, PerfectScratch& scratch)
        : ctx_(ctx), blocks_(ctx.world.blocks), paths_(scratch.cornerGrid, ctx.broadPhase),
          resolver_(ctx, &paths_), clock_(scratch.clock), stamp_(scratch.stamp),
          events_(scratch.events), changed_(scratch.changed), metAtInstant_(scratch.metAtInstant),
          crush_(scratch.crush) {}

    void run();

  private:
    // A block's position and velocity at time t (its own are valid at its clock); its motion
    // (linear, or a parabola with the exact integrator) is the context's.
    Vec2 positionAt(int i, double t) const {
        if (linear_) return blocks_[i].position + blocks_[i].velocity * (t - clock_[i]);
        return ctx_.positionAfter(i, blocks_[i].position, blocks_[i].velocity, t - clock_[i]);
    }
    Vec2 velocityAt(int i, double t) const {
        return linear_ ? blocks_[i].velocity
                       : ctx_.velocityAfter(i, blocks_[i].velocity, t - clock_[i]);
    }
    Aabb trajectory(int i, double now) const {
        if (linear_)
            return sweptAabb(positionAt(i, now), blocks_[i].size, blocks_[i].velocity,
                             ctx_.h - now);
        return ctx_.path(i, positionAt(i, now), blocks_[i].size, velocityAt(i, now), ctx_.h - now);
    }
    void registerPaths();
    void predictWalls(int i, double now, const Aabb& path);
    void predictPair(int i, int j, double now);
    void predict(int i, double now);
    // Adds a prediction. The first ones (all stamps 0) are only collected, and made a heap at
    // once: each (a, b) pair is predicted once per pair of stamps, so no two current events
    // compare equal and the order of processing does not depend on the heap's layout.
    void schedule(const Event& e) {
        events_.push_back(e);
        if (heap_) std::push_heap(events_.begin(), events_.end(), Later{});
    }
    bool isStale(const Event& e) const {
        return e.stampA != stamp_[e.a] || (e.b >= 0 && e.stampB != stamp_[e.b]);
    }
    bool resolve(const Event& e, int processed);
    int meetingsAtInstant(const Event& e);
    bool collapsesOrTraps(const Event& e, int axis, int meetings, int processed);
    bool squeezed(const Event& e, int axis) {
        return crush_.squeezed(blocks_, e.a, e.b, axis, positionAt(e.a, e.time)[axis],
                               e.b < 0 ? 0.0 : positionAt(e.b, e.time)[axis]);
    }

    SubstepContext& ctx_;
    std::vector<Block>& blocks_;
    Aabb wallsInside_; // the bounds shrunk by far more than rounding (see run())
    const bool linear_ = ctx_.acceleration == nullptr; // the Euler integrators: straight lines
    PathIndex paths_;
    Resolver resolver_;                 // its rest rule reads paths_
    std::vector<double>& clock_;        // s: the time at which each block's position is valid
    std::vector<std::uint32_t>& stamp_; // incremented on every change of velocity
    std::vector<Event>& events_;        // predicted impacts (see schedule())
    std::vector<int>& changed_;         // blocks whose velocity the last event changed
    bool heap_ = false;                 // events_ is a heap
    double instant_ = -1.0;             // s: the time of the pairs below
    std::unordered_map<std::uint64_t, int>& metAtInstant_; // collisions per pair at that time
    CrushRule& crush_;                                     // the crush rule's bounces
};

// Registers every block's path over the whole substep, and predicts its impacts with the walls
// while the path is at hand (in block order, as a separate loop did: the same events in the same
// order). The common case, a path well inside the walls (see predictWalls()), is tested here
// without a call: a call per block cost more than the test.
void PerfectSolver::registerPaths() {
    paths_.build(ctx_.world.bounds, blocks_, [&](int i) {
        const Aabb path = trajectory(i, 0.0);
        if (!contains(wallsInside_, path)) predictWalls(i, 0.0, path);
        return path;
    });
}

// Predicts block i's impact with the walls; `path` is trajectory(i, now).
void PerfectSolver::predictWalls(int i, double now, const Aabb& path) {
    // Most paths stay well inside the walls: then timeOfWallImpact's first test (the box moved by
    // the travel, computed in another order than the path) finds no impact either.
    if (contains(wallsInside_, path)) return;
    const Block& block = blocks_[i];
    if (block.kind == BodyKind::Static) return;
    const Aabb box = aabbOf(positionAt(i, now), block.size);
    const WallImpact wall = ctx_.wallImpact(i, box, velocityAt(i, now), ctx_.h - now);
    if (wall.hit()) schedule({now + wall.time, i, kWallEvent, stamp_[i], 0, wall.axes});
}

// Predicts the impact of blocks i and j (i not static) within the rest of the substep.
void PerfectSolver::predictPair(int i, int j, double now) {
    const Block &a = blocks_[i], &b = blocks_[j];
    const Impact impact =
        ctx_.impact(i, aabbOf(positionAt(i, now), a.size), velocityAt(i, now), j,
                    aabbOf(positionAt(j, now), b.size), velocityAt(j, now), ctx_.h - now);
    if (impact.hit()) schedule({now + impact.time, i, j, stamp_[i], stamp_[j], impact.axes});
}

// Predicts block i's impacts with the walls and with every neighbour whose registered box meets
// its trajectory for the rest of the substep.
void PerfectSolver::predict(int i, double now) {
    if (blocks_[i].kind == BodyKind::Static) return;
    const Aabb path = trajectory(i, now);
    predictWalls(i, now, path);
    paths_.queryOthers(path, i, [&](int j) { predictPair(i, j, now); });
}

// How many times this pair (or block and wall) has met at this event's instant, this one included.
int PerfectSolver::meetingsAtInstant(const Event& e) {
    if (e.time != instant_) {
        instant_ = e.time;
        // clear() costs one step per bucket: after a storm at one instant, start a small table
        // again, or every later event would pay for the storm's buckets.
        if (metAtInstant_.bucket_count() > 64)
            metAtInstant_ = std::unordered_map<std::uint64_t, int>{};
        else
            metAtInstant_.clear();
    }
    const auto lo = static_cast<std::uint32_t>(e.b < 0 ? e.a : std::min(e.a, e.b));
    const auto hi = static_cast<std::uint32_t>(e.b < 0 ? e.b : std::max(e.a, e.b));
    return ++metAtInstant_[(static_cast<std::uint64_t>(lo) << 32) | hi];
}

// The collapse and trap rules (see the top of the file).
bool PerfectSolver::collapsesOrTraps(const Event& e, int axis, int meetings, int processed) {
    const int allowed = processed > ctx_.world.settings.eventCap / 2 ? 1 : kRepeatsAtInstant;
    if (meetings <= allowed) return false;
    if (ctx_.world.settings.bounciness < 1.0) return true; // collapse
    const int block = blocks_[e.a].isDynamic() ? e.a : e.b;
    return block >= 0 && blocks_[block].isDynamic() &&
           resolver_.caughtBetweenInfiniteMasses(block, axis); // trap
}

bool PerfectSolver::resolve(const Event& e, int processed) {
    const int meetings = meetingsAtInstant(e);
    bool changed = false;
    for (int axis = 0; axis < 2; ++axis) {
        if (!(e.axes & (1 << axis))) continue;
        resolver_.setForceRest(collapsesOrTraps(e, axis, meetings, processed) || squeezed(e, axis));
        const Resolution r = e.b == kWallEvent ? resolver_.resolveWall(e.a, axis)
                                               : resolver_.resolvePair(e.a, e.b, axis);
        changed |= r != Resolution::None;
    }
    return changed;
}

void PerfectSolver::run() {
    const int n = static_cast<int>(blocks_.size());
    clock_.assign(n, 0.0);
    stamp_.assign(n, 0);
    crush_.reset(blocks_.size());
    events_.clear();
    metAtInstant_.clear();
    // A path and the box timeOfWallImpact tests (the block's box moved by its travel) differ by a
    // few roundings of numbers no larger than twice the bounds' largest coordinate M, so by less
    // than 2^-49·M: a path inside the bounds shrunk by 2^-40·M meets no wall in that test either.
    const Bounds& bounds = ctx_.world.bounds;
    const double largest = std::max({std::abs(bounds.min.x), std::abs(bounds.min.y),
                                     std::abs(bounds.max.x), std::abs(bounds.max.y)});
    const Vec2 margin = Vec2{1.0, 1.0} * (largest * 0x1p-40 + 0x1p-1000);
    wallsInside_ = {bounds.min + margin, bounds.max - margin};

    // Register every block's trajectory over the whole substep (predicting the walls), then
    // predict the first impacts between blocks.
    registerPaths();
    auto predictFirst = [&](int a, int b) { // a < b
        if (blocks_[a].kind != BodyKind::Static)
            predictPair(a, b, 0.0);
        else if (blocks_[b].kind != BodyKind::Static)
            predictPair(b, a, 0.0);
    };
    paths_.forEachMeetingPair(predictFirst);
    std::make_heap(events_.begin(), events_.end(), Later{});
    heap_ = true;

    // Repeat: take the earliest impact, move its blocks to it, resolve, re-predict what changed.
    double lastEventTime = 0.0;
    int processed = 0;
    std::vector<int>& changed = changed_;
    while (!events_.empty()) {
        std::pop_heap(events_.begin(), events_.end(), Later{});
        const Event e = events_.back();
        events_.pop_back();
        if (isStale(e)) continue;
        if (processed == ctx_.world.settings.eventCap) {
            ctx_.capHit = true; // the substep ends at the last event: time falls behind
            break;
        }
        ++processed;
        resolver_.setNow(e.time, &clock_);
        if (!resolve(e, processed)) continue;
        ++ctx_.stats.events;
        lastEventTime = e.time;

        changed = resolver_.changed();
        resolver_.clearChanged();
        std::sort(changed.begin(), changed.end());
        changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
        for (int j : changed) {
            ++stamp_[j];
            const Aabb path = trajectory(j, e.time);
            if (!contains(paths_.path(j), path)) paths_.set(j, path);
        }
        for (int j : changed) predict(j, e.time);
    }

    // Move every block to the end of the substep (or to the last event when the cap was hit).
    const double end = ctx_.capHit ? lastEventTime : ctx_.h;
    for (int i = 0; i < n; ++i) {
        blocks_[i].position = positionAt(i, end);
        blocks_[i].velocity = velocityAt(i, end);
    }
    ctx_.advanced = end;
}

} // namespace

void advancePerfect(SubstepContext& ctx) {
    PerfectSolver solver(ctx, ctx.scratch.perfect);
    solver.run();
}
