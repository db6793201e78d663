// str_methods.cc - str/list/tuple/dict methods and string formatting.
//
// Strings are UTF-8; lengths, indices and positions count code points, as
// Python's do. Case mapping and the is*() tests know ASCII only.
#include "frontend/pyexpr/str_methods.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/number_text.h"

namespace mdlc::pyexpr {
namespace internal {

bool IsAscii(std::string_view s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  return true;
}

std::vector<std::string> SplitCodePoints(std::string_view s) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < s.size()) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    size_t n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 1;
    n = std::min(n, s.size() - i);
    out.emplace_back(s.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace internal

namespace {

using internal::CheckArgs;
using internal::Fail;
using internal::FindKeyword;
using internal::Keywords;
using internal::Positional;

constexpr size_t kNoMax = std::numeric_limits<size_t>::max();

bool IsSpaceChar(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f' || (c >= 0x1c && c <= 0x1f); }
char Upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; }
char Lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c + 32) : c; }
bool IsAlpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool IsDigitChar(char c) { return c >= '0' && c <= '9'; }

size_t CodePointCount(std::string_view s) {
  if (internal::IsAscii(s)) return s.size();
  size_t n = 0;
  for (char c : s)
    if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++n;
  return n;
}

// byte offset of code point index cp (clamped to the end)
size_t ByteOffset(std::string_view s, size_t cp) {
  if (internal::IsAscii(s)) return std::min(cp, s.size());
  size_t n = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) {
      if (n == cp) return i;
      ++n;
    }
  }
  return s.size();
}

Result<std::string> StrArg(const Value& v, std::string_view method, std::string_view what = "argument") {
  if (!v.IsStr())
    return Fail(Error::Kind::kType, fmt::format("{}() {} must be a string, not '{}'", method, what, TypeName(v)));
  return v.AsStr();
}

// Python's [start:end] of optional slice-like arguments, as byte offsets.
Result<std::pair<size_t, size_t>> Range(const std::string& s, Positional args, size_t first, std::string_view method) {
  int64_t n = static_cast<int64_t>(CodePointCount(s));
  int64_t bounds[2] = {0, n};
  for (size_t k = 0; k < 2; ++k) {
    if (args.size() <= first + k || args[first + k].IsNone()) continue;
    if (!args[first + k].IsIntegral())
      return Fail(Error::Kind::kType, fmt::format("{}() slice indices must be integers or None", method));
    int64_t i = args[first + k].AsInt();
    if (i < 0) i = std::max<int64_t>(0, i + n);
    bounds[k] = std::min(i, n);
  }
  size_t a = ByteOffset(s, static_cast<size_t>(bounds[0]));
  size_t b = ByteOffset(s, static_cast<size_t>(bounds[1]));
  return std::pair{a, std::max(a, b)};
}

std::vector<std::string> SplitWhitespace(const std::string& s, int64_t maxsplit, bool from_right) {
  std::vector<std::string> out;
  if (!from_right) {
    size_t i = 0;
    while (true) {
      while (i < s.size() && IsSpaceChar(s[i])) ++i;
      if (i >= s.size()) break;
      if (maxsplit >= 0 && static_cast<int64_t>(out.size()) == maxsplit) {
        out.push_back(s.substr(i));  // the rest keeps its trailing white space
        break;
      }
      size_t j = i;
      while (j < s.size() && !IsSpaceChar(s[j])) ++j;
      out.push_back(s.substr(i, j - i));
      i = j;
    }
    return out;
  }
  size_t i = s.size();
  while (true) {
    while (i > 0 && IsSpaceChar(s[i - 1])) --i;
    if (i == 0) break;
    if (maxsplit >= 0 && static_cast<int64_t>(out.size()) == maxsplit) {
      out.push_back(s.substr(0, i));  // the rest keeps its leading white space
      break;
    }
    size_t j = i;
    while (j > 0 && !IsSpaceChar(s[j - 1])) --j;
    out.push_back(s.substr(j, i - j));
    i = j;
  }
  std::reverse(out.begin(), out.end());
  return out;
}

std::vector<std::string> SplitSep(const std::string& s, const std::string& sep, int64_t maxsplit, bool from_right) {
  std::vector<std::string> out;
  if (!from_right) {
    size_t start = 0;
    while (maxsplit < 0 || static_cast<int64_t>(out.size()) < maxsplit) {
      size_t at = s.find(sep, start);
      if (at == std::string::npos) break;
      out.push_back(s.substr(start, at - start));
      start = at + sep.size();
    }
    out.push_back(s.substr(start));
    return out;
  }
  size_t end = s.size();
  while (maxsplit < 0 || static_cast<int64_t>(out.size()) < maxsplit) {
    if (end < sep.size()) break;
    size_t at = s.rfind(sep, end - sep.size());
    if (at == std::string::npos) break;
    out.push_back(s.substr(at + sep.size(), end - at - sep.size()));
    end = at;
  }
  out.push_back(s.substr(0, end));
  std::reverse(out.begin(), out.end());
  return out;
}

Value StrList(std::vector<std::string> parts) {
  std::vector<Value> out;
  out.reserve(parts.size());
  for (auto& p : parts) out.push_back(Value::Str(std::move(p)));
  return Value::List(std::move(out));
}

