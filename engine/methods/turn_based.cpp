// The turn-based method (lecture, "Turn-based Simulation" and "Tips – Collision Detection"):
// move the blocks one by one, in order, over the step or until their first collision, with the
// others held still; put the block at the point of impact (exact: t = a/b) and resolve at once,
// only if the relative velocity closes. No overlaps; collisions resolve in the right direction;
// positions are slightly off and depend on the order. A resting contact (the rest rule) does not
// end a block's turn, so a block can slide along a floor it rests on.
//
// Contacts at one instant: a block that a collision sends into a body it touches cannot carry
// that velocity out (it would move into the body), so the contact resolves it at once, and so on
// along the blocks it sets moving (a light block hit while it rests on the floor bounces off the
// floor, back into the heavy block, ...). Without gravity the struck block's own turn does it,
// where the contact comes at once (time 0); with gravity, waiting would add g·h to blocks held
// still: the sequence runs in the striking block's turn. Left to later turns and steps,
// such velocities would keep growing with gravity while the blocks stand still. A sequence that
// would not end is undone (only velocities changed: the blocks hold still) and the impact's
// bodies are merged by the rest rule instead, perfectly inelastic from the velocities they had:
//  - collapse: with C < 1 a pair that meets more than kInelasticRepeats times (infinitely many
//    collisions converge at one instant: McNamara and Young 1992, inelastic collapse). With
//    C = 1 a sequence is finite (a light block between a heavy one and a wall: about
//    pi·sqrt(M/m) collisions, Galperin 2003) unless it is jammed between infinite masses (a row
//    filling the box), so only a pair that meets more than kElasticRepeats times.
//  - crush (crush.h, shared with the perfect method): a block bouncing between two infinite masses
//    that close in on it (a platform pushing it into a wall). The rest rule then reverses the
//    platforms that press, as on a wall.
//  - more contacts at one instant than the event cap (WorldSettings::eventCap).
#include "collision.h"
#include "crush.h"
#include "methods.h"
#include "scratch.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace {

constexpr int kMaxRestingContactsPerTurn = 4;
constexpr int kInelasticRepeats = 8;  // C < 1: meetings of one pair in one sequence, then merged
constexpr int kElasticRepeats = 2048; // C = 1: the same (pi·sqrt(1e6)/2 ≈ 1571 fit)
constexpr size_t kListedPairs = 16;

using FirstImpact = TurnBasedScratch::FirstImpact;

// Mistake "first-found": keeps the hit block that comes first in the list. Not inlined: the
// query's loop stays as small as without the mistake.
[[gnu::noinline]] void noteFirstInList(FirstImpact& first, int j, const Impact& impact) {
    if (!first.blocks.empty() && first.blocks.front().first < j) return;
    first.time = impact.time;
    first.wallAxes = 0;
    first.blocks.assign(1, {j, impact.axes});
}

