// The perfect method's search for impacts (impact_search.h).
//
// Paths: each block's swept box for the rest of the substep is registered in one PathIndex,
// which both the predictions and the rest rule read. At the start every pair of paths that meet
// is predicted; after an event, each block whose velocity changed is predicted against the walls
// and every block whose path meets its new trajectory.
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
#include "impact_search.h"

#include "collision.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kWindowsAbove = 2.0;  // windows when the mean travel exceeds this many windows
constexpr int kWindowsPerDoubling = 4; // a block's windows grow twice as long every this many
constexpr size_t kWindowSample = 64;   // blocks whose travel decides on windows

// The horizons: every block in a binary heap by the end of its current window (kNever for its
// last), earliest first (ties by index), each block's place kept so that a new window moves it.
class HorizonHeap {
  public:
    explicit HorizonHeap(PerfectScratch& s)
        : heap_(s.horizons), slot_(s.horizonSlot), end_(s.windowEnd) {}
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

} // namespace

ImpactSearch::ImpactSearch(SubstepContext& ctx, PerfectScratch& scratch, SubstepTimeline& timeline)
    : ctx_(ctx), blocks_(ctx.world.blocks), timeline_(timeline),
      paths_(scratch.cornerGrid, ctx.broadPhase), w_(scratch),
      windows_(scratch.windowGrid, scratch.windows) {}

void ImpactSearch::start() {
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
        paths_.forEachMeetingPair([&](int a, int b) { // a < b
            if (blocks_[a].kind != BodyKind::Static)
                predictPair(a, b, 0.0);
            else if (blocks_[b].kind != BodyKind::Static)
                predictPair(b, a, 0.0);
        });
    }
    timeline_.startQueue();
}

void ImpactSearch::changed(const std::vector<int>& changed, double now) {
    for (int j : changed) {
        const Aabb path = timeline_.trajectory(j, now);
        if (!contains(paths_.path(j), path)) paths_.set(j, path);
    }
    if (windowed_) {
        changedInWindows(changed, now);
        return;
    }
    for (int j : changed) predict(j, now);
}

// Registers every block's path over the whole substep, and predicts its impacts with the walls
// while the path is at hand (in block order, as a separate loop did: the same events in the same
// order). The common case, a path well inside the walls (see predictWalls()), is tested here
// without a call: a call per block cost more than the test.
void ImpactSearch::registerPaths() {
    paths_.build(ctx_.world.bounds, blocks_, [&](int i) {
        const Aabb path = timeline_.trajectory(i, 0.0);
        if (!contains(wallsInside_, path)) predictWalls(i, 0.0, path);
        return path;
    });
}

// Predicts block i's impact with the walls; `path` is its trajectory from `now`.
void ImpactSearch::predictWalls(int i, double now, const Aabb& path) {
    // Most paths stay well inside the walls: then timeOfWallImpact's first test (the box moved by
    // the travel, computed in another order than the path) finds no impact either.
    if (contains(wallsInside_, path)) return;
    const Block& block = blocks_[i];
    if (block.kind == BodyKind::Static) return;
    const Aabb box = aabbOf(timeline_.positionAt(i, now), block.size);
    const WallImpact wall = ctx_.wallImpact(i, box, timeline_.velocityAt(i, now), ctx_.h - now);
    if (!wall.hit()) return;
    const Event e{now + wall.time, i, kWallEvent, timeline_.stamp(i), 0, wall.axes};
    // With windows, queued when the block's window reaches it (registerWindow()): most wall
    // impacts at such speeds come after the block's next collision.
    if (windowed_ && e.time >= w_.windowEnd[i])
        w_.pendingWall[i] = e;
    else
        timeline_.schedule(e);
}

// Predicts the impact of blocks i and j (i not static) within the rest of the substep.
void ImpactSearch::predictPair(int i, int j, double now) {
    const Block &a = blocks_[i], &b = blocks_[j];
    const Impact impact = ctx_.impact(
        i, aabbOf(timeline_.positionAt(i, now), a.size), timeline_.velocityAt(i, now), j,
        aabbOf(timeline_.positionAt(j, now), b.size), timeline_.velocityAt(j, now), ctx_.h - now);
    if (impact.hit())
        timeline_.schedule(
            {now + impact.time, i, j, timeline_.stamp(i), timeline_.stamp(j), impact.axes});
}

