// The turn-based method (lecture, "Turn-based Simulation" and "Tips – Collision Detection"):
// move the blocks one by one, in order, over the step or until their first collision, with the
// others held still; put the block at the point of impact (exact: t = a/b) and resolve at once,
// only if the relative velocity closes. No overlaps; collisions resolve in the right direction;
// positions are slightly off and depend on the order. A resting contact (the rest rule) does not
// end a block's turn, so a block can slide along a floor it rests on.
#include "collision.h"
#include "methods.h"

#include <vector>

namespace {

constexpr int kMaxRestingContactsPerTurn = 4;

struct FirstImpact {
    double time = kNever; // s into the block's remaining turn
    std::uint8_t wallAxes = 0;
    // Blocks hit at that same time, each with its axes.
    std::vector<std::pair<int, std::uint8_t>> blocks;
};

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

    Resolver resolver(ctx);
    thread_local FirstImpact first;
    for (int i = 0; i < n; ++i) {
        Block& block = blocks[i];
        if (block.kind == BodyKind::Static) continue;
        double elapsed = 0.0;
        for (int contact = 0; contact <= kMaxRestingContactsPerTurn; ++contact) {
            const double remaining = ctx.h - elapsed;
            const Aabb path = ctx.path(i, block.position, block.size, block.velocity, remaining);
            if (!contains(grid.box(i), path)) grid.set(i, path);
            findFirstImpact(ctx, i, remaining, path, first);
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
            resolver.setNow(elapsed);
            bool bounced = false, rested = false;
            auto note = [&](Resolution r) {
                bounced |= r == Resolution::Bounce;
                rested |= r == Resolution::Rest;
            };
            for (int axis = 0; axis < 2; ++axis)
                if (first.wallAxes & (1 << axis)) note(resolver.resolveWall(i, axis));
            for (const auto& [j, axes] : first.blocks)
                for (int axis = 0; axis < 2; ++axis)
                    if (axes & (1 << axis)) note(resolver.resolvePair(i, j, axis));
            // Blocks hit by this one changed velocity: they may go further than they registered.
            for (int j : resolver.changed()) {
                const Block& b = blocks[j];
                const Aabb reach = ctx.path(j, b.position, b.size, b.velocity, ctx.h);
                if (!contains(grid.box(j), reach)) grid.set(j, reach);
            }
            resolver.clearChanged();
            // A bounce ends the turn (the rest of the step is lost, as in the lecture); so does
            // a "collision that is not really a collision". Only a resting contact lets it go on.
            if (bounced || !rested || moveBack) break;
        }
    }
    ctx.advanced = ctx.h;
}
