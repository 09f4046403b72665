// Does an equation on screen hold with the numbers as printed? A student with a calculator
// takes `u = (1·6 + 2·0)/(1 + 2) = 2` and gets 2; this checks that for every chain a line of text
// prints, so that what the inspector, the captions and the overlays write is true as displayed.
// Pure functions (no ImGui).
//
// A chain is `side rel side rel side ...`, rel one of = < <= > >= (also ≤ ≥). A side is an
// expression: numbers (signs, decimals, exponents; "inf", "nan"), + - (or −) · × * / ^ ² ³,
// parentheses, |x|, sqrt(x) (or √x), and names (v1', u, |dvt|, mu·|dvn|). A unit after a number
// (m, s, kg, m/s, m/s², kg·m/s, J, N, ...) is read past. Prose around the chains is skipped: a
// side ends where the expression ends (a word, ':', ',', ';').
//
// What holds:
// - The sides joined by `=` agree: every side made of numbers only evaluates, with the operands
//   as printed, to the printed result (the last side that is a plain number, "2", "-0.5",
//   "(-2)") to half a unit of the result's last printed digit (999997.136: +-0.0005; 2: +-0.5;
//   1.5e+12: +-0.05e+12), widened by 1e-9 of that half unit for the double arithmetic of the
//   check itself. A side with a name (`u`, `mu·|dvn|`) is a label: it takes the group's value.
// - Between groups, < <= > >= hold between the printed values (0.4 < 1.15).
// - An expression that evaluates to inf or nan never holds (`inf·0 = nan`).
// - A line break ends a chain, unless the next line starts with an operator or a relation (after
//   spaces; a minus followed by a space): a formula wrapped before an operator reads as one
//   chain (text_format.h, wrapFormula).
#pragma once

#include "text_format.h"

#include <string>
#include <vector>

struct EquationProblem {
    std::string chain; // the chain as printed, e.g. "u = (1·6 + 2·0)/(1 + 2) = 0"
    std::string why;   // e.g. "(1·6 + 2·0)/(1 + 2) is 2, not 0 (to +-0.5)"
};

struct EquationReport {
    int checked = 0; // relations between two numeric sides (or a side and its group's result)
    std::vector<EquationProblem> problems;
    bool holds() const { return problems.empty(); }
};

// Every chain in `text` (one line or many), checked as above. `roundedTo` > 0: the writer rounds
// results to this unit before dropping trailing zeros (formatNumber: 0.001), so a printed "1"
// stands for 1.000 and is held to +-0.0005 (a number with an exponent, "1.18e+13", keeps its own
// digits); 0: only the digits printed count.
EquationReport checkEquations(const std::string& text, double roundedTo = 0.0);
// True when every chain in `text` holds.
bool equationsHold(const std::string& text, double roundedTo = 0.0);

// The app's own lines are checked with `roundedTo` = kFormatNumberUnit (text_format.h): what
// formatNumber rounds to.
