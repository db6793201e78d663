// operators.cc - Python's operators on values: arithmetic with Python's
// int/float rules (floor division and modulo signs; ints grow past 64 bits
// into BigInts, within Limits::max_int_digits), sequence concatenation and repetition within the
// limits, membership, indexing and slicing.
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "frontend/pyexpr/internal.h"

namespace mdlc::pyexpr::internal {
namespace {

Error Unsupported(BinOp op, const Value& a, const Value& b) {
  return Fail(Error::Kind::kType, fmt::format("unsupported operand types for {}: '{}' and '{}'", BinOpText(op),
                                              TypeName(a), TypeName(b)));
}

// a ** e for ints, e >= 0
Result<Value> IntPow(const Value& a, const Value& e) {
  if (!a.IsBigInt() && !e.IsBigInt()) {
    int64_t result = 1, b = a.AsInt(), n = e.AsInt();
    bool overflow = false;
    while (n > 0 && !overflow) {
      if ((n & 1) && __builtin_mul_overflow(result, b, &result)) overflow = true;
      n >>= 1;
      if (n > 0 && __builtin_mul_overflow(b, b, &b)) overflow = true;
    }
    if (!overflow) return Value::Int(result);
  }
  BigInt base = a.AsBigInt();
  if (base.IsZero() || BigInt::Compare(base.Abs(), BigInt::FromInt64(1)) == 0) {
    bool odd = e.AsBigInt().IsOdd();
    if (base.IsZero()) return Value::Int(e.AsBigInt().IsZero() ? 1 : 0);
    return Value::Int(base.IsNegative() && odd ? -1 : 1);
  }
  // |a| >= 2: at least (bits(a) - 1) * e bits
  double bits = (static_cast<double>(base.BitLength()) - 1) * e.AsFloat();
  auto ok = CheckIntBits(bits);
  if (!ok.ok()) return std::move(ok).error();
  return BigResult(BigInt::Pow(base, static_cast<uint64_t>(e.AsInt())));
}

Result<Value> BigFloorDivMod(BinOp op, const Value& a, const Value& b) {
  BigInt q, r;
  BigInt::DivMod(a.AsBigInt(), b.AsBigInt(), &q, &r);
  return BigResult(op == BinOp::kMod ? std::move(r) : std::move(q));
}

Result<Value> FloatPow(double a, double b) {
  if (a == 0.0 && b < 0.0) return Fail(Error::Kind::kZeroDivision, "zero cannot be raised to a negative power");
  if (a < 0.0 && std::isfinite(a) && std::isfinite(b) && b != std::floor(b))
    return Fail(Error::Kind::kUnsupported,
                "a negative number raised to a fractional power is complex, and complex numbers are not supported");
  double r = std::pow(a, b);
  if (std::isinf(r) && std::isfinite(a) && std::isfinite(b))
    return Fail(Error::Kind::kOverflow, "float result out of range");
  return Value::Float(r);
}

Result<Value> FloorDivMod(BinOp op, const Value& a, const Value& b) {
  if (a.IsIntegral() && b.IsIntegral()) {
    int64_t x = a.AsInt(), y = b.AsInt();
    if (!b.IsBigInt() && y == 0)
      return Fail(Error::Kind::kZeroDivision,
                  op == BinOp::kMod ? "integer modulo by zero" : "integer division by zero");
    if (a.IsBigInt() || b.IsBigInt()) return BigFloorDivMod(op, a, b);
    if (x == std::numeric_limits<int64_t>::min() && y == -1) {
      if (op == BinOp::kMod) return Value::Int(0);
      return BigFloorDivMod(op, a, b);
    }
    int64_t q = x / y, r = x % y;
    if (r != 0 && ((r < 0) != (y < 0))) {
      r += y;
      q -= 1;
    }
    return Value::Int(op == BinOp::kMod ? r : q);
  }
  double x = a.AsFloat(), y = b.AsFloat();
  if (y == 0.0) return Fail(Error::Kind::kZeroDivision, op == BinOp::kMod ? "float modulo by zero" : "float division by zero");
  double mod = std::fmod(x, y);
  double div = (x - mod) / y;
  if (mod != 0.0) {
    if ((y < 0) != (mod < 0)) {
      mod += y;
      div -= 1.0;
    }
  } else {
    mod = std::copysign(0.0, y);
  }
  if (op == BinOp::kMod) return Value::Float(mod);
  double floordiv;
  if (div != 0.0) {
    floordiv = std::floor(div);
    if (div - floordiv > 0.5) floordiv += 1.0;
  } else {
    floordiv = std::copysign(0.0, x / y);
  }
  return Value::Float(floordiv);
}

Result<Value> Repeat(const Value& seq, int64_t times) {
  if (times < 0) times = 0;
  if (seq.IsStr()) {
    const std::string& s = seq.AsStr();
    if (times > 0 && !s.empty()) {
      if (static_cast<uint64_t>(times) > CurrentLimits().max_string_bytes / s.size() + 1) {
        auto ok = CheckStringSize(std::numeric_limits<size_t>::max());
        return std::move(ok).error();
      }
      auto ok = CheckStringSize(s.size() * static_cast<size_t>(times));
      if (!ok.ok()) return std::move(ok).error();
    }
    std::string out;
    out.reserve(s.size() * static_cast<size_t>(times));
    for (int64_t i = 0; i < times; ++i) out += s;
    return Value::Str(std::move(out));
  }
  const auto& items = seq.items();
  if (times > 0 && !items.empty()) {
    if (static_cast<uint64_t>(times) > CurrentLimits().max_items / items.size() + 1) {
      auto ok = CheckItemCount(std::numeric_limits<size_t>::max());
      return std::move(ok).error();
    }
    auto ok = CheckItemCount(items.size() * static_cast<size_t>(times));
    if (!ok.ok()) return std::move(ok).error();
  }
  std::vector<Value> out;
  out.reserve(items.size() * static_cast<size_t>(times));
  for (int64_t i = 0; i < times; ++i) out.insert(out.end(), items.begin(), items.end());
  return seq.IsList() ? Value::List(std::move(out)) : Value::Tuple(std::move(out));
}

// Python's slice index adjustment; returns the selected positions.
Result<std::vector<size_t>> SliceIndices(size_t length, const Value& lower, const Value& upper, const Value& step_v) {
  auto get = [](const Value& v, int64_t fallback) -> Result<int64_t> {
    if (v.IsNone()) return fallback;
    if (!v.IsIntegral()) return Fail(Error::Kind::kType, "slice indices must be integers or None");
    return v.AsInt();
  };
  auto step = get(step_v, 1);
  if (!step.ok()) return std::move(step).error();
  if (*step == 0) return Fail(Error::Kind::kValue, "slice step cannot be zero");
  int64_t n = static_cast<int64_t>(length);
  int64_t s = *step;
  auto adjust = [&](const Value& v, bool is_start) -> Result<int64_t> {
    int64_t def = s > 0 ? (is_start ? 0 : n) : (is_start ? n - 1 : -1);
    if (v.IsNone()) return def;
    auto i = get(v, 0);
    if (!i.ok()) return i;
    int64_t x = *i;
    if (x < 0) {
      x += n;
      if (x < 0) x = s < 0 ? -1 : 0;
    } else if (x >= n) {
      x = s < 0 ? n - 1 : n;
    }
    return x;
  };
  auto start = adjust(lower, true);
  if (!start.ok()) return std::move(start).error();
  auto stop = adjust(upper, false);
  if (!stop.ok()) return std::move(stop).error();
  std::vector<size_t> out;
  if (s > 0) {
    for (int64_t i = *start; i < *stop; i += s) out.push_back(static_cast<size_t>(i));
  } else {
    for (int64_t i = *start; i > *stop; i += s) out.push_back(static_cast<size_t>(i));
  }
  return out;
}

Result<int64_t> NormalizeIndex(const Value& index, size_t length, std::string_view type) {
  if (!index.IsIntegral())
    return Fail(Error::Kind::kType, fmt::format("{} indices must be integers or slices, not {}", type, TypeName(index)));
  int64_t i = index.AsInt();
  int64_t n = static_cast<int64_t>(length);
  if (i < 0) i += n;
  if (i < 0 || i >= n) return Fail(Error::Kind::kIndex, fmt::format("{} index out of range", type));
  return i;
}

Error MissingKey(const Value& dict, const Value& key) {
  Error e;
  if (dict.attribute_access()) {
    e.kind = Error::Kind::kAttribute;
    e.message = fmt::format("the yaml dictionary has no key {}", Repr(key));
  } else {
    e.kind = Error::Kind::kKey;
    e.message = fmt::format("key {} is not in the dictionary", Repr(key));
  }
  e.missing_name = Str(key);
  return e;
}

}  // namespace

std::string_view BinOpText(BinOp op) {
  switch (op) {
    case BinOp::kAdd: return "+";
    case BinOp::kSub: return "-";
    case BinOp::kMul: return "*";
    case BinOp::kDiv: return "/";
    case BinOp::kFloorDiv: return "//";
    case BinOp::kMod: return "%";
    case BinOp::kPow: return "**";
    case BinOp::kMatMul: return "@";
    case BinOp::kLShift: return "<<";
    case BinOp::kRShift: return ">>";
    case BinOp::kBitAnd: return "&";
    case BinOp::kBitOr: return "|";
    case BinOp::kBitXor: return "^";
  }
  return "?";
}

Result<Value> PercentFormat(const std::string& format, const Value& args);

Result<Value> ApplyBinary(BinOp op, const Value& a, const Value& b) {
  bool ints = a.IsIntegral() && b.IsIntegral();
  bool numbers = a.IsNumber() && b.IsNumber();
  bool big = a.IsBigInt() || b.IsBigInt();
  if (big && numbers && !ints && op != BinOp::kPow) {
    // a big int meets a float: float(int) must not overflow
    auto x = ToFloat(a);
    if (!x.ok()) return std::move(x).error();
    auto y = ToFloat(b);
    if (!y.ok()) return std::move(y).error();
  }
  switch (op) {
    case BinOp::kAdd:
      if (ints) {
        int64_t r;
        if (big || __builtin_add_overflow(a.AsInt(), b.AsInt(), &r)) return BigResult(a.AsBigInt() + b.AsBigInt());
        return Value::Int(r);
      }
      if (numbers) return Value::Float(a.AsFloat() + b.AsFloat());
      if (a.IsStr() && b.IsStr()) {
        auto ok = CheckStringSize(a.AsStr().size() + b.AsStr().size());
        if (!ok.ok()) return std::move(ok).error();
        return Value::Str(a.AsStr() + b.AsStr());
      }
      if ((a.IsList() && b.IsList()) || (a.IsTuple() && b.IsTuple())) {
        auto ok = CheckItemCount(a.items().size() + b.items().size());
        if (!ok.ok()) return std::move(ok).error();
        std::vector<Value> out = a.items();
        out.insert(out.end(), b.items().begin(), b.items().end());
        return a.IsList() ? Value::List(std::move(out)) : Value::Tuple(std::move(out));
      }
      return Unsupported(op, a, b);
    case BinOp::kSub:
      if (ints) {
        int64_t r;
        if (big || __builtin_sub_overflow(a.AsInt(), b.AsInt(), &r)) return BigResult(a.AsBigInt() - b.AsBigInt());
        return Value::Int(r);
      }
      if (numbers) return Value::Float(a.AsFloat() - b.AsFloat());
      return Unsupported(op, a, b);
    case BinOp::kMul:
      if (ints) {
        int64_t r;
        if (big || __builtin_mul_overflow(a.AsInt(), b.AsInt(), &r)) {
          BigInt x = a.AsBigInt(), y = b.AsBigInt();
          auto ok = CheckIntBits(static_cast<double>(x.BitLength() + y.BitLength()) - 1);
          if (!ok.ok()) return std::move(ok).error();
          return BigResult(x * y);
        }
        return Value::Int(r);
      }
      if (numbers) return Value::Float(a.AsFloat() * b.AsFloat());
      if ((a.IsStr() || a.IsSequence()) && b.IsIntegral()) return Repeat(a, b.AsInt());
      if ((b.IsStr() || b.IsSequence()) && a.IsIntegral()) return Repeat(b, a.AsInt());
      return Unsupported(op, a, b);
    case BinOp::kDiv:
      if (numbers) {
        if (b.AsFloat() == 0.0)
          return Fail(Error::Kind::kZeroDivision, ints ? "division by zero" : "float division by zero");
        if (ints && (big || std::max(std::abs(a.AsFloat()), std::abs(b.AsFloat())) > 9007199254740992.0)) {
          // correctly rounded, as Python's int / int
          auto q = BigInt::TrueDivide(a.AsBigInt(), b.AsBigInt());
          if (!q) return Fail(Error::Kind::kOverflow, "integer division result too large for a float");
          return Value::Float(*q);
        }
        return Value::Float(a.AsFloat() / b.AsFloat());
      }
      return Unsupported(op, a, b);
    case BinOp::kFloorDiv:
      if (numbers) return FloorDivMod(op, a, b);
      return Unsupported(op, a, b);
    case BinOp::kMod:
      if (numbers) return FloorDivMod(op, a, b);
      if (a.IsStr()) return PercentFormat(a.AsStr(), b);
      return Unsupported(op, a, b);
    case BinOp::kPow:
      if (ints) {
        if (b.AsInt() >= 0) return IntPow(a, b);
        if (a.AsInt() == 0) return Fail(Error::Kind::kZeroDivision, "zero cannot be raised to a negative power");
        auto x = ToFloat(a);
        if (!x.ok()) return std::move(x).error();
        return FloatPow(*x, b.AsFloat());
      }
      if (numbers) {
        auto x = ToFloat(a);
        if (!x.ok()) return std::move(x).error();
        auto y = ToFloat(b);
        if (!y.ok()) return std::move(y).error();
        return FloatPow(*x, *y);
      }
      return Unsupported(op, a, b);
    case BinOp::kMatMul: return Unsupported(op, a, b);
    case BinOp::kLShift:
    case BinOp::kRShift: {
      if (!ints) return Unsupported(op, a, b);
      int64_t x = a.AsInt(), n = b.AsInt();
      if (n < 0) return Fail(Error::Kind::kValue, "negative shift count");
      if (op == BinOp::kRShift) {
        if (a.IsBigInt()) return BigResult(a.big().ShiftRight(static_cast<size_t>(std::min<int64_t>(n, 1 << 30))));
        return Value::Int(n >= 63 ? (x < 0 ? -1 : 0) : (x >> n));
      }
      if (x == 0 && !a.IsBigInt()) return Value::Int(0);
      if (!big && n < 63) {
        int64_t r = static_cast<int64_t>(static_cast<uint64_t>(x) << n);
        if ((r >> n) == x) return Value::Int(r);
      }
      BigInt v = a.AsBigInt();
      auto ok = CheckIntBits(static_cast<double>(v.BitLength()) + b.AsFloat());
      if (!ok.ok()) return std::move(ok).error();
      return BigResult(v.ShiftLeft(static_cast<size_t>(n)));
    }
    case BinOp::kBitAnd:
    case BinOp::kBitOr:
    case BinOp::kBitXor: {
      if (!ints) return Unsupported(op, a, b);
      if (big) {
        auto bop = op == BinOp::kBitAnd ? BigInt::BitOp::kAnd : op == BinOp::kBitOr ? BigInt::BitOp::kOr : BigInt::BitOp::kXor;
        return BigResult(BigInt::Bitwise(bop, a.AsBigInt(), b.AsBigInt()));
      }
      int64_t x = a.AsInt(), y = b.AsInt();
      int64_t r = op == BinOp::kBitAnd ? (x & y) : (op == BinOp::kBitOr ? (x | y) : (x ^ y));
      if (a.IsBool() && b.IsBool()) return Value::Bool(r != 0);
      return Value::Int(r);
    }
  }
  return Unsupported(op, a, b);
}

Result<Value> ApplyUnary(UnOp op, const Value& a) {
  if (a.IsBigInt()) {
    switch (op) {
      case UnOp::kNeg: return Value::Big(-a.big());
      case UnOp::kPos: return a;
      case UnOp::kInvert: return Value::Big(a.big().Invert());
    }
  }
  if (a.IsIntegral()) {
    int64_t x = a.AsInt();
    switch (op) {
      case UnOp::kNeg:
        if (x == std::numeric_limits<int64_t>::min()) return Value::Big(-BigInt::FromInt64(x));
        return Value::Int(-x);
      case UnOp::kPos: return Value::Int(x);
      case UnOp::kInvert: return Value::Int(~x);
    }
  }
  if (a.IsFloat() && op != UnOp::kInvert) return Value::Float(op == UnOp::kNeg ? -a.AsFloat() : a.AsFloat());
  const char* text = op == UnOp::kNeg ? "-" : (op == UnOp::kPos ? "+" : "~");
  return Fail(Error::Kind::kType, fmt::format("bad operand type for unary {}: '{}'", text, TypeName(a)));
}

Result<bool> Contains(const Value& container, const Value& item) {
  switch (container.kind()) {
    case Value::Kind::kStr:
      if (!item.IsStr())
        return Fail(Error::Kind::kType,
                    fmt::format("'in <string>' needs a string on its left, not {}", TypeName(item)));
      return container.AsStr().find(item.AsStr()) != std::string::npos;
    case Value::Kind::kList:
    case Value::Kind::kTuple:
      for (const Value& v : container.items())
        if (Equal(v, item)) return true;
      return false;
    case Value::Kind::kDict:
      if (!Hash(item)) return Fail(Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(item)));
      return container.DictFind(item) != nullptr;
    case Value::Kind::kNamespace: return item.IsStr() && container.names().Find(item.AsStr()) != nullptr;
    default:
      return Fail(Error::Kind::kType, fmt::format("argument of type '{}' is not iterable", TypeName(container)));
  }
}

