// builtins.cc - Python's builtins as xacro exposes them, and the argument
// checking helpers the other builtin modules share.
#include "frontend/pyexpr/builtins.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/number_text.h"

namespace mdlc::pyexpr {
namespace internal {

Result<bool> CheckArgs(std::string_view name, Positional positional, Keywords keywords, size_t min_args,
                       size_t max_args, std::initializer_list<std::string_view> allowed_keywords) {
  for (const auto& [key, value] : keywords) {
    bool ok = false;
    for (auto allowed : allowed_keywords) ok = ok || allowed == key;
    if (!ok) return Fail(Error::Kind::kType, fmt::format("{}() got an unexpected keyword argument '{}'", name, key));
  }
  if (positional.size() < min_args) {
    return Fail(Error::Kind::kType, fmt::format("{}() takes at least {} argument{} ({} given)", name, min_args,
                                                min_args == 1 ? "" : "s", positional.size()));
  }
  if (positional.size() > max_args) {
    if (max_args == 0) return Fail(Error::Kind::kType, fmt::format("{}() takes no arguments", name));
    return Fail(Error::Kind::kType, fmt::format("{}() takes at most {} argument{} ({} given)", name, max_args,
                                                max_args == 1 ? "" : "s", positional.size()));
  }
  return true;
}

const Value* FindKeyword(Keywords keywords, std::string_view name) {
  for (const auto& [key, value] : keywords)
    if (key == name) return &value;
  return nullptr;
}

Result<int64_t> AsIndex(const Value& v, std::string_view what) {
  if (!v.IsIntegral())
    return Fail(Error::Kind::kType, fmt::format("{} needs an integer, not '{}'", what, TypeName(v)));
  return v.AsInt();
}

Result<double> AsReal(const Value& v, std::string_view function) {
  if (!v.IsNumber())
    return Fail(Error::Kind::kType, fmt::format("{}() needs a number, not '{}'", function, TypeName(v)));
  return v.AsFloat();
}

Result<Value> FloatToInt(double d) {
  if (std::isnan(d)) return Fail(Error::Kind::kValue, "cannot convert float nan to integer");
  if (std::isinf(d)) return Fail(Error::Kind::kOverflow, "cannot convert float infinity to integer");
  double t = std::trunc(d);
  if (t >= 9223372036854775808.0 || t < -9223372036854775808.0) return BigResult(*BigInt::FromDouble(t));
  return Value::Int(static_cast<int64_t>(t));
}

}  // namespace internal

namespace {

using internal::CheckArgs;
using internal::Fail;
using internal::FindKeyword;
using internal::Keywords;
using internal::Positional;

Result<Value> Unsupported(std::string_view name) {
  return Fail(Error::Kind::kUnsupported, fmt::format("the builtin {}() is not supported", name));
}

// int(text, base)
Result<Value> IntFromText(const std::string& text, int64_t base) {
  auto invalid = [&] {
    return Fail(Error::Kind::kValue, fmt::format("invalid literal for int() with base {}: {}", base, Repr(Value::Str(text))));
  };
  if (base != 0 && (base < 2 || base > 36)) return Fail(Error::Kind::kValue, "int() base must be >= 2 and <= 36, or 0");
  std::string_view s = text;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  bool negative = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  int64_t b = base;
  if (s.size() >= 2 && s[0] == '0') {
    char p = static_cast<char>(s[1] | 0x20);
    int64_t prefix_base = p == 'x' ? 16 : p == 'o' ? 8 : p == 'b' ? 2 : 0;
    if (prefix_base && (b == 0 || b == prefix_base)) {
      b = prefix_base;
      s.remove_prefix(2);
      if (!s.empty() && s[0] == '_') s.remove_prefix(1);
    }
  }
  if (b == 0) {
    b = 10;
    if (s.size() > 1 && s[0] == '0' && s.find_first_not_of("0_") != std::string_view::npos) return invalid();
  }
  if (s.empty()) return invalid();
  std::string digits;
  bool last_digit = false;
  for (size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '_' && last_digit && i + 1 < s.size()) {
      last_digit = false;
      continue;
    }
    int d = (c >= '0' && c <= '9') ? c - '0' : (c >= 'a' && c <= 'z') ? c - 'a' + 10 : (c >= 'A' && c <= 'Z') ? c - 'A' + 10 : 99;
    if (d >= b) return invalid();
    digits.push_back(c);
    last_digit = true;
  }
  if (!last_digit) return invalid();
  // Python 3.11 limits conversions in bases that are not powers of two
  if ((b & (b - 1)) != 0 && digits.size() > 4300)
    return Fail(Error::Kind::kValue,
                fmt::format("Exceeds the limit (4300 digits) for integer string conversion: value has {} digits; use "
                            "sys.set_int_max_str_digits() to increase the limit",
                            digits.size()));
  return internal::BigResult(BigInt::FromDigits(digits, static_cast<int>(b), negative));
}

Result<Value> BuiltinInt(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("int", args, kw, 0, 2, {"base"}));
  if (args.empty() && !FindKeyword(kw, "base")) return Value::Int(0);
  if (args.empty()) return Fail(Error::Kind::kType, "int() missing string argument");
  const Value& x = args[0];
  const Value* base = args.size() > 1 ? &args[1] : FindKeyword(kw, "base");
  if (base) {
    if (!x.IsStr()) return Fail(Error::Kind::kType, "int() cannot convert non-string with explicit base");
    if (!base->IsIntegral()) return Fail(Error::Kind::kType, "int() base must be an integer");
    return IntFromText(x.AsStr(), base->AsInt());
  }
  if (x.IsIntegral()) return x.IsBigInt() ? x : Value::Int(x.AsInt());
  if (x.IsFloat()) return internal::FloatToInt(x.AsFloat());
  if (x.IsStr()) return IntFromText(x.AsStr(), 10);
  return Fail(Error::Kind::kType, fmt::format("int() needs a string or a number, not '{}'", TypeName(x)));
}

