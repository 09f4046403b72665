// What the lecture's rules would give in one frame, for judging a student's trace (parting.cpp):
// the velocity a body moves with over the frame, the candidates for a velocity component after a
// collision (the momentum formula, the component reversed without Newton, unchanged) and every
// body a block would touch during the frame.
#pragma once

#include "world.h"

#include <algorithm>
#include <cmath>
#include <vector>

// The velocity a body moves with over the frame (semi-implicit Euler: the acceleration first).
Vec2 frameVelocityOf(const Block& b, const WorldSettings& s);

// The student's velocity after a collision, one component at a time, against the lecture's
// candidates: the momentum formula, the body's own component reversed (without Newton), none.
enum class Rule { Formula, Reflect, Unchanged, None };

struct Candidates {
    double formula = 0.0, reflect = 0.0, unchanged = 0.0;
    // How far apart the closest two are: how well this component tells the rules apart.
    double spread() const {
        return std::min({std::abs(formula - reflect), std::abs(formula - unchanged),
                         std::abs(reflect - unchanged)});
    }
    Rule rule(double yours, double tolerance, bool unchangedFirst) const {
        auto near = [&](double v) { return std::abs(yours - v) <= tolerance; };
        if (unchangedFirst && near(unchanged)) return Rule::Unchanged;
        if (near(formula)) return Rule::Formula;
        if (near(reflect)) return Rule::Reflect;
        if (near(unchanged)) return Rule::Unchanged;
        return Rule::None;
    }
};

// Block `i` against body `other` (a block, or a wall < 0) along `axis` with bounciness C.
Candidates candidatesFor(const std::vector<Block>& before, const WorldSettings& s, int i, int other,
                         int axis, double C);

// Every body block `i` would touch during the frame (each at its first touch), with the others
// moving at their frame velocity or, as the turn-based method has them, held still.
struct Touch {
    int other = 0; // block index or Wall
    int axis = 0;
    double t = 0.0; // fraction of the frame
};
std::vector<Touch> touchesInFrame(const std::vector<Block>& before, const Bounds& bounds,
                                  const WorldSettings& s, int i);
