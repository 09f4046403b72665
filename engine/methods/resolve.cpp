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
    if (b >= 0) {
        r.firstBelow = ctx_.world.blocks[a].position[axis] <= ctx_.world.blocks[b].position[axis];
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
    setVelocity(a, axis, v1After);
    setVelocity(b, axis, v2After);
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
    setVelocity(a, axis, after);
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
        const std::vector<Vec2>& accel = *ctx_.acceleration;
        double a = 0.0;
        if (!anchored) {
            double force = 0.0, mass = 0.0;
            bool same = true;
            for (int j : queue_) {
                force += blocks[j].mass * accel[j][axis];
                mass += blocks[j].mass;
                same &= accel[j][axis] == accel[queue_.front()][axis];
            }
            a = same ? accel[queue_.front()][axis] : force / mass;
            if (ctx_.slides) a = freeClusterAcceleration(axis, u, a);
        }
        for (int j : queue_) setAcceleration(j, axis, a);
    }
    if (ctx_.friction) {
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

// ---- Friction ----
//
// Coulomb friction, one coefficient μ for static and kinetic friction (lecture, "Application:
// Platformer": "moving platforms, friction, pushing objects"; the grading rubric's "collision
// friction"). "Practical Application - Blocks" applies the formula to one component of the
// velocity and keeps the other; with friction the other changes too, toward the other body's:
//   |Δv_t| <= μ·|Δv_n|, never past v_t,rel = 0,
// both relative velocities (t along the contact's face, n across it). As impulses: the contact's
// normal impulse J_n = |Δv_n| / (1/m1 + 1/m2) bounds the friction impulse,
//   J_t = min(μ·J_n, |v_t,rel| / (1/m1 + 1/m2)),   v_t' = v_t ∓ J_t/m for each body,
// so momentum is kept and the relative sliding only slows: friction never makes energy. Walls,
// static and kinematic blocks have infinite mass (1/m = 0): they are the reference, and what
// rests on a moving platform is carried. A pair's μ is sqrt(μ1·μ2) (Box2D's mixing rule), a
// block's its own "friction" or the world's, a wall's the world's.
//
// Resting contacts (the rest rule) give friction too: what the contact absorbed along its axis
// is the normal change (with the Euler integrators g·h per substep for a block on the floor, so
// it slides to rest at μ·g), and the loads pass down a stack to what it rests on (the floor under
// two crates carries both). With the exact integrator a resting contact absorbs an acceleration
// instead (a force N = m·g for a block on the floor): a block sliding on an infinite mass then
// decelerates at μ·N/m until it has the support's velocity (stopTime(): an event of the perfect
// method, a stop within a turn for turn-based), and after that static friction holds it up to
// μ·N/m (Slide). Between two dynamic blocks the absorbed force acts as an impulse N·(h - now) for
// the rest of the substep.

double Resolver::frictionOf(int body) const {
    const double world = ctx_.world.settings.friction;
    if (body < 0) return world;
    const double own = ctx_.world.blocks[body].friction;
    return own >= 0.0 ? own : world;
}

double Resolver::inverseMass(int body) const {
    if (body < 0) return 0.0;
    const Block& b = ctx_.world.blocks[body];
    return b.isDynamic() ? 1.0 / b.mass : 0.0;
}

double Resolver::velocityOf(int body, int axis) const {
    return body < 0 ? 0.0 : ctx_.world.blocks[body].velocity[axis];
}

// The friction impulse at the contact of a and b (b a block or a Wall) along `tangent`, bounded
// by μ·jn (N·s); returns the change of their relative velocity along it (m/s).
double Resolver::frictionImpulse(int a, int b, int tangent, double mu, double jn) {
    const double wa = inverseMass(a), wb = inverseMass(b);
    if (!(mu > 0.0 && jn > 0.0) || wa + wb == 0.0) return 0.0;
    const double va = velocityOf(a, tangent), vb = velocityOf(b, tangent), rel = va - vb;
    const double jt = mu * jn;
    // A change below the rest speed is none (as the rest rule takes such a closing for rest):
    // else the tail of a chain of contacts at one instant, each one's friction closing the next,
    // would go on without end in ever smaller steps.
    if (std::min(jt * (wa + wb), std::abs(rel)) < ctx_.world.settings.restSpeed) return 0.0;
    if (jt * (wa + wb) >= std::abs(rel)) {
        // They stop sliding: the same velocity (an infinite mass's, or the pair's centre of mass').
        const double common = wa == 0.0   ? va
                              : wb == 0.0 ? vb
                                          : centerOfMassVelocity(1.0 / wa, va, 1.0 / wb, vb);
        if (wa > 0.0) setVelocity(a, tangent, common);
        if (wb > 0.0) setVelocity(b, tangent, common);
        return std::abs(rel);
    }
    const double direction = rel > 0.0 ? 1.0 : -1.0;
    if (wa > 0.0) setVelocity(a, tangent, va - direction * jt * wa);
    if (wb > 0.0) setVelocity(b, tangent, vb + direction * jt * wb);
    return jt * (wa + wb);
}

// The friction of a bounce that changed the relative velocity along `axis` by dvn (m/s).
void Resolver::contactFriction(int a, int b, int axis, double dvn) {
    const double w = inverseMass(a) + inverseMass(b);
    if (w == 0.0) return;
    const double mu = frictionOf(a, b);
    note_ = {mu, dvn, frictionImpulse(a, b, 1 - axis, mu, dvn / w), false};
}

// Block i's friction along `tangent` on the infinite mass it rests on (its Slide, whose limit is
// set): kinetic, against its sliding, or static, holding it up to the limit.
void Resolver::slideFriction(int i, int tangent) {
    Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(i) + tangent];
    const double applied = (*ctx_.acceleration)[i][tangent] - slide.accel; // without friction
    const double rel = ctx_.world.blocks[i].velocity[tangent] - velocityOf(slide.support, tangent);
    if (rel != 0.0)
        slide.accel = rel > 0.0 ? -slide.limit : slide.limit;
    else
        slide.accel = -std::min(std::max(applied, -slide.limit), slide.limit);
    setAcceleration(i, tangent, applied + slide.accel);
}

