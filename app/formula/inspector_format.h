// The collision inspector's text: one resolved collision (CollisionRecord) written as the
// lecture's formula with its numbers filled in, e.g.
//   u = (1·6 + 2·0)/(1 + 2) = 2      v1' = 2 - 1·(6 - 2) = -2      v2' = 2 - 1·(0 - 2) = 4
// Pure functions (no ImGui), so the tests check the exact strings.
#pragma once

#include "stats.h"
#include "text_format.h"

#include <string>

struct CollisionFormula {
    std::string title; // "m1 = 1 kg  hits  m2 = 2 kg along x at t = 0.625 s"
    std::string given; // "m1 = 1, m2 = 2, v1 = 6, v2 = 0, C = 1"
    // The relative-velocity test (lecture, "Tips – Collision Resolve": resolve only when the
    // relative velocity along the axis closes), e.g.
    // "rel. vel. along x = v1 - v2 = 6 - 0 = 6 > 0: approaching, resolved", or
    // "rel. vel. along x = v1 - v2 = 3 - 4 = -1 < 0: separating, not a collision (resolved
    //  anyway: the mistake no-approach-test)".
    std::string relative;
    bool separating = false;    // the test says no collision (resolved by a mistake)
    std::string u;              // "u = (1·6 + 2·0)/(1 + 2) = 2"
    std::string v1After;        // "v1' = 2 - 1·(6 - 2) = -2"
    std::string v2After;        // "v2' = 2 - 1·(0 - 2) = 4" ("" for a wall: it does not move)
    std::string momentumBefore; // "p before = 1·6 + 2·0 = 6"
    std::string momentumAfter;  // "p after = 1·(-2) + 2·4 = 6"
    std::string note;           // why momentum is not conserved (a wall), or the rest rule
    // Coulomb friction along the other axis (physics.md, "Friction"), "" without it:
    // "friction along y: |dvt| = 0.4 < mu·|dvn| = 0.5·2.3 = 1.15 m/s (stopped sliding)" or
    // "... |dvt| = mu·|dvn| = 0.5·2.3 = 1.15 m/s (kinetic: still sliding)". The product is that
    // of the digits shown (exact), so the equation holds as printed.
    std::string friction;
    // The masses and the velocities after as its lines print them ("1000000", "0.9999999175"):
    // what another text about the same quantity (a momentum arrow's value) writes them as.
    std::string m1Text, m2Text, v1AfterText, v2AfterText;
};

// The product of two numbers as printed ("1000000" and "0.9999999175"), exact in decimal
// ("999999.9175"), of their magnitudes (signs dropped): the value a momentum m·v takes from the
// digits a formula shows for m and v, so that it never prints other digits for the same
// quantity; "" when either is not a plain decimal (an exponent, inf) or the digits are too many.
std::string productAsPrinted(const std::string& a, const std::string& b);

// The formula for `record`: each quantity (m1, m2, v1, v2, C, u, v1', v2') is written with the
// same digits in every line, as many as the chains that read it need to hold as printed; `name1`
// and `name2` name the bodies (a wall's name for walls). The symbols follow the names: blocks "m1"
// and "m2" (or "A" and "B") give m1, v1 (mA, vA), other names 1 and 2; a block hitting a wall keeps
// its own symbol (or none: m, v).
CollisionFormula collisionFormula(const CollisionRecord& record, const std::string& name1,
                                  const std::string& name2);
// "left wall", "right wall", "floor", "ceiling" for a negative CollisionRecord::other.
const char* wallName(int other);