// Predicts block i's impacts with the walls and with every neighbour whose registered path meets
// its trajectory for the rest of the substep.
void ImpactSearch::predict(int i, double now) {
    if (blocks_[i].kind == BodyKind::Static) return;
    const Aabb path = timeline_.trajectory(i, now);
    predictWalls(i, now, path);
    paths_.queryOthers(path, i, [&](int j) { predictPair(i, j, now); });
    if (ctx_.slides) predictStops(i, now);
}

// When block i, sliding on an infinite mass with friction (exact integrator), stops sliding.
void ImpactSearch::predictStops(int i, double now) {
    const Vec2 v = timeline_.velocityAt(i, now);
    for (int axis = 0; axis < 2; ++axis) {
        const double t = ctx_.stopTime(i, axis, v[axis]);
        if (t < ctx_.h - now)
            timeline_.schedule({now + t, i, kStopEvent - axis, timeline_.stamp(i), 0,
                                static_cast<std::uint8_t>(1 << axis)});
    }
}

// Windows pay when the moving blocks travel, on average, many window lengths in a substep. The
// mean travel and extent are taken over at most kWindowSample blocks spread over the list (a loop
// over all of them cost the plain search's substep 4%; this choice changes no result).
bool ImpactSearch::useWindows() {
    // Friction's stop events are predicted from the paths only.
    if (w_.windowPolicy < 0.0 || ctx_.friction) return false;
    const size_t n = blocks_.size(), samples = std::min(n, kWindowSample);
    double travel = 0.0;    // m: the moving blocks' travel over the substep, summed
    int moving = 0;         // moving blocks
    double extentSum = 0.0; // m: their extents, summed
    for (size_t k = 0; k < samples; ++k) {
        const size_t i = k * n / samples;
        const Block& b = blocks_[i];
        if (b.kind == BodyKind::Static) continue;
        double speed = std::max(std::abs(b.velocity.x), std::abs(b.velocity.y));
        if (!timeline_.linear()) {
            const Vec2 a = ctx_.accelerationOf(static_cast<int>(i));
            speed += 0.5 * std::max(std::abs(a.x), std::abs(a.y)) * ctx_.h;
        }
        travel += speed * ctx_.h;
        extentSum += std::max(b.size.x, b.size.y);
        ++moving;
    }
    if (moving == 0) return false;
    // The first window's travel: the mean extent (measured best on the storm: windows twice as
    // long cost 20% more, half as long 10% more), shorter by the policy's factor.
    windowTravel_ = extentSum / moving;
    if (w_.windowPolicy > 0.0) windowTravel_ /= w_.windowPolicy;
    return w_.windowPolicy > 0.0 || travel > kWindowsAbove * windowTravel_ * moving;
}

// The first windows (every block from time 0; a static block's for the whole substep), and the
// impacts of every pair of them that meet: the plain search's first predictions.
void ImpactSearch::startWindows() {
    const size_t n = blocks_.size();
    w_.changeSerial.assign(n, 0);
    w_.changeTime.assign(n, 0.0);
    w_.changePath.resize(n);
    if (w_.motions.size() < n) w_.motions.resize(n);
    w_.windowStart.resize(n);
    w_.windowEnd.resize(n);
    w_.windowBatch.assign(n, 0);
    w_.windowCount.assign(n, 0);
    w_.pendingWall.assign(n, Event{kNever, -1, kWallEvent, 0, 0, 0});
    for (size_t i = 0; i < n; ++i) {
        w_.motions[i].assign(1, timeline_.motion(static_cast<int>(i)));
        registerWindow(static_cast<int>(i), 0.0, 0, true);
    }
    windows_.build(ctx_.world.bounds, blocks_,
                   [&](int i) { return windowBox(i, w_.windowStart[i], w_.windowEnd[i]); });
    HorizonHeap(w_).build(static_cast<int>(n));
    windows_.forEachMeetingPair([&](int a, int b) { lookAtPair(a, b); });
}

// The earliest horizon, if it comes no later than the earliest impact: its block's next window.
bool ImpactSearch::passHorizonOfWindows() {
    const HorizonHeap horizons(w_);
    const double horizon = horizons.topTime();
    if (horizon == kNever || (!timeline_.empty() && horizon > timeline_.earliestTime()))
        return false;
    const int i = horizons.top();
    ++w_.horizonsPassed;
    const std::uint32_t batch = ++batch_;
    registerWindow(i, w_.windowEnd[i], batch);
    searchWindow(i, batch);
    return true;
}

