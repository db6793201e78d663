// number_text.cc - Python's int()/float() text parsing and float printing.
#include "frontend/pyexpr/number_text.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <system_error>

namespace mdlc::pyexpr {
namespace {

bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view Trim(std::string_view s) {
  while (!s.empty() && IsSpace(s.front())) s.remove_prefix(1);
  while (!s.empty() && IsSpace(s.back())) s.remove_suffix(1);
  return s;
}

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// Digits with single underscores between them; appends the digits to out.
// Returns the number of characters consumed (0 if no digit at the start).
size_t ReadDigits(std::string_view s, std::string& out) {
  size_t i = 0;
  if (i >= s.size() || !IsDigit(s[i])) return 0;
  while (i < s.size()) {
    if (IsDigit(s[i])) {
      out.push_back(s[i]);
      ++i;
    } else if (s[i] == '_' && i + 1 < s.size() && IsDigit(s[i + 1])) {
      ++i;
    } else {
      break;
    }
  }
  return i;
}

bool EqualsNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char c = a[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != b[i]) return false;
  }
  return true;
}

}  // namespace

std::optional<int64_t> ParsePythonInt(std::string_view text) {
  std::string_view s = Trim(text);
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  std::string digits;
  size_t used = ReadDigits(s, digits);
  if (used == 0 || used != s.size()) return std::nullopt;
  // magnitude up to 2^63 (for the negative end)
  uint64_t magnitude = 0;
  for (char c : digits) {
    uint64_t d = static_cast<uint64_t>(c - '0');
    if (magnitude > (std::numeric_limits<uint64_t>::max() - d) / 10) return std::nullopt;
    magnitude = magnitude * 10 + d;
  }
  constexpr uint64_t kMaxPositive = static_cast<uint64_t>(std::numeric_limits<int64_t>::max());
  if (negative) {
    if (magnitude > kMaxPositive + 1) return std::nullopt;
    return magnitude == kMaxPositive + 1 ? std::numeric_limits<int64_t>::min()
                                         : -static_cast<int64_t>(magnitude);
  }
  if (magnitude > kMaxPositive) return std::nullopt;
  return static_cast<int64_t>(magnitude);
}

std::optional<double> ParsePythonFloat(std::string_view text) {
  std::string_view s = Trim(text);
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  double sign = negative ? -1.0 : 1.0;
  if (EqualsNoCase(s, "inf") || EqualsNoCase(s, "infinity")) return sign * std::numeric_limits<double>::infinity();
  if (EqualsNoCase(s, "nan")) return std::copysign(std::numeric_limits<double>::quiet_NaN(), sign);
  std::string clean;
  size_t i = ReadDigits(s, clean);
  bool any_digits = i > 0;
  if (i < s.size() && s[i] == '.') {
    clean.push_back('.');
    ++i;
    size_t frac = ReadDigits(s.substr(i), clean);
    any_digits = any_digits || frac > 0;
    i += frac;
  }
  if (!any_digits) return std::nullopt;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    clean.push_back('e');
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) clean.push_back(s[i++]);
    size_t exp = ReadDigits(s.substr(i), clean);
    if (exp == 0) return std::nullopt;
    i += exp;
  }
  if (i != s.size()) return std::nullopt;
  double value = 0;
  auto [ptr, ec] = std::from_chars(clean.data(), clean.data() + clean.size(), value);
  if (ptr != clean.data() + clean.size()) return std::nullopt;
  if (ec == std::errc::result_out_of_range) {
    // from_chars leaves value unchanged: decide between overflow and underflow
    value = std::strtod(clean.c_str(), nullptr);
  } else if (ec != std::errc()) {
    return std::nullopt;
  }
  return sign * value;
}

ShortestDigits ShortestOf(double d) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, std::fabs(d), std::chars_format::scientific);
  std::string_view text(buf, static_cast<size_t>(res.ptr - buf));
  size_t e = text.find('e');
  ShortestDigits out;
  for (char c : text.substr(0, e))
    if (c != '.') out.digits.push_back(c);
  int exponent = 0;
  std::string_view exp_text = text.substr(e + 1);
  if (!exp_text.empty() && exp_text[0] == '+') exp_text.remove_prefix(1);
  std::from_chars(exp_text.data(), exp_text.data() + exp_text.size(), exponent);
  while (out.digits.size() > 1 && out.digits.back() == '0') out.digits.pop_back();
  out.decpt = exponent + 1;
  return out;
}

