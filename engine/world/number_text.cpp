#include "number_text.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace number_text {

namespace {

__extension__ typedef unsigned __int128 Wide; // GCC's and Clang's (wasm too): 128-bit products

constexpr int kMostDecimals = 22;  // 2^53 · 10^22 < 2^127: every product fits in Wide
constexpr int kMostPrecision = 17; // "%.17g" round-trips a double
constexpr double kLeast = 1e-5;    // "%g" below it: printf's ("1e-06"; the exponent found)
constexpr double kBeyond = 9007199254740992.0; // 2^53: from it, printf's

// A finite |value| < 2^53 as mantissa · 2^-shift (shift >= 0), exactly.
struct Exact {
    std::uint64_t mantissa;
    int shift;
};

Exact exactOf(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
    if (biased == 0) return {fraction, 1074}; // subnormal (or zero)
    return {fraction | (std::uint64_t{1} << 52), 1075 - biased};
}

// 10^0 .. 10^22 (10^22 < 2^74).
struct PowersOfTen {
    Wide p[kMostDecimals + 1] = {};
    constexpr PowersOfTen() {
        p[0] = 1;
        for (int n = 1; n <= kMostDecimals; ++n) p[n] = p[n - 1] * 10;
    }
};
constexpr PowersOfTen kPowers;

Wide tenTo(int n) {
    return kPowers.p[n];
}

// round(x · 10^decimals), ties to even, for x = e.mantissa · 2^-e.shift; decimals from -19 (then
// e.shift <= 53) to kMostDecimals.
Wide roundScaled(const Exact& e, int decimals) {
    Wide q, r, half;
    bool odd;
    if (decimals >= 0) {
        const Wide n = static_cast<Wide>(e.mantissa) * tenTo(decimals);
        if (e.shift == 0) return n;
        if (e.shift >= 128) return 0; // n < 2^127 <= half the divisor
        q = n >> e.shift;
        r = n - (q << e.shift);
        half = static_cast<Wide>(1) << (e.shift - 1);
        odd = (q & 1) != 0;
        if (r > half || (r == half && odd)) ++q;
        return q;
    }
    const Wide d = tenTo(-decimals) << e.shift;
    q = e.mantissa / d;
    r = e.mantissa - q * d;
    odd = (q & 1) != 0;
    // r vs d/2 without halving d (it may be odd after the shift of 0): 2r vs d.
    if (2 * r > d || (2 * r == d && odd)) ++q;
    return q;
}

// x >= 10^power exactly (power from -kMostDecimals to 22), x = e.mantissa · 2^-e.shift.
bool atLeastPowerOfTen(const Exact& e, double x, int power) {
    if (power >= 0) return x >= static_cast<double>(tenTo(power)); // 10^0..10^22: exact doubles
    if (e.shift >= 127) return false;
    return static_cast<Wide>(e.mantissa) * tenTo(-power) >= (static_cast<Wide>(1) << e.shift);
}

// The decimal digits of n into the end of `end`'s buffer, at least `least` of them (leading
// zeros); returns where they start.
char* digitsBefore(char* end, Wide n, int least) {
    char* p = end;
    while (n > 0xffffffffffffffffu) {
        const Wide q = n / 10;
        *--p = static_cast<char>('0' + static_cast<int>(n - q * 10));
        n = q;
    }
    auto small = static_cast<std::uint64_t>(n);
    while (small > 0) {
        *--p = static_cast<char>('0' + static_cast<int>(small % 10));
        small /= 10;
    }
    while (end - p < least) *--p = '0';
    return p;
}

// `text` (length n) as snprintf leaves it in out[size].
int give(char* out, std::size_t size, const char* text, std::size_t n) {
    if (size > 0) {
        const std::size_t kept = n < size ? n : size - 1;
        std::memcpy(out, text, kept);
        out[kept] = '\0';
    }
    return static_cast<int>(n);
}

// Fast-path texts: at most a sign, 16 + 22 digits, a point and an exponent.
constexpr std::size_t kText = 64;

// "%.*f" into text[kText]; its length, or -1 where printf is asked.
int fixed(char* text, double value, int decimals) {
    const double a = std::fabs(value);
    if (!(a < kBeyond) || decimals < 0 || decimals > kMostDecimals) return -1;
    char digits[kText];
    char* end = digits + sizeof digits;
    const char* first = digitsBefore(end, roundScaled(exactOf(a), decimals), decimals + 1);
    char* p = text;
    if (std::signbit(value)) *p++ = '-';
    const auto whole = static_cast<std::size_t>(end - first - decimals);
    std::memcpy(p, first, whole);
    p += whole;
    if (decimals > 0) {
        *p++ = '.';
        std::memcpy(p, first + whole, static_cast<std::size_t>(decimals));
        p += decimals;
    }
    return static_cast<int>(p - text);
}

// "%.*g" into text[kText]; its length, or -1 where printf is asked.
int general(char* text, double value, int precision) {
    if (precision == 0) precision = 1;
    const double a = std::fabs(value);
    if (precision < 0 || precision > kMostPrecision || !(a < kBeyond)) return -1;
    char* p = text;
    if (std::signbit(value)) *p++ = '-';
    if (a == 0.0) {
        *p++ = '0';
        return static_cast<int>(p - text);
    }
    if (!(a >= kLeast)) return -1;
    const Exact e = exactOf(a);
    // The decimal exponent: 10^x <= a < 10^(x + 1), from an estimate by the binary one.
    const int binary = 52 - e.shift; // a >= 1e-5 is normal: 2^binary <= a < 2^(binary + 1)
    int x = static_cast<int>(std::floor(binary * 0.30102999566398120));
    while (x < 15 && atLeastPowerOfTen(e, a, x + 1)) ++x;
    while (!atLeastPowerOfTen(e, a, x)) --x;
    Wide q = roundScaled(e, precision - 1 - x);
    if (q == tenTo(precision)) { // rounded up to the next power of ten (9.9996 -> "10.00")
        q = tenTo(precision - 1);
        ++x;
    }
    char digits[kText];
    char* end = digits + sizeof digits;
    const char* first = digitsBefore(end, q, precision); // `precision` digits
    const bool exponential = x < -4 || x >= precision;
    // The point after the first digit (exponential) or after the whole part; zeros before it.
    const int whole = exponential ? 1 : x + 1;
    const char* last = end; // trailing zeros of the fraction dropped
    while (last - first > (whole > 0 ? whole : 0) && last[-1] == '0') --last;
    if (whole <= 0) {
        *p++ = '0';
        *p++ = '.';
        for (int k = 0; k < -whole; ++k) *p++ = '0';
        std::memcpy(p, first, static_cast<std::size_t>(last - first));
        p += last - first;
    } else {
        std::memcpy(p, first, static_cast<std::size_t>(whole));
        p += whole;
        if (last - first > whole) {
            *p++ = '.';
            std::memcpy(p, first + whole, static_cast<std::size_t>(last - first - whole));
            p += last - first - whole;
        }
    }
    if (exponential) {
        *p++ = 'e';
        *p++ = x < 0 ? '-' : '+';
        const int ex = x < 0 ? -x : x;
        *p++ = static_cast<char>('0' + ex / 10);
        *p++ = static_cast<char>('0' + ex % 10);
    }
    return static_cast<int>(p - text);
}

// printf's own text of `format` ("%.*f" or "%.*g") appended to `text`.
void appendPrinted(std::string& text, const char* format, int digits, double value) {
    char t[kText];
    const int n = std::snprintf(t, sizeof t, format, digits, value);
    if (n < 0) return;
    const auto length = static_cast<std::size_t>(n);
    if (length < sizeof t) {
        text.append(t, length);
        return;
    }
    const std::size_t at = text.size();
    text.resize(at + length + 1);
    std::snprintf(&text[at], length + 1, format, digits, value);
    text.resize(at + length);
}

} // namespace

int printFixed(char* out, std::size_t size, double value, int decimals) {
    char text[kText];
    const int n = fixed(text, value, decimals);
    if (n < 0) return std::snprintf(out, size, "%.*f", decimals, value);
    return give(out, size, text, static_cast<std::size_t>(n));
}

int printGeneral(char* out, std::size_t size, double value, int precision) {
    char text[kText];
    const int n = general(text, value, precision);
    if (n < 0) return std::snprintf(out, size, "%.*g", precision, value);
    return give(out, size, text, static_cast<std::size_t>(n));
}

void appendFixed(std::string& text, double value, int decimals) {
    char t[kText];
    const int n = fixed(t, value, decimals);
    if (n >= 0)
        text.append(t, static_cast<std::size_t>(n));
    else
        appendPrinted(text, "%.*f", decimals, value);
}

void appendGeneral(std::string& text, double value, int precision) {
    char t[kText];
    const int n = general(t, value, precision);
    if (n >= 0)
        text.append(t, static_cast<std::size_t>(n));
    else
        appendPrinted(text, "%.*g", precision, value);
}

} // namespace number_text
