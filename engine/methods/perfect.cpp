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
//
// Windows (issue 13's event storm). When blocks cross the world many times per substep (a gas at
// 1e9 m/s), every path covers the whole world: each event would test its blocks against every
// other block, nearly all in vain, as the next collision comes after a fraction of a metre. Then
// the impacts are found through windows instead, as event-driven molecular dynamics does with
// cell crossings: each block registers, in a second index, its swept box over a short window of
// time (its first about a block size of travel, every fourth one twice as long), and when the
// window ends (a horizon, not an event: nothing is resolved or counted) it registers the next
// one. A pair is looked at when one of them registers a window that meets the other's current
// one. What is computed for a pair is exactly what the plain search computes (the same impact,
// from the same time and the same motions: the motion a block had then is kept, since the rest
// rule may have moved it to a later time since), and it is queued only from the two windows in
// which its time of impact lies, so once. The plain search would have queued it by then too: so
// the same events come out in the same order, and every result is bit-identical (tested for
// every shipped scene against the plain search: Windows.* in perfect_test.cpp). Stale predictions
// mostly are never made. The PathIndex stays as it was: the rest rule reads it.
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
constexpr double kWindowsAbove = 2.0; // windows when the mean travel exceeds this many windows
constexpr int kWindowsPerDoubling = 4; // a block's windows grow twice as long every this many
constexpr size_t kWindowSample = 64;   // blocks whose travel decides on windows

using Event = PerfectScratch::Event;

// Earliest first; ties in a fixed order so runs are deterministic.
struct Later {
    bool operator()(const Event& x, const Event& y) const {
        if (x.time != y.time) return x.time > y.time;
        if (x.a != y.a) return x.a > y.a;
        return x.b > y.b;
    }
};

// The horizons: every block in a binary heap by the end of its current window (kNever for its
// last), earliest first (ties by index), each block's place kept so that a new window moves it.
class HorizonHeap {
  public:
    HorizonHeap(std::vector<int>& heap, std::vector<int>& slot, const std::vector<double>& end)
        : heap_(heap), slot_(slot), end_(end) {}
    void build(int n) {
        heap_.resize(n);
        slot_.resize(n);
        for (int i = 0; i < n; ++i) heap_[i] = slot_[i] = i;
        for (int k = n / 2; k-- > 0;) down(k);
    }
    int top() const { return heap_.front(); }
    double topTime() const { return end_[heap_.front()]; }
    // Block i's window end has changed.
    void moved(int i) {
        up(slot_[i]);
        down(slot_[i]);
    }

  private:
    bool before(int a, int b) const { return end_[a] < end_[b] || (end_[a] == end_[b] && a < b); }
    void place(int k, int block) {
        heap_[k] = block;
        slot_[block] = k;
    }
    void up(int k) {
        const int block = heap_[k];
        while (k > 0 && before(block, heap_[(k - 1) / 2])) {
            place(k, heap_[(k - 1) / 2]);
            k = (k - 1) / 2;
        }
        place(k, block);
    }
    void down(int k) {
        const int n = static_cast<int>(heap_.size()), block = heap_[k];
        for (;;) {
            int c = 2 * k + 1;
            if (c >= n) break;
            if (c + 1 < n && before(heap_[c + 1], heap_[c])) ++c;
            if (!before(heap_[c], block)) break;
            place(k, heap_[c]);
            k = c;
        }
        place(k, block);
    }

    std::vector<int>& heap_;
    std::vector<int>& slot_;
    const std::vector<double>& end_;
};

