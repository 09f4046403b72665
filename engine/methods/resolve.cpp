#include "resolve.h"

#include "collision.h"

#include <algorithm>

Impact SubstepContext::impactWithOptions(int i, const Aabb& a, Vec2 va, int j, const Aabb& b,
                                         Vec2 vb, double maxTime) const {
    const Impact hit = acceleration ? timeOfImpact(a, va, (*acceleration)[i], b, vb,
                                                   j >= 0 ? (*acceleration)[j] : Vec2{}, maxTime)
                                    : timeOfImpact(a, va, b, vb, maxTime);
    if (!hit.hit() || !world.settings.has(Mistake::Discrete)) return hit;
    // Mistake "discrete" (lecture, "Discrete can give errors with high velocities: tunneling"):
    // a collision is seen only if the boxes overlap at the new positions, at the end of the
    // window; a fast block that has passed a thin one is never seen.
    const Vec2 sizeA = a.max - a.min, sizeB = b.max - b.min;
    const Vec2 endA = positionAfter(i, (a.min + a.max) * 0.5, va, maxTime);
    const Vec2 endB =
        j >= 0 ? positionAfter(j, (b.min + b.max) * 0.5, vb, maxTime) : (b.min + b.max) * 0.5;
    return overlaps(aabbOf(endA, sizeA), aabbOf(endB, sizeB)) ? hit : Impact{};
}

Resolver::Resolver(SubstepContext& context, const BlockFinder* finder, ResolveHooks* hooks)
    : ctx_(context), finder_(finder), hooks_(hooks) {}

// The rest rule: closing speeds below restSpeed + 2·|g|·h are what gravity alone adds to a
// resting contact within one substep (g·h), with a margin; they are resolved perfectly inelastic.
// With the exact integrator no margin is needed: a resting contact is found by its closing
// acceleration (approaching() below), so only the Zeno tail of a bounce below restSpeed is cut
// short (see docs/scene-format.md for the bound on the time this loses).
// With friction the forces along the axis include what friction adds in a substep, up to
// μ·|g| (g across the axis): a block pressed by gravity onto a support that slides along the
// axis closes on its neighbours that fast without any collision.
double Resolver::restThreshold(int axis) const {
    const WorldSettings& s = ctx_.world.settings;
    if (ctx_.acceleration) return s.restSpeed;
    const double frictional =
        ctx_.friction ? ctx_.maxFriction * std::abs(s.gravity[1 - axis]) : 0.0;
    return s.restSpeed + 2.0 * (std::abs(s.gravity[axis]) + frictional) * ctx_.h;
}

// Whether a and b approach along `axis` (lecture, "Tips – Collision Resolve": check the relative
// velocity); `closing` (m/s) is the speed at which they close. With the exact integrator, touching
// bodies without relative velocity that accelerate into each other (a block resting on another
// under gravity) approach too, at closing speed 0: a resting contact.
bool Resolver::approaching(int a, int b, int axis, double& closing) const {
    const Block& A = ctx_.world.blocks[a];
    const Block& B = ctx_.world.blocks[b];
    const bool aIsLower = A.position[axis] <= B.position[axis];
    closing = aIsLower ? A.velocity[axis] - B.velocity[axis] : B.velocity[axis] - A.velocity[axis];
    if (closing > 0.0) return true;
    if (closing < 0.0 || !ctx_.acceleration) return false;
    const double accelA = (*ctx_.acceleration)[a][axis], accelB = (*ctx_.acceleration)[b][axis];
    return aIsLower ? accelA > accelB : accelB > accelA;
}

void Resolver::setAcceleration(int i, int axis, double a) {
    Vec2& acceleration = (*ctx_.acceleration)[i];
    if (acceleration[axis] == a) return;
    acceleration[axis] = a;
    changed_.push_back(i); // its path changed: the perfect method predicts it again
}

void Resolver::setVelocity(int i, int axis, double v) {
    Vec2& velocity = ctx_.world.blocks[i].velocity;
    if (velocity[axis] == v) return;
    if (hooks_) hooks_->velocityChanging(i, axis, velocity[axis]);
    velocity[axis] = v;
    changed_.push_back(i);
}

