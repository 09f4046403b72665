// number_text against the C library's snprintf, byte for byte: random doubles of every size,
// values exactly halfway at the printed precision (ties to even), rounding that carries into a
// new digit (9.9996 -> "10.000"), powers of ten and their neighbours, zeros of both signs,
// subnormals, infinities, NaN, and the formats the app prints.
#include "number_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

std::string printed(const char* format, int digits, double value) {
    char text[512];
    std::snprintf(text, sizeof text, format, digits, value);
    return text;
}

// Every way number_text writes `value` with `digits`, each the same as snprintf's; the first
// difference is reported (one line, not thousands).
bool sameAsPrintf(double value, int digits, std::string& difference) {
    char text[512];
    for (const bool general : {false, true}) {
        const char* format = general ? "%.*g" : "%.*f";
        const std::string want = printed(format, digits, value);
        const int n = general ? number_text::printGeneral(text, sizeof text, value, digits)
                              : number_text::printFixed(text, sizeof text, value, digits);
        std::string appended = "x";
        if (general)
            number_text::appendGeneral(appended, value, digits);
        else
            number_text::appendFixed(appended, value, digits);
        if (text != want || n != static_cast<int>(want.size()) || appended != "x" + want) {
            char v[64];
            std::snprintf(v, sizeof v, "%a", value);
            difference = std::string(format) + " of " + v + " with " + std::to_string(digits) +
                         ": printf \"" + want + "\", number_text \"" + text + "\" (" +
                         std::to_string(n) + "), appended \"" + appended + "\"";
            return false;
        }
    }
    return true;
}

// Every value with every precision from 0 to 24 (both formats): how many differed, and the first.
int differences(const std::vector<double>& values, std::string& first) {
    int count = 0;
    for (const double v : values) {
        for (int digits = 0; digits <= 24; ++digits) {
            std::string d;
            if (!sameAsPrintf(v, digits, d) && count++ == 0) first = d;
        }
    }
    return count;
}

void expectSameAsPrintf(const std::vector<double>& values) {
    std::string first;
    EXPECT_EQ(differences(values, first), 0) << first;
}

// x and -x.
void addBothSigns(std::vector<double>& values, double x) {
    values.push_back(x);
    values.push_back(-x);
}

} // namespace

TEST(NumberText, RandomDoublesOfEverySizeAsPrintfWritesThem) {
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> exponent(-12.0, 17.0), unit(0.0, 1.0);
    std::vector<double> values;
    for (int i = 0; i < 6000; ++i) addBothSigns(values, std::pow(10.0, exponent(random)));
    // Short decimals (what a slider or a scene file holds: 0.3, 12.75, 1e-3).
    for (int i = 0; i < 3000; ++i) {
        const double whole = std::floor(unit(random) * 2000.0);
        const int decimals = static_cast<int>(unit(random) * 6.0);
        values.push_back(whole / std::pow(10.0, decimals) - 1000.0 / std::pow(10.0, decimals));
    }
    expectSameAsPrintf(values);
}

TEST(NumberText, AnyBitPatternAsPrintfWritesIt) {
    std::mt19937_64 random(42);
    std::vector<double> values;
    for (int i = 0; i < 3000; ++i) {
        const std::uint64_t bits = random();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        values.push_back(v);
    }
    expectSameAsPrintf(values);
}

TEST(NumberText, ExactTiesRoundToEven) {
    // Odd multiples of 2^-k are exactly halfway between two numbers of k - 1 decimals:
    // 0.125 with 2 decimals, 2.5 with none, 0.0625 with 3.
    std::vector<double> values;
    for (int k = 1; k <= 12; ++k) {
        for (int odd = 1; odd < 400; odd += 2) addBothSigns(values, std::ldexp(odd, -k));
        for (int odd = 1000001; odd < 1000400; odd += 2) addBothSigns(values, std::ldexp(odd, -k));
    }
    // Halfway at 1 to 4 significant digits: 125, 1.25, 2.5e+06, 0.000125 (as exact as a double).
    for (double m : {5.0, 15.0, 25.0, 125.0, 135.0, 1125.0, 1135.0, 99995.0, 99985.0})
        for (int e = -8; e <= 12; ++e) addBothSigns(values, m * std::pow(10.0, e));
    expectSameAsPrintf(values);
    EXPECT_EQ(printed("%.*f", 2, 0.125), "0.12"); // the C library rounds ties to even too
    char text[32];
    number_text::printFixed(text, sizeof text, 0.375, 2);
    EXPECT_STREQ(text, "0.38");
    number_text::printFixed(text, sizeof text, 2.5, 0);
    EXPECT_STREQ(text, "2");
    number_text::printGeneral(text, sizeof text, 0.0625, 2);
    EXPECT_STREQ(text, "0.062");
}

