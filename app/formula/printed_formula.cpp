#include "printed_formula.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

double shownNumber(const char* text) {
    // The fast path (Clinger's): a mantissa of at most 15 digits is exact in a double, and so is
    // 10^k for k <= 22; one division of the two is then rounded once, to the double nearest to
    // the decimal number: strtod's answer. (In WebAssembly strtod works in 128-bit long doubles,
    // in software: the inspector read its numbers back at a few microseconds each.)
    static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                         1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                         1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const char* c = text;
    const bool negative = *c == '-';
    if (negative) ++c;
    std::uint64_t mantissa = 0;
    int digits = 0, decimals = 0;
    bool point = false, any = false;
    for (;; ++c) {
        if (*c >= '0' && *c <= '9') {
            any = true;
            if (mantissa == 0 && *c == '0') { // leading zeros count for nothing
                if (point) ++decimals;
                continue;
            }
            if (++digits > 15) break;
            mantissa = mantissa * 10 + static_cast<std::uint64_t>(*c - '0');
            if (point) ++decimals;
        } else if (*c == '.' && !point) {
            point = true;
        } else {
            break;
        }
    }
    if (*c == '\0' && any && digits <= 15 && decimals <= 22) {
        const double v = static_cast<double>(mantissa) / kPowers[decimals];
        return negative ? -v : v;
    }
    return std::strtod(text, nullptr); // an exponent, more digits, inf, nan
}

Printed printed(double value, int extra) {
    Printed p;
    p.text = formatNumberWithDigits(value, extra);
    p.value = shownNumber(p.text.c_str());
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
    const double result = shownNumber(shownResult.c_str());
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
