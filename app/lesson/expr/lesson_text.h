// A lesson's question, choices and answer as templates of the live world (docs/lesson-format.md,
// "Computed text"): literal text with
//   {EXPR}               the expression's value as the inspector prints a number ("-2", "0.625")
//   {= EXPR}             the expression with its numbers filled in and its result, as an
//                        equation that holds with the digits shown ("-0.5·4 = -2")
//   {as written: TEXT}   text that holds only for the step as written: shown as it is while the
//                        world is, and as "(as written: TEXT)" once the lecturer changed something
//                        (spaces, commas, semicolons and colons around TEXT dropped)
//   {{ and }}            a literal brace
// Parsed when the lesson loads (every expression's names resolved, errors at their JSON path and
// column), rendered whenever it is shown. No GL, no ImGui.
#pragma once

#include "lesson_expr.h"

#include <string>
#include <vector>

struct LessonText {
    struct Part {
        enum class Kind { Literal, Value, Equation, AsWritten };
        Kind kind = Kind::Literal;
        std::string text; // Literal, AsWritten
        LessonExpr expr;  // Value, Equation
    };
    std::string source; // as written in the file
    std::vector<Part> parts;

    bool empty() const { return source.empty(); }
    // True when the text computes something from the world (it has a {...}).
    bool computed() const;
};

// Parses a template (`text` as the file has it, checked by lesson_guards::text before); throws
// scene_json::ValueError at `path` ("steps[3].answer: column 17: unknown name \"v\"").
LessonText parseLessonText(const std::string& text, const Scene& scene,
                           const std::vector<std::string>& valueNames, const std::string& path);
// The text with its numbers for `scope`; `asWritten`: the world is the step as written (its
// {as written: ...} parts stand as they are).
std::string renderLessonText(const LessonText& text, const ExprScope& scope, bool asWritten);