TEST(NumberText, RoundingThatCarriesIntoANewDigit) {
    std::vector<double> values;
    for (double v : {9.9996, 0.99995, 999.5, 9.5, 99999.95, 0.0099996, 9999999.9999, 0.000999999,
                     999999.5, 9.99999999999999, 99.9999999, 0.95, 0.995, 19.995, 9e15 - 1.0})
        addBothSigns(values, v);
    // Powers of ten and their neighbours: where the exponent of "%g" changes.
    for (int e = -30; e <= 30; ++e) {
        const double p = std::pow(10.0, e);
        for (double v : {p, std::nextafter(p, 0.0), std::nextafter(p, 1e300), p * 0.99999,
                         p * 0.9999999999, p * 1.00001, p * 9.9995, p * 9.99951, p * 0.5})
            addBothSigns(values, v);
    }
    expectSameAsPrintf(values);
    char text[32];
    number_text::printFixed(text, sizeof text, 9.9996, 3);
    EXPECT_STREQ(text, "10.000");
    number_text::printGeneral(text, sizeof text, 9.9996, 3);
    EXPECT_STREQ(text, "10");
    number_text::printGeneral(text, sizeof text, 999999.5, 6);
    EXPECT_STREQ(text, "1e+06");
}

TEST(NumberText, ZerosSubnormalsLimitsInfinitiesAndNan) {
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<double> values{0.0,
                               -0.0,
                               std::numeric_limits<double>::denorm_min(),
                               -std::numeric_limits<double>::denorm_min(),
                               std::numeric_limits<double>::min(),
                               std::numeric_limits<double>::max(),
                               -std::numeric_limits<double>::max(),
                               std::numeric_limits<double>::epsilon(),
                               inf,
                               -inf,
                               std::numeric_limits<double>::quiet_NaN(),
                               9007199254740991.0, // 2^53 - 1: the last the fast path writes
                               9007199254740992.0,
                               9007199254740993.0,
                               1e-5,
                               std::nextafter(1e-5, 0.0),
                               0.5,
                               1.0,
                               -1.0,
                               1e300};
    expectSameAsPrintf(values);
    char text[32];
    number_text::printFixed(text, sizeof text, -0.0001, 2);
    EXPECT_STREQ(text, "-0.00"); // the sign stays, as printf's
    number_text::printGeneral(text, sizeof text, -0.0, 3);
    EXPECT_STREQ(text, "-0");
}

TEST(NumberText, TheAppsFormatsAndATooSmallBuffer) {
    // What the UI prints: "%.3f" (formatNumber), "%.2f" (velocities, times), "%.3g" (axis
    // numbers, divergence), "%.4g" (side by side), "%.6g", "%.10g", "%g".
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> speed(-60.0, 60.0), time(0.0, 4000.0);
    std::vector<double> values;
    for (int i = 0; i < 20000; ++i) {
        values.push_back(speed(random));
        values.push_back(time(random));
        values.push_back(std::round(time(random) * 60.0) / 60.0); // frame times
    }
    std::string first;
    int count = 0;
    for (const double v : values) {
        for (int digits : {2, 3, 4, 6, 10}) {
            std::string d;
            if (!sameAsPrintf(v, digits, d) && count++ == 0) first = d;
        }
    }
    EXPECT_EQ(count, 0) << first;
    // Cut as snprintf cuts: the whole length returned, size - 1 characters and a NUL written.
    char small[5] = {'x', 'x', 'x', 'x', 'x'};
    EXPECT_EQ(number_text::printFixed(small, sizeof small, -12.345, 3), 7);
    EXPECT_STREQ(small, "-12.");
    EXPECT_EQ(number_text::printGeneral(small, 0, 1.5, 3), 3);
    EXPECT_EQ(small[0], '-'); // size 0: nothing written
}