Result<Value> Split(const std::string& s, Positional args, Keywords kw, bool from_right) {
  const char* name = from_right ? "rsplit" : "split";
  PYEXPR_CHECK(CheckArgs(name, args, kw, 0, 2, {"sep", "maxsplit"}));
  const Value* sep = !args.empty() ? &args[0] : FindKeyword(kw, "sep");
  const Value* max = args.size() > 1 ? &args[1] : FindKeyword(kw, "maxsplit");
  int64_t maxsplit = -1;
  if (max) {
    PYEXPR_TRY(m, internal::AsIndex(*max, std::string(name) + "() maxsplit"));
    maxsplit = m;
  }
  if (!sep || sep->IsNone()) return StrList(SplitWhitespace(s, maxsplit, from_right));
  PYEXPR_TRY(sep_text, StrArg(*sep, name, "separator"));
  if (sep_text.empty()) return Fail(Error::Kind::kValue, "empty separator");
  return StrList(SplitSep(s, sep_text, maxsplit, from_right));
}

Result<Value> Strip(const std::string& s, Positional args, Keywords kw, bool left, bool right, const char* name) {
  PYEXPR_CHECK(CheckArgs(name, args, kw, 0, 1));
  std::string chars;
  bool whitespace = args.empty() || args[0].IsNone();
  if (!whitespace) {
    PYEXPR_TRY(c, StrArg(args[0], name));
    chars = c;
  }
  auto strip_char = [&](char c) { return whitespace ? IsSpaceChar(c) : chars.find(c) != std::string::npos; };
  size_t a = 0, b = s.size();
  if (!internal::IsAscii(chars)) {
    // code point aware: strip whole code points found in chars
    auto cps = internal::SplitCodePoints(s);
    size_t i = 0, j = cps.size();
    while (left && i < j && chars.find(cps[i]) != std::string::npos) ++i;
    while (right && j > i && chars.find(cps[j - 1]) != std::string::npos) --j;
    std::string out;
    for (size_t k = i; k < j; ++k) out += cps[k];
    return Value::Str(std::move(out));
  }
  while (left && a < b && strip_char(s[a])) ++a;
  while (right && b > a && strip_char(s[b - 1])) --b;
  return Value::Str(s.substr(a, b - a));
}

Result<Value> Pad(const std::string& s, Positional args, Keywords kw, const char* name) {
  PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 2));
  PYEXPR_TRY(width, internal::AsIndex(args[0], std::string(name) + "() width"));
  std::string fill = " ";
  if (args.size() > 1) {
    PYEXPR_TRY(f, StrArg(args[1], name, "fill character"));
    if (CodePointCount(f) != 1) return Fail(Error::Kind::kType, "the fill character must be exactly one character long");
    fill = f;
  }
  int64_t len = static_cast<int64_t>(CodePointCount(s));
  if (width <= len) return Value::Str(s);
  size_t pad = static_cast<size_t>(width - len);
  PYEXPR_CHECK(internal::CheckStringSize(s.size() + pad * fill.size()));
  size_t left = 0;
  std::string n = name;
  if (n == "rjust") left = pad;
  if (n == "center") left = pad / 2 + (pad & static_cast<size_t>(width) & 1);
  std::string out;
  for (size_t i = 0; i < left; ++i) out += fill;
  out += s;
  for (size_t i = left; i < pad; ++i) out += fill;
  return Value::Str(std::move(out));
}

Result<Value> Find(const std::string& s, Positional args, Keywords kw, const char* name, bool reverse, bool raise) {
  PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 3));
  PYEXPR_TRY(sub, StrArg(args[0], name));
  PYEXPR_TRY(range, Range(s, args, 1, name));
  auto [a, b] = range;
  std::string_view window(s.data() + a, b - a);
  size_t at = reverse ? window.rfind(sub) : window.find(sub);
  if (at == std::string_view::npos) {
    if (raise) return Fail(Error::Kind::kValue, "substring not found");
    return Value::Int(-1);
  }
  return Value::Int(static_cast<int64_t>(CodePointCount(std::string_view(s.data(), a + at))));
}

Result<Value> StartsEnds(const std::string& s, Positional args, Keywords kw, bool ends) {
  const char* name = ends ? "endswith" : "startswith";
  PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 3));
  std::vector<Value> options;
  if (args[0].IsTuple()) options = args[0].items(); else options.push_back(args[0]);
  PYEXPR_TRY(range, Range(s, args, 1, name));
  std::string_view window(s.data() + range.first, range.second - range.first);
  for (const Value& o : options) {
    if (!o.IsStr())
      return Fail(Error::Kind::kType, fmt::format("{}() needs a string or a tuple of strings, not '{}'", name, TypeName(o)));
    if (ends ? window.ends_with(o.AsStr()) : window.starts_with(o.AsStr())) return Value::Bool(true);
  }
  return Value::Bool(false);
}

template <typename Pred>
Value AllChars(const std::string& s, Pred pred) {
  if (s.empty()) return Value::Bool(false);
  for (char c : s)
    if (!pred(c)) return Value::Bool(false);
  return Value::Bool(true);
}

