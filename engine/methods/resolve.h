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

// Resolves contacts between touching blocks. Every change of velocity is reported in
// changed() so event-driven code can re-predict. Positions are read through sync(), which the
// perfect method uses to bring a lazily moved block to the current time.
class Resolver {
  public:
    // `finder`: where the rest rule finds neighbours (null: ctx.broadPhase).
    explicit Resolver(SubstepContext& context, const BlockFinder* finder = nullptr);

    // The time (s since the substep start) at which contacts are being resolved, and, for the
    // perfect method, each block's own clock (its position is valid at that time).
    void setNow(double now, std::vector<double>* localTime = nullptr);

    // Blocks a and b touch along `axis` (0 = x, 1 = y); resolves if they approach.
    Resolution resolvePair(int a, int b, int axis);
    // Block a touches the wall on `axis` that it moves toward.
    Resolution resolveWall(int a, int axis);

    // Resolve the next contacts perfectly inelastic whatever their speed (the perfect method's
    // rule for a pair that collides again at the same instant).
    void setForceRest(bool force) { forceRest_ = force; }

    // Whether block i (dynamic) is caught along `axis` between infinite masses: the blocks that
    // touch it along the axis, and those that touch them, reach a wall, a static or a kinematic
    // block both below and above it. Along that line nothing can move without a collision.
    bool caughtBetweenInfiniteMasses(int i, int axis);

    const std::vector<int>& changed() const { return changed_; }
    void clearChanged() { changed_.clear(); }

    // One change of velocity: enough to undo it.
    struct VelocityChange {
        int block;
        int axis;
        double before; // m/s
    };
    // When given, every change of velocity is also appended to `undo` (turn-based undoes a
    // sequence of collisions that would not end: see turn_based.cpp).
    void setUndoLog(std::vector<VelocityChange>* undo) { undo_ = undo; }
    // Brings block i to the current time (a no-op unless lazy clocks were given).
    void sync(int i);
    // When given, every block that sync() brings to the current time is also appended to `log`
    // (the perfect method keeps the motion it had before, for impacts it finds later: perfect.cpp).
    void setSyncLog(std::vector<int>* log) { syncLog_ = log; }

  private:
    double restThreshold(int axis) const;
    bool approaching(int a, int b, int axis, double& closing) const;
    void setAcceleration(int i, int axis, double a);
    void reverseKinematic(int i, int axis);
    Resolution restCluster(int seedA, int seedB, int axis, Wall seedWall);
    void record(int a, int b, int axis, double m1, double v1, double m2, double v2, double u,
                double C, double v1After, double v2After, bool rest);
    void setVelocity(int i, int axis, double v);
    void findNear(const Aabb& box);

    SubstepContext& ctx_;
    const BlockFinder* finder_;
    double now_ = 0.0;
    std::vector<double>* localTime_ = nullptr;
    bool forceRest_ = false;
    std::vector<int> changed_;
    std::vector<VelocityChange>* undo_ = nullptr;
    std::vector<int>* syncLog_ = nullptr;
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
};
