// The turn-based method (lecture, "Turn-based Simulation" and "Tips – Collision Detection"):
// move the blocks one by one, in order, over the step or until their first collision, with the
// others held still; put the block at the point of impact (exact: t = a/b) and resolve at once,
// only if the relative velocity closes. No overlaps; collisions resolve in the right direction;
// positions are slightly off and depend on the order. A resting contact (the rest rule) does not
// end a block's turn, so a block can slide along a floor it rests on.
#include "collision.h"
#include "methods.h"
#include "scratch.h"

#include <vector>

namespace {

constexpr int kMaxRestingContactsPerTurn = 4;

struct FirstImpact {
    double time = kNever; // s into the block's remaining turn
    std::uint8_t wallAxes = 0;
    // Blocks hit at that same time, each with its axes.
    std::vector<std::pair<int, std::uint8_t>> blocks;
};

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

    const WallImpact wall = timeOfWallImpact(box, block.velocity, ctx.world.bounds, remaining);
    if (wall.hit()) {
        first.time = wall.time;
        first.wallAxes = wall.axes;
    }
    ctx.broadPhase.queryOthers(path, i, [&](int j) {
        // The others hold still: only a block the path reaches (touching counts) can be hit.
        const Aabb other = aabbOf(blocks[j]);
        if (other.min.x > path.max.x || other.max.x < path.min.x || other.min.y > path.max.y ||
            other.max.y < path.min.y)
            return;
        const Impact impact = timeOfImpact(box, block.velocity, other, Vec2{}, remaining);
        if (!impact.hit() || impact.time > first.time) return;
        if (impact.time < first.time) {
            first.time = impact.time;
            first.wallAxes = 0;
            first.blocks.clear();
        }
        first.blocks.emplace_back(j, impact.axes);
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
        return sweptAabb(blocks[i].position, blocks[i].size, blocks[i].velocity, ctx.h);
    });

    Resolver resolver(ctx);
    FirstImpact first;
    first.blocks.swap(ctx.scratch.firstImpactBlocks); // reuses the buffer, given back below
    for (int i = 0; i < n; ++i) {
        Block& block = blocks[i];
        if (block.kind == BodyKind::Static) continue;
        double elapsed = 0.0;
        for (int contact = 0; contact <= kMaxRestingContactsPerTurn; ++contact) {
            const double remaining = ctx.h - elapsed;
            const Aabb path = sweptAabb(block.position, block.size, block.velocity, remaining);
            if (!contains(grid.box(i), path)) grid.set(i, path);
            findFirstImpact(ctx, i, remaining, path, first);
            if (first.time == kNever) { // free flight for the rest of the step
                block.position += block.velocity * remaining;
                break;
            }
            // Point of impact: POI = oldPosition + t · velocity (lecture, "Point of Impact").
            block.position += block.velocity * first.time;
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
                const Aabb reach = sweptAabb(b.position, b.size, b.velocity, ctx.h);
                if (!contains(grid.box(j), reach)) grid.set(j, reach);
            }
            resolver.clearChanged();
            // A bounce ends the turn (the rest of the step is lost, as in the lecture); so does
            // a "collision that is not really a collision". Only a resting contact lets it go on.
            if (bounced || !rested) break;
        }
    }
    first.blocks.swap(ctx.scratch.firstImpactBlocks);
    ctx.advanced = ctx.h;
}
