// The move-and-correct method (lecture, "Move & Correct Method"): "just do it, clean up the mess
// later". Move all bodies over the whole step, then find overlapping pairs, push them apart along
// the axis of least penetration (shared by inverse mass), and resolve their velocities. Cheap;
// fast bodies tunnel through thin ones, and a deep overlap can be resolved in the wrong direction.
#include "collision.h"
#include "methods.h"
#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace {

// Share of a correction that block `self` takes: inverse masses, with infinite masses fixed
// unless both are infinite (a kinematic pushed out of a static block moves itself).
double correctionShare(const Block& self, const Block& other) {
    auto weight = [](const Block& b) { return b.isDynamic() ? 1.0 / b.mass : 0.0; };
    const double ws = weight(self), wo = weight(other);
    if (ws + wo > 0.0) return ws / (ws + wo);
    if (self.kind != BodyKind::Kinematic) return 0.0;
    return other.kind == BodyKind::Kinematic ? 0.5 : 1.0;
}

// The exact integrator's motion is a parabola: a block pushed back by `shift` (m) along `axis`
// against its acceleration `a` (out of a wall, a static or a kinematic block) is raised against
// that force, and the energy -m·a·shift this takes comes out of its speed along the axis (where
// its parabola passes that point, v² is less by 2·|a·shift|). Kept, it is energy the correction
// made: a block bouncing on the floor would climb higher every bounce (docs/physics.md, "Energy in
// piles"). After the resolve, so that the contact's normal change and its friction are those of
// the whole correction (a resting block's g·h).
void payForTheShift(Block& block, int axis, double a, double shift) {
    const double work = a * shift; // < 0: raised against the force
    if (!(work < 0.0)) return;
    const double v = block.velocity[axis];
    const double v2 = v * v + 2.0 * work;
    block.velocity[axis] = v2 > 0.0 ? std::copysign(std::sqrt(v2), v) : 0.0;
}

// Pushes a and b apart along the axis of least penetration and resolves their velocities.
// `bent`: the exact integrator's accelerations (null for the Euler integrators).
void correctPair(SubstepContext& ctx, Resolver& resolver, int a, int b,
                 const std::vector<Vec2>* bent) {
    Block& A = ctx.world.blocks[a];
    Block& B = ctx.world.blocks[b];
    const Vec2 extents = overlapExtents(aabbOf(A), aabbOf(B));
    if (extents.x <= 0.0 || extents.y <= 0.0) return; // an earlier correction separated them
    const int axis = extents.x < extents.y ? 0 : 1;
    const double depth = extents[axis];
    ctx.maxPenetrationSeen = std::max(ctx.maxPenetrationSeen, depth);
    // Push each block away from the other's centre: wrong when a fast block has passed it.
    const double direction = A.position[axis] <= B.position[axis] ? -1.0 : 1.0;
    const double shareA = correctionShare(A, B), shareB = correctionShare(B, A);
    A.position[axis] += direction * depth * shareA;
    B.position[axis] -= direction * depth * shareB;
    resolver.resolvePair(a, b, axis);
    // Between two finite masses the shares keep their centre of mass: no work against a uniform
    // force. Against an infinite mass the dynamic block alone moves.
    if (!bent) return;
    if (A.isDynamic() && !B.isDynamic())
        payForTheShift(A, axis, (*bent)[a][axis], direction * depth * shareA);
    if (B.isDynamic() && !A.isDynamic())
        payForTheShift(B, axis, (*bent)[b][axis], -direction * depth * shareB);
}

// Puts a block that sticks out of the bounds back on the wall, and bounces it off.
void correctWalls(SubstepContext& ctx, Resolver& resolver, int i, const std::vector<Vec2>* bent) {
    Block& block = ctx.world.blocks[i];
    const Bounds& bounds = ctx.world.bounds;
    // Most blocks touch no wall (every face strictly inside): nothing to correct.
    const Aabb start = aabbOf(block);
    if (start.min.x > bounds.min.x && start.min.y > bounds.min.y && start.max.x < bounds.max.x &&
        start.max.y < bounds.max.y)
        return;
    for (int axis = 0; axis < 2; ++axis) {
        const Aabb box = aabbOf(block);
        const double below = bounds.min[axis] - box.min[axis];
        const double above = box.max[axis] - bounds.max[axis];
        if (below > 0.0) block.position[axis] += below;
        if (above > 0.0) block.position[axis] -= above;
        ctx.maxPenetrationSeen = std::max({ctx.maxPenetrationSeen, below, above});
        const bool movingOut = (below >= 0.0 && block.velocity[axis] < 0.0) ||
                               (above >= 0.0 && block.velocity[axis] > 0.0);
        if (movingOut) resolver.resolveWall(i, axis);
        const double shift = below > 0.0 ? below : above > 0.0 ? -above : 0.0;
        if (bent) payForTheShift(block, axis, (*bent)[i][axis], shift);
    }
}

} // namespace

void advanceMoveAndCorrect(SubstepContext& ctx) {
    std::vector<Block>& blocks = ctx.world.blocks;
    const int n = static_cast<int>(blocks.size());

    // 1. Move all bodies over the whole step: position += velocity · h (with the exact
    //    integrator along the parabola, position += v·h + a·h²/2, velocity += a·h).
    for (int i = 0; i < n; ++i) {
        Block& b = blocks[i];
        if (b.kind == BodyKind::Static) continue;
        b.position = ctx.positionAfter(i, b.position, b.velocity, ctx.h);
        b.velocity = ctx.velocityAfter(i, b.velocity, ctx.h);
    }
    // The motion is done: contacts are found after a whole step, as after an Euler step, so they
    // are resolved as then (the rest rule keeps its margin for what the step added).
    const std::vector<Vec2>* bent = ctx.acceleration;
    ctx.acceleration = nullptr;

    // 2. Find the overlapping pairs at the new positions.
    BroadPhase& grid = ctx.broadPhase;
    grid.build(ctx.world.bounds, blocks, [&](int i) { return aabbOf(blocks[i]); });
    std::vector<std::pair<int, int>>& pairs = ctx.scratch.overlappingPairs;
    pairs.clear();
    grid.forEachOverlappingPair([&](int a, int b) {
        if (blocks[a].kind != BodyKind::Static || blocks[b].kind != BodyKind::Static)
            pairs.emplace_back(std::min(a, b), std::max(a, b));
    });
    // Correct in index order, whatever order the grid found the pairs in.
    std::sort(pairs.begin(), pairs.end());

    // 3. Correct the overlaps and resolve the collisions, then the walls.
    Resolver resolver(ctx);
    resolver.setNow(ctx.h);
    for (const auto& [a, b] : pairs) correctPair(ctx, resolver, a, b, bent);
    for (int i = 0; i < n; ++i)
        if (blocks[i].kind != BodyKind::Static) correctWalls(ctx, resolver, i, bent);
    ctx.advanced = ctx.h;
}