using Motion = PerfectScratch::Motion;

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
          crush_(scratch.crush), w_(scratch), windows_(scratch.windowGrid, scratch.windows),
          horizons_(scratch.horizons, scratch.horizonSlot, scratch.windowEnd) {}

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
    // The same from a motion it had (see "Windows"): the same arithmetic.
    Vec2 positionAt(int i, const Motion& m, double t) const {
        if (linear_) return m.position + m.velocity * (t - m.clock);
        return ctx_.positionAfter(i, m.position, m.velocity, t - m.clock);
    }
    Vec2 velocityAt(int i, const Motion& m, double t) const {
        return linear_ ? m.velocity : ctx_.velocityAfter(i, m.velocity, t - m.clock);
    }
    Motion motion(int i) const { return {blocks_[i].position, blocks_[i].velocity, clock_[i]}; }
    Aabb trajectory(int i, double now) const {
        if (linear_)
            return sweptAabb(positionAt(i, now), blocks_[i].size, blocks_[i].velocity,
                             ctx_.h - now);
        return ctx_.path(i, positionAt(i, now), blocks_[i].size, velocityAt(i, now), ctx_.h - now);
    }
    void registerPaths();
    void predictWalls(int i, double now, const Aabb& path);
    void predictPair(int i, int j, double now);
    void predictPairFrom(int i, const Motion& mi, int j, const Motion& mj, double now);
    void predict(int i, double now);
    // Windows (see the top of the file).
    bool useWindows();
    void startWindows();
    void registerWindow(int i, double start, std::uint32_t batch, bool build = false);
    Aabb windowBox(int i, double start, double end) const;
    void searchWindow(int i, std::uint32_t batch);
    void lookAtPair(int x, int y);
    const Motion& motionAsOf(int i, double t) const;
    void noteSyncs();
    void changedInWindows(const std::vector<int>& changed, double now);
    void nextWindow();
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
    // Windows (see the top of the file).
    PerfectScratch& w_;
    PathIndex windows_; // each block's current window
    HorizonHeap horizons_;
    bool windowed_ = false;     // this substep finds its impacts through windows
    double windowTravel_ = 0.0; // m: the first window's travel
    double travel_ = 0.0;       // m: the moving blocks' travel over the substep, summed
    int moving_ = 0;            // moving blocks
    double extentSum_ = 0.0;    // m: their extents, summed
    std::uint32_t serial_ = 0;  // events that changed a velocity so far
    std::uint32_t batch_ = 0;   // window registrations so far (one batch at a change)
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
    if (!wall.hit()) return;
    const Event e{now + wall.time, i, kWallEvent, stamp_[i], 0, wall.axes};
    // With windows, queued when the block's window reaches it (registerWindow()): most wall
    // impacts at such speeds come after the block's next collision.
    if (windowed_ && e.time >= w_.windowEnd[i])
        w_.pendingWall[i] = e;
    else
        schedule(e);
}

// Predicts the impact of blocks i and j (i not static) within the rest of the substep.
void PerfectSolver::predictPair(int i, int j, double now) {
    const Block &a = blocks_[i], &b = blocks_[j];
    const Impact impact =
        ctx_.impact(i, aabbOf(positionAt(i, now), a.size), velocityAt(i, now), j,
                    aabbOf(positionAt(j, now), b.size), velocityAt(j, now), ctx_.h - now);
    if (impact.hit()) schedule({now + impact.time, i, j, stamp_[i], stamp_[j], impact.axes});
}

// The same with the motions `mi` and `mj` they had at that time, queued only if the impact lies
// in both blocks' current windows (see lookAtPair()).
void PerfectSolver::predictPairFrom(int i, const Motion& mi, int j, const Motion& mj, double now) {
    const Block &a = blocks_[i], &b = blocks_[j];
    const Impact impact =
        ctx_.impact(i, aabbOf(positionAt(i, mi, now), a.size), velocityAt(i, mi, now), j,
                    aabbOf(positionAt(j, mj, now), b.size), velocityAt(j, mj, now), ctx_.h - now);
    if (!impact.hit()) return;
    const double time = now + impact.time;
    if (time >= w_.windowStart[i] && time < w_.windowEnd[i] && time >= w_.windowStart[j] &&
        time < w_.windowEnd[j])
        schedule({time, i, j, stamp_[i], stamp_[j], impact.axes});
}

// Predicts block i's impacts with the walls and with every neighbour whose registered box meets
// its trajectory for the rest of the substep.
void PerfectSolver::predict(int i, double now) {
    if (blocks_[i].kind == BodyKind::Static) return;
    const Aabb path = trajectory(i, now);
    predictWalls(i, now, path);
    paths_.queryOthers(path, i, [&](int j) { predictPair(i, j, now); });
}

// Windows pay when the moving blocks travel, on average, many window lengths in a substep. The
// mean travel and extent are taken over at most kWindowSample blocks spread over the list (a loop
// over all of them cost the plain search's substep 4%; this choice changes no result).
bool PerfectSolver::useWindows() {
    if (w_.windowPolicy < 0.0) return false;
    const size_t n = blocks_.size(), samples = std::min(n, kWindowSample);
    for (size_t k = 0; k < samples; ++k) {
        const size_t i = k * n / samples;
        const Block& b = blocks_[i];
        if (b.kind == BodyKind::Static) continue;
        double speed = std::max(std::abs(b.velocity.x), std::abs(b.velocity.y));
        if (!linear_) {
            const Vec2 a = ctx_.accelerationOf(static_cast<int>(i));
            speed += 0.5 * std::max(std::abs(a.x), std::abs(a.y)) * ctx_.h;
        }
        travel_ += speed * ctx_.h;
        extentSum_ += std::max(b.size.x, b.size.y);
        ++moving_;
    }
    if (moving_ == 0) return false;
    // The first window's travel: the mean extent (measured best on the storm: windows twice as
    // long cost 20% more, half as long 10% more), shorter by the policy's factor.
    windowTravel_ = extentSum_ / moving_;
    if (w_.windowPolicy > 0.0) windowTravel_ /= w_.windowPolicy;
    return w_.windowPolicy > 0.0 || travel_ > kWindowsAbove * windowTravel_ * moving_;
}

