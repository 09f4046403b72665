#include "lesson_expr.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

using Node = LessonExpr::Node;
using Kind = Node::Kind;

const std::vector<std::string> kGlobals = {
    "C",                 // bounciness
    "g",                 // m/s^2, |gravity|
    "gx",          "gy", // m/s^2, gravity's components
    "mu",                // the world's friction coefficient
    "rate",              // frames per second, 1/dt
    "dt",                // s
    "t",                 // s, the world's time
    "collisions",        // since the step began
    "contacts",          // rest-rule contacts since the step began
    "penetration",       // m, the largest overlap met since the step began
    "ke",          "px",      "py", "ke0", "px0", "py0", // totals now and at the setup
    "pe",          "pe0",     // J, potential energy in gravity (world.h: from the bounds' corner)
    "energy",      "energy0", // J, ke + pe
    "drag",                   // kg/m^3, the world's drag k
    "pi",
};

// The event's collision (CollisionRecord, body 1 the block the event names).
const std::vector<std::string> kHitQuantities = {"m1",      "m2", "v1", "v2", "v1after",
                                                 "v2after", "u",  "C",  "t",  "toi",
                                                 "x1",      "y1", "x2", "y2", "axis"};

const std::vector<std::string> kBlockQuantities = {
    "x",   "y",      "vx",    "vy", "m",  "w",  "h",  "left", "right",
    "top", "bottom", "speed", "px", "py", "ke", "fx", "fy"}; // fx, fy: N, the block's own constant
                                                             // force

double blockQuantity(const Block& b, const std::string& q) {
    if (q == "x") return b.position.x;
    if (q == "y") return b.position.y;
    if (q == "vx") return b.velocity.x;
    if (q == "vy") return b.velocity.y;
    if (q == "m") return b.mass;
    if (q == "w") return b.size.x;
    if (q == "h") return b.size.y;
    if (q == "left") return b.position.x - b.halfSize().x;
    if (q == "right") return b.position.x + b.halfSize().x;
    if (q == "bottom") return b.position.y - b.halfSize().y;
    if (q == "top") return b.position.y + b.halfSize().y;
    if (q == "speed") return std::hypot(b.velocity.x, b.velocity.y);
    if (q == "px") return b.mass * b.velocity.x;
    if (q == "py") return b.mass * b.velocity.y;
    if (q == "ke")
        return 0.5 * b.mass * (b.velocity.x * b.velocity.x + b.velocity.y * b.velocity.y);
    if (q == "fx") return b.force.x;
    if (q == "fy") return b.force.y;
    return NAN;
}

double hitQuantity(const std::string& q, const CollisionRecord* r) {
    if (!r) return NAN;
    if (q == "m1") return r->m1;
    if (q == "m2") return r->m2;
    if (q == "v1") return r->v1;
    if (q == "v2") return r->v2;
    if (q == "v1after") return r->v1After;
    if (q == "v2after") return r->v2After;
    if (q == "u") return r->u;
    if (q == "C") return r->C;
    if (q == "t") return r->time;
    if (q == "toi") return r->toi;
    if (q == "x1") return r->position1.x;
    if (q == "y1") return r->position1.y;
    if (q == "x2") return r->position2.x;
    if (q == "y2") return r->position2.y;
    return r->axis;
}

double globalQuantity(const std::string& q, const ExprScope& s) {
    if (q == "pi") return 3.14159265358979323846;
    const World* w = s.now;
    if (q.size() > 1 && q.back() == '0') w = s.setup; // ke0, px0, py0, pe0, energy0
    if (!w) return NAN;
    if (q == "C") return w->settings.bounciness;
    if (q == "g") return std::hypot(w->settings.gravity.x, w->settings.gravity.y);
    if (q == "gx") return w->settings.gravity.x;
    if (q == "gy") return w->settings.gravity.y;
    if (q == "mu") return w->settings.friction;
    if (q == "rate") return 1.0 / w->settings.dt;
    if (q == "dt") return w->settings.dt;
    if (q == "t") return w->time;
    if (q == "collisions") return s.collisions;
    if (q == "contacts") return s.contacts;
    if (q == "penetration") return s.maxPenetration;
    if (q == "drag") return w->settings.drag;
    if (q == "pe" || q == "pe0") return potentialEnergy(*w);
    if (q == "energy" || q == "energy0") return kineticEnergy(*w) + potentialEnergy(*w);
    if (q == "ke" || q == "ke0") return kineticEnergy(*w);
    if (q == "px" || q == "px0") return totalMomentum(*w).x;
    if (q == "py" || q == "py0") return totalMomentum(*w).y;
    return NAN;
}