Result<Value> BuiltinFloat(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("float", args, kw, 0, 1));
  if (args.empty()) return Value::Float(0.0);
  const Value& x = args[0];
  if (x.IsNumber()) {
    PYEXPR_TRY(d, internal::ToFloat(x));
    return Value::Float(d);
  }
  if (x.IsStr()) {
    if (auto d = ParsePythonFloat(x.AsStr())) return Value::Float(*d);
    return Fail(Error::Kind::kValue, fmt::format("could not convert string to float: {}", Repr(x)));
  }
  return Fail(Error::Kind::kType, fmt::format("float() needs a string or a number, not '{}'", TypeName(x)));
}

Result<Value> BuiltinStr(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("str", args, kw, 0, 1));
  if (args.empty()) return Value::Str("");
  std::string s = Str(args[0]);
  PYEXPR_CHECK(internal::CheckStringSize(s.size()));
  return Value::Str(std::move(s));
}

Result<Value> BuiltinRepr(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("repr", args, kw, 1, 1));
  return Value::Str(Repr(args[0]));
}

Result<Value> BuiltinLen(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("len", args, kw, 1, 1));
  const Value& x = args[0];
  switch (x.kind()) {
    case Value::Kind::kStr:
      return Value::Int(static_cast<int64_t>(internal::IsAscii(x.AsStr()) ? x.AsStr().size()
                                                                       : internal::SplitCodePoints(x.AsStr()).size()));
    case Value::Kind::kList:
    case Value::Kind::kTuple: return Value::Int(static_cast<int64_t>(x.items().size()));
    case Value::Kind::kDict: return Value::Int(static_cast<int64_t>(x.dict_items().size()));
    case Value::Kind::kNamespace: return Value::Int(static_cast<int64_t>(x.names().Names().size()));
    default: return Fail(Error::Kind::kType, fmt::format("'{}' values have no len()", TypeName(x)));
  }
}

Result<Value> BuiltinList(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("list", args, kw, 0, 1));
  if (args.empty()) return Value::List({});
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  return Value::List(std::move(items));
}

Result<Value> BuiltinTuple(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("tuple", args, kw, 0, 1));
  if (args.empty()) return Value::Tuple({});
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  return Value::Tuple(std::move(items));
}

