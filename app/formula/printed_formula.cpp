#include "printed_formula.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

Printed printed(double value, int extra) {
    Printed p;
    p.text = formatNumberWithDigits(value, extra);
    p.value = std::strtod(p.text.c_str(), nullptr);
    return p;
}

Printed printedOperand(double value, int extra) {
    const Printed p = printed(value, extra);
    return !p.text.empty() && p.text[0] == '-' ? parenthesized(p) : p;
}

Printed operator+(const Printed& a, const Printed& b) {
    return {a.text + " + " + b.text, a.value + b.value};
}

Printed operator-(const Printed& a, const Printed& b) {
    return {a.text + " - " + b.text, a.value - b.value};
}

Printed operator*(const Printed& a, const Printed& b) {
    return {a.text + "\u00b7" + b.text, a.value * b.value};
}

Printed operator/(const Printed& a, const Printed& b) {
    return {a.text + "/" + b.text, a.value / b.value};
}

Printed parenthesized(const Printed& a) {
    return {"(" + a.text + ")", a.value};
}

Printed negated(const Printed& a) {
    return {"-" + a.text, -a.value};
}

bool givesResult(const Printed& formula, const std::string& shownResult) {
    const double result = std::strtod(shownResult.c_str(), nullptr);
    if (!std::isfinite(result) || !std::isfinite(formula.value)) return false;
    // The unit of the last digit shown: 10^(exponent - decimals).
    const std::size_t point = shownResult.find('.'), e = shownResult.find('e');
    const std::size_t mantissaEnd = e == std::string::npos ? shownResult.size() : e;
    const int decimals = point == std::string::npos ? 0 : static_cast<int>(mantissaEnd - point - 1);
    const int exponent = e == std::string::npos ? 0 : std::atoi(shownResult.c_str() + e + 1);
    double unit = std::pow(10.0, exponent - decimals);
    if (e == std::string::npos) unit = std::min(unit, kFormatNumberUnit);
    const double tolerance = 0.5 * unit * (1.0 + 1e-9);
    return std::abs(formula.value - result) <= tolerance;
}