// The first windows (every block from time 0; a static block's for the whole substep), and the
// impacts of every pair of them that meet: the plain search's first predictions.
void PerfectSolver::startWindows() {
    const size_t n = blocks_.size();
    w_.changeSerial.assign(n, 0);
    w_.changeTime.assign(n, 0.0);
    w_.changePath.resize(n);
    if (w_.motions.size() < n) w_.motions.resize(n);
    w_.windowStart.resize(n);
    w_.windowEnd.resize(n);
    w_.windowBatch.assign(n, 0);
    w_.windowCount.assign(n, 0);
    w_.syncLog.clear();
    w_.pendingWall.assign(n, Event{kNever, -1, kWallEvent, 0, 0, 0});
    for (size_t i = 0; i < n; ++i) {
        w_.motions[i].assign(1, motion(static_cast<int>(i)));
        registerWindow(static_cast<int>(i), 0.0, 0, true);
    }
    windows_.build(ctx_.world.bounds, blocks_,
                   [&](int i) { return windowBox(i, w_.windowStart[i], w_.windowEnd[i]); });
    horizons_.build(static_cast<int>(n));
    windows_.forEachMeetingPair([&](int a, int b) { lookAtPair(a, b); });
    resolver_.setSyncLog(&w_.syncLog);
}

// Block i's next window from `start`: the time to travel windowTravel_ (fastest axis), doubled
// every kWindowsPerDoubling windows since its last change (a lone fast block needs only a few per
// crossing of the world; in a dense storm nearly every window stays short enough for the
// CornerGrid's cells), until the end of the substep. `build`: the index is built afterwards (the
// first windows).
void PerfectSolver::registerWindow(int i, double start, std::uint32_t batch, bool build) {
    const Block& block = blocks_[i];
    double end = kNever;
    if (block.kind != BodyKind::Static) {
        const Vec2 v = velocityAt(i, start);
        double speed = std::max(std::abs(v.x), std::abs(v.y));
        if (!linear_) {
            const Vec2 a = ctx_.accelerationOf(i);
            speed += std::max(std::abs(a.x), std::abs(a.y)) * (ctx_.h - start);
        }
        const int k = std::min(w_.windowCount[i]++ / kWindowsPerDoubling, 60);
        end = start + std::ldexp(windowTravel_ / speed, k);
        // Past the substep (or no motion, or no progress in doubles): the last window.
        if (!(end > start && end < ctx_.h)) end = kNever;
    }
    w_.windowStart[i] = start;
    w_.windowEnd[i] = end;
    w_.windowBatch[i] = batch;
    // A wall impact predicted earlier comes within this window: queue it now, before any event
    // after `start`.
    Event& wall = w_.pendingWall[i];
    if (wall.a == i && wall.stampA == stamp_[i] && wall.time < end) {
        schedule(wall);
        wall.a = -1;
    }
    if (build) return;
    horizons_.moved(i);
    windows_.set(i, windowBox(i, start, end));
}

// The box block i sweeps over [start, end) (end kNever: to the end of the substep), widened by
// far more than the rounding in which the impact and these boxes can differ: both come from
// positions no larger than the box's coordinates plus the travel in a substep, whose rounding is
// 2^-53 of those, and the widened box must meet the other's at every time of impact within.
Aabb PerfectSolver::windowBox(int i, double start, double end) const {
    const Block& block = blocks_[i];
    if (block.kind == BodyKind::Static) return paths_.path(i);
    const Vec2 p = positionAt(i, start), v = velocityAt(i, start);
    Aabb box = ctx_.path(i, p, block.size, v, std::min(end, ctx_.h) - start);
    const Vec2 a = ctx_.accelerationOf(i);
    const double magnitude = std::max({std::abs(box.min.x), std::abs(box.min.y),
                                       std::abs(box.max.x), std::abs(box.max.y)}) +
                             (std::abs(v.x) + std::abs(v.y)) * ctx_.h +
                             (std::abs(a.x) + std::abs(a.y)) * ctx_.h * ctx_.h;
    const double margin = magnitude * 0x1p-36 + 4.0 * kTouchTolerance;
    box.min = box.min - Vec2{margin, margin};
    box.max = box.max + Vec2{margin, margin};
    return box;
}

