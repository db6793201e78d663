// math_module.cc - the math module's constants and functions.
#include "frontend/pyexpr/math_module.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "frontend/pyexpr/internal.h"

namespace mdlc::pyexpr {
namespace {

using internal::CheckArgs;
using internal::Fail;
using internal::FindKeyword;
using internal::Keywords;
using internal::Positional;

Error Domain() { return Fail(Error::Kind::kValue, "math domain error (the argument is outside the function's domain)"); }
Error Range() { return Fail(Error::Kind::kOverflow, "math range error (the result is too large for a float)"); }

// A one-argument float function with Python's error rules: a nan from a
// non-nan argument is a domain error; an infinite result from a finite
// argument a range error when the function can overflow, else a domain error.
Value Func1(const std::string& name, double (*f)(double), bool can_overflow) {
  return Value::Function(name, [name, f, can_overflow](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], name));
    double r = f(x);
    if (std::isnan(r) && !std::isnan(x)) return Domain();
    if (std::isinf(r) && std::isfinite(x)) return can_overflow ? Range() : Domain();
    return Value::Float(r);
  });
}

template <typename F>
Value Fn(const std::string& name, F f) {
  return Value::Function(name, NativeFunction(f));
}

Result<int64_t> IntArg(const Value& v, std::string_view name) {
  if (v.IsFloat())
    return Fail(Error::Kind::kType, fmt::format("{}() needs an integer, not 'float'", name));
  return internal::AsIndex(v, std::string(name) + "()");
}

double Radians(double x) { return x * (std::numbers::pi / 180.0); }
double Degrees(double x) { return x * (180.0 / std::numbers::pi); }

// Shewchuk's exact summation of floats, rounded once (as math.fsum).
Result<double> ExactSum(const std::vector<Value>& items) {
  std::vector<double> partials;
  double special = 0.0;
  bool have_special = false, inf_plus = false, inf_minus = false;
  for (const Value& v : items) {
    PYEXPR_TRY(x, internal::AsReal(v, "fsum"));
    if (!std::isfinite(x)) {
      if (std::isinf(x)) (x > 0 ? inf_plus : inf_minus) = true;
      special += x;
      have_special = true;
      continue;
    }
    size_t i = 0;
    for (double y : partials) {
      if (std::fabs(x) < std::fabs(y)) std::swap(x, y);
      double hi = x + y;
      double lo = y - (hi - x);
      if (lo != 0.0) partials[i++] = lo;
      x = hi;
      if (!std::isfinite(hi)) return Fail(Error::Kind::kOverflow, "intermediate overflow in fsum");
    }
    partials.resize(i);
    partials.push_back(x);
  }
  if (have_special) {
    if (inf_plus && inf_minus) return Domain();
    return special;
  }
  if (partials.empty()) return 0.0;
  size_t n = partials.size();
  double hi = partials[--n];
  double lo = 0.0;
  while (n > 0) {
    double x = hi;
    double y = partials[--n];
    hi = x + y;
    double yr = hi - x;
    lo = y - yr;
    if (lo != 0.0) break;
  }
  // round half to even correctly when the rest of the partials push past a tie
  if (n > 0 && ((lo < 0.0 && partials[n - 1] < 0.0) || (lo > 0.0 && partials[n - 1] > 0.0))) {
    double y = lo * 2.0;
    double x = hi + y;
    double yr = x - hi;
    if (y == yr) hi = x;
  }
  return hi;
}

Result<Value> Log(Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs("log", args, kw, 1, 2));
  PYEXPR_TRY(x, internal::AsReal(args[0], "log"));
  auto ln = [](double v) -> Result<double> {
    if (std::isnan(v)) return v;
    if (v <= 0.0) return Domain();
    return std::log(v);
  };
  PYEXPR_TRY(num, ln(x));
  if (args.size() == 1) return Value::Float(num);
  PYEXPR_TRY(b, internal::AsReal(args[1], "log"));
  PYEXPR_TRY(den, ln(b));
  if (den == 0.0) return Fail(Error::Kind::kZeroDivision, "float division by zero");
  return Value::Float(num / den);
}

Result<Value> Rounding(const std::string& name, double (*f)(double), Positional args, Keywords kw) {
  PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 1));
  if (args[0].IsIntegral()) return args[0].IsBigInt() ? args[0] : Value::Int(args[0].AsInt());
  PYEXPR_TRY(x, internal::AsReal(args[0], name));
  return internal::FloatToInt(f(x));
}