Result<Value> StrMethod(const std::string& s, const std::string& method, Positional args, Keywords kw) {
  const char* m = method.c_str();
  if (method == "format") return internal::FormatString(s, args, kw);
  if (method == "split") return Split(s, args, kw, false);
  if (method == "rsplit") return Split(s, args, kw, true);
  if (method == "splitlines") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 1, {"keepends"}));
    const Value* keep = !args.empty() ? &args[0] : FindKeyword(kw, "keepends");
    bool keepends = keep && Truthy(*keep);
    std::vector<std::string> out;
    size_t i = 0;
    while (i < s.size()) {
      size_t j = i;
      while (j < s.size() && s[j] != '\n' && s[j] != '\r' && s[j] != '\v' && s[j] != '\f' && !(s[j] >= 0x1c && s[j] <= 0x1e)) ++j;
      size_t eol = j;
      if (j < s.size()) eol = (s[j] == '\r' && j + 1 < s.size() && s[j + 1] == '\n') ? j + 2 : j + 1;
      out.push_back(s.substr(i, (keepends ? eol : j) - i));
      i = eol;
    }
    return StrList(std::move(out));
  }
  if (method == "join") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 1));
    PYEXPR_TRY(items, internal::Iterate(args[0]));
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) {
      if (!items[i].IsStr())
        return Fail(Error::Kind::kType, fmt::format("join() item {} is a '{}', not a string", i, TypeName(items[i])));
      if (i) out += s;
      out += items[i].AsStr();
      PYEXPR_CHECK(internal::CheckStringSize(out.size()));
    }
    return Value::Str(std::move(out));
  }
  if (method == "replace") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 2, 3));
    PYEXPR_TRY(old_text, StrArg(args[0], m));
    PYEXPR_TRY(new_text, StrArg(args[1], m));
    int64_t count = -1;
    if (args.size() > 2) {
      PYEXPR_TRY(c, internal::AsIndex(args[2], "replace() count"));
      count = c;
    }
    std::string out;
    if (old_text.empty()) {
      auto cps = internal::SplitCodePoints(s);
      int64_t done = 0;
      for (size_t i = 0; i <= cps.size(); ++i) {
        if (count < 0 || done < count) {
          out += new_text;
          ++done;
        }
        if (i < cps.size()) out += cps[i];
        PYEXPR_CHECK(internal::CheckStringSize(out.size()));
      }
      return Value::Str(std::move(out));
    }
    size_t start = 0;
    int64_t done = 0;
    while (count < 0 || done < count) {
      size_t at = s.find(old_text, start);
      if (at == std::string::npos) break;
      out.append(s, start, at - start);
      out += new_text;
      PYEXPR_CHECK(internal::CheckStringSize(out.size()));
      start = at + old_text.size();
      ++done;
    }
    out.append(s, start);
    PYEXPR_CHECK(internal::CheckStringSize(out.size()));
    return Value::Str(std::move(out));
  }
  if (method == "strip") return Strip(s, args, kw, true, true, m);
  if (method == "lstrip") return Strip(s, args, kw, true, false, m);
  if (method == "rstrip") return Strip(s, args, kw, false, true, m);
  if (method == "upper" || method == "lower" || method == "capitalize" || method == "title" || method == "swapcase") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    std::string out = s;
    bool prev_cased = false;
    for (size_t i = 0; i < out.size(); ++i) {
      char c = out[i];
      if (method == "upper") c = Upper(c);
      else if (method == "lower") c = Lower(c);
      else if (method == "capitalize") c = i == 0 ? Upper(c) : Lower(c);
      else if (method == "swapcase") c = IsAlpha(c) ? (c >= 'a' ? Upper(c) : Lower(c)) : c;
      else c = prev_cased ? Lower(c) : Upper(c);
      prev_cased = IsAlpha(c);
      out[i] = c;
    }
    return Value::Str(std::move(out));
  }
  if (method == "startswith") return StartsEnds(s, args, kw, false);
  if (method == "endswith") return StartsEnds(s, args, kw, true);
  if (method == "find") return Find(s, args, kw, m, false, false);
  if (method == "rfind") return Find(s, args, kw, m, true, false);
  if (method == "index") return Find(s, args, kw, m, false, true);
  if (method == "rindex") return Find(s, args, kw, m, true, true);
  if (method == "count") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 3));
    PYEXPR_TRY(sub, StrArg(args[0], m));
    PYEXPR_TRY(range, Range(s, args, 1, m));
    std::string_view window(s.data() + range.first, range.second - range.first);
    if (sub.empty()) return Value::Int(static_cast<int64_t>(CodePointCount(window) + 1));
    int64_t n = 0;
    for (size_t at = window.find(sub); at != std::string_view::npos; at = window.find(sub, at + sub.size())) ++n;
    return Value::Int(n);
  }
  if (method == "partition" || method == "rpartition") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 1));
    PYEXPR_TRY(sep, StrArg(args[0], m));
    if (sep.empty()) return Fail(Error::Kind::kValue, "empty separator");
    bool r = method == "rpartition";
    size_t at = r ? s.rfind(sep) : s.find(sep);
    if (at == std::string::npos)
      return r ? Value::Tuple({Value::Str(""), Value::Str(""), Value::Str(s)})
               : Value::Tuple({Value::Str(s), Value::Str(""), Value::Str("")});
    return Value::Tuple({Value::Str(s.substr(0, at)), Value::Str(sep), Value::Str(s.substr(at + sep.size()))});
  }
  if (method == "isdigit" || method == "isdecimal" || method == "isnumeric") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return AllChars(s, IsDigitChar);
  }
  if (method == "isalpha") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return AllChars(s, IsAlpha);
  }
  if (method == "isalnum") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return AllChars(s, [](char c) { return IsAlpha(c) || IsDigitChar(c); });
  }
  if (method == "isspace") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return AllChars(s, IsSpaceChar);
  }
  if (method == "isupper" || method == "islower") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    bool upper = method == "isupper", cased = false;
    for (char c : s) {
      if (!IsAlpha(c)) continue;
      cased = true;
      if ((c >= 'A' && c <= 'Z') != upper) return Value::Bool(false);
    }
    return Value::Bool(cased);
  }
  if (method == "zfill") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 1));
    PYEXPR_TRY(width, internal::AsIndex(args[0], "zfill() width"));
    int64_t len = static_cast<int64_t>(CodePointCount(s));
    if (width <= len) return Value::Str(s);
    PYEXPR_CHECK(internal::CheckStringSize(static_cast<size_t>(width)));
    std::string out = s;
    size_t sign = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
    out.insert(sign, static_cast<size_t>(width - len), '0');
    return Value::Str(std::move(out));
  }
  if (method == "center" || method == "ljust" || method == "rjust") return Pad(s, args, kw, m);
  return Fail(Error::Kind::kAttribute, "");
}

