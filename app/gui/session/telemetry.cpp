#include "telemetry.h"

std::size_t Telemetry::bytes() const {
    return velocity.bytes() + momentum.bytes() + energy.bytes() +
           (collisionTimes.size() + watchedCollisionTimes.size()) * sizeof(double) +
           recent.size() * sizeof(CollisionRecord) + velocitySpace.bytes();
}

void Telemetry::clear() {
    velocity.clear();
    momentum.clear();
    energy.clear();
    collisionTimes.clear();
    watchedCollisionTimes.clear();
    recent.clear();
    velocitySpace.clear();
    watched = -1;
}

int watchedBlock(const World& world, int selected) {
    const int n = static_cast<int>(world.blocks.size());
    if (selected >= 0 && selected < n) return selected;
    for (int i = 0; i < n; ++i) {
        if (world.blocks[static_cast<std::size_t>(i)].isDynamic()) return i;
    }
    return -1;
}

void Telemetry::record(const World& world, int selected, const std::vector<CollisionRecord>& log) {
    const int w = watchedBlock(world, selected);
    if (w != watched) {
        velocity.clear();
        watchedCollisionTimes.clear();
        watched = w;
    }
    if (w >= 0) {
        const Vec2 v = world.blocks[static_cast<std::size_t>(w)].velocity;
        const double vv[2] = {v.x, v.y};
        velocity.push(world.time, vv);
    }
    velocitySpace.record(world, log);
    const Vec2 p = totalMomentum(world);
    const double pp[2] = {p.x, p.y};
    momentum.push(world.time, pp);
    const double ke = kineticEnergy(world), pe = potentialEnergy(world);
    const double e[3] = {ke, pe, ke + pe};
    energy.push(world.time, e);
    for (const CollisionRecord& r : log) {
        if (r.rest) continue;
        collisionTimes.push_back(r.time);
        if (collisionTimes.size() > kCollisionMarkers) collisionTimes.pop_front();
        if (r.block == w || r.other == w) {
            watchedCollisionTimes.push_back(r.time);
            if (watchedCollisionTimes.size() > kCollisionMarkers) watchedCollisionTimes.pop_front();
        }
        recent.push_back(r);
        if (recent.size() > kRecentCollisions) recent.pop_front();
    }
}

void Telemetry::truncateAfter(double t) {
    velocity.truncateAfter(t);
    momentum.truncateAfter(t);
    energy.truncateAfter(t);
    while (!collisionTimes.empty() && collisionTimes.back() > t) collisionTimes.pop_back();
    while (!watchedCollisionTimes.empty() && watchedCollisionTimes.back() > t) {
        watchedCollisionTimes.pop_back();
    }
    while (!recent.empty() && recent.back().time > t) recent.pop_back();
    velocitySpace.truncateAfter(t);
}
