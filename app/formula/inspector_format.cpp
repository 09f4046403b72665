#include "inspector_format.h"

#include <cmath>
#include <cstdio>

const char* wallName(int other) {
    switch (other) {
    case kWallLeft:
        return "left wall";
    case kWallRight:
        return "right wall";
    case kWallBottom:
        return "floor";
    case kWallTop:
        return "ceiling";
    default:
        return "wall";
    }
}

namespace {

std::string vAfterLine(const std::string& v, double u, double C, double before, double after) {
    // v' = u - C·(v - u)
    return v + "' = " + formatNumber(u) + " - " + operand(C) + "·(" + formatNumber(before) + " - " +
           operand(u) + ") = " + formatNumber(after);
}

// The relative-velocity test along `axis`: `lower` and `upper` name the velocities of the body
// on the lower side and the one on the upper side (the wall's is 0), which approach when
// lower - upper > 0.
void relativeLine(CollisionFormula& f, char axis, const std::string& lowerName, double lower,
                  const std::string& upperName, double upper) {
    const double closing = lower - upper;
    f.relative = std::string("rel. vel. along ") + axis + " = " + lowerName + " - " + upperName +
                 " = " + formatNumber(lower) + " - " + operand(upper) + " = " +
                 formatNumber(closing);
    const std::string shown = formatNumber(closing);
    if (shown == "0") {
        f.relative += ": not closing, resolved";
    } else if (closing > 0.0) {
        f.relative += " > 0: approaching, resolved";
    } else {
        f.separating = true;
        f.relative += " < 0: separating, not a collision (resolved anyway: the mistake "
                      "no-approach-test)";
    }
}

} // namespace

CollisionFormula collisionFormula(const CollisionRecord& r, const std::string& name1,
                                  const std::string& name2) {
    CollisionFormula f;
    const char axis = r.axis == 0 ? 'x' : 'y';
    const bool wall = r.other < 0;
    // The symbols: m1, v1 for block "m1"; 1 and 2 when the names give none (or the same one).
    std::string s1 = formulaSymbol(name1), s2 = wall ? std::string() : formulaSymbol(name2);
    if (!wall && (s1.empty() || s2.empty() || s1 == s2)) {
        s1 = "1";
        s2 = "2";
    }
    const std::string m1 = "m" + s1, v1 = "v" + s1, m2 = "m" + s2, v2 = "v" + s2;
    f.title =
        name1 + "  hits  " + name2 + "  along " + axis + " at t = " + formatNumber(r.time) + " s";
    const bool finite1 = std::isfinite(r.m1), finite2 = std::isfinite(r.m2);
    if (wall) {
        f.given = m1 + " = " + formatNumber(r.m1) + ", " + v1 + " = " + formatNumber(r.v1) +
                  ", C = " + formatNumber(r.C) + "; the " + name2 + " does not move";
        // The wall is on the upper side of the block (right, ceiling) or the lower (left, floor).
        if (r.other == kWallRight || r.other == kWallTop)
            relativeLine(f, axis, v1, r.v1, "0", 0.0);
        else
            relativeLine(f, axis, "0", 0.0, v1, r.v1);
        f.u = "u = " + formatNumber(r.u) + "   (the " + name2 + "'s velocity: infinite mass)";
        f.v1After = vAfterLine(v1, r.u, r.C, r.v1, r.v1After);
        f.momentumBefore = "p" + s1 + " before = " + operand(r.m1) + "·" + operand(r.v1) + " = " +
                           formatNumber(r.m1 * r.v1) + " kg·m/s";
        f.momentumAfter = "p" + s1 + " after  = " + operand(r.m1) + "·" + operand(r.v1After) +
                          " = " + formatNumber(r.m1 * r.v1After) + " kg·m/s";
        f.note = "A wall takes any impulse: the block's momentum is not conserved.";
        if (r.rest) f.note = "Rest rule: closing too slowly to bounce, resolved with C = 0.";
        return f;
    }
    f.given = m1 + " = " + formatNumber(r.m1) + ", " + m2 + " = " + formatNumber(r.m2) + ", " + v1 +
              " = " + formatNumber(r.v1) + ", " + v2 + " = " + formatNumber(r.v2) +
              ", C = " + formatNumber(r.C);
    if (r.firstBelow)
        relativeLine(f, axis, v1, r.v1, v2, r.v2);
    else
        relativeLine(f, axis, v2, r.v2, v1, r.v1);
    if (finite1 && finite2) {
        f.u = "u = (" + operand(r.m1) + "·" + operand(r.v1) + " + " + operand(r.m2) + "·" +
              operand(r.v2) + ")/(" + formatNumber(r.m1) + " + " + formatNumber(r.m2) +
              ") = " + formatNumber(r.u);
    } else if (!finite2) {
        f.u = "u = " + v2 + " = " + formatNumber(r.u) + "   (" + m2 + " is infinite)";
    } else {
        f.u = "u = " + v1 + " = " + formatNumber(r.u) + "   (" + m1 + " is infinite)";
    }
    f.v1After = vAfterLine(v1, r.u, r.C, r.v1, r.v1After);
    f.v2After = vAfterLine(v2, r.u, r.C, r.v2, r.v2After);
    if (finite1 && finite2) {
        f.momentumBefore = "p before = " + operand(r.m1) + "·" + operand(r.v1) + " + " +
                           operand(r.m2) + "·" + operand(r.v2) + " = " +
                           formatNumber(r.m1 * r.v1 + r.m2 * r.v2) + " kg·m/s";
        f.momentumAfter = "p after  = " + operand(r.m1) + "·" + operand(r.v1After) + " + " +
                          operand(r.m2) + "·" + operand(r.v2After) + " = " +
                          formatNumber(r.m1 * r.v1After + r.m2 * r.v2After) + " kg·m/s";
    } else {
        const double m = finite1 ? r.m1 : r.m2;
        const double before = finite1 ? r.v1 : r.v2, after = finite1 ? r.v1After : r.v2After;
        const std::string who = "p" + (finite1 ? s1 : s2);
        f.momentumBefore = who + " before = " + operand(m) + "·" + operand(before) + " = " +
                           formatNumber(m * before) + " kg·m/s";
        f.momentumAfter = who + " after  = " + operand(m) + "·" + operand(after) + " = " +
                          formatNumber(m * after) + " kg·m/s";
        f.note =
            "An infinite mass takes any impulse: momentum of the finite body is not conserved.";
    }
    if (r.rest) f.note = "Rest rule: closing too slowly to bounce, resolved with C = 0.";
    return f;
}