// The first impact of block i moving for `remaining` seconds along `path` (its swept box) with
// everything else held still.
void findFirstImpact(SubstepContext& ctx, int i, double remaining, const Aabb& path,
                     FirstImpact& first) {
    const std::vector<Block>& blocks = ctx.world.blocks;
    const Block& block = blocks[i];
    const Aabb box = aabbOf(block);
    first.time = kNever;
    first.wallAxes = 0;
    first.blocks.clear();

    const WallImpact wall = ctx.wallImpact(i, box, block.velocity, remaining);
    if (wall.hit()) {
        first.time = wall.time;
        first.wallAxes = wall.axes;
    }
    // Keeps the earliest impact (and every block hit at that same time).
    auto keepEarliest = [&](int j, const Impact& impact) {
        if (!impact.hit() || impact.time > first.time) return;
        if (impact.time < first.time) {
            first.time = impact.time;
            first.wallAxes = 0;
            first.blocks.clear();
        }
        first.blocks.emplace_back(j, impact.axes);
    };
    // The others hold still: only a block the path reaches (touching counts) can be hit.
    auto reaches = [&](const Aabb& other) {
        return !(other.min.x > path.max.x || other.max.x < path.min.x || other.max.y < path.min.y ||
                 other.min.y > path.max.y);
    };
    if (ctx.plain()) { // linear motion, no mistakes: the plain time of impact, in a tight loop
        ctx.broadPhase.queryOthers(path, i, [&](int j) {
            const Aabb other = aabbOf(blocks[j]);
            if (reaches(other))
                keepEarliest(j, timeOfImpact(box, block.velocity, other, Vec2{}, remaining));
        });
        return;
    }
    // Mistake "first-found" (lecture, "BAD: resolving wrong collision"): the first block in list
    // order that the path hits wins, not the earliest; walls only when no block is hit.
    const bool firstFound = ctx.world.settings.has(Mistake::FirstFound);
    ctx.broadPhase.queryOthers(path, i, [&](int j) {
        const Aabb other = aabbOf(blocks[j]);
        if (!reaches(other)) return;
        const Impact impact = ctx.impact(i, box, block.velocity, -1, other, Vec2{}, remaining);
        if (firstFound && impact.hit())
            noteFirstInList(first, j, impact);
        else
            keepEarliest(j, impact);
    });
}

// With friction: block i touches, along one axis, neighbours that it does not approach (they
// move as it does: a pushed pair merged by the rest rule), but that are held still in its turn,
// so they stop it at once. The lecture's turn-based would end its turn there and lose the motion
// along the face too (gravity would then add to a block that never falls). Instead its motion
// along that axis is held for the rest of the turn (its velocity kept, given back at the end),
// and it moves along the face.
struct HeldAxis {
    int axis = -1;
    double velocity = 0.0;     // m/s, along the axis
    double acceleration = 0.0; // m/s^2 (the exact integrator's)

    // Holds the axis of `first` (one axis for all its impacts); false if there is none.
    bool hold(SubstepContext& ctx, int i, const FirstImpact& first) {
        std::uint8_t axes = first.wallAxes;
        for (const auto& hit : first.blocks) axes |= hit.second;
        if (axis >= 0 || (axes != kAxisX && axes != kAxisY)) return false;
        axis = axes == kAxisX ? 0 : 1;
        Block& block = ctx.world.blocks[i];
        velocity = block.velocity[axis];
        block.velocity[axis] = 0.0;
        if (ctx.acceleration) {
            acceleration = (*ctx.acceleration)[i][axis];
            (*ctx.acceleration)[i][axis] = 0.0;
        }
        return true;
    }
    // Gives the held motion back (unless a collision has set one since).
    void release(SubstepContext& ctx, int i) {
        if (axis < 0) return;
        Block& block = ctx.world.blocks[i];
        if (block.velocity[axis] == 0.0) block.velocity[axis] = velocity;
        if (ctx.acceleration && (*ctx.acceleration)[i][axis] == 0.0)
            (*ctx.acceleration)[i][axis] = acceleration;
        axis = -1;
    }
};

// Friction with the exact integrator: if block i, sliding on an infinite mass, comes to its
// support's velocity before its first impact (at `impact`, s from now) and within the `remaining`
// turn, moves it there, lets it stop sliding (Resolver::stopSliding) and returns true.
bool stopsSlidingFirst(SubstepContext& ctx, Resolver& resolver, int i, double impact,
                       double remaining, double& elapsed) {
    Block& block = ctx.world.blocks[i];
    double stop = std::min(impact, remaining);
    int axis = -1;
    for (int k = 0; k < 2; ++k) {
        const double t = ctx.stopTime(i, k, block.velocity[k]);
        if (t < stop) stop = t, axis = k;
    }
    if (axis < 0) return false;
    block.position = ctx.positionAfter(i, block.position, block.velocity, stop);
    block.velocity = ctx.velocityAfter(i, block.velocity, stop);
    elapsed += stop;
    resolver.setNow(elapsed);
    resolver.stopSliding(i, axis);
    resolver.clearChanged();
    return true;
}

