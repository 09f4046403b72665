#include "parting.h"

#include "collision.h"
#include "inspector_format.h"
#include "resolve.h"
#include "rule_candidates.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>

namespace {

constexpr const char* kResolveSlide = "Tips - Collision Resolve";
constexpr const char* kFormulaSlide = "Collisions on a Line - Full Formula";
constexpr const char* kPoiSlide = "Point of Impact (POI) Calculation";
// A time of impact this close to a frame's start or end (a fraction of the frame) lies on the
// boundary: single-precision rounding decides which frame the collision falls in.
constexpr double kBoundary = 1e-3;

const char* axisName(int axis) {
    return axis == 0 ? "x" : "y";
}

std::string speed(double v) {
    return formatQuantity(v, "m/s");
}

std::string at(Vec2 p) {
    return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ")";
}

std::string bodyName(const Scene& scene, int index) {
    return index < 0 ? wallName(index) : traceBlockName(scene, index);
}

void add(PartingCollision& p, std::string id, std::string says, std::string slide,
         bool convention = false) {
    p.findings.push_back({std::move(id), std::move(says), std::move(slide), convention});
}

// A corner hit: the block meets the body along both axes at one instant, and the reference
// resolves both; an engine that resolves one axis only keeps the other component.
bool judgeCorner(PartingCollision& p, const Scene& scene, const std::vector<Block>& before,
                 const WorldSettings& s, const std::vector<CollisionRecord>& frameLog,
                 const Tolerance& tol) {
    const CollisionRecord& r = p.record;
    const auto corner =
        std::find_if(frameLog.begin(), frameLog.end(), [&](const CollisionRecord& c) {
            return c.axis != r.axis && c.time == r.time && c.block == r.block && c.other == r.other;
        });
    if (corner == frameLog.end()) return false;
    const Vec2 v = frameVelocityOf(before[static_cast<std::size_t>(p.block)], s);
    const Vec2 ys = p.yoursVelocity, ref = p.referenceVelocity;
    auto near = [&](double a, double b) { return std::abs(a - b) <= tol.velocity; };
    for (int kept = 0; kept < 2; ++kept) {
        const int resolved = 1 - kept;
        if (near(ys[resolved], ref[resolved]) && near(ys[kept], v[kept]) &&
            !near(v[kept], ref[kept])) {
            add(p, "corner",
                traceBlockName(scene, p.block) + " meets " + bodyName(scene, r.other) +
                    " at a corner: the faces along x and along y touch at the same instant (t = " +
                    formatNumber(r.toi) +
                    " of the frame). The reference resolves both axes (v' = " + at(ref) +
                    " m/s); your engine resolved " + axisName(resolved) + " only and kept v" +
                    axisName(kept) + " = " + speed(ys[kept]) +
                    ". The lecture's rules leave a corner open (the sandbox bounces off both "
                    "faces, as off a "
                    "corner): this difference is a convention, not a mistake",
                "Point of Impact for AABBs", true);
            return true;
        }
    }
    return false;
}

// The student's velocity just after the collision against the lecture's rules, axis by axis.
void judgeVelocity(PartingCollision& p, const Scene& scene, const std::vector<Block>& before,
                   const WorldSettings& s, const Tolerance& tol) {
    const CollisionRecord& r = p.record;
    const int a = r.axis, o = 1 - a;
    const int other = r.block == p.block ? r.other : r.block;
    const double C = r.C; // 0 when the rest rule resolved it
    const Candidates along = candidatesFor(before, s, p.block, other, a, C);
    const Candidates across = candidatesFor(before, s, p.block, other, o, C);
    const Vec2 ys = p.yoursVelocity;
    const double tolV = std::max(
        tol.velocity, 1e-9 * std::max(std::abs(along.unchanged), std::abs(across.unchanged)));
    const Rule ruleAlong = along.rule(ys[a], tolV, false);
    // Across the axis "unchanged" comes first: with nothing moving across, every rule gives 0.
    const Rule ruleAcross = across.rule(ys[o], tolV, true);
    const std::string A = axisName(a), O = axisName(o);
    const std::string name = traceBlockName(scene, p.block);
    const double reference = p.referenceVelocity[a];
    const std::string theirs = "the reference's v" + A + "' = " + speed(reference);
    const Rule referenceRule = s.resolve == Resolve::Momentum ? Rule::Formula : Rule::Reflect;
    if (ruleAlong == referenceRule && ruleAcross == Rule::Unchanged) return; // right
    if (ruleAcross == Rule::Unchanged && ruleAlong == Rule::Reflect) {
        add(p, "without-newton",
            name + " reverses its own velocity along " + A + " (v" + A + "' = -C·v = " +
                speed(ys[a]) + ") instead of the momentum formula v' = u - C·(v - u) (" + theirs +
                "): without Newton, the two blocks' momentum is not kept",
            "Demo: bouncing squares; with/without Newton");
        return;
    }
    if (ruleAcross == Rule::Unchanged && ruleAlong == Rule::Formula) {
        add(p, "with-newton",
            name + " leaves with the momentum formula v' = u - C·(v - u) (v" + A +
                "' = " + speed(ys[a]) +
                "); the scene is without Newton: each block reverses its own "
                "velocity (" +
                theirs + ")",
            "Demo: bouncing squares; with/without Newton");
        return;
    }
    if (ruleAlong == Rule::Unchanged && ruleAcross != Rule::Unchanged) {
        // Another collision across the axis in this frame, resolved instead of the earliest?
        for (const Touch& t : touchesInFrame(before, scene.bounds, s, p.block)) {
            if (t.axis != o) continue;
            const Candidates c = candidatesFor(before, s, p.block, t.other, o, s.bounciness);
            if (c.rule(ys[o], tolV, true) == Rule::Formula ||
                c.rule(ys[o], tolV, true) == Rule::Reflect) {
                add(p, "wrong-collision",
                    name + " bounced off " + bodyName(scene, t.other) + " along " + O +
                        " (at t = " + formatNumber(t.t) + " of the frame; v" + O + " " +
                        speed(across.unchanged) + " to " + speed(ys[o]) +
                        ") instead of the earliest collision of the frame, with " +
                        bodyName(scene, other) + " along " + A + " (" + theirs +
                        "): find the first one, and only resolve that one",
                    mistakeSlide(Mistake::FirstFound));
                return;
            }
        }
        add(p, "wrong-axis",
            "the collision is along " + A + " (" + (a == 0 ? "left and right" : "top and bottom") +
                " faces meet), but your engine changed v" + O + " (" + speed(across.unchanged) +
                " to " + speed(ys[o]) + ") and kept v" + A + " (" + speed(ys[a]) +
                "): the formula applied on the wrong axis; it belongs to the velocities' " + A +
                " coordinates only (" + theirs + ")",
            kResolveSlide);
        return;
    }
    if (ruleAlong != Rule::Unchanged && ruleAlong != Rule::None && ruleAcross != Rule::Unchanged) {
        add(p, "both-axes",
            "your engine changed both coordinates of " + name + "'s velocity (v" + O + " " +
                speed(across.unchanged) + " to " + speed(ys[o]) +
                "); the formula is applied to the collision's axis, " + A + ", only",
            kResolveSlide);
        return;
    }
    if (ruleAlong == Rule::Unchanged && ruleAcross == Rule::Unchanged) {
        const bool stillAcross = std::abs(across.unchanged) <= tolV;
        add(p, "not-resolved",
            name + " kept its velocity through the collision (v" + A + " = " + speed(ys[a]) + ", " +
                theirs +
                "): your engine did not find the collision (a discrete check at "
                "the new position misses a block that passes the other within one frame: "
                "tunnelling) or did not resolve it" +
                (stillAcross ? " (or resolved it along " + O +
                                   ", where nothing moves and the formula changes nothing)"
                             : std::string()),
            mistakeSlide(Mistake::Discrete));
        return;
    }
    if (ruleAcross == Rule::Unchanged) {
        // Along the axis, some other value: which bounciness, sign or masses would give it?
        const Block& me = before[static_cast<std::size_t>(p.block)];
        const double v = along.unchanged;
        const double m2 = other >= 0 ? before[static_cast<std::size_t>(other)].mass : kInfiniteMass;
        const double v2 =
            other >= 0 ? frameVelocityOf(before[static_cast<std::size_t>(other)], s)[a] : 0.0;
        const double u = centerOfMassVelocity(me.mass, v, m2, v2);
        const double uSwapped = centerOfMassVelocity(m2, v, me.mass, v2);
        if (std::isfinite(m2) && std::abs(velocityAfterCollision(v, uSwapped, C) - ys[a]) <= tolV) {
            add(p, "masses-swapped",
                name + "'s v" + A + "' = " + speed(ys[a]) +
                    " is the formula with the two masses swapped in u = (m1·v1 + m2·v2)/(m1 + "
                    "m2); " +
                    theirs,
                kFormulaSlide);
            return;
        }
        if (std::abs(v - u) > tolV) {
            const double Cs = (u - ys[a]) / (v - u);
            if (C > 0.0 && std::abs(Cs + C) <= 1e-3) {
                add(p, "formula-sign",
                    name + "'s v" + A + "' = " + speed(ys[a]) +
                        " is u + C·(v - u): the formula's sign; v' = u - C·(v - u) gives " +
                        speed(along.formula),
                    kFormulaSlide);
                return;
            }
            if (Cs >= -0.05 && Cs <= 1.05) {
                add(p, "bounciness",
                    name + "'s v" + A + "' = " + speed(ys[a]) +
                        " is the formula v' = u - C·(v - u) with C = " + formatNumber(Cs) +
                        "; the scene's bounciness is C = " + formatNumber(C) + " (" + theirs + ")",
                    kFormulaSlide);
                return;
            }
        }
    }
    add(p, "velocity-unexplained",
        name + "'s velocity just after the collision, " + at(ys) +
            " m/s, is none of the lecture's rules: the formula gives v" + A +
            "' = " + speed(along.formula) + " with v" + O + " unchanged (" +
            speed(across.unchanged) + "), " + theirs,
        kFormulaSlide);
}

// The student's position after the collision against where the lecture's rules put the block,
// given the velocity the student's block left with.
void judgePosition(PartingCollision& p, const Scene& scene, const Tolerance& tol) {
    const PoiView& poi = p.poi;
    const Vec2 ys = p.yoursPosition;
    auto near = [&](Vec2 q) {
        return std::abs(q.x - ys.x) <= tol.position && std::abs(q.y - ys.y) <= tol.position;
    };
    if (near(p.referencePosition)) return;
    const std::string name = traceBlockName(scene, p.block);
    const Vec2 onward = poi.ghost + p.yoursVelocity * ((1.0 - poi.t) * poi.dt);
    const std::string A = axisName(poi.axis);
    const std::string ghost =
        "the point of impact POI = oldPosition + t·velocity = " + at(poi.ghost) +
        " (t = a/b = " + formatNumber(poi.t) + ")";
    if (near(poi.crooked) && !near(poi.ghost)) {
        add(p, "move-back",
            name + " is at " + at(ys) + ": it moved the whole frame to " + at(poi.newPosition) +
                " and was pushed back along " + A + " only, instead of being put at " + ghost,
            mistakeSlide(Mistake::MoveBack));
        return;
    }
    if (near(poi.newPosition)) {
        add(p, "not-corrected",
            name + " stays where the whole frame took it, " + at(ys) +
                ", overlapping what it hit: the new position is not corrected (" + ghost + ")",
            kPoiSlide);
        return;
    }
    if (near(poi.oldPosition) && !near(poi.ghost)) {
        add(p, "put-back",
            name + " is put back where it started the frame, " + at(ys) + ", instead of at " +
                ghost,
            mistakeSlide(Mistake::MoveBack));
        return;
    }
    if (near(poi.ghost)) {
        add(p, "stops-at-impact",
            name + " stops at " + ghost +
                " and loses the rest of its frame, as the turn-based method does; the reference "
                "goes on to " +
                at(p.referencePosition),
            "Turn-based Simulation");
        return;
    }
    if (near(onward)) {
        add(p, "goes-on-after-impact",
            name + " goes on after " + ghost +
                " for the rest of the frame, as the perfect method does; the reference is at " +
                at(p.referencePosition),
            "Perfect Simulation");
        return;
    }
    // Where did the student's block turn? Going on after its impact with the velocity it left
    // with: p = old + t·v·dt + (1 - t)·v'·dt along the axis.
    const int a = poi.axis;
    const double v = poi.velocity[a], w = p.yoursVelocity[a];
    if (std::abs(v - w) * poi.dt > tol.position) {
        const double ts = (ys[a] - poi.oldPosition[a] - w * poi.dt) / ((v - w) * poi.dt);
        // Only a turn inside the frame, clearly apart from the reference's, says something.
        if (ts > 0.01 && ts < 0.99 && std::abs(ts - poi.t) > 0.01) {
            add(p, "time-of-impact",
                name + " is at " + at(ys) + ": going on after its impact, it turned at t = " +
                    formatNumber(ts) + " of the frame along " + A +
                    ", the reference at t = a/b = " + formatNumber(poi.a) + " m / " +
                    formatNumber(poi.b) + " m = " + formatNumber(poi.t) +
                    ": the point of impact must be exact",
                kPoiSlide);
            return;
        }
    }
    add(p, "position-unexplained",
        name + " is at " + at(ys) + ", none of the places the lecture's rules give: " + ghost +
            ", the reference's " + at(p.referencePosition),
        kPoiSlide);
}

// No collision of the block in the parting frame: a collision the reference does not have, or
// the free flight (the integration).
void judgeFreeFlight(PartingCollision& p, const Scene& scene, const Block& before,
                     const WorldSettings& s, const Tolerance& tol) {
    const std::string name = traceBlockName(scene, p.block);
    const Vec2 v1 = p.referenceVelocity;
    for (int axis = 0; axis < 2; ++axis) {
        const double yours = p.yoursVelocity[axis];
        if (std::abs(yours - v1[axis]) > tol.velocity && std::abs(yours) > tol.velocity &&
            std::abs(v1[axis]) > tol.velocity && (yours > 0) != (v1[axis] > 0)) {
            add(p, "extra-collision",
                name + "'s v" + axisName(axis) + " turned to " + speed(yours) +
                    " where the reference has no collision in this frame (it keeps " +
                    speed(v1[axis]) +
                    "): a collision that is not really a collision (only "
                    "resolve when the relative velocity closes), or one the reference's blocks "
                    "do not reach",
                kResolveSlide);
            return;
        }
    }
    if (!before.isDynamic()) return;
    const Vec2 a = accelerationOf(s, before, s.dt);
    const double dt = s.dt;
    const Vec2 explicitEuler = before.position + before.velocity * dt;
    const Vec2 semiImplicit = before.position + (before.velocity + a * dt) * dt;
    const Vec2 parabola = before.position + before.velocity * dt + a * (0.5 * dt * dt);
    const Vec2 ys = p.yoursPosition;
    auto near = [&](Vec2 q) {
        return std::abs(q.x - ys.x) <= tol.position && std::abs(q.y - ys.y) <= tol.position;
    };
    if (near(p.referencePosition)) return;
    if (near(explicitEuler) && !near(semiImplicit))
        add(p, "explicit-euler",
            name + " moved with the velocity from before the acceleration was added (position "
                   "first, then velocity: explicit Euler); the lecture adds the acceleration to "
                   "the velocity first",
            "Integration");
    else if (near(parabola) && !near(semiImplicit))
        add(p, "exact-parabola",
            name + " follows the exact parabola p + v·dt + a·dt²/2; the lecture's step is "
                   "piecewise linear",
            "Integration");
    else if (near(semiImplicit))
        add(p, "free-flight",
            name + " moved freely, as the lecture's integration says, to " + at(ys) +
                "; the reference's " + methodName(s.method) + " method has it at " +
                at(p.referencePosition) + " (it stopped or turned it within the frame)",
            "Integration");
}

// The body of `r` whose velocity tells the rules apart best (a block at rest hit by another
// reverses nothing: its formula and its reflection differ, its reflection and "unchanged" not).
int mostTelling(const CollisionRecord& r, const std::vector<Block>& before, const WorldSettings& s,
                const Trace& trace) {
    auto traced = [&](int i) {
        return i >= 0 &&
               std::find(trace.blocks.begin(), trace.blocks.end(), i) != trace.blocks.end() &&
               before[static_cast<std::size_t>(i)].isDynamic();
    };
    if (!traced(r.other)) return r.block;
    if (!traced(r.block)) return r.other;
    const double spread1 = candidatesFor(before, s, r.block, r.other, r.axis, r.C).spread();
    const double spread2 = candidatesFor(before, s, r.other, r.block, r.axis, r.C).spread();
    return spread2 > spread1 ? r.other : r.block;
}

bool tracedRow(const Trace& trace, std::int64_t frame, int block, Vec2& position, Vec2& velocity) {
    const auto it = std::find(trace.blocks.begin(), trace.blocks.end(), block);
    if (it == trace.blocks.end()) return false;
    const auto b = static_cast<std::size_t>(it - trace.blocks.begin());
    for (const TraceRow& row : trace.rows)
        if (row.frame == frame) {
            position = row.position[b];
            velocity = row.velocity[b];
            return true;
        }
    return false;
}

} // namespace

