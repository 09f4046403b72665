// Formulas with their numbers as printed: each operand is written as formatNumberWithDigits
// writes it and carries the value a reader takes from those digits, so a formula built from them
// ("1·6 + 2·0", "(1·6 + 2·0)/(1 + 2)") is at once its text and what a student with a calculator
// gets from it, worked out as written (left to right, · and / before + and -). The digits an
// equation needs are chosen on these numbers (equationWithFewestDigits): nothing is written to be
// read back. The equation checker (equation_check.h) stays the tests' independent judge.
#pragma once

#include "text_format.h"

#include <string>

struct Printed {
    std::string text;   // "1·(-2) + 2·4"
    double value = 0.0; // what the digits in `text` give
};

// The number a text of formatNumberWithDigits' gives: std::strtod's answer, bit for bit (faster
// for its usual texts, "-0.932", "2.376").
double shownNumber(const char* text);
// `value` as formatNumberWithDigits(value, extra) writes it ("0.99999354"), and that number.
Printed printed(double value, int extra);
// The same in parentheses when negative, as operand() writes it: "(-2)".
Printed printedOperand(double value, int extra);
Printed operator+(const Printed& a, const Printed& b); // "a + b"
Printed operator-(const Printed& a, const Printed& b); // "a - b"
Printed operator*(const Printed& a, const Printed& b); // "a·b"
Printed operator/(const Printed& a, const Printed& b); // "a/b"
Printed parenthesized(const Printed& a);               // "(a)"
Printed negated(const Printed& a);                     // "-a"

// True when `formula` gives `shownResult`, a number as formatNumber writes it: within half a unit
// of its last digit, and of kFormatNumberUnit when formatNumber dropped zeros (its "1" is 1.000),
// widened by 1e-9 of that half unit for the double arithmetic; a number with an exponent keeps its
// own digits. An infinite or undefined value is given by nothing.
bool givesResult(const Printed& formula, const std::string& shownResult);

// "formula = result": `formula(extra)` with the fewest extra digits (0 to kMostExtraDigits) that
// give `result` as formatNumber writes it ("1·3.594 + 1000000·0.999993541 = 999997.135", not
// "... + 1000000·1 = ..."), with all of them when none does. `*used` is raised to the digits taken
// (the givens beside a formula are then written with as many).
template <class Formula>
std::string equationWithFewestDigits(const Formula& formula, double result, int* used = nullptr) {
    const std::string shown = formatNumber(result);
    int extra = 0;
    Printed written = formula(extra);
    while (extra < kMostExtraDigits && !givesResult(written, shown)) written = formula(++extra);
    if (used && *used < extra) *used = extra;
    return written.text + " = " + shown;
}
