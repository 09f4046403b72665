// What the lecture's rules would give in one frame (rule_candidates.h).
#include "rule_candidates.h"

#include "collision.h"
#include "resolve.h"

Vec2 frameVelocityOf(const Block& b, const WorldSettings& s) {
    if (b.isDynamic()) return b.velocity + accelerationOf(s, b, s.dt) * s.dt;
    if (b.kind == BodyKind::Kinematic) return b.velocity;
    return {};
}

Candidates candidatesFor(const std::vector<Block>& before, const WorldSettings& s, int i, int other,
                         int axis, double C) {
    const Block& me = before[static_cast<std::size_t>(i)];
    const double v = frameVelocityOf(me, s)[axis];
    double m2 = kInfiniteMass, v2 = 0.0;
    if (other >= 0) {
        const Block& o = before[static_cast<std::size_t>(other)];
        m2 = o.mass;
        v2 = frameVelocityOf(o, s)[axis];
    }
    const double u = centerOfMassVelocity(me.mass, v, m2, v2);
    return {velocityAfterCollision(v, u, C), -C * v, v};
}

std::vector<Touch> touchesInFrame(const std::vector<Block>& before, const Bounds& bounds,
                                  const WorldSettings& s, int i) {
    std::vector<Touch> touches;
    const Block& me = before[static_cast<std::size_t>(i)];
    const Vec2 v = frameVelocityOf(me, s);
    const Aabb box = aabbOf(me);
    for (int axis = 0; axis < 2; ++axis) { // each wall the block moves toward
        if (v[axis] == 0.0) continue;
        const double gap =
            v[axis] > 0.0 ? bounds.max[axis] - box.max[axis] : box.min[axis] - bounds.min[axis];
        const double t = gap / (std::abs(v[axis]) * s.dt);
        if (t >= 0.0 && t <= 1.0) touches.push_back({wallOnAxis(axis, v[axis]), axis, t});
    }
    for (std::size_t j = 0; j < before.size(); ++j) {
        if (static_cast<int>(j) == i) continue;
        const Aabb other = aabbOf(before[j]);
        Impact hit = timeOfImpact(box, v, other, frameVelocityOf(before[j], s), s.dt);
        if (!hit.hit()) hit = timeOfImpact(box, v, other, Vec2{}, s.dt);
        for (int axis = 0; axis < 2; ++axis)
            if (hit.axes & (1 << axis))
                touches.push_back({static_cast<int>(j), axis, hit.time / s.dt});
    }
    return touches;
}