Result<Value> BuiltinDict(Positional args, Keywords kw) {
  if (args.size() > 1) return Fail(Error::Kind::kType, fmt::format("dict() takes at most 1 argument ({} given)", args.size()));
  std::vector<Value::Item> items;
  if (!args.empty()) {
    const Value& x = args[0];
    if (x.IsDict()) {
      items = x.dict_items();
    } else {
      PYEXPR_TRY(seq, internal::Iterate(x));
      for (size_t i = 0; i < seq.size(); ++i) {
        PYEXPR_TRY(pair, internal::Iterate(seq[i]));
        if (pair.size() != 2)
          return Fail(Error::Kind::kValue,
                      fmt::format("dictionary update sequence element #{} has length {}; 2 is required", i, pair.size()));
        if (!Hash(pair[0])) return Fail(Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(pair[0])));
        items.emplace_back(pair[0], pair[1]);
      }
    }
  }
  for (const auto& [key, value] : kw) items.emplace_back(Value::Str(key), value);
  return Value::Dict(std::move(items));
}

Result<Value> MinMax(bool is_max, Positional args, Keywords kw) {
  const char* name = is_max ? "max" : "min";
  PYEXPR_CHECK(CheckArgs(name, args, kw, 1, std::numeric_limits<size_t>::max(), {"key", "default"}));
  std::vector<Value> items;
  if (args.size() == 1) {
    PYEXPR_TRY(seq, internal::Iterate(args[0]));
    items = std::move(seq);
  } else {
    if (FindKeyword(kw, "default"))
      return Fail(Error::Kind::kType, fmt::format("{}() cannot take 'default' with several positional arguments", name));
    items.assign(args.begin(), args.end());
  }
  if (items.empty()) {
    if (const Value* d = FindKeyword(kw, "default")) return *d;
    return Fail(Error::Kind::kValue, fmt::format("{}() of an empty sequence", name));
  }
  const Value* key = FindKeyword(kw, "key");
  if (key && key->IsNone()) key = nullptr;
  size_t best = 0;
  Value best_key = items[0];
  if (key) {
    PYEXPR_TRY(k, internal::Call(*key, std::span<const Value>(&items[0], 1)));
    best_key = std::move(k);
  }
  for (size_t i = 1; i < items.size(); ++i) {
    Value k = items[i];
    if (key) {
      PYEXPR_TRY(kk, internal::Call(*key, std::span<const Value>(&items[i], 1)));
      k = std::move(kk);
    }
    PYEXPR_TRY(better, Compare(k, is_max ? CompareOp::kGt : CompareOp::kLt, best_key));
    if (better) {
      best = i;
      best_key = std::move(k);
    }
  }
  return items[best];
}

// round(x, n) for a float: correctly rounded from the binary value, ties to even.
double RoundFloat(double x, int64_t n) {
  if (!std::isfinite(x) || x == 0.0) return x;
  if (n > 323) return x;
  if (n < -308) return 0.0 * x;
  std::string text;
  if (n >= 0) {
    text = FormatFloatFixed(x, static_cast<int>(n));
  } else {
    int k = static_cast<int>(-n);
    ShortestDigits s = ShortestOf(x);
    int d = s.decpt - 1;  // floor(log10(|x|))
    if (d >= k) {
      text = FormatFloatExp(x, d - k);
    } else if (d == k - 1) {
      double half = std::strtod(fmt::format("5e{}", k - 1).c_str(), nullptr);
      double ax = std::fabs(x);
      double r = ax > half ? std::strtod(fmt::format("1e{}", k).c_str(), nullptr) : 0.0;
      return std::copysign(r, x);
    } else {
      return std::copysign(0.0, x);
    }
  }
  double r = std::strtod(text.c_str(), nullptr);
  return r == 0.0 ? std::copysign(0.0, x) : r;
}

