// The numbers a lesson's texts print and the conditions its choices state, as expressions of the
// live world (docs/lesson-format.md, "Expressions"): `-C*block.vx0`, `m1.vx == u - C*(m1.vx0 - u)`,
// `abs(crate.x - 6.67) < 0.01`. Parsed once when the lesson loads (every name resolved against
// the step's scene: a misspelt block is an error at its JSON path), evaluated whenever the world
// changes, and printed with its numbers filled in as the inspector prints them (printed_formula.h:
// an equation holds with the digits shown). No GL, no ImGui.
#pragma once

#include "printed_formula.h"
#include "scene.h"
#include "world.h"

#include <string>
#include <vector>

// One parsed expression. Numbers, names, + - * / ^, parentheses, abs() sqrt() min() max() floor()
// ceil() atan(); for a condition also == != < <= > >= (== within 1e-9 of the larger magnitude, at
// least 1e-9), and, or, not.
struct LessonExpr {
    struct Node {
        enum class Kind {
            Number,  // a literal, `text` as written
            Global,  // C, g, t, ... (`name`)
            Block,   // a block's quantity now or at the setup (`block`, `name`, `atSetup`)
            Value,   // one of the step's named values (`block` is its index)
            Hit,     // a number of the event's collision (hit.u, hit.v1, ...: `name`)
            Group,   // (a): the author's parentheses, kept when printed
            Negate,  // -a
            Not,     // not a
            Binary,  // a op b: + - * / ^
            Compare, // a op b: == != < <= > >=
            Logic,   // a and b, a or b
            Call,    // abs(a), sqrt(a), min(a, b), max(a, b)
        };
        Kind kind = Kind::Number;
        std::string text; // a literal's digits; an operator; a function's or a name's name
        double number = 0.0;
        int block = -1;       // Block: the block's index; Value: the value's index
        bool atSetup = false; // Block: the quantity at the setup (a name ending in 0: x0, vx0)
        std::vector<int> args;
    };
    std::string source; // as written
    std::vector<Node> nodes;
    int root = -1;
    bool condition = false; // true or false rather than a number

    bool empty() const { return root < 0; }
};

// What the names of an expression read: the world at the setup (t = 0, the question asked) and
// the world now (at the event for an answer; the setup itself for a question), with what the run
// counted up to now.
struct ExprScope {
    const World* setup = nullptr;
    const World* now = nullptr;
    int collisions = 0;          // since the step began (rest-rule contacts not counted)
    int contacts = 0;            // rest-rule contacts since the step began
    double maxPenetration = 0.0; // m, the largest overlap met since the step began
    // The step's named values (LessonStep::values), which an expression may read by name.
    const std::vector<LessonExpr>* values = nullptr;
    // The collision the event is (a collision event's, oriented so that body 1 is the block the
    // event names); null for other events and at the setup.
    const CollisionRecord* hit = nullptr;
    // Where the step's blocks are in these worlds (lesson_runner.h, liveBlockIndex): the step's
    // block i is world block (*blocks)[i], -1 when it is gone; none: the same index.
    const std::vector<int>* blocks = nullptr;
};

// Parses `text` against `scene` (block names) and the step's `values` defined before it (their
// names, in order); throws scene_json::ValueError at `path` with the column and what is wrong
// (`steps[3].choices[1].if: column 12: no block named "m3" in the step's scene`). `condition`: the
// expression must be a condition (a comparison, and/or/not of them); otherwise a number.
// `columnOffset`: where the expression starts in the text it was taken from (a `{...}` of a
// template), added to the columns errors name.
LessonExpr parseLessonExpr(const std::string& text, const Scene& scene,
                           const std::vector<std::string>& valueNames, bool condition,
                           const std::string& path, std::size_t columnOffset = 0);

// The value of `e` in `scope` (a condition: 1 or 0). NaN when a name reads a block the world no
// longer has (a block removed) or a world that is missing.
double evaluate(const LessonExpr& e, const ExprScope& scope);
// True when the condition `e` holds in `scope`.
bool holds(const LessonExpr& e, const ExprScope& scope);
// `e` with every name replaced by its value, written with `extra` more digits than the inspector's
// three decimals (printed_formula.h): "-0.5·4", "(1·6 + 2·0)/(1 + 2)"; its value is what those
// digits give.
Printed printedExpr(const LessonExpr& e, const ExprScope& scope, int extra);
// "formula = result" as the inspector writes an equation: the fewest extra digits with which the
// printed formula gives the printed result ("-0.5·4 = -2").
std::string printedEquation(const LessonExpr& e, const ExprScope& scope);

// The names an expression may read, for the docs and error messages.
const std::vector<std::string>& lessonGlobalNames();
const std::vector<std::string>& lessonBlockQuantities();
const std::vector<std::string>& lessonHitQuantities();
