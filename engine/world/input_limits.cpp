#include "input_limits.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace limits {

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[32];
    // Whole numbers below a million in full ("1000", not "1e3").
    if (value == std::floor(value) && std::abs(value) < 1e6) {
        std::snprintf(text, sizeof text, "%.0f", value);
        return text;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        std::snprintf(text, sizeof text, "%.*g", precision, value);
        if (std::strtod(text, nullptr) == value) break;
    }
    // "1e-06" -> "1e-6", "1e+15" -> "1e15".
    std::string out = text;
    const std::size_t e = out.find('e');
    if (e == std::string::npos) return out;
    std::size_t digits = e + 1;
    const bool negative = out[digits] == '-';
    if (out[digits] == '+' || out[digits] == '-') ++digits;
    while (digits + 1 < out.size() && out[digits] == '0') ++digits;
    return out.substr(0, e + 1) + (negative ? "-" : "") + out.substr(digits);
}

std::string describe(const Range& range) {
    std::string text = range.whole ? "a whole number from " : "from ";
    text += formatNumber(range.min) + " to " + formatNumber(range.max);
    if (*range.unit) text += std::string(" ") + range.unit;
    return text;
}

std::string violation(const Range& range, double value) {
    const bool inside = value >= range.min && value <= range.max; // false for NaN
    if (inside && (!range.whole || value == std::floor(value))) return "";
    return "must be " + describe(range) + ", not " + formatNumber(value);
}

std::string accelerationViolation(double force, double mass) {
    const double a = force / mass;
    if (a <= kGravity.max) return "";
    return "force / mass must be at most " + formatNumber(kGravity.max) + " m/s^2, not " +
           formatNumber(a) + " (" + formatNumber(force) + " N on " + formatNumber(mass) + " kg)";
}

std::string textViolation(std::string_view text, const Range& range, double& value) {
    double x = 0.0;
    if (!parseNumber(text, x))
        return "must be " + std::string(range.whole ? "" : "a decimal number ") + describe(range);
    if (std::string problem = violation(range, x); !problem.empty()) return problem;
    value = x;
    return "";
}

std::string lengthViolation(double length, double magnitude, const Range& range) {
    if (std::string problem = violation(range, length); !problem.empty()) return problem;
    const double least = kResolution * magnitude;
    if (length >= least) return "";
    return "must be at least " + formatNumber(kResolution) +
           " of the coordinates it sits at (at least " + formatNumber(least) + " m at " +
           formatNumber(magnitude) + "), not " + formatNumber(length);
}

bool parseNumber(std::string_view text, double& value) {
    std::size_t i = 0;
    auto digits = [&] {
        const std::size_t start = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        return i - start;
    };
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    std::size_t mantissa = digits();
    if (i < text.size() && text[i] == '.') {
        ++i;
        mantissa += digits();
    }
    if (mantissa == 0) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        if (digits() == 0) return false;
    }
    if (i != text.size()) return false;
    // The grammar above is a subset of strtod's; ERANGE (overflow to ±inf, underflow towards 0)
    // is left to the range checks.
    const std::string copy(text);
    errno = 0;
    value = std::strtod(copy.c_str(), nullptr);
    return true;
}

} // namespace limits