// |a - b| within 1e-9 of the larger magnitude (at least 1e-9): equal as the engine computes.
bool nearlyEqual(double a, double b) {
    return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

double eval(const LessonExpr& e, int i, const ExprScope& s) {
    const Node& n = e.nodes[static_cast<std::size_t>(i)];
    const auto arg = [&](std::size_t k) { return eval(e, n.args[k], s); };
    switch (n.kind) {
    case Kind::Number:
        return n.number;
    case Kind::Global:
        return globalQuantity(n.text, s);
    case Kind::Block: {
        const World* w = n.atSetup ? s.setup : s.now;
        int index = n.block;
        if (s.blocks)
            index = static_cast<std::size_t>(n.block) < s.blocks->size()
                        ? (*s.blocks)[static_cast<std::size_t>(n.block)]
                        : -1;
        if (!w || index < 0 || static_cast<std::size_t>(index) >= w->blocks.size()) return NAN;
        return blockQuantity(w->blocks[static_cast<std::size_t>(index)], n.text);
    }
    case Kind::Hit:
        return hitQuantity(n.text, s.hit);
    case Kind::Value:
        if (!s.values || static_cast<std::size_t>(n.block) >= s.values->size()) return NAN;
        return evaluate((*s.values)[static_cast<std::size_t>(n.block)], s);
    case Kind::Group:
        return arg(0);
    case Kind::Negate:
        return -arg(0);
    case Kind::Not:
        return arg(0) != 0.0 ? 0.0 : 1.0;
    case Kind::Binary: {
        const double a = arg(0), b = arg(1);
        if (n.text == "+") return a + b;
        if (n.text == "-") return a - b;
        if (n.text == "*") return a * b;
        if (n.text == "/") return a / b;
        return std::pow(a, b);
    }
    case Kind::Compare: {
        const double a = arg(0), b = arg(1);
        if (std::isnan(a) || std::isnan(b)) return 0.0; // nothing holds of a missing block
        bool r = false;
        if (n.text == "==")
            r = nearlyEqual(a, b);
        else if (n.text == "!=")
            r = !nearlyEqual(a, b);
        else if (n.text == "<")
            r = a < b;
        else if (n.text == "<=")
            r = a <= b;
        else if (n.text == ">")
            r = a > b;
        else
            r = a >= b;
        return r ? 1.0 : 0.0;
    }
    case Kind::Logic: {
        const bool a = arg(0) != 0.0;
        if (n.text == "and") return a && arg(1) != 0.0 ? 1.0 : 0.0;
        return a || arg(1) != 0.0 ? 1.0 : 0.0;
    }
    case Kind::Call:
        if (n.text == "abs") return std::abs(arg(0));
        if (n.text == "sqrt") return std::sqrt(arg(0));
        if (n.text == "floor") return std::floor(arg(0));
        if (n.text == "ceil") return std::ceil(arg(0));
        if (n.text == "atan") return std::atan(arg(0));
        if (n.text == "min") return std::min(arg(0), arg(1));
        return std::max(arg(0), arg(1));
    }
    return NAN;
}

// `leftmost`: the node starts its expression or its parentheses, so a negative number there needs
// no parentheses of its own ("-1 - 1·(3 - (-1))"), unless it is raised to a power ("(-2)²").
Printed print(const LessonExpr& e, int i, const ExprScope& s, int extra, bool leftmost) {
    const Node& n = e.nodes[static_cast<std::size_t>(i)];
    const auto arg = [&](std::size_t k, bool first = false) {
        return print(e, n.args[k], s, extra, first);
    };
    switch (n.kind) {
    case Kind::Number: {
        Printed p;
        p.text = n.text;
        p.value = n.number;
        return p;
    }
    case Kind::Group:
        return parenthesized(arg(0, true));
    case Kind::Negate:
        return negated(arg(0));
    case Kind::Binary: {
        const Printed a = arg(0, leftmost && n.text != "^"), b = arg(1);
        if (n.text == "+") return a + b;
        if (n.text == "-") return a - b;
        if (n.text == "*") return a * b;
        if (n.text == "/") return a / b;
        const Node& exponent = e.nodes[static_cast<std::size_t>(n.args[1])];
        if (exponent.kind == Kind::Number && exponent.number == 2.0)
            return {a.text + "\u00b2", a.value * a.value};
        return {a.text + "^" + b.text, std::pow(a.value, b.value)};
    }
    case Kind::Call:
        if (n.text == "abs") {
            const Printed a = arg(0, true);
            return {"|" + a.text + "|", std::abs(a.value)};
        }
        if (n.text == "sqrt") {
            const Printed a = arg(0, true);
            return {"sqrt(" + a.text + ")", std::sqrt(a.value)};
        }
        return printedOperand(eval(e, i, s), extra); // min, max, floor, ...: their value
    default: // a name: its value as an operand, "(-2)" when negative
        return leftmost ? printed(eval(e, i, s), extra) : printedOperand(eval(e, i, s), extra);
    }
}

} // namespace

double evaluate(const LessonExpr& e, const ExprScope& scope) {
    return e.empty() ? NAN : eval(e, e.root, scope);
}

bool holds(const LessonExpr& e, const ExprScope& scope) {
    return !e.empty() && evaluate(e, scope) != 0.0;
}

Printed printedExpr(const LessonExpr& e, const ExprScope& scope, int extra) {
    if (e.empty()) return {};
    return print(e, e.root, scope, extra, true);
}

std::string printedEquation(const LessonExpr& e, const ExprScope& scope) {
    return equationWithFewestDigits([&](int extra) { return printedExpr(e, scope, extra); },
                                    evaluate(e, scope));
}

const std::vector<std::string>& lessonGlobalNames() {
    return kGlobals;
}

const std::vector<std::string>& lessonBlockQuantities() {
    return kBlockQuantities;
}

const std::vector<std::string>& lessonHitQuantities() {
    return kHitQuantities;
}
