// value.h - the values of mdlc's Python expression interpreter (pyexpr).
//
// xacro evaluates `${...}` as Python; pyexpr interprets the subset xacro
// files use without running any Python. A Value is one Python object of the
// kinds below, cheap to copy: scalars inline, everything else behind a
// shared_ptr to an immutable heap object. Str() and Repr() print exactly as
// Python 3.11's str() and repr() do, because the printed text ends up in the
// generated model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "frontend/pyexpr/bigint.h"

namespace mdlc::pyexpr {

// What went wrong while lexing, parsing or evaluating an expression (or
// while a host function ran). Messages are lower-case, without a trailing
// period.
struct Error {
  enum class Kind {
    kSyntax,
    kName,
    kType,
    kValue,
    kIndex,
    kKey,
    kZeroDivision,
    kOverflow,
    kAttribute,
    kLimit,
    kUnsupported,
    kHost
  };
  Error() = default;
  Error(Kind k, std::string text, size_t at = 0) : kind(k), message(std::move(text)), offset(at) {}
  Kind kind = Kind::kValue;
  std::string message;
  size_t offset = 0;          // byte offset in the expression text of the problem
  std::string missing_name;   // kName / kAttribute / kKey: the name not found
  bool fatal = false;         // set by host functions (xacro.fatal)
};

// The kind's name as Python spells its exception ("NameError", ...).
std::string_view ErrorKindName(Error::Kind kind);

// A value or the Error that prevented it.
template <typename T>
class Result {
 public:
  Result(T value) : v_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: implicit
  Result(Error error) : v_(std::in_place_index<1>, std::move(error)) {}  // NOLINT: implicit
  template <typename U>
    requires(std::is_constructible_v<T, U &&> && !std::is_same_v<std::decay_t<U>, T> &&
             !std::is_same_v<std::decay_t<U>, Error>)
  Result(U&& value) : v_(std::in_place_index<0>, T(std::forward<U>(value))) {}  // NOLINT: implicit

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  T& value() & { return std::get<0>(v_); }
  const T& value() const& { return std::get<0>(v_); }
  T&& value() && { return std::get<0>(std::move(v_)); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }
  T&& operator*() && { return std::move(*this).value(); }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  const Error& error() const& { return std::get<1>(v_); }
  Error& error() & { return std::get<1>(v_); }
  Error&& error() && { return std::get<1>(std::move(v_)); }

 private:
  std::variant<T, Error> v_;
};

class Value;
class NameTable;

// A host-supplied (or builtin) callable.
using NativeFunction = std::function<Result<Value>(
    std::span<const Value> positional, std::span<const std::pair<std::string, Value>> keywords)>;

class Value {
 public:
  enum class Kind : uint8_t {
    kNone,
    kBool,
    kInt,
    kFloat,
    kStr,
    kList,
    kTuple,
    kDict,
    kFunction,
    kNamespace,
    kOpaque
  };
  using Item = std::pair<Value, Value>;

  Value() = default;  // None
  static Value Bool(bool b);
  static Value Int(int64_t i);
  // An int of any size: a 64-bit int when it fits, else a big int (Python
  // has one int type; kind() is kInt either way).
  static Value Big(BigInt i);
  static Value Float(double d);
  static Value Str(std::string s);
  static Value List(std::vector<Value> items);
  static Value Tuple(std::vector<Value> items);
  // Insertion-ordered; a key given twice keeps its first place and its last
  // value (as a Python dict literal does). Keys must be hashable (None, bool,
  // int, float, str, tuples of those); other keys are compared by identity.
  // attribute_access: xacro's YamlDictWrapper (dotify): d.key reads
  // d['key'], a missing key is an attribute error, and dicts and lists read
  // through it are wrapped too.
  static Value Dict(std::vector<Item> items, bool attribute_access = false);
  static Value Function(std::string name, NativeFunction fn);
  // `math.`, `python.`, `xacro.`: attribute access looks up names.
  static Value Namespace(std::string name, std::shared_ptr<const NameTable> names);
  // Host data an expression can only pass around (and compare by identity).
  static Value Opaque(std::string type_name, std::shared_ptr<const void> payload);