Result<Value> Subscript(const Value& obj, const Value& index) {
  switch (obj.kind()) {
    case Value::Kind::kList:
    case Value::Kind::kTuple: {
      auto i = NormalizeIndex(index, obj.items().size(), obj.IsList() ? "list" : "tuple");
      if (!i.ok()) return std::move(i).error();
      return WrapChild(obj, obj.items()[static_cast<size_t>(*i)]);
    }
    case Value::Kind::kStr: {
      const std::string& s = obj.AsStr();
      if (IsAscii(s)) {
        auto i = NormalizeIndex(index, s.size(), "string");
        if (!i.ok()) return std::move(i).error();
        return Value::Str(std::string(1, s[static_cast<size_t>(*i)]));
      }
      auto cps = SplitCodePoints(s);
      auto i = NormalizeIndex(index, cps.size(), "string");
      if (!i.ok()) return std::move(i).error();
      return Value::Str(cps[static_cast<size_t>(*i)]);
    }
    case Value::Kind::kDict: {
      if (!Hash(index)) return Fail(Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(index)));
      const Value* v = obj.DictFind(index);
      if (!v) return MissingKey(obj, index);
      return WrapChild(obj, *v);
    }
    case Value::Kind::kNamespace: {
      const Value* v = index.IsStr() ? obj.names().Find(index.AsStr()) : nullptr;
      if (!v) {
        Error e{Error::Kind::kKey, fmt::format("{} has no name {}", obj.name(), Repr(index))};
        e.missing_name = Str(index);
        return e;
      }
      return *v;
    }
    default:
      return Fail(Error::Kind::kType, fmt::format("'{}' values cannot be indexed", TypeName(obj)));
  }
}

