// internal.h - helpers shared by pyexpr's source files (not part of the API).
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "frontend/pyexpr/evaluate.h"
#include "frontend/pyexpr/value.h"

// Evaluates expr (a Result); on error returns the error from the enclosing
// function, else binds the value to var.
#define PYEXPR_CONCAT_INNER(a, b) a##b
#define PYEXPR_CONCAT(a, b) PYEXPR_CONCAT_INNER(a, b)
#define PYEXPR_TRY(var, expr)                                  \
  auto PYEXPR_CONCAT(var, _result) = (expr);                   \
  if (!PYEXPR_CONCAT(var, _result).ok())                       \
    return std::move(PYEXPR_CONCAT(var, _result)).error();     \
  auto var = std::move(*PYEXPR_CONCAT(var, _result))

// Returns the error of a Result expression from the enclosing function,
// which returns a Result too.
#define PYEXPR_CHECK(expr)                                            \
  do {                                                                \
    auto pyexpr_check_ = (expr);                                      \
    if (!pyexpr_check_.ok()) return std::move(pyexpr_check_).error(); \
  } while (0)

namespace mdlc::pyexpr::internal {

using Keywords = std::span<const std::pair<std::string, Value>>;
using Positional = std::span<const Value>;

inline Error Fail(Error::Kind kind, std::string message) { return Error{kind, std::move(message)}; }

// The limits of the evaluation running on this thread (defaults outside one).
const Limits& CurrentLimits();
class LimitsScope {
 public:
  explicit LimitsScope(const Limits& limits);
  ~LimitsScope();
  LimitsScope(const LimitsScope&) = delete;
  LimitsScope& operator=(const LimitsScope&) = delete;

 private:
  const Limits* previous_;
  size_t previous_steps_;
};

// kLimit errors when a result would exceed the limits.
Result<bool> CheckStringSize(size_t bytes);
Result<bool> CheckItemCount(size_t items);
// Counts one comprehension iteration or lambda call of the evaluation
// running on this thread; kLimit past Limits::max_steps.
Result<bool> CountStep();

// Calls a callable value (a Function).
Result<Value> Call(const Value& callee, Positional positional, Keywords keywords = {});

// Python's iteration: the items of a list/tuple, the characters of a str, the
// keys of a dict; items of an attribute-access list/dict come out wrapped.
Result<std::vector<Value>> Iterate(const Value& v);

// A child read out of an attribute-access container keeps the wrapping.
inline Value WrapChild(const Value& container, const Value& child) {
  return container.attribute_access() ? child.WithAttributeAccess(true) : child;
}

// Python's operators (operators.cc).
enum class BinOp { kAdd, kSub, kMul, kDiv, kFloorDiv, kMod, kPow, kMatMul, kLShift, kRShift, kBitAnd, kBitOr, kBitXor };
enum class UnOp { kNeg, kPos, kInvert };
Result<Value> ApplyBinary(BinOp op, const Value& a, const Value& b);
Result<Value> ApplyUnary(UnOp op, const Value& a);
std::string_view BinOpText(BinOp op);
Result<bool> Contains(const Value& container, const Value& item);  // `item in container`
// obj[index]
Result<Value> Subscript(const Value& obj, const Value& index);
// obj[lower:upper:step] (None for an omitted part)
Result<Value> Slice(const Value& obj, const Value& lower, const Value& upper, const Value& step);

// Argument checking for builtins: "name() takes ..." errors.
Result<bool> CheckArgs(std::string_view name, Positional positional, Keywords keywords, size_t min_args,
                       size_t max_args, std::initializer_list<std::string_view> allowed_keywords = {});
const Value* FindKeyword(Keywords keywords, std::string_view name);

// A number as an index: int or bool, else kType naming the use.
Result<int64_t> AsIndex(const Value& v, std::string_view what);
// A number as a float (int, bool, float), else kType naming the function.
Result<double> AsReal(const Value& v, std::string_view function);

// Python's float -> int conversion (truncation), with its errors.
Result<Value> FloatToInt(double d);
// An int of any size as a Value, or kLimit when it has more bits than
// Limits::max_int_digits allows.
Result<Value> BigResult(BigInt i);
// kLimit when an int of about `bits` bits would exceed the limit.
Result<bool> CheckIntBits(double bits);
// float(v) for an int or bool (an OverflowError when too large) or a float.
Result<double> ToFloat(const Value& v);

// Attribute lookup on str/list/dict values (their methods; str_methods.cc).
Result<Value> Method(const Value& self, std::string_view name);

// Python's str.format on a template (str_methods.cc).
Result<Value> FormatString(const std::string& format, Positional positional, Keywords keywords);
// format(value, spec)
Result<std::string> FormatValue(const Value& v, std::string_view spec);

// Code-point aware views on UTF-8 strings (str_methods.cc).
bool IsAscii(std::string_view s);
std::vector<std::string> SplitCodePoints(std::string_view s);

// the math module's names (math_module.cc)
void AddMathNames(NameTable& table);

}  // namespace mdlc::pyexpr::internal