double SubstepContext::stopTime(int i, int axis, double velocity) const {
    if (!slides) return kNever;
    const Slide& slide = (*slides)[2 * static_cast<size_t>(i) + axis];
    if (!slide.on) return kNever;
    const double rel =
        velocity - (slide.support < 0 ? 0.0 : world.blocks[slide.support].velocity[axis]);
    const double a = (*acceleration)[i][axis];
    if (rel == 0.0 || a == 0.0 || (rel > 0.0) == (a > 0.0)) return kNever;
    return -rel / a;
}

Resolution Resolver::stopSliding(int i, int axis) {
    sync(i);
    const size_t changedBefore = changed_.size();
    const Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(i) + axis];
    setVelocity(i, axis, velocityOf(slide.support, axis));
    slideFriction(i, axis); // now static (or kinetic the other way, if what drives it is stronger)
    return changed_.size() > changedBefore ? Resolution::Rest : Resolution::None;
}

// Notes the contact of member i (box `box`) with block j along `axis`, if they touch there.
void Resolver::touch(int i, const Aabb& box, int j, int axis) {
    const Aabb other = aabbOf(ctx_.world.blocks[j]);
    const int side = faceContact(box, other, axis);
    if (side == 0) return;
    const int t = 1 - axis;
    const double overlap = std::min(box.max[t], other.max[t]) - std::max(box.min[t], other.min[t]);
    touches_.push_back({i, j, side, overlap});
}

