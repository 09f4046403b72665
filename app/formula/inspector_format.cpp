#include "inspector_format.h"

#include "printed_formula.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <utility>

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

// v' = u - C·(v - u), the lecture's formula.
std::string formulaLine(const std::string& v, double u, double C, double before, double after,
                        int* used) {
    const auto formula = [&](int x) {
        return printed(u, x) -
               printedOperand(C, x) * parenthesized(printed(before, x) - printedOperand(u, x));
    };
    return v + "' = " + equationWithFewestDigits(formula, after, used);
}

// v' = -C·v: without Newton, each body reverses its own component as off a wall at rest.
std::string reflectLine(const std::string& v, double C, double before, double after, int* used) {
    const auto formula = [&](int x) {
        return negated(printedOperand(C, x)) * printedOperand(before, x);
    };
    return v + "' = -C·" + v + " = " + equationWithFewestDigits(formula, after, used);
}

// A body of infinite mass: unchanged, or reversed (a kinematic block on a wall, on another
// infinite mass, or pressing a crushed group).
std::string infiniteLine(const std::string& v, double before, double after) {
    if (after == before)
        return v + "' = " + v + " = " + formatNumber(after) + "   (infinite mass: unchanged)";
    return v + "' = -" + v + " = " + formatNumber(after) + "   (infinite mass: it reverses)";
}

// "p before = 1·6 + 2·0 = 6 kg·m/s" over the finite bodies given as (mass, velocity) pairs.
std::string momentumLine(const std::string& label,
                         std::initializer_list<std::pair<double, double>> bodies, int* used) {
    double total = 0.0;
    for (const auto& [m, v] : bodies) total += m * v;
    const auto formula = [&](int x) {
        Printed sum;
        for (const auto& [m, v] : bodies) {
            const Printed momentum = printedOperand(m, x) * printedOperand(v, x);
            sum = sum.text.empty() ? momentum : sum + momentum;
        }
        return sum;
    };
    return label + " = " + equationWithFewestDigits(formula, total, used) + " kg·m/s";
}

