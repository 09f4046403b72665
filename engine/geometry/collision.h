// Collision math for axis-aligned blocks as small pure functions (lecture, "Collisions: detect and
// resolve", "Point of Impact for AABBs" and "Collisions on a Line – Full Formula").
#pragma once

#include "world.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

struct Aabb {
    Vec2 min; // m
    Vec2 max; // m
};

inline Aabb aabbOf(Vec2 position, Vec2 size) {
    return {position - size * 0.5, position + size * 0.5};
}
inline Aabb aabbOf(const Block& block) {
    return aabbOf(block.position, block.size);
}
// The box covering a block's motion from `position` over `time` seconds at `velocity`.
inline Aabb sweptAabb(Vec2 position, Vec2 size, Vec2 velocity, double time) {
    const Vec2 half = size * 0.5, end = position + velocity * time;
    return {{std::min(position.x, end.x) - half.x, std::min(position.y, end.y) - half.y},
            {std::max(position.x, end.x) + half.x, std::max(position.y, end.y) + half.y}};
}
inline bool contains(const Aabb& outer, const Aabb& inner) {
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && outer.max.x >= inner.max.x &&
           outer.max.y >= inner.max.y;
}

// Lecture slide "AABB collision detection": P and Q overlap iff P.right > Q.left,
// P.left < Q.right, P.top > Q.bottom and P.bottom < Q.top. Touching faces do not overlap.
// Without branches (non-short-circuit &), like meets() below: the broad phases test pairs that
// pass one comparison and fail another in no predictable order.
inline bool overlaps(const Aabb& p, const Aabb& q) {
    return (p.max.x > q.min.x) & (p.min.x < q.max.x) & (p.max.y > q.min.y) & (p.min.y < q.max.y);
}
// How far the boxes overlap along each axis (m); a component <= 0 means no overlap on that axis.
inline Vec2 overlapExtents(const Aabb& p, const Aabb& q) {
    return {std::min(p.max.x, q.max.x) - std::max(p.min.x, q.min.x),
            std::min(p.max.y, q.max.y) - std::max(p.min.y, q.min.y)};
}
// Penetration depth (m): the smaller axis overlap, or 0 when the boxes do not overlap.
double penetration(const Aabb& p, const Aabb& q);
// How far a box sticks out of the bounds (m), 0 when inside (touching a wall is inside).
double outsideDepth(const Aabb& box, const Bounds& bounds);

// Bits of Impact::axes: the collision axis. A corner hit (equal entry times) sets both.
constexpr std::uint8_t kAxisX = 1;
constexpr std::uint8_t kAxisY = 2;
constexpr double kNever = std::numeric_limits<double>::infinity();
// m: faces closer than this touch. Positions at a time of impact agree only to rounding, so a
// block resting on another may overlap it by 1e-16 m; that is contact, not penetration.
constexpr double kTouchTolerance = 1e-9;

// The broad phases' test: boxes that touch, or miss each other by less than kTouchTolerance (a
// box computed one way may differ by rounding from the same box computed another, and no contact
// may be lost). Without branches (non-short-circuit &): near pairs pass one test and fail another
// in no predictable order.
inline bool meets(const Aabb& a, const Aabb& b) {
    constexpr double t = kTouchTolerance;
    return (a.max.x >= b.min.x - t) & (a.min.x <= b.max.x + t) & (a.max.y >= b.min.y - t) &
           (a.min.y <= b.max.y + t);
}

// How box b touches box a face to face along `axis`: +1 when b's lower face lies on a's upper
// face (within kTouchTolerance), -1 when b's upper face lies on a's lower face, 0 otherwise
// (apart, or side by side: overlapping by no more than kTouchTolerance along the other axis).
inline int faceContact(const Aabb& a, const Aabb& b, int axis) {
    const int other = 1 - axis;
    const double sideOverlap =
        std::min(a.max[other], b.max[other]) - std::max(a.min[other], b.min[other]);
    if (sideOverlap <= kTouchTolerance) return 0;
    if (std::abs(b.min[axis] - a.max[axis]) <= kTouchTolerance) return 1;
    if (std::abs(a.min[axis] - b.max[axis]) <= kTouchTolerance) return -1;
    return 0;
}

struct Impact {
    double time = kNever;  // s from now until the faces first touch
    std::uint8_t axes = 0; // kAxisX | kAxisY; 0 when there is no impact
    bool hit() const { return axes != 0; }
};

