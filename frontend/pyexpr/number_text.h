// number_text.h - Python's number texts: int(str), float(str), repr(float).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace mdlc::pyexpr {

// int(text) in base 10: surrounding whitespace, a sign, digits with single
// underscores between them. nullopt if Python rejects the text or the value
// does not fit in 64 bits.
std::optional<int64_t> ParsePythonInt(std::string_view text);

// float(text): surrounding whitespace, a sign, inf/infinity/nan in any case,
// decimal digits with an optional point and exponent, single underscores
// between digits. Out-of-range values become +-inf or 0 as in Python.
std::optional<double> ParsePythonFloat(std::string_view text);

// Python's repr(float) (and str(float)): the shortest text that reads back
// to the same double; scientific when the decimal exponent is < -4 or >= 16.
std::string FloatRepr(double d);

// The shortest round-trip digits of |d| (finite, non-zero) and its decimal
// exponent: |d| = 0.d1d2... * 10^decpt.
struct ShortestDigits {
  std::string digits;
  int decpt = 0;
};
ShortestDigits ShortestOf(double d);

// Python's format codes on floats, correctly rounded from the binary value:
// 'f' (precision digits after the point), 'e' (precision digits after the
// first), 'g' (precision significant digits, trailing zeros removed unless
// alternate). Non-finite values print as inf / nan. No sign for positive.
std::string FormatFloatFixed(double d, int precision);
std::string FormatFloatExp(double d, int precision, bool upper = false);
std::string FormatFloatGeneral(double d, int precision, bool alternate = false, bool upper = false);

}  // namespace mdlc::pyexpr