Result<Value> BuiltinRound(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("round", args, kw, 0, 2, {"number", "ndigits"}));
  const Value* x = !args.empty() ? &args[0] : FindKeyword(kw, "number");
  if (!x) return Fail(Error::Kind::kType, "round() missing required argument 'number'");
  const Value* nd = args.size() > 1 ? &args[1] : FindKeyword(kw, "ndigits");
  if (nd && nd->IsNone()) nd = nullptr;
  if (!x->IsNumber()) return Fail(Error::Kind::kType, fmt::format("type {} doesn't define __round__ method", TypeName(*x)));
  if (nd && !nd->IsIntegral())
    return Fail(Error::Kind::kType, fmt::format("'{}' object cannot be interpreted as an integer", TypeName(*nd)));
  if (x->IsIntegral()) {
    int64_t v = x->AsInt();
    if (!nd || nd->AsInt() >= 0) return x->IsBigInt() ? *x : Value::Int(v);
    if (x->IsBigInt() || nd->IsBigInt() || -nd->AsInt() >= 19) {
      // v = q*m + r with 0 <= r < m; ties to even
      if (nd->IsBigInt() || static_cast<double>(-nd->AsInt()) > static_cast<double>(x->AsBigInt().BitLength()) / 3.3 + 2)
        return Value::Int(0);
      BigInt m = BigInt::Pow(BigInt::FromInt64(10), static_cast<uint64_t>(-nd->AsInt()));
      BigInt q, r;
      BigInt::DivMod(x->AsBigInt(), m, &q, &r);
      int c = BigInt::Compare(r + r, m);
      if (c > 0 || (c == 0 && q.IsOdd())) q = q + BigInt::FromInt64(1);
      return internal::BigResult(q * m);
    }
    int64_t k = -nd->AsInt();
    int64_t m = 1;
    for (int64_t i = 0; i < k; ++i) m *= 10;
    int64_t q = v / m, r = v % m;
    if (r < 0) {
      r += m;
      q -= 1;
    }
    // now v = q*m + r with 0 <= r < m
    if (2 * r > m || (2 * r == m && (q & 1))) q += 1;
    int64_t out;
    if (__builtin_mul_overflow(q, m, &out)) return internal::BigResult(BigInt::FromInt64(q) * BigInt::FromInt64(m));
    return Value::Int(out);
  }
  double d = x->AsFloat();
  if (!nd) return internal::FloatToInt(std::nearbyint(d));
  return Value::Float(RoundFloat(d, nd->AsInt()));
}

Result<Value> BuiltinAbs(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("abs", args, kw, 1, 1));
  const Value& x = args[0];
  if (x.IsIntegral()) {
    if (x.IsBigInt() || x.AsInt() == std::numeric_limits<int64_t>::min()) return Value::Big(x.AsBigInt().Abs());
    return Value::Int(x.AsInt() < 0 ? -x.AsInt() : x.AsInt());
  }
  if (x.IsFloat()) return Value::Float(std::fabs(x.AsFloat()));
  return Fail(Error::Kind::kType, fmt::format("bad operand type for abs(): '{}'", TypeName(x)));
}

Result<Value> AllAny(bool is_all, Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs(is_all ? "all" : "any", args, kw, 1, 1));
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  for (const Value& v : items)
    if (Truthy(v) != is_all) return Value::Bool(!is_all);
  return Value::Bool(is_all);
}

Result<Value> BuiltinDivmod(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("divmod", args, kw, 2, 2));
  if (!args[0].IsNumber() || !args[1].IsNumber())
    return Fail(Error::Kind::kType, fmt::format("unsupported operand types for divmod(): '{}' and '{}'",
                                                TypeName(args[0]), TypeName(args[1])));
  PYEXPR_TRY(q, internal::ApplyBinary(internal::BinOp::kFloorDiv, args[0], args[1]));
  PYEXPR_TRY(r, internal::ApplyBinary(internal::BinOp::kMod, args[0], args[1]));
  return Value::Tuple({q, r});
}

Result<Value> BuiltinEnumerate(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("enumerate", args, kw, 1, 2, {"start"}));
  const Value* start = args.size() > 1 ? &args[1] : FindKeyword(kw, "start");
  int64_t i = 0;
  if (start) {
    PYEXPR_TRY(s, internal::AsIndex(*start, "enumerate() start"));
    i = s;
  }
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  std::vector<Value> out;
  out.reserve(items.size());
  for (auto& v : items) out.push_back(Value::Tuple({Value::Int(i++), std::move(v)}));
  return Value::List(std::move(out));
}