// The Euclidean norm, scaled by a power of two and summed in extended
// precision so the result is (almost always) the correctly rounded one, as
// Python's is.
Result<Value> Hypot(const std::vector<double>& v) {
  double max = 0.0;
  bool any_nan = false;
  for (double x : v) {
    if (std::isinf(x)) return Value::Float(std::numeric_limits<double>::infinity());
    any_nan = any_nan || std::isnan(x);
    max = std::max(max, std::fabs(x));
  }
  if (any_nan) return Value::Float(std::numeric_limits<double>::quiet_NaN());
  if (max == 0.0) return Value::Float(0.0);
  if (v.size() == 1) return Value::Float(max);
  int e = 0;
  std::frexp(max, &e);
  long double sum = 0.0L;
  for (double x : v) {
    long double scaled = std::ldexp(static_cast<long double>(x), -e);
    sum += scaled * scaled;
  }
  double r = std::ldexp(static_cast<double>(std::sqrt(sum)), e);
  if (std::isinf(r)) return Range();
  return Value::Float(r);
}

Result<std::vector<double>> Floats(Positional args, std::string_view name) {
  std::vector<double> out;
  for (const Value& v : args) {
    PYEXPR_TRY(x, internal::AsReal(v, name));
    out.push_back(x);
  }
  return out;
}

}  // namespace