Result<Value> Slice(const Value& obj, const Value& lower, const Value& upper, const Value& step) {
  if (obj.IsSequence()) {
    auto idx = SliceIndices(obj.items().size(), lower, upper, step);
    if (!idx.ok()) return std::move(idx).error();
    std::vector<Value> out;
    out.reserve(idx->size());
    for (size_t i : *idx) out.push_back(obj.items()[i]);
    Value r = obj.IsList() ? Value::List(std::move(out)) : Value::Tuple(std::move(out));
    return r.WithAttributeAccess(obj.attribute_access());
  }
  if (obj.IsStr()) {
    const std::string& s = obj.AsStr();
    std::string out;
    if (IsAscii(s)) {
      auto idx = SliceIndices(s.size(), lower, upper, step);
      if (!idx.ok()) return std::move(idx).error();
      for (size_t i : *idx) out.push_back(s[i]);
    } else {
      auto cps = SplitCodePoints(s);
      auto idx = SliceIndices(cps.size(), lower, upper, step);
      if (!idx.ok()) return std::move(idx).error();
      for (size_t i : *idx) out += cps[i];
    }
    return Value::Str(std::move(out));
  }
  return Fail(Error::Kind::kType, fmt::format("'{}' values cannot be sliced", TypeName(obj)));
}

}  // namespace mdlc::pyexpr::internal
