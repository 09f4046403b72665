#include "velocity_space.h"

#include "text_format.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit vector along (sqrt(m1), sqrt(m2)): the direction block-block collisions keep.
Vec2 collisionLine(const VelocitySpacePair& pair) {
    const Vec2 n{std::sqrt(pair.m1), std::sqrt(pair.m2)};
    return n / length(n);
}

} // namespace

VelocitySpacePair velocitySpacePair(const World& world) {
    VelocitySpacePair pair;
    int dynamic = 0;
    int first = -1, second = -1;
    for (std::size_t i = 0; i < world.blocks.size(); ++i) {
        if (!world.blocks[i].isDynamic()) continue;
        ++dynamic;
        if (first < 0)
            first = static_cast<int>(i);
        else if (second < 0)
            second = static_cast<int>(i);
    }
    if (dynamic != 2) {
        pair.why = "Velocity space needs exactly two dynamic blocks; this scene has " +
                   std::to_string(dynamic) + ".";
        return pair;
    }
    pair.block1 = first;
    pair.block2 = second;
    pair.m1 = world.blocks[static_cast<std::size_t>(first)].mass;
    pair.m2 = world.blocks[static_cast<std::size_t>(second)].mass;
    return pair;
}

Vec2 velocitySpacePoint(const VelocitySpacePair& pair, double v1, double v2) {
    return {std::sqrt(pair.m1) * v1, std::sqrt(pair.m2) * v2};
}

double momentumOfPoint(const VelocitySpacePair& pair, Vec2 point) {
    return std::sqrt(pair.m1) * point.x + std::sqrt(pair.m2) * point.y;
}

double kineticEnergyOfPoint(Vec2 point) {
    return 0.5 * dot(point, point);
}

Vec2 reflectBlockCollision(const VelocitySpacePair& pair, Vec2 point, double C) {
    const Vec2 d = collisionLine(pair);
    const Vec2 along = d * dot(point, d); // the centre of mass's velocity: kept
    return along - (point - along) * C;   // w = v - u becomes -C·w
}

Vec2 reflectWallHit(Vec2 point, bool firstBlock, double C) {
    return firstBlock ? Vec2{-C * point.x, point.y} : Vec2{point.x, -C * point.y};
}

double reflectionAngle(const VelocitySpacePair& pair) {
    const double light = std::min(pair.m1, pair.m2), heavy = std::max(pair.m1, pair.m2);
    return std::atan(std::sqrt(light / heavy));
}

long long predictedCollisions(const VelocitySpacePair& pair) {
    return static_cast<long long>(std::ceil(kPi / reflectionAngle(pair))) - 1;
}

std::string velocitySpaceCount(const VelocitySpacePair& pair) {
    if (!pair.valid()) return pair.why;
    return "The reflection lines meet at theta = atan(sqrt(m_light/m_heavy)) = " +
           formatNumber(reflectionAngle(pair)) +
           " rad: a light block between a wall and the heavy one makes ceil(pi/theta) - 1 = " +
           std::to_string(predictedCollisions(pair)) + " collisions (C = 1).";
}

std::string velocitySpaceCaption(const VelocitySpacePair& pair) {
    if (!pair.valid()) return pair.why;
    return "Axes x = sqrt(m1)·v1, y = sqrt(m2)·v2 (along x). Circle: kinetic energy "
           "(2·KE = r²). Line: momentum (sqrt(m1)·x + sqrt(m2)·y = p). "
           "Each collision reflects the point: block on block across the dashed line along "
           "(sqrt(m1), sqrt(m2)) (C < 1 pulls it in toward it), a wall flips one axis. " +
           velocitySpaceCount(pair) + " For mass ratios 100^k, the digits of pi.";
}

void VelocitySpacePath::clear() {
    samples_.clear();
    pair_ = VelocitySpacePair{};
}

void VelocitySpacePath::push(const VelocitySpaceSample& s) {
    samples_.push_back(s);
    if (samples_.size() > kMaxSamples) samples_.pop_front();
}

void VelocitySpacePath::record(const World& world, const std::vector<CollisionRecord>& log) {
    const VelocitySpacePair pair = velocitySpacePair(world);
    if (pair.block1 != pair_.block1 || pair.block2 != pair_.block2 || pair.m1 != pair_.m1 ||
        pair.m2 != pair_.m2) {
        samples_.clear();
        pair_ = pair;
    }
    if (!pair_.valid()) return;
    // The frame's collisions in order, from the last state drawn.
    VelocitySpaceSample s = samples_.empty() ? VelocitySpaceSample{} : samples_.back();
    if (!samples_.empty()) {
        for (const CollisionRecord& r : log) {
            if (r.axis != 0) continue;
            bool changed = false;
            const auto set = [&changed](double& v, double value) {
                changed |= v != value;
                v = value;
            };
            if (r.block == pair_.block1) set(s.v1, r.v1After);
            if (r.block == pair_.block2) set(s.v2, r.v1After);
            if (r.other == pair_.block1) set(s.v1, r.v2After);
            if (r.other == pair_.block2) set(s.v2, r.v2After);
            if (!changed) continue;
            s.t = r.time;
            push(s);
        }
    }
    // The state at the end of the frame (what forces did besides).
    const double v1 = world.blocks[static_cast<std::size_t>(pair_.block1)].velocity.x;
    const double v2 = world.blocks[static_cast<std::size_t>(pair_.block2)].velocity.x;
    if (samples_.empty() || samples_.back().v1 != v1 || samples_.back().v2 != v2)
        push({world.time, v1, v2});
}

void VelocitySpacePath::truncateAfter(double t) {
    while (!samples_.empty() && samples_.back().t > t) samples_.pop_back();
}