Result<Value> SeqMethod(const Value& self, const std::string& method, Positional args, Keywords kw) {
  const char* m = method.c_str();
  if (method == "index") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 3));
    const auto& items = self.items();
    int64_t n = static_cast<int64_t>(items.size());
    int64_t bounds[2] = {0, n};
    for (size_t k = 0; k < 2; ++k) {
      if (args.size() <= k + 1) continue;
      PYEXPR_TRY(i, internal::AsIndex(args[k + 1], "index()"));
      int64_t v = i < 0 ? std::max<int64_t>(0, i + n) : std::min(i, n);
      bounds[k] = v;
    }
    for (int64_t i = bounds[0]; i < bounds[1]; ++i)
      if (Equal(items[static_cast<size_t>(i)], args[0])) return Value::Int(i);
    return Fail(Error::Kind::kValue, fmt::format("{} is not in the {}", Repr(args[0]), TypeName(self)));
  }
  if (method == "count") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 1));
    int64_t n = 0;
    for (const Value& v : self.items()) n += Equal(v, args[0]) ? 1 : 0;
    return Value::Int(n);
  }
  if (method == "copy" && self.IsList()) {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return Value::List(self.items());
  }
  return Fail(Error::Kind::kAttribute, "");
}

Result<Value> DictMethod(const Value& self, const std::string& method, Positional args, Keywords kw) {
  const char* m = method.c_str();
  if (method == "get") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 1, 2));
    if (!Hash(args[0])) return Fail(Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(args[0])));
    if (const Value* v = self.DictFind(args[0])) return internal::WrapChild(self, *v);
    return args.size() > 1 ? args[1] : Value();
  }
  // keys(), values() and items() are lists here (views in Python; only
  // their str() differs)
  if (method == "keys" || method == "values" || method == "items") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    std::vector<Value> out;
    for (const auto& [key, value] : self.dict_items()) {
      if (method == "keys") out.push_back(key);
      else if (method == "values") out.push_back(internal::WrapChild(self, value));
      else out.push_back(Value::Tuple({key, internal::WrapChild(self, value)}));
    }
    return Value::List(std::move(out));
  }
  if (method == "copy") {
    PYEXPR_CHECK(CheckArgs(m, args, kw, 0, 0));
    return Value::Dict(self.dict_items());
  }
  return Fail(Error::Kind::kAttribute, "");
}

bool HasMethod(const Value& self, std::string_view name) {
  static const char* kStr[] = {"format", "split", "rsplit", "splitlines", "join", "replace", "strip", "lstrip", "rstrip",
                               "upper", "lower", "capitalize", "title", "swapcase", "startswith", "endswith", "find",
                               "rfind", "index", "rindex", "count", "partition", "rpartition", "isdigit", "isdecimal",
                               "isnumeric", "isalpha", "isalnum", "isspace", "isupper", "islower", "zfill", "center",
                               "ljust", "rjust"};
  static const char* kList[] = {"index", "count", "copy"};
  static const char* kTuple[] = {"index", "count"};
  static const char* kDict[] = {"get", "keys", "values", "items", "copy"};
  auto in = [&](auto& names) {
    for (const char* n : names)
      if (name == n) return true;
    return false;
  };
  if (self.IsStr()) return in(kStr);
  if (self.IsList()) return in(kList);
  if (self.IsTuple()) return in(kTuple);
  if (self.IsDict()) return in(kDict);
  return false;
}

}  // namespace

namespace internal {

Result<Value> Method(const Value& self, std::string_view name) {
  if (!HasMethod(self, name)) {
    Error e{Error::Kind::kAttribute, fmt::format("'{}' values have no attribute '{}'", TypeName(self), name)};
    e.missing_name = std::string(name);
    return e;
  }
  std::string method(name);
  std::string full = TypeName(self) + "." + method;
  return Value::Function(full, [self, method](Positional args, Keywords kw) -> Result<Value> {
    if (self.IsStr()) return StrMethod(self.AsStr(), method, args, kw);
    if (self.IsDict()) return DictMethod(self, method, args, kw);
    return SeqMethod(self, method, args, kw);
  });
}

}  // namespace internal

// ---- format specs ----

namespace {

struct Spec {
  std::string fill = " ";
  char align = 0;
  char sign = '-';
  bool z = false;
  bool alternate = false;
  int64_t width = -1;
  char grouping = 0;
  int64_t precision = -1;
  char type = 0;
};

Result<Spec> ParseSpec(std::string_view s) {
  Spec spec;
  size_t i = 0;
  auto is_align = [](char c) { return c == '<' || c == '>' || c == '^' || c == '='; };
  // fill may be a multi-byte code point
  size_t first_len = 0;
  if (!s.empty()) {
    unsigned char c = static_cast<unsigned char>(s[0]);
    first_len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : 4;
    first_len = std::min(first_len, s.size());
  }
  if (s.size() > first_len && is_align(s[first_len])) {
    spec.fill = std::string(s.substr(0, first_len));
    spec.align = s[first_len];
    i = first_len + 1;
  } else if (!s.empty() && is_align(s[0])) {
    spec.align = s[0];
    i = 1;
  }
  if (i < s.size() && (s[i] == '+' || s[i] == '-' || s[i] == ' ')) spec.sign = s[i++];
  if (i < s.size() && s[i] == 'z') {
    spec.z = true;
    ++i;
  }
  if (i < s.size() && s[i] == '#') {
    spec.alternate = true;
    ++i;
  }
  if (i < s.size() && s[i] == '0') {
    if (!spec.align) {
      spec.fill = "0";
      spec.align = '=';
    }
    ++i;
  }
  auto number = [&](int64_t& out) {
    size_t start = i;
    int64_t v = 0;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
      v = std::min<int64_t>(v * 10 + (s[i] - '0'), int64_t{1} << 40);
      ++i;
    }
    if (i > start) out = v;
    return i > start;
  };
  number(spec.width);
  if (i < s.size() && (s[i] == ',' || s[i] == '_')) spec.grouping = s[i++];
  if (i < s.size() && s[i] == '.') {
    ++i;
    if (!number(spec.precision)) return Fail(Error::Kind::kValue, "format specifier missing precision");
  }
  if (i < s.size()) spec.type = s[i++];
  if (i != s.size()) return Fail(Error::Kind::kValue, fmt::format("invalid format specifier '{}'", s));
  if (spec.width > 0) PYEXPR_CHECK(internal::CheckStringSize(static_cast<size_t>(spec.width)));
  if (spec.precision > 0) PYEXPR_CHECK(internal::CheckStringSize(static_cast<size_t>(spec.precision)));
  return spec;
}