Result<Value> BuiltinFilter(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("filter", args, kw, 2, 2));
  PYEXPR_TRY(items, internal::Iterate(args[1]));
  std::vector<Value> out;
  for (const Value& v : items) {
    bool keep;
    if (args[0].IsNone()) {
      keep = Truthy(v);
    } else {
      PYEXPR_TRY(r, internal::Call(args[0], std::span<const Value>(&v, 1)));
      keep = Truthy(r);
    }
    if (keep) out.push_back(v);
  }
  return Value::List(std::move(out));
}

Result<Value> BuiltinMap(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("map", args, kw, 2, std::numeric_limits<size_t>::max()));
  std::vector<std::vector<Value>> seqs;
  size_t n = std::numeric_limits<size_t>::max();
  for (size_t i = 1; i < args.size(); ++i) {
    PYEXPR_TRY(items, internal::Iterate(args[i]));
    n = std::min(n, items.size());
    seqs.push_back(std::move(items));
  }
  std::vector<Value> out;
  out.reserve(n);
  std::vector<Value> call_args(seqs.size());
  for (size_t k = 0; k < n; ++k) {
    for (size_t s = 0; s < seqs.size(); ++s) call_args[s] = seqs[s][k];
    PYEXPR_TRY(r, internal::Call(args[0], call_args));
    out.push_back(std::move(r));
  }
  return Value::List(std::move(out));
}

Result<Value> BuiltinZip(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("zip", args, kw, 0, std::numeric_limits<size_t>::max(), {"strict"}));
  std::vector<std::vector<Value>> seqs;
  size_t n = args.empty() ? 0 : std::numeric_limits<size_t>::max();
  for (const Value& a : args) {
    PYEXPR_TRY(items, internal::Iterate(a));
    n = std::min(n, items.size());
    seqs.push_back(std::move(items));
  }
  std::vector<Value> out;
  out.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    std::vector<Value> t;
    for (auto& s : seqs) t.push_back(s[k]);
    out.push_back(Value::Tuple(std::move(t)));
  }
  return Value::List(std::move(out));
}

Result<Value> BuiltinReversed(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("reversed", args, kw, 1, 1));
  if (!args[0].IsSequence() && !args[0].IsStr() && !args[0].IsDict())
    return Fail(Error::Kind::kType, fmt::format("'{}' values cannot be reversed", TypeName(args[0])));
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  return Value::List(std::vector<Value>(items.rbegin(), items.rend()));
}

Result<Value> BuiltinSum(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("sum", args, kw, 1, 2, {"start"}));
  const Value* start = args.size() > 1 ? &args[1] : FindKeyword(kw, "start");
  Value acc = start ? *start : Value::Int(0);
  if (acc.IsStr()) return Fail(Error::Kind::kType, "sum() cannot add strings (use ''.join(seq))");
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  for (const Value& v : items) {
    PYEXPR_TRY(next, internal::ApplyBinary(internal::BinOp::kAdd, acc, v));
    acc = std::move(next);
  }
  return acc;
}

Result<Value> BuiltinOrd(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("ord", args, kw, 1, 1));
  if (!args[0].IsStr()) return Fail(Error::Kind::kType, fmt::format("ord() needs a string, not '{}'", TypeName(args[0])));
  auto cps = internal::SplitCodePoints(args[0].AsStr());
  if (cps.size() != 1)
    return Fail(Error::Kind::kType, fmt::format("ord() needs a single character, but the string has {}", cps.size()));
  const std::string& c = cps[0];
  uint32_t cp = static_cast<unsigned char>(c[0]);
  if (c.size() > 1) {
    cp = c.size() == 2 ? (cp & 0x1F) : c.size() == 3 ? (cp & 0x0F) : (cp & 0x07);
    for (size_t i = 1; i < c.size(); ++i) cp = (cp << 6) | (static_cast<unsigned char>(c[i]) & 0x3F);
  }
  return Value::Int(cp);
}