// Resolves the contacts of one instant of a block's turn: its impacts, then every contact that a
// changed velocity now closes (see the top of the file).
class Contacts final : ResolveHooks {
  public:
    Contacts(SubstepContext& ctx, TurnBasedScratch& s)
        : ctx_(ctx), blocks_(ctx.world.blocks), resolver_(ctx, nullptr, this), s_(s) {
        s_.isPending.resize(2 * blocks_.size(), 0); // all 0: settle() leaves none set
        allowed_ = ctx.world.settings.bounciness < 1.0 ? kInelasticRepeats : kElasticRepeats;
    }

    Resolver& resolver() { return resolver_; }

    // Block i has reached `first` at `now` (s into the substep): resolves its impacts and the
    // sequence they set off. `bounced` and `rested` say how i's own impacts were resolved.
    void resolveInstant(int i, const FirstImpact& first, double now, bool& bounced, bool& rested) {
        resolver_.setNow(now);
        // A block that moved into a body it touched (time 0) starts a sequence. One that moved
        // to its impact leaves the contacts of the blocks it hit to their turns, where they come
        // at once (time 0), unless gravity would add g·h to them while they wait.
        const bool moved = first.time > 0.0;
        sequence_ = !moved || ctx_.world.settings.gravity != Vec2{};
        if (!sequence_) {
            resolveImpacts(i, first, bounced, rested);
            return;
        }
        mover_ = moved ? i : -1; // it touches nothing else it would run into
        s_.meetings.clear();
        if (s_.meetingMap.bucket_count() > 64) // clear() costs one step per bucket
            s_.meetingMap = std::unordered_map<std::uint64_t, int>{};
        else if (!s_.meetingMap.empty())
            s_.meetingMap.clear();
        s_.crush.reset(blocks_.size());
        s_.undo.clear();
        keepUndo_ = true;
        const int collisionsBefore = ctx_.stats.collisions;
        const int contactsBefore = ctx_.stats.contacts;
        const size_t logBefore = ctx_.log ? ctx_.log->size() : 0;
        merge_ = endless_ = false;
        resolutions_ = 0;
        resolveImpacts(i, first, bounced, rested);
        settle();
        keepUndo_ = false;
        if (!endless_) return;
        // A sequence that would not end: undo it (the blocks are where they were, only their
        // velocities changed) and merge the impacts' bodies by the rest rule instead.
        for (auto c = s_.undo.rbegin(); c != s_.undo.rend(); ++c)
            blocks_[c->block].velocity[c->axis] = c->before;
        ctx_.stats.collisions = collisionsBefore;
        ctx_.stats.contacts = contactsBefore;
        if (ctx_.log) ctx_.log->resize(logBefore);
        merge_ = true;
        endless_ = false;
        resolutions_ = 0;
        resolveImpacts(i, first, bounced, rested);
        settle();
    }

  private:
    // While a sequence may still be undone, every change of velocity is kept (ResolveHooks).
    void velocityChanging(int i, int axis, double before) override {
        if (keepUndo_) s_.undo.push_back({i, axis, before});
    }

    void resolveImpacts(int i, const FirstImpact& first, bool& bounced, bool& rested) {
        bounced = rested = false;
        auto note = [&](Resolution r) {
            bounced |= r == Resolution::Bounce;
            rested |= r == Resolution::Rest;
        };
        for (int axis = 0; axis < 2; ++axis)
            if (first.wallAxes & (1 << axis)) note(resolve(i, CrushRule::kWall, axis));
        for (const auto& [j, axes] : first.blocks)
            for (int axis = 0; axis < 2; ++axis)
                if (axes & (1 << axis)) note(resolve(i, j, axis));
    }