std::string Group(const std::string& digits, char sep, size_t every = 3) {
  std::string out;
  size_t n = digits.size();
  for (size_t i = 0; i < n; ++i) {
    if (i && (n - i) % every == 0) out.push_back(sep);
    out.push_back(digits[i]);
  }
  return out;
}

// pads sign+body to the width
std::string Align(const Spec& spec, const std::string& sign, const std::string& body, char default_align) {
  size_t len = CodePointCount(sign) + CodePointCount(body);
  char align = spec.align ? spec.align : default_align;
  if (spec.width < 0 || static_cast<size_t>(spec.width) <= len) return sign + body;
  size_t pad = static_cast<size_t>(spec.width) - len;
  auto fill = [&](size_t n) {
    std::string f;
    for (size_t i = 0; i < n; ++i) f += spec.fill;
    return f;
  };
  switch (align) {
    case '<': return sign + body + fill(pad);
    case '^': return fill(pad / 2) + sign + body + fill(pad - pad / 2);
    case '=': return sign + fill(pad) + body;
    default: return fill(pad) + sign + body;
  }
}

std::string SignText(const Spec& spec, bool negative) {
  if (negative) return "-";
  if (spec.sign == '+') return "+";
  if (spec.sign == ' ') return " ";
  return "";
}

// Python's format of a float with no type and a precision
std::string FloatNoTypePrecision(double d, int p) {
  if (p == 0) p = 1;
  std::string e = FormatFloatExp(d, p - 1);
  int exponent = d == 0 ? 0 : std::atoi(e.c_str() + e.find('e') + 1);
  std::string out;
  if (exponent >= -4 && exponent < p - 1) {
    out = FormatFloatFixed(d, p - 1 - exponent);
    if (out.find('.') != std::string::npos) {
      while (out.back() == '0') out.pop_back();
      if (out.back() == '.') out.pop_back();
    }
    if (out.find('.') == std::string::npos) out += ".0";
  } else {
    size_t at = e.find('e');
    std::string mantissa = e.substr(0, at);
    if (mantissa.find('.') != std::string::npos) {
      while (mantissa.back() == '0') mantissa.pop_back();
      if (mantissa.back() == '.') mantissa.pop_back();
    }
    out = mantissa + e.substr(at);
  }
  return out;
}

Result<std::string> FormatFloat(double d, const Spec& spec) {
  char type = spec.type;
  bool negative = std::signbit(d) && !std::isnan(d);
  double a = std::fabs(d);
  std::string body;
  int precision = spec.precision < 0 ? 6 : static_cast<int>(spec.precision);
  bool upper = type == 'E' || type == 'F' || type == 'G';
  switch (type) {
    case 0:
      body = spec.precision < 0 ? FloatRepr(a) : FloatNoTypePrecision(a, precision);
      break;
    case 'f':
    case 'F': body = FormatFloatFixed(a, precision); break;
    case 'e':
    case 'E': body = FormatFloatExp(a, precision, upper); break;
    case 'g':
    case 'G':
    case 'n': body = FormatFloatGeneral(a, precision, spec.alternate, upper); break;
    case '%': body = std::isfinite(a) ? FormatFloatFixed(a * 100, precision) + "%" : FormatFloatFixed(a, 0) + "%"; break;
    default:
      return Fail(Error::Kind::kValue, fmt::format("unknown format code '{}' for a float", type));
  }
  if (type == 'F' || (upper && !std::isfinite(a))) {
    for (char& c : body) c = Upper(c);
  }
  if (spec.alternate && body.find('.') == std::string::npos && std::isfinite(a) && type != 'g' && type != 'G') {
    size_t e = body.find_first_of("eE%");
    body.insert(e == std::string::npos ? body.size() : e, ".");
  }
  if (spec.z && negative && body.find_first_not_of("0.e+-E%") == std::string::npos) negative = false;
  if (spec.grouping && std::isfinite(a)) {
    size_t end = body.find_first_of(".eE%");
    if (end == std::string::npos) end = body.size();
    body = Group(body.substr(0, end), spec.grouping) + body.substr(end);
  }
  return Align(spec, SignText(spec, negative), body, '>');
}

