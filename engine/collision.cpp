#include "collision.h"

#include <algorithm>
#include <cmath>

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
    WallImpact impact;
    impact.time = std::min(times[0], times[1]);
    if (impact.time > maxTime) return {};
    if (times[0] == impact.time) impact.axes |= kAxisX;
    if (times[1] == impact.time) impact.axes |= kAxisY;
    return impact;
}

Wall wallOnAxis(int axis, double velocity) {
    if (axis == 0) return velocity > 0.0 ? kWallRight : kWallLeft;
    return velocity > 0.0 ? kWallTop : kWallBottom;
}
