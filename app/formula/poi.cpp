#include "poi.h"

#include "collision.h"
#include "printed_formula.h"
#include "text_format.h"

#include <cmath>

namespace {

// The velocity a block moves with over the frame (semi-implicit Euler, lecture "Integration"):
// v + a·dt, with a everything the engine adds (gravity, the block's force, drag: accelerationOf).
Vec2 frameVelocity(const Block& b, const WorldSettings& s) {
    if (b.isDynamic()) return b.velocity + accelerationOf(s, b, s.dt) * s.dt;
    if (b.kind == BodyKind::Kinematic) return b.velocity;
    return {};
}

} // namespace

PoiView computePoi(const std::vector<Block>& before, const Bounds& bounds,
                   const WorldSettings& settings, double frameStart, int block) {
    PoiView p;
    if (block < 0 || block >= static_cast<int>(before.size()) || !(settings.dt > 0.0)) return p;
    const Block& me = before[static_cast<std::size_t>(block)];
    const double dt = settings.dt;
    const Vec2 v = frameVelocity(me, settings);
    const Aabb box = aabbOf(me);
    double best = kNever;
    std::uint8_t axes = 0;
    int other = 0;
    Vec2 otherVelocity; // a wall's: 0
    const WallImpact wall = timeOfWallImpact(box, v, bounds, dt);
    if (wall.hit()) {
        best = wall.time;
        axes = wall.axes;
        const int axis = (wall.axes & kAxisX) ? 0 : 1;
        other = wallOnAxis(axis, axis == 0 ? v.x : v.y);
    }
    for (std::size_t j = 0; j < before.size(); ++j) {
        if (static_cast<int>(j) == block) continue;
        const Block& o = before[j];
        const Vec2 vo = frameVelocity(o, settings);
        const Impact hit = timeOfImpact(box, v, aabbOf(o), vo, dt);
        if (hit.hit() && hit.time < best) {
            best = hit.time;
            axes = hit.axes;
            other = static_cast<int>(j);
            otherVelocity = vo;
        }
    }
    if (!axes || !std::isfinite(best)) return p;
    p.valid = true;
    p.block = block;
    p.other = other;
    p.axis = (axes & kAxisX) ? 0 : 1;
    p.frameStart = frameStart;
    p.dt = dt;
    p.size = me.size;
    p.velocity = v;
    p.oldPosition = me.position;
    p.newPosition = me.position + v * dt;
    p.t = best / dt;
    p.ghost = me.position + v * best;
    p.crooked = movedBackAlongAxis(p.newPosition, p.ghost, p.axis);
    // a and b are distances between the facing sides: they close at the relative speed (a block
    // at rest that is hit has moved nothing, yet its t is the mover's).
    const Vec2 closing = v - otherVelocity;
    const double speed = std::abs(p.axis == 0 ? closing.x : closing.y);
    p.a = speed * best;
    p.b = speed * dt;
    return p;
}

std::string poiEquation(const PoiView& p, bool units) {
    const char axis = p.axis == 0 ? 'x' : 'y';
    const auto formula = [&](int extra) { return printed(p.a, extra) / printed(p.b, extra); };
    const std::string equation = "t = a/b = " + equationWithFewestDigits(formula, p.t);
    return units ? equation + " of the frame   (a, b: m along " + axis + ")"
                 : equation + " of frame";
}