Result<std::string> FormatInt(const Value& value, const Spec& spec) {
  char type = spec.type;
  if (type == 'e' || type == 'E' || type == 'f' || type == 'F' || type == 'g' || type == 'G' || type == '%') {
    if (value.IsBigInt() && !value.big().ToDouble())
      return Fail(Error::Kind::kOverflow, "int too large to convert to float");
    return FormatFloat(value.AsFloat(), spec);
  }
  if (spec.precision >= 0) return Fail(Error::Kind::kValue, "precision is not allowed in an integer format specifier");
  if (value.IsBigInt()) {
    if (type == 'c') return Fail(Error::Kind::kOverflow, "%c arg not in range(0x110000)");
    if (type != 0 && type != 'd' && type != 'n' && type != 'b' && type != 'o' && type != 'x' && type != 'X')
      return Fail(Error::Kind::kValue, fmt::format("unknown format code '{}' for an int", type));
    int base = type == 'b' ? 2 : type == 'o' ? 8 : (type == 'x' || type == 'X') ? 16 : 10;
    std::string body = value.big().Abs().ToString(base), prefix;
    if (type == 'X')
      for (char& c : body) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (base != 10 && spec.alternate) prefix = std::string("0") + type;
    if (spec.grouping) body = Group(body, spec.grouping, base == 10 ? 3 : 4);
    return Align(spec, SignText(spec, value.big().IsNegative()) + prefix, body, '>');
  }
  int64_t v = value.AsInt();
  bool negative = v < 0;
  uint64_t mag = negative ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  std::string body, prefix;
  switch (type) {
    case 0:
    case 'd':
    case 'n': body = std::to_string(mag); break;
    case 'b':
    case 'o':
    case 'x':
    case 'X': {
      int base = type == 'b' ? 2 : type == 'o' ? 8 : 16;
      const char* digits = type == 'X' ? "0123456789ABCDEF" : "0123456789abcdef";
      do {
        body.insert(body.begin(), digits[mag % static_cast<uint64_t>(base)]);
        mag /= static_cast<uint64_t>(base);
      } while (mag);
      if (spec.alternate) prefix = std::string("0") + type;
      break;
    }
    case 'c': {
      if (v < 0 || v > 0x10FFFF) return Fail(Error::Kind::kOverflow, "%c arg not in range(0x110000)");
      std::string s;
      uint32_t cp = static_cast<uint32_t>(v);
      if (cp < 0x80) s.push_back(static_cast<char>(cp));
      else if (cp < 0x800) { s.push_back(static_cast<char>(0xC0 | (cp >> 6))); s.push_back(static_cast<char>(0x80 | (cp & 0x3F))); }
      else if (cp < 0x10000) { s.push_back(static_cast<char>(0xE0 | (cp >> 12))); s.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F))); s.push_back(static_cast<char>(0x80 | (cp & 0x3F))); }
      else { s.push_back(static_cast<char>(0xF0 | (cp >> 18))); s.push_back(static_cast<char>(0x80 | ((cp >> 12) & 0x3F))); s.push_back(static_cast<char>(0x80 | ((cp >> 6) & 0x3F))); s.push_back(static_cast<char>(0x80 | (cp & 0x3F))); }
      return Align(spec, "", s, '<');
    }
    default: return Fail(Error::Kind::kValue, fmt::format("unknown format code '{}' for an int", type));
  }
  if (spec.grouping) body = Group(body, spec.grouping, (type == 0 || type == 'd' || type == 'n') ? 3 : 4);
  return Align(spec, SignText(spec, negative) + prefix, body, '>');
}

}  // namespace

Result<std::string> FormatWithSpec(const Value& v, std::string_view spec_text) {
  if (spec_text.empty()) return Str(v);
  PYEXPR_TRY(spec, ParseSpec(spec_text));
  if (v.IsFloat()) return FormatFloat(v.AsFloat(), spec);
  if (v.IsIntegral()) return FormatInt(v, spec);
  if (v.IsStr()) {
    if (spec.type != 0 && spec.type != 's')
      return Fail(Error::Kind::kValue, fmt::format("unknown format code '{}' for a str", spec.type));
    if (spec.sign != '-' || spec.alternate || spec.grouping || spec.z)
      return Fail(Error::Kind::kValue, "sign, '#', 'z' and grouping are not allowed in a string format specifier");
    if (spec.align == '=') return Fail(Error::Kind::kValue, "'=' alignment is not allowed in a string format specifier");
    std::string s = v.AsStr();
    if (spec.precision >= 0 && static_cast<size_t>(spec.precision) < CodePointCount(s))
      s = s.substr(0, ByteOffset(s, static_cast<size_t>(spec.precision)));
    return Align(spec, "", s, '<');
  }
  return Fail(Error::Kind::kType, fmt::format("a '{}' value cannot be formatted with a format specifier", TypeName(v)));
}

