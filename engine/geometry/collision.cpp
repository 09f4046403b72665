#include "collision.h"

#include <algorithm>
#include <cmath>
#include <utility>

double penetration(const Aabb& p, const Aabb& q) {
    const Vec2 extents = overlapExtents(p, q);
    if (extents.x <= 0.0 || extents.y <= 0.0) return 0.0;
    return std::min(extents.x, extents.y);
}

double outsideDepth(const Aabb& box, const Bounds& bounds) {
    return std::max({0.0, bounds.min.x - box.min.x, box.max.x - bounds.max.x,
                     bounds.min.y - box.min.y, box.max.y - bounds.max.y});
}

namespace {

// Entry and exit time of two intervals moving apart or together along one axis.
struct AxisTimes {
    double enter = -kNever;
    double exit = kNever;
    double gap = 0.0; // m between the faces that meet first (negative when overlapping)
};

// Returns false when the intervals never overlap (apart and not approaching, or merely touching
// with no relative motion along this axis).
bool axisTimes(double minA, double maxA, double minB, double maxB, double relativeVelocity,
               AxisTimes& out) {
    if (relativeVelocity > 0.0) { // A moves toward +axis relative to B: A.max meets B.min
        out.gap = minB - maxA;
        out.enter = out.gap / relativeVelocity;
        out.exit = (maxB - minA) / relativeVelocity;
        return true;
    }
    if (relativeVelocity < 0.0) { // A.min meets B.max
        out.gap = minA - maxB;
        out.enter = out.gap / -relativeVelocity;
        out.exit = (minB - maxA) / relativeVelocity;
        return true;
    }
    // No relative motion: they overlap on this axis for all time, or never.
    out.gap = -kNever;
    return maxA > minB && minA < maxB;
}

// The wall impact from the time to the wall on each axis: the earlier, both on a tie.
WallImpact earliestWall(const double times[2], double maxTime) {
    WallImpact impact;
    impact.time = std::min(times[0], times[1]);
    if (impact.time > maxTime) return {};
    if (times[0] == impact.time) impact.axes |= kAxisX;
    if (times[1] == impact.time) impact.axes |= kAxisY;
    return impact;
}

} // namespace

Impact timeOfImpact(const Aabb& a, Vec2 velocityA, const Aabb& b, Vec2 velocityB, double maxTime) {
    const Vec2 relative = velocityA - velocityB;
    AxisTimes x, y;
    if (!axisTimes(a.min.x, a.max.x, b.min.x, b.max.x, relative.x, x)) return {};
    if (!axisTimes(a.min.y, a.max.y, b.min.y, b.max.y, relative.y, y)) return {};

    const double enter = std::max(x.enter, y.enter);
    const double exit = std::min(x.exit, y.exit);
    // Faces meet later than they part, or after the window, or the boxes are already parting.
    if (enter >= exit || enter > maxTime || exit <= 0.0) return {};

    // The collision axis is the one whose entry comes last; a tie is a corner hit. Entry times
    // that agree to rounding (relative 1e-12) count as a tie so symmetric scenes stay symmetric.
    const double tieTolerance = 1e-12 * std::max(1.0, std::abs(enter));
    Impact impact;
    impact.time = std::max(enter, 0.0);
    if (x.enter >= enter - tieTolerance) impact.axes |= kAxisX;
    if (y.enter >= enter - tieTolerance) impact.axes |= kAxisY;
    if (enter <= 0.0) {
        // Already touching (or overlapping by rounding): a real contact only on an axis along
        // which A moves toward B's centre; otherwise they are parting and nothing happens.
        const Vec2 towardB = (b.min + b.max) - (a.min + a.max);
        if (towardB.x * relative.x <= 0.0) impact.axes &= ~kAxisX;
        if (towardB.y * relative.y <= 0.0) impact.axes &= ~kAxisY;
        if (impact.axes == 0) return {};
    }
    if (impact.axes == kAxisX || impact.axes == kAxisY) {
        const int other = impact.axes == kAxisX ? 1 : 0;
        const double shift = relative[other] * impact.time;
        const double overlap = std::min(a.max[other] + shift, b.max[other]) -
                               std::max(a.min[other] + shift, b.min[other]);
        const double towardB = (b.min[other] + b.max[other]) - (a.min[other] + a.max[other]);
        if (overlap <= kTouchTolerance && !(relative[other] * towardB > 0.0)) return {};
    }
    return impact;
}

