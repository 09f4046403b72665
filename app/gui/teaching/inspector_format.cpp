#include "inspector_format.h"

#include <cmath>
#include <cstdio>

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[48];
    const double a = std::abs(value);
    if (a >= 1e6 || (a > 0.0 && a < 5e-4)) {
        std::snprintf(text, sizeof text, "%.3g", value);
        return text;
    }
    std::snprintf(text, sizeof text, "%.3f", value);
    std::string s = text;
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
    if (s == "-0") s = "0";
    return s;
}

std::string operand(double value) {
    const std::string s = formatNumber(value);
    return !s.empty() && s[0] == '-' ? "(" + s + ")" : s;
}

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

std::string vAfterLine(const char* name, double u, double C, double v, double after) {
    // v' = u - C·(v - u)
    return std::string(name) + "' = " + formatNumber(u) + " - " + operand(C) + "·(" +
           formatNumber(v) + " - " + operand(u) + ") = " + formatNumber(after);
}

} // namespace

CollisionFormula collisionFormula(const CollisionRecord& r, const std::string& name1,
                                  const std::string& name2) {
    CollisionFormula f;
    const char axis = r.axis == 0 ? 'x' : 'y';
    f.title =
        name1 + "  hits  " + name2 + "  along " + axis + " at t = " + formatNumber(r.time) + " s";
    f.given = "m1 = " + formatNumber(r.m1) + ", m2 = " + formatNumber(r.m2) +
              ", v1 = " + formatNumber(r.v1) + ", v2 = " + formatNumber(r.v2) +
              ", C = " + formatNumber(r.C);
    const bool finite1 = std::isfinite(r.m1), finite2 = std::isfinite(r.m2);
    if (finite1 && finite2) {
        f.u = "u = (" + operand(r.m1) + "·" + operand(r.v1) + " + " + operand(r.m2) + "·" +
              operand(r.v2) + ")/(" + formatNumber(r.m1) + " + " + formatNumber(r.m2) +
              ") = " + formatNumber(r.u);
    } else if (!finite2) {
        f.u = "u = v2 = " + formatNumber(r.u) + "   (m2 is infinite)";
    } else {
        f.u = "u = v1 = " + formatNumber(r.u) + "   (m1 is infinite)";
    }
    f.v1After = vAfterLine("v1", r.u, r.C, r.v1, r.v1After);
    f.v2After = vAfterLine("v2", r.u, r.C, r.v2, r.v2After);
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
        const char* who = finite1 ? "p1" : "p2";
        f.momentumBefore = std::string(who) + " before = " + operand(m) + "·" + operand(before) +
                           " = " + formatNumber(m * before) + " kg·m/s";
        f.momentumAfter = std::string(who) + " after  = " + operand(m) + "·" + operand(after) +
                          " = " + formatNumber(m * after) + " kg·m/s";
        f.note =
            "An infinite mass takes any impulse: momentum of the finite body is not conserved.";
    }
    if (r.rest) f.note = "Rest rule: closing too slowly to bounce, resolved with C = 0.";
    return f;
}