// Resolver::bounce with the exact integrator: a collision or friction (not the rest rule's merge)
// has changed block i's velocity along `axis`. Its acceleration along the axis is then its forces'
// again: a support that held it (the rest rule's acceleration 0 on the floor) holds nothing it
// moves away from, and kept, that 0 would carry it up without gravity's deceleration, making
// energy (m·g·v per second; docs/physics.md, "Energy in piles"). If it still presses on what it
// touches, the contact comes again at this instant and the rest rule holds it again. With friction
// its slides change too (releaseSlides, friction.cpp).
void Resolver::freeAcceleration(int i, int axis) {
    if (!ctx_.world.blocks[i].isDynamic()) return;
    if (ctx_.slides) {
        releaseSlides(i, axis);
        return;
    }
    setAcceleration(i, axis, (*ctx_.forces)[i][axis]);
}

void Resolver::reverseKinematic(int i, int axis) {
    const Block& b = ctx_.world.blocks[i];
    if (b.kind == BodyKind::Kinematic) setVelocity(i, axis, -b.velocity[axis]);
}

void Resolver::record(int a, int b, int axis, double m1, double v1, double m2, double v2, double u,
                      double C, double v1After, double v2After, ResolveRule rule) {
    const bool rest = rule >= ResolveRule::RestFree;
    // One count of collisions: a resting contact (the rest rule) is counted apart, so a settled
    // pile's collision count stands still.
    ++(rest ? ctx_.stats.contacts : ctx_.stats.collisions);
    if (!ctx_.log) return;
    CollisionRecord r;
    r.time = ctx_.startTime + now_;
    r.toi = ctx_.h > 0.0 ? now_ / ctx_.h : 0.0;
    r.block = a;
    r.other = b;
    r.axis = axis;
    r.m1 = m1, r.m2 = m2, r.v1 = v1, r.v2 = v2, r.u = u, r.C = C;
    r.v1After = v1After, r.v2After = v2After, r.rest = rest;
    r.rule = rule;
    if (rest) r.restBodies = static_cast<int>(queue_.size()), r.restForced = forceRest_;
    r.mu = note_.mu, r.dvn = note_.dvn, r.dvt = note_.dvt, r.perSecond = note_.perSecond;
    r.position1 = ctx_.world.blocks[a].position;
    if (b >= 0) {
        r.position2 = ctx_.world.blocks[b].position;
        r.firstBelow = r.position1[axis] <= r.position2[axis];
    }
    ctx_.log->push_back(r);
}

Resolution Resolver::resolvePair(int a, int b, int axis, RestRule rest) {
    forceRest_ = rest == RestRule::Always;
    note_ = FrictionNote{};
    sync(a);
    sync(b);
    std::vector<Block>& blocks = ctx_.world.blocks;
    const Block& A = blocks[a];
    const Block& B = blocks[b];
    const WorldSettings& settings = ctx_.world.settings;
    // Resolve only when they approach along the axis (lecture, "Tips – Collision Resolve"),
    // unless the mistake "no-approach-test" is made: then separating bodies are resolved too.
    double closing = 0.0;
    const bool approach = approaching(a, b, axis, closing);
    if (!approach && !settings.has(Mistake::NoApproachTest)) return Resolution::None;

    const double m1 = A.mass, m2 = B.mass;
    const double v1 = A.velocity[axis], v2 = B.velocity[axis];
    if (!A.isDynamic() && !B.isDynamic()) {
        // Two infinite masses: a kinematic block reverses, as on hitting a wall.
        reverseKinematic(a, axis);
        reverseKinematic(b, axis);
        record(a, b, axis, m1, v1, m2, v2, 0.0, 1.0, A.velocity[axis], B.velocity[axis],
               ResolveRule::Reverse);
        return Resolution::Bounce;
    }
    if (forceRest_ || (approach && closing < restThreshold(axis)))
        return restCluster(a, b, axis, Wall{0});

    const double C = settings.bounciness;
    // Without Newton (resolve "reflect"): each body reverses its own component as off a wall at
    // rest, v' = -C·v, whatever the other's mass and velocity: momentum is not conserved.
    // Against an infinite mass both resolves are the same: u is that body's velocity.
    const bool reflect = settings.resolve == Resolve::Reflect && A.isDynamic() && B.isDynamic();
    const double u = reflect ? 0.0 : centerOfMassVelocity(m1, v1, m2, v2);
    const double v1After = A.isDynamic() ? velocityAfterCollision(v1, u, C) : v1;
    const double v2After = B.isDynamic() ? velocityAfterCollision(v2, u, C) : v2;
    bounce(a, axis, v1After);
    bounce(b, axis, v2After);
    if (ctx_.friction) contactFriction(a, b, axis, std::abs((v1After - v2After) - (v1 - v2)));
    record(a, b, axis, m1, v1, m2, v2, u, C, v1After, v2After,
           reflect ? ResolveRule::Reflect : ResolveRule::Formula);
    return Resolution::Bounce;
}