WallImpact timeOfWallImpactNearWalls(const Aabb& box, Vec2 velocity, const Bounds& bounds,
                                     double maxTime) {
    double times[2] = {kNever, kNever};
    for (int axis = 0; axis < 2; ++axis) {
        const double v = velocity[axis];
        // Distance from the leading face to the wall ahead (lecture: "Boundary collision").
        if (v > 0.0) times[axis] = std::max(0.0, bounds.max[axis] - box.max[axis]) / v;
        if (v < 0.0) times[axis] = std::max(0.0, box.min[axis] - bounds.min[axis]) / -v;
    }
    return earliestWall(times, maxTime);
}

Wall wallOnAxis(int axis, double velocity) {
    if (axis == 0) return velocity > 0.0 ? kWallRight : kWallLeft;
    return velocity > 0.0 ? kWallTop : kWallBottom;
}

// ---- Constant acceleration ----

namespace {

// Real roots of a2·t² + b·t + c = 0, ascending; returns how many (a double root counts once).
// The form without cancellation: q = -(b + sign(b)·sqrt(b² - 4·a2·c))/2, roots q/a2 and c/q.
int quadraticRoots(double a2, double b, double c, double roots[2]) {
    if (a2 == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double discriminant = b * b - 4.0 * a2 * c;
    if (discriminant < 0.0) return 0;
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    if (q == 0.0) { // b = 0 and c = 0
        roots[0] = 0.0;
        return 1;
    }
    roots[0] = q / a2;
    roots[1] = c / q;
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return roots[0] == roots[1] ? 1 : 2;
}

// The first time in [0, maxTime] at which gap(t) = c + b·t + a2·t² reaches 0 while falling (a face
// reaching a wall); 0 when it already touches (c <= 0) and moves or accelerates into it.
double firstContact(double c, double b, double a2, double maxTime) {
    if (c <= 0.0 && (b < 0.0 || (b == 0.0 && a2 < 0.0))) return 0.0;
    double roots[2];
    const int n = quadraticRoots(a2, b, c, roots);
    for (int k = 0; k < n; ++k)
        if (roots[k] > 0.0 && roots[k] <= maxTime && b + 2.0 * a2 * roots[k] < 0.0) return roots[k];
    return kNever;
}

// Whether two intervals [lo, hi] shifted by s overlap with positive length along one axis:
// gl < s < gh with gl = b.min - a.max, gh = b.max - a.min.
bool axisOverlaps(double gl, double gh, double s) {
    return s > gl && s < gh;
}

} // namespace

Aabb sweptAabb(Vec2 position, Vec2 size, Vec2 velocity, Vec2 acceleration, double time) {
    if (acceleration == Vec2{}) return sweptAabb(position, size, velocity, time);
    const Vec2 half = size * 0.5;
    const Vec2 end = positionAfter(position, velocity, acceleration, time);
    Aabb box{{std::min(position.x, end.x), std::min(position.y, end.y)},
             {std::max(position.x, end.x), std::max(position.y, end.y)}};
    for (int axis = 0; axis < 2; ++axis) {
        if (acceleration[axis] == 0.0) continue;
        const double turn = -velocity[axis] / acceleration[axis];
        if (turn > 0.0 && turn < time) {
            const double x =
                position[axis] + velocity[axis] * turn + 0.5 * acceleration[axis] * turn * turn;
            box.min[axis] = std::min(box.min[axis], x);
            box.max[axis] = std::max(box.max[axis], x);
        }
    }
    return {box.min - half, box.max + half};
}

Impact timeOfImpact(const Aabb& a, Vec2 velocityA, Vec2 accelerationA, const Aabb& b,
                    Vec2 velocityB, Vec2 accelerationB, double maxTime) {
    const Vec2 acceleration = accelerationA - accelerationB;
    if (acceleration == Vec2{}) return timeOfImpact(a, velocityA, b, velocityB, maxTime);
    const Vec2 velocity = velocityA - velocityB;
    // A's displacement relative to B: s(t) = v·t + a·t²/2; per axis they overlap for gl < s < gh.
    auto shift = [&](int axis, double t) {
        return velocity[axis] * t + 0.5 * acceleration[axis] * t * t;
    };
    const Vec2 gl = b.min - a.max, gh = b.max - a.min;
    // Every instant at which a face meets a face on either axis cuts [0, maxTime] into pieces
    // within which the overlap on each axis does not change; the first piece in which both axes
    // overlap starts at the impact.
    double cuts[10];
    std::uint8_t cutAxes[10];
    int n = 0;
    cuts[n] = 0.0, cutAxes[n++] = 0;
    for (int axis = 0; axis < 2; ++axis) {
        for (const double face : {gl[axis], gh[axis]}) {
            double roots[2];
            const int k = quadraticRoots(0.5 * acceleration[axis], velocity[axis], -face, roots);
            for (int r = 0; r < k; ++r)
                if (roots[r] > 0.0 && roots[r] <= maxTime)
                    cuts[n] = roots[r], cutAxes[n++] = static_cast<std::uint8_t>(1 << axis);
        }
    }
    cuts[n] = maxTime, cutAxes[n++] = 0;
    // Sort by time (at most 10 entries).
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) {
            std::swap(cuts[j], cuts[j - 1]);
            std::swap(cutAxes[j], cutAxes[j - 1]);
        }
    for (int i = 0; i + 1 < n; ++i) {
        if (!(cuts[i + 1] > cuts[i])) continue;
        const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
        if (!axisOverlaps(gl.x, gh.x, shift(0, mid)) || !axisOverlaps(gl.y, gh.y, shift(1, mid)))
            continue;
        Impact impact;
        impact.time = cuts[i];
        const Vec2 towardB = (b.min + b.max) - (a.min + a.max);
        if (impact.time == 0.0) {
            // Touching (or overlapping by rounding) at the start: a contact on the axes along
            // which A moves, or with no relative velocity accelerates, toward B's centre; of two,
            // the one overlapping less (the face that met last).
            for (int axis = 0; axis < 2; ++axis) {
                const double motion = velocity[axis] != 0.0 ? velocity[axis] : acceleration[axis];
                if (motion * towardB[axis] > 0.0)
                    impact.axes |= static_cast<std::uint8_t>(1 << axis);
            }
            if (impact.axes == (kAxisX | kAxisY)) {
                const Vec2 extents = overlapExtents(a, b);
                if (extents.x < extents.y) impact.axes = kAxisX;
                if (extents.y < extents.x) impact.axes = kAxisY;
            }
            if (impact.axes == 0) continue; // parting now; they may meet again later
        } else {
            // The axes whose faces met at this instant (within rounding: a corner hit).
            const double tie = 1e-12 * std::max(1.0, impact.time);
            for (int j = 0; j < n; ++j)
                if (std::abs(cuts[j] - impact.time) <= tie) impact.axes |= cutAxes[j];
            if (impact.axes == 0) continue;
        }
        if (impact.axes == kAxisX || impact.axes == kAxisY) {
            // An edge graze, as in the linear timeOfImpact: no collision.
            const int other = impact.axes == kAxisX ? 1 : 0;
            const double s = shift(other, impact.time);
            const double overlap =
                std::min(a.max[other] + s, b.max[other]) - std::max(a.min[other] + s, b.min[other]);
            const double closing = velocity[other] + acceleration[other] * impact.time;
            if (overlap <= kTouchTolerance && !(closing * towardB[other] > 0.0)) continue;
        }
        return impact;
    }
    return {};
}

WallImpact timeOfWallImpact(const Aabb& box, Vec2 velocity, Vec2 acceleration, const Bounds& bounds,
                            double maxTime) {
    if (acceleration == Vec2{}) return timeOfWallImpact(box, velocity, bounds, maxTime);
    double times[2];
    for (int axis = 0; axis < 2; ++axis) {
        const double v = velocity[axis], a2 = 0.5 * acceleration[axis];
        // The lower face down to the lower wall, the upper face up to the upper wall.
        const double down = firstContact(box.min[axis] - bounds.min[axis], v, a2, maxTime);
        const double up = firstContact(bounds.max[axis] - box.max[axis], -v, -a2, maxTime);
        times[axis] = std::min(down, up);
    }
    return earliestWall(times, maxTime);
}