Result<Value> BuiltinRange(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("range", args, kw, 1, 3));
  int64_t v[3] = {0, 0, 1};
  for (size_t i = 0; i < args.size(); ++i) {
    if (!args[i].IsIntegral())
      return Fail(Error::Kind::kType, fmt::format("'{}' object cannot be interpreted as an integer", TypeName(args[i])));
  }
  if (args.size() == 1) {
    v[1] = args[0].AsInt();
  } else {
    v[0] = args[0].AsInt();
    v[1] = args[1].AsInt();
    if (args.size() == 3) v[2] = args[2].AsInt();
  }
  if (v[2] == 0) return Fail(Error::Kind::kValue, "range() step must not be zero");
  __int128 start = v[0], stop = v[1], step = v[2];
  __int128 count = 0;
  if (step > 0 && start < stop) count = (stop - start + step - 1) / step;
  if (step < 0 && start > stop) count = (start - stop - step - 1) / (-step);
  if (count > static_cast<__int128>(internal::CurrentLimits().max_items)) {
    PYEXPR_CHECK(internal::CheckItemCount(std::numeric_limits<size_t>::max()));
  }
  std::vector<Value> out;
  out.reserve(static_cast<size_t>(count));
  for (__int128 i = 0; i < count; ++i) out.push_back(Value::Int(static_cast<int64_t>(start + i * step)));
  return Value::List(std::move(out));
}

// Stable merge sort that stops at the first comparison error.
Result<bool> MergeSort(std::vector<size_t>& order, const std::vector<Value>& keys, bool reverse) {
  std::vector<size_t> tmp(order.size());
  for (size_t width = 1; width < order.size(); width *= 2) {
    for (size_t lo = 0; lo < order.size(); lo += 2 * width) {
      size_t mid = std::min(lo + width, order.size()), hi = std::min(lo + 2 * width, order.size());
      size_t i = lo, j = mid, k = lo;
      while (i < mid && j < hi) {
        // take from the right only when it sorts strictly before the left
        auto before = reverse ? Compare(keys[order[j]], CompareOp::kGt, keys[order[i]])
                              : Compare(keys[order[j]], CompareOp::kLt, keys[order[i]]);
        if (!before.ok()) return before;
        tmp[k++] = *before ? order[j++] : order[i++];
      }
      while (i < mid) tmp[k++] = order[i++];
      while (j < hi) tmp[k++] = order[j++];
    }
    order.swap(tmp);
  }
  return true;
}

Result<Value> BuiltinSorted(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("sorted", args, kw, 1, 1, {"key", "reverse"}));
  PYEXPR_TRY(items, internal::Iterate(args[0]));
  const Value* key = FindKeyword(kw, "key");
  const Value* reverse = FindKeyword(kw, "reverse");
  std::vector<Value> keys = items;
  if (key && !key->IsNone()) {
    for (size_t i = 0; i < items.size(); ++i) {
      PYEXPR_TRY(k, internal::Call(*key, std::span<const Value>(&items[i], 1)));
      keys[i] = std::move(k);
    }
  }
  std::vector<size_t> order(items.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  PYEXPR_CHECK(MergeSort(order, keys, reverse && Truthy(*reverse)));
  std::vector<Value> out;
  out.reserve(order.size());
  for (size_t i : order) out.push_back(items[i]);
  return Value::List(std::move(out));
}

// the builtin type functions by name, for isinstance() and type()
bool IsInstanceOf(const Value& x, const Value& cls) {
  if (!cls.IsFunction()) return false;
  const std::string& n = cls.name();
  if (n == "int") return x.IsIntegral();
  if (n == "float") return x.IsFloat();
  if (n == "str") return x.IsStr();
  if (n == "list") return x.IsList();
  if (n == "tuple") return x.IsTuple();
  if (n == "dict") return x.IsDict();
  return false;
}

Result<Value> BuiltinIsinstance(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("isinstance", args, kw, 2, 2));
  std::vector<Value> classes;
  if (args[1].IsTuple()) classes = args[1].items(); else classes.push_back(args[1]);
  for (const Value& cls : classes) {
    static const char* kTypes[] = {"int", "float", "str", "list", "tuple", "dict"};
    bool known = false;
    for (const char* t : kTypes) known = known || (cls.IsFunction() && cls.name() == t);
    if (!known) return Fail(Error::Kind::kUnsupported, "isinstance() supports only int, float, str, list, tuple and dict");
    if (IsInstanceOf(args[0], cls)) return Value::Bool(true);
  }
  return Value::Bool(false);
}