Resolution Resolver::resolveWall(int a, int axis, RestRule rest) {
    forceRest_ = rest == RestRule::Always;
    note_ = FrictionNote{};
    sync(a);
    const Block& A = ctx_.world.blocks[a];
    const double v = A.velocity[axis];
    // At rest against a wall, with the exact integrator: it accelerates into the wall.
    const double into = v != 0.0 || !ctx_.acceleration ? v : (*ctx_.acceleration)[a][axis];
    if (into == 0.0 || A.kind == BodyKind::Static) return Resolution::None;
    const Wall wall = wallOnAxis(axis, into);
    if (A.kind == BodyKind::Kinematic) {
        reverseKinematic(a, axis);
        record(a, wall, axis, A.mass, v, kInfiniteMass, 0.0, 0.0, 1.0, -v, 0.0,
               ResolveRule::Reverse);
        return Resolution::Bounce;
    }
    if (forceRest_ || std::abs(v) < restThreshold(axis)) return restCluster(a, -1, axis, wall);
    // A wall has infinite mass and u = 0, so v' = -C·v (lecture, "Bounce elasticity").
    const double C = ctx_.world.settings.bounciness;
    const double after = velocityAfterCollision(v, 0.0, C);
    bounce(a, axis, after);
    if (ctx_.friction) contactFriction(a, wall, axis, std::abs(after - v));
    record(a, wall, axis, A.mass, v, kInfiniteMass, 0.0, 0.0, C, after, 0.0, ResolveRule::Formula);
    return Resolution::Bounce;
}

void Resolver::findNear(const Aabb& box) {
    found_.clear();
    if (finder_)
        finder_->find(box, found_);
    else
        ctx_.broadPhase.query(box, [&](int j) { found_.push_back(j); });
}

bool Resolver::caughtBetweenInfiniteMasses(int seed, int axis) {
    std::vector<Block>& blocks = ctx_.world.blocks;
    const Bounds& bounds = ctx_.world.bounds;
    inCluster_.resize(blocks.size(), 0);
    queue_.assign(1, seed);
    inCluster_[seed] = 1;
    bool below = false, above = false;
    for (size_t q = 0; q < queue_.size() && !(below && above); ++q) {
        const int i = queue_[q];
        sync(i);
        const Aabb box = aabbOf(blocks[i]);
        below |= box.min[axis] - bounds.min[axis] <= kTouchTolerance;
        above |= bounds.max[axis] - box.max[axis] <= kTouchTolerance;
        Aabb probe = box;
        probe.min[axis] -= kTouchTolerance;
        probe.max[axis] += kTouchTolerance;
        findNear(probe);
        for (int j : found_) {
            if (inCluster_[j]) continue;
            sync(j);
            const int side = faceContact(box, aabbOf(blocks[j]), axis);
            if (side == 0) continue; // apart, or side by side
            if (!blocks[j].isDynamic()) {
                (side > 0 ? above : below) = true;
                continue;
            }
            inCluster_[j] = 1;
            queue_.push_back(j);
        }
    }
    for (int j : queue_) inCluster_[j] = 0;
    return below && above;
}

