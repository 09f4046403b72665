// A double as printf's "%.*f" and "%.*g" write it, byte for byte, without printf: the UI writes
// dozens of numbers a frame, and in the browser every printf of a double goes through musl's
// general formatter (issue 42). The value is read exactly (a double is an integer times a power
// of two) and rounded once, ties to even, as glibc's and musl's printf round it in the default
// rounding mode; what the fast path does not cover (more than 22 decimals, 17 significant digits,
// magnitudes from 2^53 or below 1e-5 for "%g", infinities and NaN) is printf's own.
#pragma once

#include <cstddef>
#include <string>

namespace number_text {

// As std::snprintf(out, size, "%.*f", decimals, value): at most size - 1 characters and a NUL
// written (when size > 0); returns the length of the whole text.
int printFixed(char* out, std::size_t size, double value, int decimals);
// As std::snprintf(out, size, "%.*g", precision, value).
int printGeneral(char* out, std::size_t size, double value, int precision);

// The same, appended to `text`.
void appendFixed(std::string& text, double value, int decimals);
void appendGeneral(std::string& text, double value, int precision);

} // namespace number_text