PartingCollision findPartingCollision(const Scene& scene, const WorldSettings& settings,
                                      const Trace& trace, const RunMatch& match,
                                      const Tolerance& tol) {
    PartingCollision p;
    const Difference& d = match.first();
    if (!d.found()) return p;
    p.differing = p.block = d.block;
    Scene sc = scene;
    sc.settings = settings;
    World world = makeWorld(sc);
    world.settings.measureTime = false; // no step's time is shown (in the browser: two JS calls)
    std::vector<CollisionRecord> log;
    auto involves = [&](const CollisionRecord& r) {
        return r.block == d.block || r.other == d.block;
    };
    Vec2 previousVelocity = world.blocks[static_cast<std::size_t>(d.block)].velocity;
    for (std::int64_t frame = 1; frame < d.frame; ++frame) {
        log.clear();
        previousVelocity = world.blocks[static_cast<std::size_t>(d.block)].velocity;
        world.step(&log);
        for (const CollisionRecord& r : log)
            if (involves(r)) {
                p.found = true;
                p.frame = frame;
                p.record = r;
            }
    }
    const std::vector<Block> before = world.blocks;
    const double frameStart = world.time;
    std::vector<CollisionRecord> frameLog;
    if (d.frame > 0) {
        world.step(&frameLog);
        log = frameLog;
        for (const CollisionRecord& r : log)
            if (involves(r)) {
                p.found = p.inPartingFrame = true;
                p.frame = d.frame;
                p.record = r;
                break; // the block's first collision of the frame
            }
    }
    if (p.inPartingFrame) p.block = mostTelling(p.record, before, settings, trace);
    const Block& now = world.blocks[static_cast<std::size_t>(p.block)];
    p.referencePosition = now.position;
    p.referenceVelocity = now.velocity;
    p.yoursKnown = tracedRow(trace, d.frame, p.block, p.yoursPosition, p.yoursVelocity);
    if (!p.yoursKnown || d.frame == 0) return p;

    // A collision on the frame's boundary: one engine resolves it at the end of this frame, the
    // other at the start of the next (or the other way round), as rounding decides.
    log.clear();
    World next = world;
    next.step(&log);
    const Vec2 nextVelocity = next.blocks[static_cast<std::size_t>(p.block)].velocity;
    auto sameVelocity = [&](Vec2 v) {
        return std::abs(v.x - p.yoursVelocity.x) <= tol.velocity &&
               std::abs(v.y - p.yoursVelocity.y) <= tol.velocity;
    };
    const auto early = std::find_if(log.begin(), log.end(), [&](const CollisionRecord& r) {
        return (r.block == p.block || r.other == p.block) && r.toi <= kBoundary;
    });
    const bool late = p.inPartingFrame && p.record.toi >= 1.0 - kBoundary;
    if ((early != log.end() && sameVelocity(nextVelocity)) ||
        (late && sameVelocity(previousVelocity))) {
        const CollisionRecord r = early != log.end() ? *early : p.record;
        if (early != log.end()) { // the reference's collision is the next frame's
            p.found = true;
            p.inPartingFrame = false;
            p.frame = d.frame + 1;
            p.record = r;
        }
        add(p, "frame-boundary",
            traceBlockName(scene, p.block) + "'s collision with " +
                bodyName(scene, r.block == p.block ? r.other : r.block) +
                " falls on a frame's boundary (t = " + formatNumber(r.toi) + " of frame " +
                std::to_string(early != log.end() ? d.frame + 1 : d.frame) +
                "): your engine resolves it in frame " +
                std::to_string(early != log.end() ? d.frame : d.frame + 1) +
                ". Single-precision rounding decides which frame such a collision falls in; the "
                "frames before agree, so this is rounding, not a mistake",
            "", true);
        return p;
    }
    if (!p.inPartingFrame) {
        judgeFreeFlight(p, scene, before[static_cast<std::size_t>(p.block)], settings, tol);
        return p;
    }
    p.poi = computePoi(before, scene.bounds, settings, frameStart, p.block);
    if (!judgeCorner(p, scene, before, settings, frameLog, tol))
        judgeVelocity(p, scene, before, settings, tol);
    if (p.poi.valid && p.poi.axis == p.record.axis && p.findings.empty())
        judgePosition(p, scene, tol);
    return p;
}
