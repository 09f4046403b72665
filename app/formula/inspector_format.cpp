#include "inspector_format.h"

#include "printed_formula.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <initializer_list>
#include <utility>
#include <vector>

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

// The quantities of a record that several lines print: each is written with its own digits, the
// same in every line (the givens, the formulas that take it, the line whose result it is).
enum Quantity { kM1, kM2, kV1, kV2, kC, kU, kV1After, kV2After, kQuantities };

// The lines of one record written with given digits per quantity; `wanted` collects, for each
// chain that does not give its result with those digits, the input that needs one more.
struct LineWriter {
    const CollisionRecord& r;
    int digits[kQuantities] = {};
    std::vector<Quantity> wanted; // one more digit for each: a chain did not hold without it

    double value(Quantity q) const {
        const double values[kQuantities] = {r.m1, r.m2, r.v1, r.v2, r.C, r.u, r.v1After, r.v2After};
        return values[q];
    }
    Printed plain(Quantity q) const { return printed(value(q), digits[q]); }
    Printed operand(Quantity q) const { return printedOperand(value(q), digits[q]); }
    std::string text(Quantity q) const { return formatNumberWithDigits(value(q), digits[q]); }
    // "formula = result", `result` as printed. A chain that does not give its result asks for
    // one more digit of the input whose rounding costs it most (a giant's velocity, not the
    // small block's beside it), found by writing the formula again with that input's every digit.
    std::string equation(const std::function<Printed()>& formula, const std::string& result,
                         const std::vector<Quantity>& inputs) {
        const Printed written = formula();
        if (!givesResult(written, result)) {
            Quantity costliest = kQuantities;
            double most = -1.0;
            for (Quantity q : inputs) {
                if (digits[q] >= kMostExtraDigits) continue;
                const int own = digits[q];
                digits[q] = kMostExtraDigits;
                const double cost = std::abs(formula().value - written.value);
                digits[q] = own;
                if (cost > most) most = cost, costliest = q;
            }
            if (costliest != kQuantities) wanted.push_back(costliest);
        }
        return written.text + " = " + result;
    }

    // v' = u - C·(v - u), the lecture's formula.
    std::string formulaLine(const std::string& v, Quantity before, Quantity after) {
        const auto formula = [&] {
            return plain(kU) - operand(kC) * parenthesized(plain(before) - operand(kU));
        };
        return v + "' = " + equation(formula, text(after), {kU, kC, before});
    }

    // v' = -C·v: without Newton, each body reverses its own component as off a wall at rest.
    std::string reflectLine(const std::string& v, Quantity before, Quantity after) {
        const auto formula = [&] { return negated(operand(kC)) * operand(before); };
        return v + "' = -C·" + v + " = " + equation(formula, text(after), {kC, before});
    }

    // A body of infinite mass: unchanged, or reversed (a kinematic block on a wall, on another
    // infinite mass, or pressing a crushed group).
    std::string infiniteLine(const std::string& v, Quantity before, Quantity after) const {
        if (value(after) == value(before))
            return v + "' = " + v + " = " + text(after) + "   (infinite mass: unchanged)";
        return v + "' = -" + v + " = " + text(after) + "   (infinite mass: it reverses)";
    }

    // "p before = 1·6 + 2·0 = 6 kg·m/s" over the finite bodies given as (mass, velocity) pairs.
    std::string momentumLine(const std::string& label,
                             std::initializer_list<std::pair<Quantity, Quantity>> bodies) {
        double total = 0.0;
        std::vector<Quantity> inputs;
        for (const auto& [m, v] : bodies) {
            total += value(m) * value(v);
            inputs.push_back(m);
            inputs.push_back(v);
        }
        const auto formula = [&] {
            Printed sum;
            for (const auto& [m, v] : bodies) {
                const Printed momentum = operand(m) * operand(v);
                sum = sum.text.empty() ? momentum : sum + momentum;
            }
            return sum;
        };
        return label + " = " + equation(formula, formatNumber(total), inputs) + " kg·m/s";
    }