void AddMathModule(NameTable& t) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  t.Set("pi", Value::Float(std::numbers::pi));
  t.Set("e", Value::Float(std::numbers::e));
  t.Set("tau", Value::Float(2 * std::numbers::pi));
  t.Set("inf", Value::Float(kInf));
  t.Set("nan", Value::Float(std::numeric_limits<double>::quiet_NaN()));

  struct One {
    const char* name;
    double (*f)(double);
    bool can_overflow;
  };
  static const One kOne[] = {
      {"sin", [](double x) { return std::sin(x); }, false},
      {"cos", [](double x) { return std::cos(x); }, false},
      {"tan", [](double x) { return std::tan(x); }, false},
      {"asin", [](double x) { return std::asin(x); }, false},
      {"acos", [](double x) { return std::acos(x); }, false},
      {"atan", [](double x) { return std::atan(x); }, false},
      {"sinh", [](double x) { return std::sinh(x); }, true},
      {"cosh", [](double x) { return std::cosh(x); }, true},
      {"tanh", [](double x) { return std::tanh(x); }, false},
      {"asinh", [](double x) { return std::asinh(x); }, false},
      {"acosh", [](double x) { return std::acosh(x); }, false},
      {"atanh", [](double x) { return std::atanh(x); }, false},
      {"sqrt", [](double x) { return std::sqrt(x); }, false},
      {"cbrt", [](double x) { return std::cbrt(x); }, false},
      {"exp", [](double x) { return std::exp(x); }, true},
      {"exp2", [](double x) { return std::exp2(x); }, true},
      {"expm1", [](double x) { return std::expm1(x); }, true},
      {"log2", [](double x) { return x <= 0 ? std::numeric_limits<double>::quiet_NaN() : std::log2(x); }, false},
      {"log10", [](double x) { return x <= 0 ? std::numeric_limits<double>::quiet_NaN() : std::log10(x); }, false},
      {"log1p", [](double x) { return x <= -1 ? std::numeric_limits<double>::quiet_NaN() : std::log1p(x); }, false},
      {"fabs", [](double x) { return std::fabs(x); }, false},
      {"erf", [](double x) { return std::erf(x); }, false},
      {"erfc", [](double x) { return std::erfc(x); }, false},
  };
  for (const One& f : kOne) t.Set(f.name, Func1(f.name, f.f, f.can_overflow));
  // no error checks: an infinite result of a huge argument is Python's answer too
  using Fp = double (*)(double);
  for (auto [name, f] : {std::pair<const char*, Fp>{"degrees", Degrees}, std::pair<const char*, Fp>{"radians", Radians}}) {
    std::string n = name;
    Fp fp = f;
    t.Set(n, Fn(n, [n, fp](Positional args, Keywords kw) -> Result<Value> {
      PYEXPR_CHECK(CheckArgs(n, args, kw, 1, 1));
      PYEXPR_TRY(x, internal::AsReal(args[0], n));
      return Value::Float(fp(x));
    }));
  }

  auto gamma_like = [](const std::string& name, double (*f)(double)) {
    return Fn(name, [name, f](Positional args, Keywords kw) -> Result<Value> {
      PYEXPR_CHECK(CheckArgs(name, args, kw, 1, 1));
      PYEXPR_TRY(x, internal::AsReal(args[0], name));
      if (std::isnan(x)) return Value::Float(x);
      if (std::isinf(x)) {
        if (name == "gamma" && x < 0) return Domain();
        return Value::Float(kInf);
      }
      if (x <= 0 && x == std::floor(x)) return Domain();
      double r = f(x);
      if (std::isinf(r)) return Range();
      return Value::Float(r);
    });
  };
  t.Set("gamma", gamma_like("gamma", [](double x) { return std::tgamma(x); }));
  t.Set("lgamma", gamma_like("lgamma", [](double x) { return std::lgamma(x); }));

  t.Set("log", Fn("log", Log));
  t.Set("floor", Fn("floor", [](Positional a, Keywords k) { return Rounding("floor", [](double x) { return std::floor(x); }, a, k); }));
  t.Set("ceil", Fn("ceil", [](Positional a, Keywords k) { return Rounding("ceil", [](double x) { return std::ceil(x); }, a, k); }));
  t.Set("trunc", Fn("trunc", [](Positional a, Keywords k) { return Rounding("trunc", [](double x) { return std::trunc(x); }, a, k); }));

  auto two = [](const std::string& name, auto f) {
    return Fn(name, [name, f](Positional args, Keywords kw) -> Result<Value> {
      PYEXPR_CHECK(CheckArgs(name, args, kw, 2, 2));
      PYEXPR_TRY(x, internal::AsReal(args[0], name));
      PYEXPR_TRY(y, internal::AsReal(args[1], name));
      return f(x, y);
    });
  };
  t.Set("atan2", two("atan2", [](double y, double x) -> Result<Value> { return Value::Float(std::atan2(y, x)); }));
  t.Set("copysign", two("copysign", [](double x, double y) -> Result<Value> { return Value::Float(std::copysign(x, y)); }));
  t.Set("fmod", two("fmod", [](double x, double y) -> Result<Value> {
    if (std::isnan(x) || std::isnan(y)) return Value::Float(std::numeric_limits<double>::quiet_NaN());
    if (std::isinf(x) || y == 0.0) return Domain();
    return Value::Float(std::fmod(x, y));
  }));
  t.Set("remainder", two("remainder", [](double x, double y) -> Result<Value> {
    if (std::isnan(x) || std::isnan(y)) return Value::Float(std::numeric_limits<double>::quiet_NaN());
    if (std::isinf(x) || y == 0.0) return Domain();
    return Value::Float(std::remainder(x, y));
  }));
  t.Set("pow", two("pow", [](double x, double y) -> Result<Value> {
    if (x == 0.0 && y < 0.0 && std::isfinite(y)) return Domain();
    if (x < 0.0 && std::isfinite(x) && std::isfinite(y) && y != std::floor(y)) return Domain();
    double r = std::pow(x, y);
    if (std::isinf(r) && std::isfinite(x) && std::isfinite(y)) return Range();
    return Value::Float(r);
  }));
  t.Set("nextafter", two("nextafter", [](double x, double y) -> Result<Value> { return Value::Float(std::nextafter(x, y)); }));

  t.Set("ulp", Fn("ulp", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("ulp", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "ulp"));
    if (std::isnan(x)) return Value::Float(x);
    x = std::fabs(x);
    if (std::isinf(x)) return Value::Float(x);
    double next = std::nextafter(x, kInf);
    if (std::isinf(next)) return Value::Float(x - std::nextafter(x, -kInf));
    return Value::Float(next - x);
  }));
  t.Set("modf", Fn("modf", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("modf", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "modf"));
    if (std::isinf(x)) return Value::Tuple({Value::Float(std::copysign(0.0, x)), Value::Float(x)});
    double ip;
    double frac = std::modf(x, &ip);
    return Value::Tuple({Value::Float(frac), Value::Float(ip)});
  }));
  t.Set("frexp", Fn("frexp", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("frexp", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "frexp"));
    if (!std::isfinite(x) || x == 0.0) return Value::Tuple({Value::Float(x), Value::Int(0)});
    int e = 0;
    double m = std::frexp(x, &e);
    return Value::Tuple({Value::Float(m), Value::Int(e)});
  }));
  t.Set("ldexp", Fn("ldexp", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("ldexp", args, kw, 2, 2));
    PYEXPR_TRY(x, internal::AsReal(args[0], "ldexp"));
    PYEXPR_TRY(i, IntArg(args[1], "ldexp"));
    if (x == 0.0 || !std::isfinite(x)) return Value::Float(x);
    int e = static_cast<int>(std::clamp<int64_t>(i, -100000, 100000));
    double r = std::ldexp(x, e);
    if (std::isinf(r)) return Range();
    return Value::Float(r);
  }));
  t.Set("isfinite", Fn("isfinite", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("isfinite", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "isfinite"));
    return Value::Bool(std::isfinite(x));
  }));
  t.Set("isinf", Fn("isinf", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("isinf", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "isinf"));
    return Value::Bool(std::isinf(x));
  }));
  t.Set("isnan", Fn("isnan", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("isnan", args, kw, 1, 1));
    PYEXPR_TRY(x, internal::AsReal(args[0], "isnan"));
    return Value::Bool(std::isnan(x));
  }));
  t.Set("isclose", Fn("isclose", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("isclose", args, kw, 2, 2, {"rel_tol", "abs_tol"}));
    PYEXPR_TRY(a, internal::AsReal(args[0], "isclose"));
    PYEXPR_TRY(b, internal::AsReal(args[1], "isclose"));
    double rel = 1e-09, abs_tol = 0.0;
    if (const Value* v = FindKeyword(kw, "rel_tol")) {
      PYEXPR_TRY(r, internal::AsReal(*v, "isclose"));
      rel = r;
    }
    if (const Value* v = FindKeyword(kw, "abs_tol")) {
      PYEXPR_TRY(r, internal::AsReal(*v, "isclose"));
      abs_tol = r;
    }
    if (rel < 0.0 || abs_tol < 0.0) return Fail(Error::Kind::kValue, "tolerances must be non-negative");
    if (a == b) return Value::Bool(true);
    if (std::isinf(a) || std::isinf(b)) return Value::Bool(false);
    double diff = std::fabs(b - a);
    return Value::Bool((diff <= std::fabs(rel * b)) || (diff <= std::fabs(rel * a)) || (diff <= abs_tol));
  }));
  t.Set("hypot", Fn("hypot", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("hypot", args, kw, 0, std::numeric_limits<size_t>::max()));
    PYEXPR_TRY(v, Floats(args, "hypot"));
    return Hypot(v);
  }));
  t.Set("dist", Fn("dist", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("dist", args, kw, 2, 2));
    PYEXPR_TRY(p, internal::Iterate(args[0]));
    PYEXPR_TRY(q, internal::Iterate(args[1]));
    if (p.size() != q.size()) return Fail(Error::Kind::kValue, "both points must have the same number of dimensions");
    std::vector<double> d;
    for (size_t i = 0; i < p.size(); ++i) {
      PYEXPR_TRY(a, internal::AsReal(p[i], "dist"));
      PYEXPR_TRY(b, internal::AsReal(q[i], "dist"));
      d.push_back(a - b);
    }
    return Hypot(d);
  }));
  t.Set("fsum", Fn("fsum", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("fsum", args, kw, 1, 1));
    PYEXPR_TRY(items, internal::Iterate(args[0]));
    PYEXPR_TRY(s, ExactSum(items));
    return Value::Float(s);
  }));
  t.Set("prod", Fn("prod", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("prod", args, kw, 1, 1, {"start"}));
    PYEXPR_TRY(items, internal::Iterate(args[0]));
    const Value* start = FindKeyword(kw, "start");
    Value acc = start ? *start : Value::Int(1);
    for (const Value& v : items) {
      PYEXPR_TRY(next, internal::ApplyBinary(internal::BinOp::kMul, acc, v));
      acc = std::move(next);
    }
    return acc;
  }));
  t.Set("factorial", Fn("factorial", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("factorial", args, kw, 1, 1));
    PYEXPR_TRY(n, IntArg(args[0], "factorial"));
    if (n < 0) return Fail(Error::Kind::kValue, "factorial() is not defined for negative values");
    PYEXPR_CHECK(internal::CheckIntBits(std::lgamma(static_cast<double>(n) + 1) / std::log(2.0)));
    BigInt r = BigInt::FromInt64(1);
    for (int64_t i = 2; i <= n; ++i) r = r * BigInt::FromInt64(i);
    return internal::BigResult(std::move(r));
  }));
  t.Set("isqrt", Fn("isqrt", [](Positional args, Keywords kw) -> Result<Value> {
    PYEXPR_CHECK(CheckArgs("isqrt", args, kw, 1, 1));
    PYEXPR_TRY(n, IntArg(args[0], "isqrt"));
    if (n < 0) return Fail(Error::Kind::kValue, "isqrt() argument must be nonnegative");
    if (args[0].IsBigInt()) return Value::Big(args[0].big().Isqrt());
    auto r = static_cast<int64_t>(std::sqrt(static_cast<double>(n)));
    while (r > 0 && static_cast<__int128>(r) * r > n) --r;
    while (static_cast<__int128>(r + 1) * (r + 1) <= n) ++r;
    return Value::Int(r);
  }));
  auto gcd_lcm = [](const std::string& name, bool is_gcd) {
    return Fn(name, [name, is_gcd](Positional args, Keywords kw) -> Result<Value> {
      PYEXPR_CHECK(CheckArgs(name, args, kw, 0, std::numeric_limits<size_t>::max()));
      BigInt acc = BigInt::FromInt64(is_gcd ? 0 : 1);
      for (const Value& v : args) {
        PYEXPR_TRY(checked, IntArg(v, name));
        (void)checked;
        BigInt x = v.AsBigInt().Abs();
        if (is_gcd) {
          acc = BigInt::Gcd(acc, x);
        } else {
          if (acc.IsZero() || x.IsZero()) {
            acc = BigInt();
            continue;
          }
          BigInt q;
          BigInt::DivModMagnitude(acc, BigInt::Gcd(acc, x), &q, nullptr);
          PYEXPR_CHECK(internal::CheckIntBits(static_cast<double>(q.BitLength() + x.BitLength())));
          acc = q * x;
        }
      }
      return internal::BigResult(std::move(acc));
    });
  };
  t.Set("gcd", gcd_lcm("gcd", true));
  t.Set("lcm", gcd_lcm("lcm", false));
  auto comb_perm = [](const std::string& name, bool is_comb) {
    return Fn(name, [name, is_comb](Positional args, Keywords kw) -> Result<Value> {
      PYEXPR_CHECK(CheckArgs(name, args, kw, is_comb ? 2 : 1, 2));
      PYEXPR_TRY(n, IntArg(args[0], name));
      int64_t k = n;
      if (args.size() > 1 && !args[1].IsNone()) {
        PYEXPR_TRY(kk, IntArg(args[1], name));
        k = kk;
      }
      if (n < 0) return Fail(Error::Kind::kValue, "n must be a non-negative integer");
      if (k < 0) return Fail(Error::Kind::kValue, "k must be a non-negative integer");
      BigInt big_n = args[0].AsBigInt(), big_k = BigInt::FromInt64(k);
      if (args.size() > 1 && !args[1].IsNone()) big_k = args[1].AsBigInt();
      if (BigInt::Compare(big_k, big_n) > 0) return Value::Int(0);
      if (is_comb && BigInt::Compare(big_k + big_k, big_n) > 0) big_k = big_n - big_k;
      k = big_k.ToInt64().value_or(std::numeric_limits<int64_t>::max());
      // log2 of the result, to refuse before computing what the limit forbids
      double nd = args[0].AsFloat(), kd = big_k.ToDouble().value_or(HUGE_VAL);
      PYEXPR_CHECK(internal::CheckIntBits(kd));  // the result has at least k bits
      double k_factorial = is_comb ? std::lgamma(kd + 1) : 0.0;
      double bits = nd < 1e15 ? (std::lgamma(nd + 1) - std::lgamma(nd - kd + 1) - k_factorial) / std::log(2.0)
                              : kd * std::log2(nd) - k_factorial / std::log(2.0);
      PYEXPR_CHECK(internal::CheckIntBits(bits));
      BigInt r = BigInt::FromInt64(1);
      for (int64_t i = 1; i <= k; ++i) {
        if (is_comb) {
          BigInt::DivModMagnitude(r * (big_n - big_k + BigInt::FromInt64(i)), BigInt::FromInt64(i), &r, nullptr);
        } else {
          r = r * (big_n - BigInt::FromInt64(i - 1));
        }
      }
      return internal::BigResult(std::move(r));
    });
  };
  t.Set("comb", comb_perm("comb", true));
  t.Set("perm", comb_perm("perm", false));
}

namespace internal {
void AddMathNames(NameTable& table) { AddMathModule(table); }
}  // namespace internal

}  // namespace mdlc::pyexpr