Result<Value> BuiltinType(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("type", args, kw, 1, 1));
  const char* name = nullptr;
  switch (args[0].kind()) {
    case Value::Kind::kInt: name = "int"; break;
    case Value::Kind::kFloat: name = "float"; break;
    case Value::Kind::kStr: name = "str"; break;
    case Value::Kind::kList: name = "list"; break;
    case Value::Kind::kTuple: name = "tuple"; break;
    case Value::Kind::kDict: name = "dict"; break;
    default:
      return Fail(Error::Kind::kUnsupported, fmt::format("type() of a '{}' value is not supported", TypeName(args[0])));
  }
  return *StandardGlobals().Find(name);
}

std::shared_ptr<NameTable> BuildGlobals() {
  auto globals = std::make_shared<NameTable>();
  auto python = std::make_shared<NameTable>();
  auto fn = [](std::string name, auto f) { return Value::Function(std::move(name), NativeFunction(f)); };
  std::vector<std::pair<std::string, Value>> core = {
      {"list", fn("list", BuiltinList)},
      {"dict", fn("dict", BuiltinDict)},
      {"map", fn("map", BuiltinMap)},
      {"len", fn("len", BuiltinLen)},
      {"str", fn("str", BuiltinStr)},
      {"float", fn("float", BuiltinFloat)},
      {"int", fn("int", BuiltinInt)},
      {"True", Value::Bool(true)},
      {"False", Value::Bool(false)},
      {"min", fn("min", [](Positional a, Keywords k) { return MinMax(false, a, k); })},
      {"max", fn("max", [](Positional a, Keywords k) { return MinMax(true, a, k); })},
      {"round", fn("round", BuiltinRound)},
      {"sorted", fn("sorted", BuiltinSorted)},
      {"range", fn("range", BuiltinRange)},
  };
  for (const auto& [name, value] : core) {
    globals->Set(name, value);
    python->Set(name, value);
  }
  std::vector<std::pair<std::string, Value>> more = {
      {"abs", fn("abs", BuiltinAbs)},
      {"all", fn("all", [](Positional a, Keywords k) { return AllAny(true, a, k); })},
      {"any", fn("any", [](Positional a, Keywords k) { return AllAny(false, a, k); })},
      {"divmod", fn("divmod", BuiltinDivmod)},
      {"enumerate", fn("enumerate", BuiltinEnumerate)},
      {"filter", fn("filter", BuiltinFilter)},
      {"isinstance", fn("isinstance", BuiltinIsinstance)},
      {"ord", fn("ord", BuiltinOrd)},
      {"repr", fn("repr", BuiltinRepr)},
      {"reversed", fn("reversed", BuiltinReversed)},
      {"sum", fn("sum", BuiltinSum)},
      {"tuple", fn("tuple", BuiltinTuple)},
      {"type", fn("type", BuiltinType)},
      {"zip", fn("zip", BuiltinZip)},
  };
  for (const auto& [name, value] : more) python->Set(name, value);
  for (const char* name : {"complex", "frozenset", "hash", "issubclass", "slice", "set"}) {
    std::string n = name;
    python->Set(n, fn(n, [n](Positional, Keywords) { return Unsupported(n); }));
  }
  auto math = std::make_shared<NameTable>();
  internal::AddMathNames(*math);
  for (const auto& name : math->Names()) globals->Set(name, *math->Find(name));
  globals->Set("python", Value::Namespace("python", python));
  globals->Set("math", Value::Namespace("math", math));
  return globals;
}

}  // namespace

const NameTable& StandardGlobals() {
  static const std::shared_ptr<NameTable> globals = BuildGlobals();
  return *globals;
}

Value Dotify(const Value& dict) { return dict.IsDict() ? dict.WithAttributeAccess(true) : dict; }

std::vector<std::string> Tokenize(std::string_view s, std::string_view separators, bool skip_empty) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || separators.find(s[i]) != std::string_view::npos) {
      if (!skip_empty || i > start) out.emplace_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

}  // namespace mdlc::pyexpr