// Block i has registered a window (in `batch`): the pairs with every block whose current window
// meets it. A block of the same batch registered before the search: the pair is looked at once,
// from the lower index.
void PerfectSolver::searchWindow(int i, std::uint32_t batch) {
    windows_.queryOthers(windows_.path(i), i, [&](int j) {
        if (w_.windowBatch[j] == batch && j < i) return;
        lookAtPair(i, j);
    });
}

// What the plain search predicts for blocks x and y: from the later of their last changes, by
// the block that changed then (both, when one event changed both; the first predictions at time
// 0 as predictFirst in run()), when its trajectory met the other's registered path (which has not
// changed since), with the motions they had then; queued if the impact lies in both windows.
void PerfectSolver::lookAtPair(int x, int y) {
    const std::uint32_t ex = w_.changeSerial[x], ey = w_.changeSerial[y];
    if (ex == 0 && ey == 0) {
        const int lo = std::min(x, y), hi = std::max(x, y);
        const bool staticLo = blocks_[lo].kind == BodyKind::Static;
        const bool staticHi = blocks_[hi].kind == BodyKind::Static;
        if ((staticLo && staticHi) || !meets(paths_.path(lo), paths_.path(hi))) return;
        const int a = staticLo ? hi : lo, b = staticLo ? lo : hi;
        predictPairFrom(a, w_.motions[a].front(), b, w_.motions[b].front(), 0.0);
        return;
    }
    auto from = [&](int a, int b) {
        const double now = w_.changeTime[a];
        if (meets(paths_.path(b), w_.changePath[a]))
            predictPairFrom(a, w_.motions[a].front(), b, motionAsOf(b, now), now);
    };
    if (ex >= ey) from(x, y);
    if (ey >= ex) from(y, x);
}

// Block i's motion as the plain search saw it at time t (no earlier than its last change): the
// last one noted at or before t (a sync at t itself moves it by nothing).
const Motion& PerfectSolver::motionAsOf(int i, double t) const {
    const std::vector<Motion>& list = w_.motions[i];
    for (size_t k = list.size(); k-- > 1;)
        if (list[k].clock <= t) return list[k];
    return list.front();
}

// Notes the motion of every block the last event brought to its time without changing it.
void PerfectSolver::noteSyncs() {
    for (int i : w_.syncLog)
        if (w_.motions[i].back().clock != clock_[i]) w_.motions[i].push_back(motion(i));
    w_.syncLog.clear();
}

// The blocks an event changed (sorted, paths registered): each starts a new window, and each
// looks at the pairs the plain search would predict (after their wall impacts).
void PerfectSolver::changedInWindows(const std::vector<int>& changed, double now) {
    const std::uint32_t batch = ++batch_;
    ++serial_;
    for (int j : changed) {
        w_.changeSerial[j] = serial_;
        w_.changeTime[j] = now;
        w_.changePath[j] = trajectory(j, now);
        w_.motions[j].assign(1, motion(j));
        w_.windowCount[j] = 0;
        registerWindow(j, now, batch);
    }
    for (int j : changed) {
        predictWalls(j, now, w_.changePath[j]);
        searchWindow(j, batch);
    }
}

// The earliest horizon: its block's next window.
void PerfectSolver::nextWindow() {
    const int i = horizons_.top();
    ++w_.horizonsPassed;
    const std::uint32_t batch = ++batch_;
    registerWindow(i, w_.windowEnd[i], batch);
    searchWindow(i, batch);
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
    windowed_ = useWindows();
    if (windowed_) {
        startWindows();
    } else {
        auto predictFirst = [&](int a, int b) { // a < b
            if (blocks_[a].kind != BodyKind::Static)
                predictPair(a, b, 0.0);
            else if (blocks_[b].kind != BodyKind::Static)
                predictPair(b, a, 0.0);
        };
        paths_.forEachMeetingPair(predictFirst);
    }
    std::make_heap(events_.begin(), events_.end(), Later{});
    heap_ = true;

    // Repeat: take the earliest impact, move its blocks to it, resolve, re-predict what changed.
    // With windows, every horizon up to that impact's time comes first (it may find impacts
    // at that time that come before it).
    double lastEventTime = 0.0;
    int processed = 0;
    std::vector<int>& changed = changed_;
    for (;;) {
        if (windowed_ && horizons_.topTime() < kNever &&
            (events_.empty() || horizons_.topTime() <= events_.front().time)) {
            nextWindow();
            continue;
        }
        if (events_.empty()) break;
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
        const bool resolved = resolve(e, processed);
        if (windowed_) noteSyncs();
        if (!resolved) continue;
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
        if (windowed_) {
            changedInWindows(changed, e.time);
            continue;
        }
        for (int j : changed) predict(j, e.time);
    }
    resolver_.setSyncLog(nullptr);

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
