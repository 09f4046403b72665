// Collision resolve (lecture, "Collisions on a Line – Full Formula"), shared by the three methods:
// the formula on one axis, pair and wall contacts, infinite masses, and the rest rule.
#pragma once

#include "broad_phase.h"
#include "collision.h"
#include "stats.h"
#include "world.h"

#include <cmath>
#include <utility>
#include <vector>

// Velocity of the centre of mass along one axis (lecture, "Momentum"):
// u = (m1·v1 + m2·v2) / (m1 + m2). With one infinite mass (a wall, static or kinematic block),
// u is that body's velocity.
inline double centerOfMassVelocity(double m1, double v1, double m2, double v2) {
    if (std::isinf(m1)) return v1;
    if (std::isinf(m2)) return v2;
    return (m1 * v1 + m2 * v2) / (m1 + m2);
}

// Velocity after a collision on a line with bounciness C (lecture): v' = u - C·(v - u).
inline double velocityAfterCollision(double v, double u, double C) {
    return u - C * (v - u);
}

struct StepScratch;

// With friction and the exact integrator, how a block slides along one axis on the infinite masses
// (walls, static and kinematic blocks) it rests on: friction is then a constant deceleration
// within the substep, which ends when the block has the same velocity as its support
// (friction.cpp). One per block and axis, reset every substep.
struct Slide {
    bool on = false;    // it rests on an infinite mass along the other axis
    int support = 0;    // that body: a block index, or a Wall (negative)
    double limit = 0.0; // m/s^2: μ·N/m, the most friction can change its acceleration
    double accel = 0.0; // m/s^2: friction's part of its acceleration along the axis now
};

// What one substep of a method works with: the world, the buffers it may reuse (scratch.h; its
// broad phase), the statistics and log.
struct SubstepContext {
    World& world;
    StepScratch& scratch;
    BroadPhase& broadPhase; // scratch.broadPhase
    StepStats& stats;
    std::vector<CollisionRecord>* log; // may be null
    double h;                          // s, substep length
    double startTime;                  // s, world time at the start of the substep
    double advanced = 0.0;             // s, how far the method got (h unless the cap was hit)
    bool capHit = false;               // the perfect method's event cap ended the substep
    double maxPenetrationSeen = 0.0;   // m, overlap the method met (move-and-correct)
    // m/s^2 per block over this substep: the exact integrator's constant accelerations (the rest
    // rule zeroes them for supported blocks). Null for the Euler integrators: motion is linear.
    std::vector<Vec2>* acceleration = nullptr;
    // The exact integrator: each block's forces' acceleration at the substep's start (what moves
    // it when nothing holds it; null for the Euler integrators).
    const std::vector<Vec2>* forces = nullptr;
    // Friction (friction.cpp): some μ > 0 (else no friction code runs: the results are those
    // without it, bit for bit). With the exact integrator also each block's slides (2 per block:
    // x, y).
    bool friction = false;
    double maxFriction = 0.0; // the largest μ of the world and its blocks
    std::vector<Slide>* slides = nullptr;

    // How blocks move within the substep and where the methods detect impacts: the methods call
    // these instead of the linear formulas, so the integrator and the mistake "discrete" are
    // read here only.
    // Linear motion and no mistakes: the methods' inner loops may call the linear formulas.
    bool plain() const { return !acceleration && !world.settings.mistakes; }
    Vec2 accelerationOf(int i) const { return acceleration ? (*acceleration)[i] : Vec2{}; }
    Vec2 positionAfter(int i, Vec2 p, Vec2 v, double t) const {
        return acceleration ? ::positionAfter(p, v, (*acceleration)[i], t) : p + v * t;
    }
    Vec2 velocityAfter(int i, Vec2 v, double t) const {
        return acceleration ? ::velocityAfter(v, (*acceleration)[i], t) : v;
    }
    // The box block i sweeps from p over t seconds.
    Aabb path(int i, Vec2 p, Vec2 size, Vec2 v, double t) const {
        return acceleration ? sweptAabb(p, size, v, (*acceleration)[i], t)
                            : sweptAabb(p, size, v, t);
    }
    // Impact of block i (box a, velocity va) and block j (box b, velocity vb) within maxTime;
    // j < 0: a body held still (the turn-based method's others).
    Impact impact(int i, const Aabb& a, Vec2 va, int j, const Aabb& b, Vec2 vb,
                  double maxTime) const {
        if (plain()) return timeOfImpact(a, va, b, vb, maxTime); // the common case, inline
        return impactWithOptions(i, a, va, j, b, vb, maxTime);
    }
    // Friction with the exact integrator: when block i, sliding along `axis` on its support
    // (Slide) at `velocity`, will have the support's velocity (s from then; kNever: never).
    double stopTime(int i, int axis, double velocity) const;
    Impact impactWithOptions(int i, const Aabb& a, Vec2 va, int j, const Aabb& b, Vec2 vb,
                             double maxTime) const;
    WallImpact wallImpact(int i, const Aabb& box, Vec2 v, double maxTime) const {
        return acceleration ? timeOfWallImpact(box, v, (*acceleration)[i], world.bounds, maxTime)
                            : timeOfWallImpact(box, v, world.bounds, maxTime);
    }
};