// A slow contact: the seed bodies and everything touching them along the axis that does not
// part from them (a resting stack, a block on a platform) move on together as one perfectly
// inelastic body: every dynamic member takes the cluster's centre-of-mass velocity u, or the
// velocity of the infinite masses it rests on. Infinite masses anchor the cluster; the search
// does not pass through them. Anchors that disagree (a platform pressing the cluster against a
// wall, two platforms squeezing it) crush it: the platforms that press reverse, as on a wall.
//
// The answer does not depend on the order in which the search meets the bodies: which bodies
// belong is a property of each touching pair (the velocities do not change during the search),
// a platform presses if it closes on any member, and the sums run over the members sorted by
// index.
Resolution Resolver::restCluster(int seedA, int seedB, int axis, Wall seedWall) {
    std::vector<Block>& blocks = ctx_.world.blocks;
    const Bounds& bounds = ctx_.world.bounds;
    const double threshold = restThreshold(axis);
    const size_t changedBefore = changed_.size();
    inCluster_.resize(blocks.size(), 0);
    members_.clear();
    queue_.clear();
    kinematics_.clear();
    touches_.clear();
    // The static anchors (walls, static blocks) below and above the cluster.
    bool staticBelow = seedWall == kWallLeft || seedWall == kWallBottom;
    bool staticAbove = seedWall == kWallRight || seedWall == kWallTop;

    // `closing` > 0: the pair of j and the member that found it approaches; `above`: j lies
    // above that member along the axis.
    auto add = [&](int j, double closing, bool above) {
        const Block& b = blocks[j];
        if (b.kind == BodyKind::Static) {
            (above ? staticAbove : staticBelow) = true;
            return;
        }
        if (inCluster_[j]) {
            if (b.kind == BodyKind::Kinematic)
                for (Anchor& k : kinematics_)
                    if (k.block == j) {
                        k.presses |= closing > 0.0;
                        (above ? k.above : k.below) = true;
                    }
            return;
        }
        inCluster_[j] = 1;
        members_.push_back(j);
        if (b.isDynamic())
            queue_.push_back(j);
        else
            kinematics_.push_back({j, closing > 0.0, !above, above});
    };
    const double v1 = blocks[seedA].velocity[axis];
    const double v2 = seedB >= 0 ? blocks[seedB].velocity[axis] : 0.0;
    // The seed pair approaches (resolvePair and resolveWall checked); each lies on one side of
    // the other.
    const bool bAboveA = seedB >= 0 && blocks[seedB].position[axis] > blocks[seedA].position[axis];
    add(seedA, 1.0, seedB >= 0 && !bAboveA);
    if (seedB >= 0) add(seedB, 1.0, bAboveA);

    for (size_t q = 0; q < queue_.size(); ++q) {
        const int i = queue_[q];
        const Aabb box = aabbOf(blocks[i]);
        const double vi = blocks[i].velocity[axis];
        Aabb probe = box;
        probe.min[axis] -= kTouchTolerance;
        probe.max[axis] += kTouchTolerance;
        findNear(probe);
        for (int j : found_) {
            if (inCluster_[j] && blocks[j].isDynamic()) {
                // Friction: a member not searched from yet touches this one (once per pair).
                if (ctx_.friction && inCluster_[j] == 1) touch(i, box, j, axis);
                continue;
            }
            sync(j);
            const int side = faceContact(box, aabbOf(blocks[j]), axis);
            if (side == 0) continue; // apart, or side by side: not resting on each other
            const double vj = blocks[j].velocity[axis];
            const bool above = side > 0;                      // j is on top of i
            const double closing = above ? vi - vj : vj - vi; // > 0: they press together
            // A body that parts, or closes faster than a resting contact, is not resting on the
            // cluster: its contact is a collision of its own (unless the method forces the rest).
            if (closing > -threshold && (forceRest_ || closing < threshold)) {
                add(j, closing, above);
                if (ctx_.friction) touch(i, box, j, axis);
            }
        }
        // Walls are infinite masses at rest.
        if (box.min[axis] - bounds.min[axis] <= kTouchTolerance && vi < threshold) {
            staticBelow = true;
            if (ctx_.friction)
                touches_.push_back(
                    {i, wallOnAxis(axis, -1.0), -1, box.max[1 - axis] - box.min[1 - axis]});
        }
        if (bounds.max[axis] - box.max[axis] <= kTouchTolerance && vi > -threshold) {
            staticAbove = true;
            if (ctx_.friction)
                touches_.push_back(
                    {i, wallOnAxis(axis, 1.0), 1, box.max[1 - axis] - box.min[1 - axis]});
        }
        if (ctx_.friction) inCluster_[i] = 2; // searched from
    }
    std::sort(members_.begin(), members_.end());
    std::sort(queue_.begin(), queue_.end());
    std::sort(kinematics_.begin(), kinematics_.end(),
              [](const Anchor& x, const Anchor& y) { return x.block < y.block; });

    // The anchors (infinite masses) and their velocities along the axis: 0 for walls and static
    // blocks, else the platforms'. The cluster moves with them when they agree.
    double u = 0.0;
    const bool restsOnStatic = staticBelow || staticAbove;
    bool anchored = restsOnStatic, jammed = false;
    for (const Anchor& k : kinematics_) {
        const double vk = blocks[k.block].velocity[axis];
        if (!anchored) {
            anchored = true;
            u = vk;
        } else if (vk != u) {
            jammed = true;
        }
    }
    if (!anchored || jammed) {
        double momentum = 0.0, mass = 0.0;
        for (int j : queue_) { // the dynamic members, by index
            momentum += blocks[j].mass * blocks[j].velocity[axis];
            mass += blocks[j].mass;
        }
        u = momentum / mass;
    }
    if (jammed) {
        // Anchors that disagree crush the cluster: the platforms that press on it reverse, and
        // it moves as freely as the anchors on its two sides let it (no faster toward one below
        // than it moves, nor toward one above).
        double lowest = staticBelow ? 0.0 : -kInfiniteMass;
        double highest = staticAbove ? 0.0 : kInfiniteMass;
        for (const Anchor& k : kinematics_) {
            if (k.presses) reverseKinematic(k.block, axis);
            const double vk = blocks[k.block].velocity[axis];
            if (k.below) lowest = std::max(lowest, vk);
            if (k.above) highest = std::min(highest, vk);
        }
        u = lowest <= highest ? std::min(std::max(u, lowest), highest) : 0.5 * (lowest + highest);
    }
    if (ctx_.friction) { // what friction needs of the merge: each dynamic member's before
        velocityBefore_.clear();
        accelBefore_.clear();
        for (int j : queue_) {
            velocityBefore_.push_back(blocks[j].velocity[axis]);
            accelBefore_.push_back(ctx_.acceleration ? (*ctx_.acceleration)[j][axis] : 0.0);
        }
    }
    for (int j : members_) {
        if (blocks[j].isDynamic()) setVelocity(j, axis, u);
        inCluster_[j] = 0;
    }
    // With the exact integrator the members also move on together: with the acceleration of
    // their anchors (0: walls, static and kinematic blocks do not accelerate), or, free, with the
    // cluster's own (total force over total mass) when the members' differ.
    if (ctx_.acceleration) {
        double a = 0.0;
        if (!anchored) {
            // From the forces on the members (ctx_.forces), not their accelerations now: a
            // member that an earlier contact held (its acceleration 0 on a support it has left)
            // is free again, and a held acceleration would take gravity's work off the cluster.
            const std::vector<Vec2>& free = *ctx_.forces;
            double force = 0.0, mass = 0.0;
            bool same = true;
            for (int j : queue_) {
                force += blocks[j].mass * free[j][axis];
                mass += blocks[j].mass;
                same &= free[j][axis] == free[queue_.front()][axis];
            }
            a = same ? free[queue_.front()][axis] : force / mass;
            if (ctx_.slides) a = freeClusterAcceleration(axis, u, a);
        }
        for (int j : queue_) setAcceleration(j, axis, a);
    }
    if (ctx_.friction && !repeated_) {
        bool below = staticBelow, above = staticAbove;
        for (const Anchor& k : kinematics_) below |= k.below, above |= k.above;
        clusterFriction(axis, below, above, seedA, seedB >= 0 ? seedB : seedWall);
    }
    const double m2 = seedB >= 0 ? blocks[seedB].mass : kInfiniteMass;
    const ResolveRule rule = jammed     ? ResolveRule::RestCrushed
                             : anchored ? ResolveRule::RestAnchored
                                        : ResolveRule::RestFree;
    record(seedA, seedB >= 0 ? seedB : seedWall, axis, blocks[seedA].mass, v1, m2, v2, u, 0.0,
           blocks[seedA].velocity[axis], seedB >= 0 ? blocks[seedB].velocity[axis] : 0.0, rule);
    return changed_.size() > changedBefore ? Resolution::Rest : Resolution::None;
}