    // Block a against block b (b >= 0) or the wall it moves toward (b = CrushRule::kWall),
    // along `axis`; the two touch there and approach.
    Resolution resolve(int a, int b, int axis) {
        if (!sequence_)
            return b < 0 ? resolver_.resolveWall(a, axis) : resolver_.resolvePair(a, b, axis);
        if (endless_ || resolutions_ >= ctx_.world.settings.eventCap) {
            endless_ = !merge_; // the event cap bounds the work whatever happens
            return Resolution::None;
        }
        ++resolutions_;
        if (!merge_ && (repeats(a, b) || squeezed(a, b, axis))) {
            endless_ = true;
            return Resolution::None;
        }
        const size_t changedBefore = resolver_.changed().size();
        const RestRule rest = merge_ ? RestRule::Always : RestRule::WhenSlow;
        const Resolution r =
            b < 0 ? resolver_.resolveWall(a, axis, rest) : resolver_.resolvePair(a, b, axis, rest);
        // The blocks sent on at new velocities: their other contacts along the axis come next.
        const std::vector<int>& changed = resolver_.changed();
        for (size_t k = changedBefore; k < changed.size(); ++k) {
            const int j = changed[k];
            std::uint8_t& flag = s_.isPending[2 * static_cast<size_t>(j) + axis];
            if (blocks_[j].isDynamic() && !flag && j != mover_) {
                flag = 1;
                s_.pending.emplace_back(j, axis);
            }
        }
        return r;
    }

    // Resolves, one by one, the contacts the changes of velocity so far have made closing.
    void settle() {
        std::vector<std::pair<int, int>>& pending = s_.pending;
        for (size_t next = 0; next < pending.size(); ++next) {
            // Not a structured binding: clang 14 (sanitizer and browser builds) cannot capture
            // one in the lambda below in C++17.
            const int j = pending[next].first, axis = pending[next].second;
            s_.isPending[2 * static_cast<size_t>(j) + axis] = 0;
            if (endless_) continue;
            const Aabb box = aabbOf(blocks_[j]);
            const double v = blocks_[j].velocity[axis];
            const Bounds& bounds = ctx_.world.bounds;
            if ((v < 0.0 && box.min[axis] - bounds.min[axis] <= kTouchTolerance) ||
                (v > 0.0 && bounds.max[axis] - box.max[axis] <= kTouchTolerance))
                resolve(j, CrushRule::kWall, axis);
            ctx_.broadPhase.queryOthers(box, j, [&, j = j, axis = axis](int k) {
                const int side = faceContact(box, aabbOf(blocks_[k]), axis);
                if (side == 0) return;
                const double vj = blocks_[j].velocity[axis], vk = blocks_[k].velocity[axis];
                if ((side > 0 ? vj - vk : vk - vj) > 0.0) resolve(j, k, axis);
            });
        }
        pending.clear();
    }

    // The collapse rule: whether the pair has met more than allowed_ times at this instant.
    bool repeats(int a, int b) {
        const auto lo = static_cast<std::uint32_t>(b < 0 ? a : std::min(a, b));
        const auto hi = static_cast<std::uint32_t>(b < 0 ? b : std::max(a, b));
        const std::uint64_t pair = (static_cast<std::uint64_t>(lo) << 32) | hi;
        // Nearly every instant has a pair or two: a short list, a table past kListedPairs.
        std::vector<std::pair<std::uint64_t, int>>& list = s_.meetings;
        for (auto& [p, count] : list)
            if (p == pair) return ++count > allowed_;
        if (list.size() < kListedPairs) {
            list.emplace_back(pair, 1);
            return 1 > allowed_;
        }
        return ++s_.meetingMap[pair] > allowed_;
    }
    // The crush rule.
    bool squeezed(int a, int b, int axis) {
        return s_.crush.squeezed(blocks_, a, b, axis, blocks_[a].position[axis],
                                 b < 0 ? 0.0 : blocks_[b].position[axis]);
    }

    SubstepContext& ctx_;
    std::vector<Block>& blocks_;
    Resolver resolver_;
    TurnBasedScratch& s_;
    int allowed_ = kInelasticRepeats;
    bool sequence_ = false; // resolving a sequence at one instant
    int mover_ = -1;        // the block that moved to this instant's impact, if any
    bool merge_ = false;    // merging: every contact by the rest rule
    bool endless_ = false;  // the sequence would not end: to be undone
    bool keepUndo_ = false; // keeping the changes of velocity in s_.undo
    int resolutions_ = 0;   // contacts resolved at this instant
};

} // namespace