// Time of impact of two moving boxes within [0, maxTime] (lecture, "Point of Impact (POI)
// Calculation": t = a/b, per axis). Per axis the faces meet at t_enter = gap / closing speed and
// part at t_exit; the boxes touch when the later entry comes before the earlier exit, and the
// collision axis is the one whose entry comes last while the other overlaps. Boxes already
// touching or overlapping by rounding on the entry axis report time 0. Only approaching motion
// counts: boxes at rest relative to each other never collide, and faces that meet while the
// other axis overlaps by no more than kTouchTolerance and does not close (a block sliding along
// another it rests on, an edge graze) do not collide either.
Impact timeOfImpact(const Aabb& a, Vec2 velocityA, const Aabb& b, Vec2 velocityB, double maxTime);

struct WallImpact {
    double time = kNever;  // s from now
    std::uint8_t axes = 0; // which walls: kAxisX (left or right), kAxisY (bottom or top)
    bool hit() const { return axes != 0; }
};
// Time at which a moving box first touches a wall of the bounds, within [0, maxTime]; a box
// already touching a wall and moving into it reports time 0.
// Inline: most boxes stay well inside the walls over the window, and then no division is needed;
// timeOfWallImpactNearWalls (collision.cpp) does the rest.
WallImpact timeOfWallImpactNearWalls(const Aabb& box, Vec2 velocity, const Bounds& bounds,
                                     double maxTime);
inline WallImpact timeOfWallImpact(const Aabb& box, Vec2 velocity, const Bounds& bounds,
                                   double maxTime) {
    const Vec2 travel = velocity * maxTime;
    if (box.min.x + std::min(travel.x, 0.0) > bounds.min.x &&
        box.max.x + std::max(travel.x, 0.0) < bounds.max.x &&
        box.min.y + std::min(travel.y, 0.0) > bounds.min.y &&
        box.max.y + std::max(travel.y, 0.0) < bounds.max.y)
        return {};
    return timeOfWallImpactNearWalls(box, velocity, bounds, maxTime);
}
// The wall a box moving with `velocity` hits along `axis` (its sign picks the side).
Wall wallOnAxis(int axis, double velocity);

// The lecture's crooked result ("BAD: no exact point of impact"): the block moved the whole step
// to newPosition, then back out of the overlap along the collision axis only, to the point of
// impact's coordinate on that axis; the other axis keeps the whole step's motion.
inline Vec2 movedBackAlongAxis(Vec2 newPosition, Vec2 pointOfImpact, int axis) {
    Vec2 p = newPosition;
    p[axis] = pointOfImpact[axis];
    return p;
}

// ---- Constant acceleration: the exact integrator's parabolas (lecture, "Integration": the true
// movement is a parabola, not piecewise linear). With zero acceleration each function below
// gives exactly (bit for bit) its linear counterpart above. ----

// Position and velocity `t` seconds on from (p, v) under acceleration a: p + v·t + a·t²/2, v + a·t.
inline Vec2 positionAfter(Vec2 p, Vec2 v, Vec2 a, double t) {
    return p + v * t + a * (0.5 * t * t);
}
inline Vec2 velocityAfter(Vec2 v, Vec2 a, double t) {
    return v + a * t;
}
// The box covering a block's parabola over [0, time]: both ends and, per axis, the turning point
// (t = -v/a) when it falls inside.
Aabb sweptAabb(Vec2 position, Vec2 size, Vec2 velocity, Vec2 acceleration, double time);
// Time of impact of two boxes moving with constant accelerations, within [0, maxTime]: per axis the
// faces meet at the roots of gap = v·t + a·t²/2 (t = a/b when a = 0), so a box can enter, leave
// and enter again; the impact is the first instant both axes overlap, its axis the one that
// entered last. Touching boxes that accelerate into each other with no relative velocity (a block
// resting on a static one, under gravity) report time 0. With equal accelerations the motion
// relative to each other is linear: then this is timeOfImpact above.
Impact timeOfImpact(const Aabb& a, Vec2 velocityA, Vec2 accelerationA, const Aabb& b,
                    Vec2 velocityB, Vec2 accelerationB, double maxTime);
// The same for a box and the walls (infinite masses at rest).
WallImpact timeOfWallImpact(const Aabb& box, Vec2 velocity, Vec2 acceleration, const Bounds& bounds,
                            double maxTime);