// The exact integrator's acceleration of a free cluster (no anchor along `axis`) moving at u,
// with the friction its members meet on the infinite masses they rest on along the other axis:
// kinetic where the cluster slides on them, static (together, up to the sum of the limits) where
// it does not. Each member's Slide keeps its share.
double Resolver::freeClusterAcceleration(int axis, double u, double withoutFriction) {
    std::vector<Slide>& slides = *ctx_.slides;
    const std::vector<Vec2>& accel = *ctx_.acceleration;
    const std::vector<Block>& blocks = ctx_.world.blocks;
    double force = 0.0, mass = 0.0, holding = 0.0;
    bool any = false;
    for (int j : queue_) {
        Slide& slide = slides[2 * static_cast<size_t>(j) + axis];
        const double m = blocks[j].mass;
        mass += m;
        if (!slide.on) {
            force += m * accel[j][axis];
            continue;
        }
        any = true;
        force += m * (accel[j][axis] - slide.accel);
        const double rel = u - velocityOf(slide.support, axis);
        if (rel != 0.0)
            force -= (rel > 0.0 ? 1.0 : -1.0) * m * slide.limit;
        else
            holding += m * slide.limit;
    }
    if (!any) return withoutFriction;
    // Static friction takes up to `holding` of what drives the cluster.
    const double held = std::min(std::max(force, -holding), holding);
    for (int j : queue_) {
        Slide& slide = slides[2 * static_cast<size_t>(j) + axis];
        if (!slide.on) continue;
        const double rel = u - velocityOf(slide.support, axis);
        if (rel != 0.0)
            slide.accel = rel > 0.0 ? -slide.limit : slide.limit;
        else
            slide.accel = holding > 0.0 ? -held / holding * slide.limit : 0.0;
    }
    return (force - held) / mass;
}