  Kind kind() const { return kind_; }
  bool IsNone() const { return kind_ == Kind::kNone; }
  bool IsBool() const { return kind_ == Kind::kBool; }
  bool IsInt() const { return kind_ == Kind::kInt; }      // not bool
  bool IsBigInt() const { return kind_ == Kind::kInt && heap_ != nullptr; }  // beyond 64 bits
  bool IsFloat() const { return kind_ == Kind::kFloat; }
  bool IsStr() const { return kind_ == Kind::kStr; }
  bool IsList() const { return kind_ == Kind::kList; }
  bool IsTuple() const { return kind_ == Kind::kTuple; }
  bool IsDict() const { return kind_ == Kind::kDict; }
  bool IsFunction() const { return kind_ == Kind::kFunction; }
  bool IsNamespace() const { return kind_ == Kind::kNamespace; }
  bool IsOpaque() const { return kind_ == Kind::kOpaque; }
  bool IsIntegral() const { return kind_ == Kind::kBool || kind_ == Kind::kInt; }  // bool or int
  bool IsNumber() const { return IsIntegral() || kind_ == Kind::kFloat; }
  bool IsSequence() const { return kind_ == Kind::kList || kind_ == Kind::kTuple; }

  bool AsBool() const { return scalar_.b; }        // kBool
  int64_t AsInt() const;                           // kInt or kBool; a big int saturates to INT64_MIN/MAX
  double AsFloat() const;                          // kFloat, kInt or kBool; a big int too large: +-inf
  const BigInt& big() const;                       // IsBigInt()
  BigInt AsBigInt() const;                         // kInt or kBool, any size
  const std::string& AsStr() const;                // kStr
  const std::vector<Value>& items() const;         // kList, kTuple
  const std::vector<Item>& dict_items() const;     // kDict
  const Value* DictFind(const Value& key) const;   // kDict; nullptr if missing
  const Value* DictFind(std::string_view key) const;
  bool attribute_access() const { return attribute_access_; }  // kDict, kList
  // The same list or dict, wrapped (or not) for attribute access; other
  // values unchanged.
  Value WithAttributeAccess(bool on) const;
  const std::string& name() const;                 // kFunction, kNamespace
  const NativeFunction& function() const;          // kFunction
  const NameTable& names() const;                  // kNamespace
  const std::string& opaque_type() const;          // kOpaque
  const std::shared_ptr<const void>& opaque_payload() const;
  const void* identity() const { return heap_.get(); }  // heap values

 private:
  Kind kind_ = Kind::kNone;
  bool attribute_access_ = false;
  union {
    bool b;
    int64_t i;
    double d;
  } scalar_{};
  std::shared_ptr<const void> heap_;
};

// Names of a namespace, or the globals.
class NameTable {
 public:
  void Set(std::string name, Value v);
  const Value* Find(std::string_view name) const;
  std::vector<std::string> Names() const;  // sorted

 private:
  std::map<std::string, Value, std::less<>> names_;
};

// Python's type name of the value ("int", "str", "NoneType", ...).
std::string TypeName(const Value& v);

std::string Str(const Value& v);   // Python's str()
std::string Repr(const Value& v);  // Python's repr()
bool Truthy(const Value& v);       // Python's bool()

// Python's ==. (1 == 1.0 == True; no equality across other kinds.)
bool Equal(const Value& a, const Value& b);
// Python's hash() for the hashable kinds, consistent with Equal; nullopt for
// unhashable values (list, dict).
std::optional<uint64_t> Hash(const Value& v);
enum class CompareOp { kLt, kLe, kGt, kGe };
// Python's ordering comparisons; a kType error across incomparable kinds.
Result<bool> Compare(const Value& a, CompareOp op, const Value& b);

}  // namespace mdlc::pyexpr