    // The relative-velocity test along `axis`: `lower` and `upper` name the velocities of the
    // body on the lower side and the one on the upper side (kQuantities: a wall's, 0), which
    // approach when lower - upper > 0.
    void relativeLine(CollisionFormula& f, char axis, const std::string& lowerName, Quantity lower,
                      const std::string& upperName, Quantity upper) {
        const auto velocity = [&](Quantity q) { return q == kQuantities ? 0.0 : value(q); };
        const double closing = velocity(lower) - velocity(upper);
        const std::string shown = formatNumber(closing);
        const auto formula = [&] {
            return (lower == kQuantities ? printed(0.0, 0) : plain(lower)) -
                   (upper == kQuantities ? printed(0.0, 0) : operand(upper));
        };
        std::vector<Quantity> inputs;
        for (Quantity q : {lower, upper})
            if (q != kQuantities) inputs.push_back(q);
        f.relative = std::string("rel. vel. along ") + axis + " = " + lowerName + " - " +
                     upperName + " = " + equation(formula, shown, inputs);
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
    std::string restRuleLine() const {
        const std::string u = "u = " + text(kU) + "   (rest rule: ";
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

    CollisionFormula lines(const std::string& name1, const std::string& name2);
};

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

CollisionFormula LineWriter::lines(const std::string& name1, const std::string& name2) {
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
    if (wall) {
        if (r.other == kWallRight || r.other == kWallTop)
            relativeLine(f, axis, v1, kV1, "0", kQuantities);
        else
            relativeLine(f, axis, "0", kQuantities, v1, kV1);
        if (r.rest && r.rule != ResolveRule::RestAnchored)
            f.u = restRuleLine();
        else
            f.u = "u = " + text(kU) + "   (the " + name2 + "'s velocity: infinite mass)";
        if (!finite1) {
            f.v1After = infiniteLine(v1, kV1, kV1After);
        } else {
            f.v1After = formulaLine(v1, kV1, kV1After);
            f.momentumBefore = momentumLine("p" + s1 + " before", {{kM1, kV1}});
            f.momentumAfter = momentumLine("p" + s1 + " after ", {{kM1, kV1After}});
            f.note = "A wall takes any impulse: the block's momentum is not conserved.";
        }
        f.given = m1 + " = " + text(kM1) + ", " + v1 + " = " + text(kV1) + ", C = " + text(kC) +
                  "; the " + name2 + " does not move";
    } else {
        if (r.firstBelow)
            relativeLine(f, axis, v1, kV1, v2, kV2);
        else
            relativeLine(f, axis, v2, kV2, v1, kV1);
        if (r.rule == ResolveRule::Reflect) {
            f.u = "without Newton (reflect): no u, each block reverses its own velocity";
            f.v1After = reflectLine(v1, kV1, kV1After);
            f.v2After = reflectLine(v2, kV2, kV2After);
        } else if (r.rule == ResolveRule::Reverse) {
            f.u = "two infinite masses: a moving one reverses, as on a wall";
        } else if (finite1 && finite2 && (!r.rest || restFormula)) {
            // u = (m1·v1 + m2·v2)/(m1 + m2), the lecture's velocity of the centre of mass.
            const auto formula = [&] {
                return parenthesized(operand(kM1) * operand(kV1) + operand(kM2) * operand(kV2)) /
                       parenthesized(plain(kM1) + plain(kM2));
            };
            f.u = "u = " + equation(formula, text(kU), {kM1, kV1, kM2, kV2});
        } else if (r.rest && (r.rule != ResolveRule::RestAnchored || (finite1 && finite2))) {
            f.u = restRuleLine();
        } else if (!finite2) {
            f.u = "u = " + v2 + " = " + text(kU) + "   (" + m2 + " is infinite)";
        } else {
            f.u = "u = " + v1 + " = " + text(kU) + "   (" + m1 + " is infinite)";
        }
        if (r.rule != ResolveRule::Reflect) {
            f.v1After = finite1 ? formulaLine(v1, kV1, kV1After) : infiniteLine(v1, kV1, kV1After);
            f.v2After = finite2 ? formulaLine(v2, kV2, kV2After) : infiniteLine(v2, kV2, kV2After);
        }
        if (finite1 && finite2) {
            f.momentumBefore = momentumLine("p before", {{kM1, kV1}, {kM2, kV2}});
            f.momentumAfter = momentumLine("p after ", {{kM1, kV1After}, {kM2, kV2After}});
            if (r.rule == ResolveRule::Reflect)
                f.note = "Without Newton the momentum is not conserved: no equal and opposite "
                         "reaction.";
        } else if (finite1 || finite2) {
            const Quantity m = finite1 ? kM1 : kM2;
            const Quantity before = finite1 ? kV1 : kV2, after = finite1 ? kV1After : kV2After;
            const std::string who = "p" + (finite1 ? s1 : s2);
            f.momentumBefore = momentumLine(who + " before", {{m, before}});
            f.momentumAfter = momentumLine(who + " after ", {{m, after}});
            f.note =
                "An infinite mass takes any impulse: momentum of the finite body is not conserved.";
        }
        f.given = m1 + " = " + text(kM1) + ", " + m2 + " = " + text(kM2) + ", " + v1 + " = " +
                  text(kV1) + ", " + v2 + " = " + text(kV2) + ", C = " + text(kC);
    }
    if (r.rest) {
        f.note = r.restForced ? "Rest rule: a sequence that would not end (collapse, trap or "
                                "crush), resolved perfectly inelastic (C = 0)."
                              : "Rest rule: closing too slowly to bounce, resolved with C = 0.";
    }
    f.friction = frictionLine(r);
    return f;
}

} // namespace

// Each quantity is written with the same digits in every line: the giant's v2 is not "1" in u's
// formula and 0.9999987301 among the givens, nor u "1" in its line and 0.9999993651 in v2'. All
// start with formatNumber's three decimals; a chain that does not give its result as printed
// (printed_formula.h, givesResult) gives one more digit to the quantity it reads whose rounding
// costs it most, and the lines are written again, until every chain holds (or its inputs have
// kMostExtraDigits). A result read by a later line (u, v1', v2') keeps its own digits, so the lines
// before it take more.
CollisionFormula collisionFormula(const CollisionRecord& r, const std::string& name1,
                                  const std::string& name2) {
    LineWriter writer{r, {}, {}};
    for (;;) {
        writer.wanted.clear();
        CollisionFormula f = writer.lines(name1, name2);
        if (writer.wanted.empty()) {
            f.m1Text = writer.text(kM1);
            f.m2Text = writer.text(kM2);
            f.v1AfterText = writer.text(kV1After);
            f.v2AfterText = writer.text(kV2After);
            return f;
        }
        for (Quantity q : writer.wanted)
            writer.digits[q] = std::min(writer.digits[q] + 1, kMostExtraDigits);
    }
}

std::string productAsPrinted(const std::string& a, const std::string& b) {
    const auto magnitude = [](const std::string& x) {
        return !x.empty() && x[0] == '-' ? x.substr(1) : x;
    };
    return exactProduct(magnitude(a), magnitude(b));
}