namespace internal {

Result<std::string> FormatValue(const Value& v, std::string_view spec) { return FormatWithSpec(v, spec); }

Result<Value> FormatString(const std::string& format, Positional positional, Keywords keywords) {
  std::string out;
  size_t auto_index = 0;
  bool used_auto = false, used_manual = false;
  // resolves one field name to a value
  auto resolve = [&](std::string_view field) -> Result<Value> {
    size_t end = field.find_first_of(".[");
    std::string_view head = field.substr(0, end);
    Value v;
    if (head.empty()) {
      if (used_manual) return Fail(Error::Kind::kValue, "cannot switch from manual field numbering to automatic numbering");
      used_auto = true;
      if (auto_index >= positional.size())
        return Fail(Error::Kind::kIndex, fmt::format("format() has no positional argument {}", auto_index));
      v = positional[auto_index++];
    } else if (head.find_first_not_of("0123456789") == std::string_view::npos) {
      if (used_auto) return Fail(Error::Kind::kValue, "cannot switch from automatic field numbering to manual numbering");
      used_manual = true;
      size_t i = std::stoul(std::string(head.substr(0, 9)));
      if (i >= positional.size()) return Fail(Error::Kind::kIndex, fmt::format("format() has no positional argument {}", i));
      v = positional[i];
    } else {
      const Value* kv = FindKeyword(keywords, head);
      if (!kv) {
        Error e{Error::Kind::kKey, fmt::format("format() has no keyword argument '{}'", head)};
        e.missing_name = std::string(head);
        return e;
      }
      v = *kv;
    }
    size_t i = end == std::string_view::npos ? field.size() : end;
    while (i < field.size()) {
      if (field[i] == '[') {
        size_t close = field.find(']', i);
        if (close == std::string_view::npos) return Fail(Error::Kind::kValue, "missing ']' in format string");
        std::string key(field.substr(i + 1, close - i - 1));
        Value k = (!key.empty() && key.find_first_not_of("0123456789") == std::string::npos)
                      ? Value::Int(std::stoll(key.substr(0, 18)))
                      : Value::Str(key);
        PYEXPR_TRY(next, Subscript(v, k));
        v = std::move(next);
        i = close + 1;
      } else if (field[i] == '.') {
        size_t next_at = field.find_first_of(".[", i + 1);
        std::string attr(field.substr(i + 1, (next_at == std::string_view::npos ? field.size() : next_at) - i - 1));
        if (v.IsDict() && v.attribute_access() && v.DictFind(attr)) {
          v = WrapChild(v, *v.DictFind(attr));
        } else if (v.IsNamespace() && v.names().Find(attr)) {
          v = *v.names().Find(attr);
        } else {
          Error e{Error::Kind::kAttribute, fmt::format("'{}' values have no attribute '{}'", TypeName(v), attr)};
          e.missing_name = attr;
          return e;
        }
        i = next_at == std::string_view::npos ? field.size() : next_at;
      } else {
        return Fail(Error::Kind::kValue, "only '.' or '[' may follow ']' in a format field");
      }
    }
    return v;
  };
  size_t i = 0;
  while (i < format.size()) {
    char c = format[i];
    if (c == '}') {
      if (i + 1 < format.size() && format[i + 1] == '}') {
        out.push_back('}');
        i += 2;
        continue;
      }
      return Fail(Error::Kind::kValue, "single '}' encountered in format string");
    }
    if (c != '{') {
      out.push_back(c);
      ++i;
      continue;
    }
    if (i + 1 < format.size() && format[i + 1] == '{') {
      out.push_back('{');
      i += 2;
      continue;
    }
    // find the matching '}' (one level of nested fields in the spec)
    size_t j = i + 1;
    int depth = 1;
    while (j < format.size() && depth > 0) {
      if (format[j] == '{') ++depth;
      else if (format[j] == '}') --depth;
      if (depth > 0) ++j;
    }
    if (j >= format.size()) return Fail(Error::Kind::kValue, "single '{' encountered in format string");
    std::string field = format.substr(i + 1, j - i - 1);
    i = j + 1;
    std::string spec, conversion;
    size_t colon = std::string::npos;
    {
      int bracket = 0;
      for (size_t k = 0; k < field.size(); ++k) {
        if (field[k] == '[') ++bracket;
        else if (field[k] == ']') --bracket;
        else if (bracket == 0 && (field[k] == ':' || field[k] == '!')) {
          colon = k;
          break;
        }
      }
    }
    std::string name = field.substr(0, colon);
    if (colon != std::string::npos) {
      std::string rest = field.substr(colon);
      if (rest[0] == '!') {
        if (rest.size() < 2 || (rest.size() > 2 && rest[2] != ':'))
          return Fail(Error::Kind::kValue, "expected ':' after conversion specifier");
        conversion = rest.substr(1, 1);
        rest = rest.size() > 2 ? rest.substr(2) : "";
      }
      if (!rest.empty()) spec = rest.substr(1);
    }
    PYEXPR_TRY(v, resolve(name));
    if (conversion == "r" || conversion == "a") v = Value::Str(Repr(v));
    else if (conversion == "s") v = Value::Str(Str(v));
    else if (!conversion.empty()) return Fail(Error::Kind::kValue, fmt::format("unknown conversion specifier {}", conversion));
    // nested replacement fields in the spec
    std::string expanded;
    for (size_t k = 0; k < spec.size(); ++k) {
      if (spec[k] == '{') {
        size_t close = spec.find('}', k);
        if (close == std::string::npos) return Fail(Error::Kind::kValue, "unmatched '{' in format spec");
        PYEXPR_TRY(nested, resolve(spec.substr(k + 1, close - k - 1)));
        expanded += Str(nested);
        k = close;
      } else {
        expanded.push_back(spec[k]);
      }
    }
    PYEXPR_TRY(text, FormatWithSpec(v, expanded));
    out += text;
    PYEXPR_CHECK(CheckStringSize(out.size()));
  }
  return Value::Str(std::move(out));
}

// printf-style `format % args`: %s %r %a %d %i %u %f %F %e %E %g %G %x %X %o %c %%
// with flags, width and precision (a `*` width or precision and the %(name)s
// mapping form too).
Result<Value> PercentFormat(const std::string& format, const Value& args) {
  std::vector<Value> items;
  const Value* mapping = nullptr;
  if (args.IsTuple()) items = args.items();
  else if (args.IsDict()) mapping = &args;
  else items.push_back(args);
  size_t next = 0;
  auto take = [&]() -> Result<Value> {
    if (next >= items.size()) return Fail(Error::Kind::kType, "not enough arguments for format string");
    return items[next++];
  };
  std::string out;
  bool used_mapping = false;
  for (size_t i = 0; i < format.size(); ++i) {
    char c = format[i];
    if (c != '%') {
      out.push_back(c);
      continue;
    }
    if (++i >= format.size()) return Fail(Error::Kind::kValue, "incomplete format");
    Value value;
    bool have_value = false;
    if (format[i] == '(') {
      size_t close = format.find(')', i);
      if (close == std::string::npos) return Fail(Error::Kind::kValue, "incomplete format key");
      if (!mapping) return Fail(Error::Kind::kType, "format requires a mapping");
      std::string key = format.substr(i + 1, close - i - 1);
      const Value* v = mapping->DictFind(key);
      if (!v) {
        Error e{Error::Kind::kKey, fmt::format("key '{}' is not in the mapping", key)};
        e.missing_name = key;
        return e;
      }
      value = *v;
      have_value = true;
      used_mapping = true;
      i = close + 1;
    }
    Spec spec;
    spec.align = '>';
    bool left = false, zero = false;
    for (; i < format.size(); ++i) {
      char f = format[i];
      if (f == '-') left = true;
      else if (f == '+') spec.sign = '+';
      else if (f == ' ') { if (spec.sign != '+') spec.sign = ' '; }
      else if (f == '#') spec.alternate = true;
      else if (f == '0') zero = true;
      else break;
    }
    auto number = [&](int64_t& target) -> Result<bool> {
      if (i < format.size() && format[i] == '*') {
        ++i;
        PYEXPR_TRY(w, take());
        PYEXPR_TRY(n, AsIndex(w, "* width"));
        target = n;
        return true;
      }
      int64_t v = 0;
      bool any = false;
      while (i < format.size() && format[i] >= '0' && format[i] <= '9') {
        v = std::min<int64_t>(v * 10 + (format[i++] - '0'), int64_t{1} << 40);
        any = true;
      }
      if (any) target = v;
      return true;
    };
    PYEXPR_CHECK(number(spec.width));
    if (spec.width < -1) {
      left = true;
      spec.width = -spec.width;
    }
    if (i < format.size() && format[i] == '.') {
      ++i;
      spec.precision = 0;
      PYEXPR_CHECK(number(spec.precision));
    }
    while (i < format.size() && (format[i] == 'h' || format[i] == 'l' || format[i] == 'L')) ++i;
    if (i >= format.size()) return Fail(Error::Kind::kValue, "incomplete format");
    char conv = format[i];
    if (conv == '%') {
      out.push_back('%');
      continue;
    }
    if (!have_value) {
      if (mapping) {
        value = *mapping;
      } else {
        PYEXPR_TRY(v, take());
        value = std::move(v);
      }
    }
    if (spec.width > 0) PYEXPR_CHECK(CheckStringSize(static_cast<size_t>(spec.width)));
    if (left) spec.align = '<';
    else if (zero && conv != 's' && conv != 'r' && conv != 'a' && conv != 'c') {
      spec.fill = "0";
      spec.align = '=';
    }
    std::string text;
    switch (conv) {
      case 's':
      case 'r':
      case 'a': {
        std::string s = conv == 's' ? Str(value) : Repr(value);
        if (spec.precision >= 0 && static_cast<size_t>(spec.precision) < CodePointCount(s))
          s = s.substr(0, ByteOffset(s, static_cast<size_t>(spec.precision)));
        spec.precision = -1;
        text = Align(spec, "", s, '>');
        break;
      }
      case 'd':
      case 'i':
      case 'u': {
        Value n = value;
        if (value.IsFloat()) {
          PYEXPR_TRY(t, FloatToInt(value.AsFloat()));
          n = t;
        } else if (!value.IsIntegral()) {
          return Fail(Error::Kind::kType, fmt::format("%{} format: a real number is required, not {}", conv, TypeName(value)));
        }
        spec.precision = -1;
        spec.type = 'd';
        PYEXPR_TRY(t, FormatInt(n, spec));
        text = t;
        break;
      }
      case 'x':
      case 'X':
      case 'o': {
        if (!value.IsIntegral())
          return Fail(Error::Kind::kType, fmt::format("%{} format: an integer is required, not {}", conv, TypeName(value)));
        spec.precision = -1;
        spec.type = conv;
        PYEXPR_TRY(t, FormatInt(value, spec));
        text = t;
        break;
      }
      case 'c': {
        if (value.IsStr() && CodePointCount(value.AsStr()) == 1) {
          text = Align(spec, "", value.AsStr(), '>');
        } else if (value.IsIntegral()) {
          spec.type = 'c';
          spec.align = left ? '<' : '>';
          PYEXPR_TRY(t, FormatInt(value, spec));
          text = t;
        } else {
          return Fail(Error::Kind::kType, "%c requires an int or a single character");
        }
        break;
      }
      case 'f':
      case 'F':
      case 'e':
      case 'E':
      case 'g':
      case 'G': {
        if (!value.IsNumber())
          return Fail(Error::Kind::kType, fmt::format("%{} format: a real number is required, not {}", conv, TypeName(value)));
        spec.type = conv;
        if (spec.precision < 0) spec.precision = 6;
        PYEXPR_TRY(t, FormatFloat(value.AsFloat(), spec));
        text = t;
        break;
      }
      default:
        return Fail(Error::Kind::kValue, fmt::format("unsupported format character '{}'", conv));
    }
    out += text;
    PYEXPR_CHECK(CheckStringSize(out.size()));
  }
  if (!mapping && next < items.size())
    return Fail(Error::Kind::kType, "not all arguments converted during string formatting");
  (void)used_mapping;
  return Value::Str(std::move(out));
}

}  // namespace internal
}  // namespace mdlc::pyexpr