// Where the rest rule looks for the bodies that touch a cluster member: every block whose
// registered box meets `box`, appended to `found` in any order (the rule's answer does not depend
// on it). The BroadPhase by default; the perfect method passes the index of its paths.
class BlockFinder {
  public:
    virtual void find(const Aabb& box, std::vector<int>& found) const = 0;

  protected:
    ~BlockFinder() = default;
};

// What resolving a contact did: nothing (not approaching), a bounce by the formula (or a
// kinematic reversing), or the rest rule's perfectly inelastic merge.
enum class Resolution { None, Bounce, Rest };

// When a contact is resolved by the rest rule: when it closes slowly (WorldSettings::restSpeed),
// or always, whatever its speed (the perfect and turn-based methods' rules for what never ends:
// inelastic collapse, a trap between infinite masses, a crush; perfect.cpp, turn_based.cpp).
enum class RestRule { WhenSlow, Always };

// What a method adds to resolving, called back by the Resolver as it works (each hook does
// nothing unless the method overrides it).
class ResolveHooks {
  public:
    // Block i is about to be read at the resolver's time `now` (s since the substep start): the
    // perfect method moves its blocks lazily, each valid at its own clock, and brings it there.
    virtual void bringToNow(int /*i*/, double /*now*/) {}
    // Block i's velocity along `axis` is about to change from `before` (m/s): turn-based keeps
    // these to undo a sequence of collisions that would not end.
    virtual void velocityChanging(int /*i*/, int /*axis*/, double /*before*/) {}

  protected:
    ~ResolveHooks() = default;
};

// Resolves contacts between touching blocks. Every change of velocity is reported in
// changed() so event-driven code can re-predict.
class Resolver {
  public:
    // `finder`: where the rest rule finds neighbours (null: ctx.broadPhase). `hooks`: the
    // method's (null: none).
    explicit Resolver(SubstepContext& context, const BlockFinder* finder = nullptr,
                      ResolveHooks* hooks = nullptr);

    // The time (s since the substep start) at which contacts are being resolved.
    void setNow(double now) { now_ = now; }
    // The contact about to be resolved, of two blocks, has met more often at this instant than
    // the method resolves as it comes (perfect.cpp: the collapse and trap rules). A rest-rule
    // merge of it then carries no friction: each merge's friction changes both blocks' velocities
    // along the other axis by up to μ·Δv_n, which closes a neighbouring contact along that axis
    // again, whose merge's friction closes this one again; with μ ≥ 1 that never shrinks, and the
    // event cap ended the substep with the forces' g·h given and no time passed (energy in piles
    // with μ = 2: docs/physics.md, "Energy in piles"). Against an infinite mass friction only
    // slows the block toward it, which closes nothing again.
    void setRepeated(bool repeated) { repeated_ = repeated; }

    // Blocks a and b touch along `axis` (0 = x, 1 = y); resolves if they approach.
    Resolution resolvePair(int a, int b, int axis, RestRule rest = RestRule::WhenSlow);
    // Block a touches the wall on `axis` that it moves toward.
    Resolution resolveWall(int a, int axis, RestRule rest = RestRule::WhenSlow);

    // Block i, sliding along `axis`, has its support's velocity (stopTime()): it moves on with
    // the support, held by static friction (up to Slide::limit).
    Resolution stopSliding(int i, int axis);