namespace {

std::string ExponentText(int exponent, bool upper) {
  std::string out(1, upper ? 'E' : 'e');
  out.push_back(exponent < 0 ? '-' : '+');
  int magnitude = exponent < 0 ? -exponent : exponent;
  if (magnitude < 10) out.push_back('0');
  out += std::to_string(magnitude);
  return out;
}

// digits (no point) with decimal exponent decpt, in positional notation.
std::string Positional(const std::string& digits, int decpt) {
  std::string out;
  if (decpt <= 0) {
    out = "0.";
    out.append(static_cast<size_t>(-decpt), '0');
    out += digits;
  } else if (static_cast<size_t>(decpt) >= digits.size()) {
    out = digits;
    out.append(static_cast<size_t>(decpt) - digits.size(), '0');
  } else {
    out = digits.substr(0, static_cast<size_t>(decpt)) + "." + digits.substr(static_cast<size_t>(decpt));
  }
  return out;
}

std::string NonFinite(double d, bool upper) {
  if (std::isnan(d)) return upper ? "NAN" : "nan";
  return std::string(d < 0 ? "-" : "") + (upper ? "INF" : "inf");
}

}  // namespace

std::string FloatRepr(double d) {
  if (!std::isfinite(d)) return NonFinite(d, false);
  std::string sign = std::signbit(d) ? "-" : "";
  if (d == 0) return sign + "0.0";
  ShortestDigits s = ShortestOf(d);
  if (s.decpt <= -4 || s.decpt > 16) {
    std::string out = sign + s.digits.substr(0, 1);
    if (s.digits.size() > 1) out += "." + s.digits.substr(1);
    return out + ExponentText(s.decpt - 1, false);
  }
  std::string out = sign + Positional(s.digits, s.decpt);
  if (out.find('.') == std::string::npos) out += ".0";
  return out;
}

std::string FormatFloatFixed(double d, int precision) {
  if (!std::isfinite(d)) return NonFinite(d, false);
  std::string buf(static_cast<size_t>(precision) + 330, '\0');
  auto res = std::to_chars(buf.data(), buf.data() + buf.size(), d, std::chars_format::fixed, precision);
  buf.resize(static_cast<size_t>(res.ptr - buf.data()));
  return buf;
}

std::string FormatFloatExp(double d, int precision, bool upper) {
  if (!std::isfinite(d)) return NonFinite(d, upper);
  std::string buf(static_cast<size_t>(precision) + 40, '\0');
  auto res = std::to_chars(buf.data(), buf.data() + buf.size(), d, std::chars_format::scientific, precision);
  buf.resize(static_cast<size_t>(res.ptr - buf.data()));
  size_t e = buf.find('e');
  int exponent = std::atoi(buf.c_str() + e + 1);
  return buf.substr(0, e) + ExponentText(exponent, upper);
}

std::string FormatFloatGeneral(double d, int precision, bool alternate, bool upper) {
  if (!std::isfinite(d)) return NonFinite(d, upper);
  if (precision == 0) precision = 1;
  int exponent = 0;
  if (d != 0) {
    std::string e = FormatFloatExp(d, precision - 1);
    exponent = std::atoi(e.c_str() + e.find('e') + 1);
  }
  std::string out;
  if (exponent >= -4 && exponent < precision) {
    out = FormatFloatFixed(d, precision - 1 - exponent);
    if (!alternate && out.find('.') != std::string::npos) {
      while (out.back() == '0') out.pop_back();
      if (out.back() == '.') out.pop_back();
    }
  } else {
    out = FormatFloatExp(d, precision - 1, upper);
    if (!alternate) {
      size_t e = out.find(upper ? 'E' : 'e');
      std::string mantissa = out.substr(0, e);
      if (mantissa.find('.') != std::string::npos) {
        while (mantissa.back() == '0') mantissa.pop_back();
        if (mantissa.back() == '.') mantissa.pop_back();
      }
      out = mantissa + out.substr(e);
    }
  }
  return out;
}

}  // namespace mdlc::pyexpr
