// The perfect method (lecture, "Perfect Simulation"):
//   while CurrentTime < TargetTime: t = earliest collision; move all bodies to t; resolve; repeat.
// Exact for linear motion: no overlap, no tunnelling. Implemented as event-driven molecular
// dynamics does it: a priority queue of predicted impacts, each block moved lazily (its position
// is valid at its own clock), and after a collision only the blocks whose velocity changed are
// re-predicted (substep_timeline.h). Stale predictions are recognised by a per-block stamp that
// every change of velocity increments.
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
//
// Where the impacts come from (the paths, or windows in an event storm): impact_search.h.
#include "crush.h"
#include "impact_search.h"
#include "methods.h"
#include "scratch.h"
#include "substep_timeline.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace {

constexpr int kRepeatsAtInstant = 8; // meetings of one pair at one instant (collapse, trap)

class PerfectSolver final : ResolveHooks {
  public:
    explicit PerfectSolver(SubstepContext& ctx, PerfectScratch& scratch)
        : ctx_(ctx), blocks_(ctx.world.blocks), timeline_(ctx, scratch),
          search_(ctx, scratch, timeline_), resolver_(ctx, &search_.paths(), this),
          changed_(scratch.changed), metAtInstant_(scratch.metAtInstant), crush_(scratch.crush) {}

    void run();

  private:
    // The Resolver reads block i at the current event's time: it is moved there (ResolveHooks).
    void bringToNow(int i, double now) override {
        if (timeline_.bringTo(i, now)) search_.moved(i);
    }
    bool resolve(const Event& e, int processed);
    int meetingsAtInstant(const Event& e);
    int allowedMeetings(int processed) const;
    bool collapsesOrTraps(const Event& e, int axis, bool repeated);
    bool squeezed(const Event& e, int axis) {
        return crush_.squeezed(blocks_, e.a, e.b, axis, timeline_.positionAt(e.a, e.time)[axis],
                               e.b < 0 ? 0.0 : timeline_.positionAt(e.b, e.time)[axis]);
    }

    SubstepContext& ctx_;
    std::vector<Block>& blocks_;
    SubstepTimeline timeline_;  // each block's clock, and the predicted impacts
    ImpactSearch search_;       // predicts them
    Resolver resolver_;         // its rest rule reads the search's paths
    std::vector<int>& changed_; // blocks whose velocity the last event changed
    double instant_ = -1.0;     // s: the time of the pairs below
    std::unordered_map<std::uint64_t, int>& metAtInstant_; // collisions per pair at that time
    CrushRule& crush_;                                     // the crush rule's bounces
};

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

// How many meetings of one pair at one instant are resolved as they come (see the top of the
// file); past half the event cap, one.
int PerfectSolver::allowedMeetings(int processed) const {
    return processed > ctx_.world.settings.eventCap / 2 ? 1 : kRepeatsAtInstant;
}

// The collapse and trap rules (see the top of the file), for a contact that has met `repeated`ly
// (more often than allowedMeetings) at this instant.
bool PerfectSolver::collapsesOrTraps(const Event& e, int axis, bool repeated) {
    if (!repeated) return false;
    if (ctx_.world.settings.bounciness < 1.0) return true; // collapse
    const int block = blocks_[e.a].isDynamic() ? e.a : e.b;
    return block >= 0 && blocks_[block].isDynamic() &&
           resolver_.caughtBetweenInfiniteMasses(block, axis); // trap
}

// Resolves the event's contact along each axis it touches on (lecture, "Collisions on a Line –
// Full Formula"), by the rest rule whenever one of the rules above says so. Returns whether a
// velocity (or, exact integrator, an acceleration) changed.
bool PerfectSolver::resolve(const Event& e, int processed) {
    // A block that stops sliding (friction, the exact integrator): no contact to resolve.
    if (isStop(e)) return resolver_.stopSliding(e.a, stopAxis(e)) != Resolution::None;
    const bool repeated = meetingsAtInstant(e) > allowedMeetings(processed);
    // Two blocks meeting again and again at one instant (Resolver::setRepeated).
    resolver_.setRepeated(repeated && e.b >= 0 && blocks_[e.a].isDynamic() &&
                          blocks_[e.b].isDynamic());
    bool changed = false;
    for (int axis = 0; axis < 2; ++axis) {
        if (!(e.axes & (1 << axis))) continue;
        const RestRule rest = collapsesOrTraps(e, axis, repeated) || squeezed(e, axis)
                                  ? RestRule::Always
                                  : RestRule::WhenSlow;
        const Resolution r = e.b == kWallEvent ? resolver_.resolveWall(e.a, axis, rest)
                                               : resolver_.resolvePair(e.a, e.b, axis, rest);
        changed |= r != Resolution::None;
    }
    return changed;
}

// The lecture's loop. Gravity and the other forces have changed the velocities already (World::
// step, semi-implicit Euler) or bend the paths (the exact integrator's parabolas).
void PerfectSolver::run() {
    crush_.reset(blocks_.size());
    metAtInstant_.clear();
    timeline_.reset(); // CurrentTime = 0 for every block
    search_.start();   // the first predicted impacts

    // While CurrentTime < TargetTime:
    double lastEventTime = 0.0;
    int processed = 0;
    for (;;) {
        // Compute time t of the earliest collision (with windows, every horizon up to it comes
        // first: it may bring an earlier one). None left: the substep ends without one.
        if (search_.passHorizon()) continue;
        if (timeline_.empty()) break;
        const Event e = timeline_.popEarliest();
        if (timeline_.isStale(e)) continue; // a velocity it was predicted from has changed
        if (processed == ctx_.world.settings.eventCap) {
            ctx_.capHit = true; // the substep ends at the last event: time falls behind
            break;
        }
        ++processed;
        // Move the bodies to t (lazily: the resolver brings each block it reads there) and resolve.
        resolver_.setNow(e.time);
        if (!resolve(e, processed)) continue;
        ++ctx_.stats.events;
        lastEventTime = e.time;
        // What changed velocity is predicted again.
        changed_ = resolver_.changed();
        resolver_.clearChanged();
        std::sort(changed_.begin(), changed_.end());
        changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
        for (int j : changed_) timeline_.restamp(j);
        search_.changed(changed_, e.time);
    }

    // Move all bodies to the end of the substep (t = min(t, TargetTime)), or to the last event
    // when the cap was hit.
    const double end = ctx_.capHit ? lastEventTime : ctx_.h;
    for (int i = 0; i < static_cast<int>(blocks_.size()); ++i) {
        blocks_[i].position = timeline_.positionAt(i, end);
        blocks_[i].velocity = timeline_.velocityAt(i, end);
    }
    ctx_.advanced = end;
}

} // namespace

void advancePerfect(SubstepContext& ctx) {
    PerfectSolver solver(ctx, ctx.scratch.perfect);
    solver.run();
}