    // Whether block i (dynamic) is caught along `axis` between infinite masses: the blocks that
    // touch it along the axis, and those that touch them, reach a wall, a static or a kinematic
    // block both below and above it. Along that line nothing can move without a collision.
    bool caughtBetweenInfiniteMasses(int i, int axis);

    const std::vector<int>& changed() const { return changed_; }
    void clearChanged() { changed_.clear(); }

  private:
    double restThreshold(int axis) const;
    bool approaching(int a, int b, int axis, double& closing) const;
    void setAcceleration(int i, int axis, double a);
    void reverseKinematic(int i, int axis);
    Resolution restCluster(int seedA, int seedB, int axis, Wall seedWall);
    void record(int a, int b, int axis, double m1, double v1, double m2, double v2, double u,
                double C, double v1After, double v2After, ResolveRule rule);
    void setVelocity(int i, int axis, double v);
    // A collision or friction (not the rest rule's merge) sets block i's velocity along `axis`;
    // with the exact integrator a change frees its acceleration (freeAcceleration). Here, inline:
    // every collision passes through it, and the Euler integrators need the velocity alone.
    void bounce(int i, int axis, double v) {
        const double before = ctx_.world.blocks[i].velocity[axis];
        setVelocity(i, axis, v);
        if (ctx_.acceleration && before != v) freeAcceleration(i, axis);
    }
    void freeAcceleration(int i, int axis);
    void findNear(const Aabb& box);
    // Friction (friction.cpp).
    double frictionOf(int body) const;
    double frictionOf(int a, int b) const { return mixedFriction(frictionOf(a), frictionOf(b)); }
    double inverseMass(int body) const;
    double velocityOf(int body, int axis) const;
    double frictionImpulse(int a, int b, int tangent, double mu, double jn);
    void contactFriction(int a, int b, int axis, double dvn);
    void slideFriction(int i, int tangent);
    void releaseSlides(int i, int axis);
    void touch(int i, const Aabb& box, int j, int axis);
    double freeClusterAcceleration(int axis, double u, double withoutFriction);
    void clusterFriction(int axis, bool anchoredBelow, bool anchoredAbove, int seedA,
                         int seedOther);
    void sync(int i) {
        if (hooks_) hooks_->bringToNow(i, now_);
    }

    SubstepContext& ctx_;
    const BlockFinder* finder_;
    ResolveHooks* hooks_;
    double now_ = 0.0;
    bool forceRest_ = false; // the contact being resolved: RestRule::Always
    bool repeated_ = false;  // setRepeated
    std::vector<int> changed_;
    // The friction of the contact being resolved, for its record.
    struct FrictionNote {
        double mu = 0.0, dvn = 0.0, dvt = 0.0;
        bool perSecond = false;
    } note_;
    // Scratch for the rest rule's cluster search.
    std::vector<int> members_;
    std::vector<int> queue_;
    std::vector<int> found_;
    std::vector<unsigned char> inCluster_;
    struct Anchor {
        int block;    // a kinematic member
        bool presses; // it approaches a member that touches it
        bool below;   // it lies below a member it touches
        bool above;   // it lies above one
    };
    std::vector<Anchor> kinematics_;
    // Friction in the cluster: the contacts along the axis (a dynamic member and the body it
    // touches, `side` +1 when that body lies above it), and per dynamic member (queue_'s order)
    // its velocity and acceleration before the merge and the load it carries.
    struct Touch {
        int block;
        int other; // a block index or a Wall
        int side;
        double width; // m: how far they overlap along the other axis
    };
    std::vector<Touch> touches_;
    std::vector<double> velocityBefore_, accelBefore_;
    // Per dynamic member: the momentum change it passes to what holds it (N·s), and with the exact
    // integrator the force its contacts take (N) and that force's change at this event (N).
    std::vector<double> impulseLoad_, forceLoad_, changeLoad_;
    // Per touch: the member it holds, its support, and the loads it carries (N·s, N, N).
    struct Carried {
        int held, support;
        double width; // m
        double jn, fn, fd;
    };
    std::vector<Carried> carried_;
    std::vector<int> order_, rank_; // members by distance from the anchors, and each one's place
};
