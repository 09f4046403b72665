// What one step reports, and the record of one resolved collision (what the inspector shows).
#pragma once

#include "vec2.h"

#include <cstdint>

// Walls have negative indices in CollisionRecord::other.
enum Wall : int { kWallLeft = -1, kWallRight = -2, kWallBottom = -3, kWallTop = -4 };

struct StepStats {
    int collisions = 0;           // resolved collisions this frame, walls included; resting
                                  // contacts of the rest rule not (they are `contacts`)
    int contacts = 0;             // resting contacts resolved by the rest rule this frame
    int events = 0;               // perfect method: event instants processed this frame
    double maxPenetration = 0.0;  // m, largest overlap seen (end of frame, or met by the method)
    Vec2 momentum;                // kg·m/s, total over dynamic blocks
    double kineticEnergy = 0.0;   // J
    double potentialEnergy = 0.0; // J
    int eventCapHits = 0;         // substeps whose event cap ended them early
    double simulatedTime = 0.0;   // s actually advanced (less than dt when the cap held time back)
    double stepMs = 0.0;          // ms of wall-clock time spent in the step (0 when not timed)
    bool timed = false;           // stepMs was measured (WorldSettings::measureTime)
};

// What a run adds up over its steps: counts summed, the largest overlap kept. The one place
// totals are accumulated (the app's Statistics and its methods side by side, sandbox-cli run,
// the stability matrix).
struct StepTotals {
    std::int64_t steps = 0;
    std::int64_t collisions = 0;   // walls included, resting contacts not
    std::int64_t contacts = 0;     // resting contacts resolved by the rest rule
    std::int64_t events = 0;       // perfect method: event instants
    std::int64_t eventCapHits = 0; // substeps whose event cap ended them early
    double maxPenetration = 0.0;   // m, largest overlap of any step
    double stepMs = 0.0;           // ms of wall-clock time spent in the steps
};

// Adds one step's stats to `totals`.
inline void addStep(StepTotals& totals, const StepStats& step) {
    ++totals.steps;
    totals.collisions += step.collisions;
    totals.contacts += step.contacts;
    totals.events += step.events;
    totals.eventCapHits += step.eventCapHits;
    if (step.maxPenetration > totals.maxPenetration) totals.maxPenetration = step.maxPenetration;
    totals.stepMs += step.stepMs;
}

// The rule that resolved a collision (CollisionRecord::rule): what the inspector prints.
enum class ResolveRule : std::uint8_t {
    Formula, // the lecture's formula; with an infinite mass u is that body's velocity
    Reflect, // without Newton (resolve "reflect"): each body v' = -C·v, u unused (0)
    Reverse, // no finite mass (a kinematic block and a wall or an infinite mass): it reverses
    // The rest rule (resolve.h), perfectly inelastic: every dynamic block of the resting group
    // takes u, which is
    RestFree,     // the group's momentum over its mass (restBodies blocks, no infinite mass)
    RestAnchored, // the velocity of the infinite masses it rests on (they agree)
    RestCrushed,  // between infinite masses that disagree: the pressing ones reverse, u clamped
};

// One resolved collision along one axis, with the numbers of the lecture's formula:
// u = (m1·v1 + m2·v2) / (m1 + m2),  v' = u - C·(v - u).
struct CollisionRecord {
    double time = 0.0;         // s, world time of impact
    double toi = 0.0;          // fraction of the (sub)step at which the faces touched (t = a/b)
    int block = 0;             // index of the first body
    int other = 0;             // index of the second body, or a Wall (negative)
    int axis = 0;              // 0 = x, 1 = y
    double m1 = 0.0, m2 = 0.0; // kg (infinity for walls, static and kinematic)
    double v1 = 0.0, v2 = 0.0; // m/s, velocity components along the axis before
    double u = 0.0;            // m/s, centre-of-mass velocity along the axis
    double C = 0.0;            // bounciness used (0 when the rest rule applied)
    double v1After = 0.0, v2After = 0.0; // m/s after
    bool rest = false;                   // resolved by the rest rule (a resting contact)
    ResolveRule rule = ResolveRule::Formula;
    int restBodies = 0;      // the rest rule: the dynamic blocks that took u
    bool restForced = false; // the rest rule whatever the speed (collapse, trap, crush)
    // Friction along the other axis (friction.cpp): μ of the pair, and how much the
    // contact changed the two bodies' relative velocity along its axis (dvn) and along the other
    // (dvt, |dvt| <= μ·|dvn|). perSecond: a resting contact under the exact integrator, whose
    // friction is a deceleration: both are then changes of acceleration (m/s^2).
    double mu = 0.0;
    double dvn = 0.0, dvt = 0.0; // m/s (m/s^2 when perSecond)
    bool perSecond = false;
    // Two bodies: the first one's centre is at most the other's along the axis, so they approach
    // when v1 - v2 > 0 (else when v2 - v1 > 0): the relative-velocity test the inspector shows
    // (lecture, "Tips – Collision Resolve"). A wall's side is in `other`.
    bool firstBelow = true;
    // m, the two bodies' centres when the contact was resolved: with the perfect and turn-based
    // methods where they touched (the point of impact, within the frame), with move-and-correct
    // after the move back. A wall's is (0, 0).
    Vec2 position1, position2;
};