void advanceTurnBased(SubstepContext& ctx) {
    std::vector<Block>& blocks = ctx.world.blocks;
    const int n = static_cast<int>(blocks.size());
    BroadPhase& grid = ctx.broadPhase;

    // Every block registers the box it can sweep this step; a block whose velocity changes
    // re-registers before its turn, so the queries see every block wherever it is.
    grid.build(ctx.world.bounds, blocks, [&](int i) {
        return ctx.path(i, blocks[i].position, blocks[i].size, blocks[i].velocity, ctx.h);
    });
    const bool moveBack = ctx.world.settings.has(Mistake::MoveBack);

    TurnBasedScratch& scratch = ctx.scratch.turnBased;
    Contacts contacts(ctx, scratch);
    Resolver& resolver = contacts.resolver();
    FirstImpact& first = scratch.first;
    for (int i = 0; i < n; ++i) {
        Block& block = blocks[i];
        if (block.kind == BodyKind::Static) continue;
        double elapsed = 0.0;
        HeldAxis held; // with friction: the axis along which it is held this turn, if any
        for (int contact = 0; contact <= kMaxRestingContactsPerTurn; ++contact) {
            const double remaining = ctx.h - elapsed;
            const Aabb path = ctx.path(i, block.position, block.size, block.velocity, remaining);
            if (!contains(grid.box(i), path)) grid.set(i, path);
            findFirstImpact(ctx, i, remaining, path, first);
            if (ctx.slides && stopsSlidingFirst(ctx, resolver, i, first.time, remaining, elapsed))
                continue;
            if (first.time == kNever) { // free flight for the rest of the step
                block.position = ctx.positionAfter(i, block.position, block.velocity, remaining);
                block.velocity = ctx.velocityAfter(i, block.velocity, remaining);
                break;
            }
            // Point of impact: POI = oldPosition + t · velocity (lecture, "Point of Impact").
            const Vec2 poi = ctx.positionAfter(i, block.position, block.velocity, first.time);
            if (moveBack) {
                // Mistake "move-back" (lecture, "BAD: no exact point of impact"): moved the whole
                // step, then back out along the collision axis only.
                const std::uint8_t axes =
                    first.blocks.empty() ? first.wallAxes : first.blocks.front().second;
                const Vec2 whole = ctx.positionAfter(i, block.position, block.velocity, remaining);
                if (axes == kAxisX || axes == kAxisY)
                    block.position = movedBackAlongAxis(whole, poi, axes == kAxisX ? 0 : 1);
                else
                    block.position = poi;
            } else {
                block.position = poi;
            }
            block.velocity = ctx.velocityAfter(i, block.velocity, first.time);
            elapsed += first.time;
            bool bounced = false, rested = false;
            contacts.resolveInstant(i, first, elapsed, bounced, rested);
            // Blocks hit by this one changed velocity: they may go further than they registered.
            for (int j : resolver.changed()) {
                const Block& b = blocks[j];
                const Aabb reach = ctx.path(j, b.position, b.size, b.velocity, ctx.h);
                if (!contains(grid.box(j), reach)) grid.set(j, reach);
            }
            resolver.clearChanged();
            // With friction a block pressed along a face by a neighbour that moves with it (a
            // crate pushed on, a block beside one held by its floor) slides along that face.
            if (ctx.friction && !bounced && !rested && !moveBack && first.time == 0.0 &&
                held.hold(ctx, i, first))
                continue;
            // A bounce ends the turn (the rest of the step is lost, as in the lecture); so does
            // a "collision that is not really a collision". Only a resting contact lets it go on.
            if (bounced || !rested || moveBack) break;
        }
        held.release(ctx, i);
    }
    ctx.advanced = ctx.h;
}