// Notes the motion of a block the resolver brought to a later time without changing it.
void ImpactSearch::noteMotion(int i) {
    if (w_.motions[i].back().clock != timeline_.clock(i))
        w_.motions[i].push_back(timeline_.motion(i));
}

// The blocks an event changed (sorted, paths registered): each starts a new window, and each
// looks at the pairs the plain search would predict (after their wall impacts).
void ImpactSearch::changedInWindows(const std::vector<int>& changed, double now) {
    const std::uint32_t batch = ++batch_;
    ++serial_;
    for (int j : changed) {
        w_.changeSerial[j] = serial_;
        w_.changeTime[j] = now;
        w_.changePath[j] = timeline_.trajectory(j, now);
        w_.motions[j].assign(1, timeline_.motion(j));
        w_.windowCount[j] = 0;
        registerWindow(j, now, batch);
    }
    for (int j : changed) {
        predictWalls(j, now, w_.changePath[j]);
        searchWindow(j, batch);
    }
}

// Block i's next window from `start`: the time to travel windowTravel_ (fastest axis), doubled
// every kWindowsPerDoubling windows since its last change (a lone fast block needs only a few per
// crossing of the world; in a dense storm nearly every window stays short enough for the
// CornerGrid's cells), until the end of the substep. `build`: the index is built afterwards (the
// first windows).
void ImpactSearch::registerWindow(int i, double start, std::uint32_t batch, bool build) {
    const Block& block = blocks_[i];
    double end = kNever;
    if (block.kind != BodyKind::Static) {
        const Vec2 v = timeline_.velocityAt(i, start);
        double speed = std::max(std::abs(v.x), std::abs(v.y));
        if (!timeline_.linear()) {
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
    if (wall.a == i && wall.stampA == timeline_.stamp(i) && wall.time < end) {
        timeline_.schedule(wall);
        wall.a = -1;
    }
    if (build) return;
    HorizonHeap(w_).moved(i);
    windows_.set(i, windowBox(i, start, end));
}

// The box block i sweeps over [start, end) (end kNever: to the end of the substep), widened by
// far more than the rounding in which the impact and these boxes can differ: both come from
// positions no larger than the box's coordinates plus the travel in a substep, whose rounding is
// 2^-53 of those, and the widened box must meet the other's at every time of impact within.
Aabb ImpactSearch::windowBox(int i, double start, double end) const {
    const Block& block = blocks_[i];
    if (block.kind == BodyKind::Static) return paths_.path(i);
    const Vec2 p = timeline_.positionAt(i, start), v = timeline_.velocityAt(i, start);
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
void ImpactSearch::searchWindow(int i, std::uint32_t batch) {
    windows_.queryOthers(windows_.path(i), i, [&](int j) {
        if (w_.windowBatch[j] == batch && j < i) return;
        lookAtPair(i, j);
    });
}

// What the plain search predicts for blocks x and y: from the later of their last changes, by
// the block that changed then (both, when one event changed both; the first predictions at time
// 0 as start() does), when its trajectory met the other's registered path (which has not
// changed since), with the motions they had then; queued if the impact lies in both windows.
void ImpactSearch::lookAtPair(int x, int y) {
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

// predictPair() with the motions `mi` and `mj` they had at that time, queued only if the impact
// lies in both blocks' current windows (see lookAtPair()).
void ImpactSearch::predictPairFrom(int i, const Motion& mi, int j, const Motion& mj, double now) {
    const Block &a = blocks_[i], &b = blocks_[j];
    const Impact impact = ctx_.impact(i, aabbOf(timeline_.positionAt(i, mi, now), a.size),
                                      timeline_.velocityAt(i, mi, now), j,
                                      aabbOf(timeline_.positionAt(j, mj, now), b.size),
                                      timeline_.velocityAt(j, mj, now), ctx_.h - now);
    if (!impact.hit()) return;
    const double time = now + impact.time;
    if (time >= w_.windowStart[i] && time < w_.windowEnd[i] && time >= w_.windowStart[j] &&
        time < w_.windowEnd[j])
        timeline_.schedule({time, i, j, timeline_.stamp(i), timeline_.stamp(j), impact.axes});
}

// Block i's motion as the plain search saw it at time t (no earlier than its last change): the
// last one noted at or before t (a move to t itself moves it by nothing).
const Motion& ImpactSearch::motionAsOf(int i, double t) const {
    const std::vector<Motion>& list = w_.motions[i];
    for (size_t k = list.size(); k-- > 1;)
        if (list[k].clock <= t) return list[k];
    return list.front();
}