// The friction of a merged cluster's contacts along `axis` (see "Friction" above). The loads:
// each dynamic member's momentum change (and, exact, the force its contacts take). Anchored on
// one side, each member passes its load and what it carries to the bodies that hold it on that
// side, shared by the widths they touch (a stack passes its weight down to the floor); otherwise
// (free, or squeezed from both sides) each contact carries what its two bodies' changes say.
void Resolver::clusterFriction(int axis, bool below, bool above, int seedA, int seedOther) {
    const int tangent = 1 - axis;
    const std::vector<Block>& blocks = ctx_.world.blocks;
    const bool exact = ctx_.slides && ctx_.acceleration;
    const size_t n = queue_.size();
    auto slot = [&](int body) -> int { // its place in queue_ (sorted), or -1
        if (body < 0) return -1;
        const auto it = std::lower_bound(queue_.begin(), queue_.end(), body);
        return it != queue_.end() && *it == body ? static_cast<int>(it - queue_.begin()) : -1;
    };
    impulseLoad_.assign(n, 0.0);
    forceLoad_.assign(n, 0.0);
    changeLoad_.assign(n, 0.0);
    for (size_t k = 0; k < n; ++k) {
        const int j = queue_[k];
        const double m = blocks[j].mass;
        impulseLoad_[k] = m * (blocks[j].velocity[axis] - velocityBefore_[k]);
        if (!exact) continue;
        const double a = (*ctx_.acceleration)[j][axis];
        forceLoad_[k] = m * (a - (*ctx_.forces)[j][axis]);
        changeLoad_[k] = m * (a - accelBefore_[k]);
    }
    std::sort(touches_.begin(), touches_.end(), [](const Touch& x, const Touch& y) {
        return x.block != y.block ? x.block < y.block : x.other < y.other;
    });
    carried_.clear();
    order_.clear();
    if (below != above) {
        // Members from the farthest from the anchors, each passing its loads to its holders.
        const int down = below ? -1 : 1;
        const double sign = below ? 1.0 : -1.0; // a load that presses on the holder is positive
        for (size_t k = 0; k < n; ++k) order_.push_back(static_cast<int>(k));
        std::sort(order_.begin(), order_.end(), [&](int x, int y) {
            const double px = blocks[queue_[x]].position[axis];
            const double py = blocks[queue_[y]].position[axis];
            return px != py ? (below ? px > py : px < py) : x < y;
        });
        rank_.assign(n, 0);
        for (size_t r = 0; r < n; ++r) rank_[order_[r]] = static_cast<int>(r);
        for (const Touch& c : touches_) {
            if (c.side == down)
                carried_.push_back({c.block, c.other, c.width, 0.0, 0.0, 0.0});
            else if (slot(c.other) >= 0)
                carried_.push_back({c.other, c.block, c.width, 0.0, 0.0, 0.0});
        }
        std::stable_sort(carried_.begin(), carried_.end(), [&](const Carried& x, const Carried& y) {
            return rank_[slot(x.held)] < rank_[slot(y.held)];
        });
        for (size_t first = 0, last = 0; first < carried_.size(); first = last) {
            const int k = slot(carried_[first].held);
            double width = 0.0;
            for (last = first;
                 last < carried_.size() && carried_[last].held == carried_[first].held; ++last)
                width += carried_[last].width;
            if (!(width > 0.0)) continue;
            for (size_t c = first; c < last; ++c) {
                Carried& touch = carried_[c];
                const double share = touch.width / width;
                const int s = slot(touch.support);
                if (s >= 0) {
                    impulseLoad_[s] += impulseLoad_[k] * share;
                    forceLoad_[s] += forceLoad_[k] * share;
                    changeLoad_[s] += changeLoad_[k] * share;
                }
                touch.jn = std::max(0.0, sign * impulseLoad_[k] * share);
                touch.fn = std::max(0.0, sign * forceLoad_[k] * share);
                touch.fd = std::max(0.0, sign * changeLoad_[k] * share);
            }
        }
    } else {
        for (const Touch& c : touches_) {
            const int k = slot(c.block), s = slot(c.other);
            const double w = inverseMass(c.block) + inverseMass(c.other);
            auto carries = [&](const std::vector<double>& load) {
                const double other = s >= 0 ? load[s] * inverseMass(c.other) : 0.0;
                return std::abs(load[k] * inverseMass(c.block) - other) / w;
            };
            carried_.push_back({c.block, c.other, c.width, carries(impulseLoad_),
                                carries(forceLoad_), carries(changeLoad_)});
        }
    }

    // The friction: impulses, and with the exact integrator the slides on infinite masses.
    if (exact)
        for (int j : queue_) {
            Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(j) + tangent];
            slide.on = false;
            slide.limit = 0.0;
        }
    const double rest = ctx_.h - now_; // s: the substep left
    const Carried* seed = nullptr;
    double seedDvt = 0.0;
    for (const Carried& c : carried_) {
        const double mu = frictionOf(c.held, c.support);
        const bool infinite = inverseMass(c.support) == 0.0;
        const double jn = c.jn + (exact && !infinite ? c.fd * rest : 0.0);
        const double dvt = frictionImpulse(c.held, c.support, tangent, mu, jn);
        if (exact && infinite && c.fn > 0.0 && mu > 0.0) {
            Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(c.held) + tangent];
            if (!slide.on) slide.support = c.support;
            slide.on = true;
            slide.limit += mu * c.fn * inverseMass(c.held);
        }
        if ((c.held == seedA && c.support == seedOther) ||
            (c.held == seedOther && c.support == seedA)) {
            seed = &c;
            seedDvt = dvt;
        }
    }
    if (exact)
        for (int j : queue_) {
            Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(j) + tangent];
            if (slide.on) {
                slideFriction(j, tangent);
            } else if (slide.accel != 0.0) { // no longer resting on an infinite mass
                setAcceleration(j, tangent, (*ctx_.acceleration)[j][tangent] - slide.accel);
                slide.accel = 0.0;
            }
        }
    if (!seed) return;
    const double mu = frictionOf(seed->held, seed->support);
    const double w = inverseMass(seed->held) + inverseMass(seed->support);
    const bool infinite = inverseMass(seed->support) == 0.0;
    if (exact && infinite && seed->fn > 0.0) {
        // A deceleration: the seed's share of the block's friction (m/s^2).
        const Slide& slide = (*ctx_.slides)[2 * static_cast<size_t>(seed->held) + tangent];
        const double dvn = seed->fn * w;
        note_ = {mu, dvn, slide.limit > 0.0 ? std::abs(slide.accel) * mu * dvn / slide.limit : 0.0,
                 true};
    } else {
        note_ = {mu, (seed->jn + (exact && !infinite ? seed->fd * rest : 0.0)) * w, seedDvt, false};
    }
}
