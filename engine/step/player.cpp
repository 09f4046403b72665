#include "player.h"

#include "collision.h"

PlayerKeys scriptedKeys(const std::vector<ScriptedKeys>& script, double t, double dt) {
    constexpr double slack = 1e-9; // s: frame start times are sums of dt and carry rounding
    PlayerKeys held;
    for (const ScriptedKeys& s : script) {
        const double end = s.at + (s.duration > 0.0 ? s.duration : dt);
        if (t < s.at - slack || t >= end - slack) continue;
        held.left |= s.keys.left;
        held.right |= s.keys.right;
        held.up |= s.keys.up;
    }
    return held;
}

int standsOn(const World& world, int i) {
    const Aabb box = aabbOf(world.blocks[static_cast<size_t>(i)]);
    if (box.min.y - world.bounds.min.y <= kTouchTolerance) return kFloorBelow;
    for (size_t j = 0; j < world.blocks.size(); ++j) {
        if (static_cast<int>(j) == i) continue;
        if (faceContact(box, aabbOf(world.blocks[j]), 1) == -1) return static_cast<int>(j);
    }
    return kNothingBelow;
}

namespace {

bool controllable(const World& world, const PlayerDef& player) {
    return player.block >= 0 && player.block < static_cast<int>(world.blocks.size()) &&
           world.blocks[static_cast<size_t>(player.block)].isDynamic();
}

} // namespace

Vec2 playerPush(const World& world, const PlayerDef& player, PlayerKeys keys) {
    if (!controllable(world, player)) return {};
    const double direction = (keys.right ? 1.0 : 0.0) - (keys.left ? 1.0 : 0.0);
    return {direction * player.force, 0.0};
}

Vec2 applyPlayerKeys(World& world, const PlayerDef& player, PlayerKeys keys) {
    if (!controllable(world, player)) return {};
    if (keys.up) {
        const int below = standsOn(world, player.block);
        if (below != kNothingBelow) {
            // A jump: launched at `jump` relative to its support (a lift moving up adds its own
            // speed), it rises jump²/(2·|g|) above where it left (lecture, "Integration").
            const double support =
                below >= 0 ? world.blocks[static_cast<size_t>(below)].velocity.y : 0.0;
            world.blocks[static_cast<size_t>(player.block)].velocity.y = support + player.jump;
        }
    }
    return playerPush(world, player, keys);
}

StepStats stepWithPlayer(World& world, const PlayerDef& player, PlayerKeys keys,
                         std::vector<CollisionRecord>* log) {
    const Vec2 push = applyPlayerKeys(world, player, keys);
    if (push == Vec2{}) return world.step(log);
    Block& b = world.blocks[static_cast<size_t>(player.block)];
    const Vec2 own = b.force;
    b.force = own + push;
    StepStats stats = world.step(log);
    world.blocks[static_cast<size_t>(player.block)].force = own;
    return stats;
}