// The relative-velocity test along `axis`: `lower` and `upper` name the velocities of the body
// on the lower side and the one on the upper side (the wall's is 0), which approach when
// lower - upper > 0.
void relativeLine(CollisionFormula& f, char axis, const std::string& lowerName, double lower,
                  const std::string& upperName, double upper) {
    const double closing = lower - upper;
    const std::string shown = formatNumber(closing);
    const auto formula = [&](int x) { return printed(lower, x) - printedOperand(upper, x); };
    f.relative = std::string("rel. vel. along ") + axis + " = " + lowerName + " - " + upperName +
                 " = " + equationWithFewestDigits(formula, closing);
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

// What the rest rule did, for CollisionFormula::u when it is not the pair's formula.
std::string restRuleLine(const CollisionRecord& r) {
    const std::string u = "u = " + formatNumber(r.u) + "   (rest rule: ";
    switch (r.rule) {
    case ResolveRule::RestAnchored:
        return u + "the resting blocks move with the infinite mass they rest on)";
    case ResolveRule::RestCrushed:
        return u + "squeezed between infinite masses that move apart or together: the ones "
                   "pressing reverse)";
    default:
        return u + "the " + std::to_string(r.restBodies) +
               " resting blocks move together: their momentum over their mass)";
    }
}

// The product of two numbers as formatNumber writes them ("0.5", "2.3"), exact in decimal
// ("1.15"), so that "0.5·2.3 = 1.15" holds with the digits shown; "" when either is not a plain
// decimal (scientific, inf) or the digits are too many.
std::string exactProduct(const std::string& a, const std::string& b) {
    unsigned long long mantissa = 1;
    int decimals = 0;
    for (const std::string& s : {a, b}) {
        if (s.empty() || s.size() > 12) return "";
        unsigned long long m = 0;
        bool point = false;
        for (char c : s) {
            if (c == '.' && !point) {
                point = true;
            } else if (c >= '0' && c <= '9') {
                m = m * 10 + static_cast<unsigned long long>(c - '0');
                decimals += point ? 1 : 0;
            } else {
                return "";
            }
        }
        if (m != 0 && mantissa > ~0ull / m) return "";
        mantissa *= m;
    }
    std::string digits = std::to_string(mantissa);
    if (decimals == 0) return digits;
    if (static_cast<int>(digits.size()) <= decimals)
        digits.insert(0, static_cast<std::size_t>(decimals + 1) - digits.size(), '0');
    std::string out = digits.substr(0, digits.size() - static_cast<std::size_t>(decimals)) + "." +
                      digits.substr(digits.size() - static_cast<std::size_t>(decimals));
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
    return out;
}

// The friction line (CollisionFormula::friction) of a record with mu > 0.
std::string frictionLine(const CollisionRecord& r) {
    if (!(r.mu > 0.0)) return "";
    const char tangent = r.axis == 0 ? 'y' : 'x';
    const char* unit = r.perSecond ? " m/s²" : " m/s";
    const std::string mu = formatNumber(r.mu), dvn = formatNumber(std::abs(r.dvn));
    const std::string dvt = formatNumber(std::abs(r.dvt)), bound = exactProduct(mu, dvn);
    const std::string product =
        "mu·|dvn| = " + mu + "·" + dvn + (bound.empty() ? "" : " = " + bound);
    std::string line = std::string("friction along ") + tangent + ": ";
    if (r.perSecond) line = std::string("friction along ") + tangent + " (resting, per second): ";
    // Kinetic: the whole bound was used (to rounding), or the digits shown cannot tell it apart.
    const bool kinetic = std::abs(r.dvt) >= std::abs(r.mu * r.dvn) * (1.0 - kNoiseRelative) ||
                         bound.empty() ||
                         std::strtod(dvt.c_str(), nullptr) >= std::strtod(bound.c_str(), nullptr);
    if (kinetic) return line + "|dvt| = " + product + unit + " (kinetic: still sliding)";
    return line + "|dvt| = " + dvt + " < " + product + unit + " (stopped sliding)";
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
    const bool finite1 = std::isfinite(r.m1), finite2 = std::isfinite(r.m2) && !wall;
    const bool restFormula = r.rule == ResolveRule::RestFree && r.restBodies == 2;
    // The digits the formula lines needed: the givens are written with as many.
    int used = 0;
    if (wall) {
        if (r.other == kWallRight || r.other == kWallTop)
            relativeLine(f, axis, v1, r.v1, "0", 0.0);
        else
            relativeLine(f, axis, "0", 0.0, v1, r.v1);
        if (r.rest && r.rule != ResolveRule::RestAnchored)
            f.u = restRuleLine(r);
        else
            f.u = "u = " + formatNumber(r.u) + "   (the " + name2 + "'s velocity: infinite mass)";
        if (!finite1) {
            f.v1After = infiniteLine(v1, r.v1, r.v1After);
        } else {
            f.v1After = formulaLine(v1, r.u, r.C, r.v1, r.v1After, &used);
            f.momentumBefore = momentumLine("p" + s1 + " before", {{r.m1, r.v1}}, &used);
            f.momentumAfter = momentumLine("p" + s1 + " after ", {{r.m1, r.v1After}}, &used);
            f.note = "A wall takes any impulse: the block's momentum is not conserved.";
        }
        f.given = m1 + " = " + formatNumberWithDigits(r.m1, used) + ", " + v1 + " = " +
                  formatNumberWithDigits(r.v1, used) +
                  ", C = " + formatNumberWithDigits(r.C, used) + "; the " + name2 +
                  " does not move";
    } else {
        if (r.firstBelow)
            relativeLine(f, axis, v1, r.v1, v2, r.v2);
        else
            relativeLine(f, axis, v2, r.v2, v1, r.v1);
        if (r.rule == ResolveRule::Reflect) {
            f.u = "without Newton (reflect): no u, each block reverses its own velocity";
            f.v1After = reflectLine(v1, r.C, r.v1, r.v1After, &used);
            f.v2After = reflectLine(v2, r.C, r.v2, r.v2After, &used);
        } else if (r.rule == ResolveRule::Reverse) {
            f.u = "two infinite masses: a moving one reverses, as on a wall";
        } else if (finite1 && finite2 && (!r.rest || restFormula)) {
            // u = (m1·v1 + m2·v2)/(m1 + m2), the lecture's velocity of the centre of mass.
            const auto formula = [&](int x) {
                const Printed m1 = printedOperand(r.m1, x), m2 = printedOperand(r.m2, x);
                return parenthesized(m1 * printedOperand(r.v1, x) + m2 * printedOperand(r.v2, x)) /
                       parenthesized(printed(r.m1, x) + printed(r.m2, x));
            };
            f.u = "u = " + equationWithFewestDigits(formula, r.u, &used);
        } else if (r.rest && (r.rule != ResolveRule::RestAnchored || (finite1 && finite2))) {
            f.u = restRuleLine(r);
        } else if (!finite2) {
            f.u = "u = " + v2 + " = " + formatNumber(r.u) + "   (" + m2 + " is infinite)";
        } else {
            f.u = "u = " + v1 + " = " + formatNumber(r.u) + "   (" + m1 + " is infinite)";
        }
        if (r.rule != ResolveRule::Reflect) {
            f.v1After = finite1 ? formulaLine(v1, r.u, r.C, r.v1, r.v1After, &used)
                                : infiniteLine(v1, r.v1, r.v1After);
            f.v2After = finite2 ? formulaLine(v2, r.u, r.C, r.v2, r.v2After, &used)
                                : infiniteLine(v2, r.v2, r.v2After);
        }
        if (finite1 && finite2) {
            f.momentumBefore = momentumLine("p before", {{r.m1, r.v1}, {r.m2, r.v2}}, &used);
            f.momentumAfter =
                momentumLine("p after ", {{r.m1, r.v1After}, {r.m2, r.v2After}}, &used);
            if (r.rule == ResolveRule::Reflect)
                f.note = "Without Newton the momentum is not conserved: no equal and opposite "
                         "reaction.";
        } else if (finite1 || finite2) {
            const double m = finite1 ? r.m1 : r.m2;
            const double before = finite1 ? r.v1 : r.v2, after = finite1 ? r.v1After : r.v2After;
            const std::string who = "p" + (finite1 ? s1 : s2);
            f.momentumBefore = momentumLine(who + " before", {{m, before}}, &used);
            f.momentumAfter = momentumLine(who + " after ", {{m, after}}, &used);
            f.note =
                "An infinite mass takes any impulse: momentum of the finite body is not conserved.";
        }
        f.given = m1 + " = " + formatNumberWithDigits(r.m1, used) + ", " + m2 + " = " +
                  formatNumberWithDigits(r.m2, used) + ", " + v1 + " = " +
                  formatNumberWithDigits(r.v1, used) + ", " + v2 + " = " +
                  formatNumberWithDigits(r.v2, used) + ", C = " + formatNumberWithDigits(r.C, used);
    }
    if (r.rest) {
        f.note = r.restForced ? "Rest rule: a sequence that would not end (collapse, trap or "
                                "crush), resolved perfectly inelastic (C = 0)."
                              : "Rest rule: closing too slowly to bounce, resolved with C = 0.";
    }
    f.friction = frictionLine(r);
    return f;
}
