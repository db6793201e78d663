// value.cc - Value construction, str()/repr(), equality, hashing, ordering.
#include "frontend/pyexpr/value.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "frontend/pyexpr/number_text.h"

namespace mdlc::pyexpr {
namespace {

struct StrObj {
  std::string s;
};
struct SeqObj {
  std::vector<Value> items;
};
struct DictObj {
  std::vector<Value::Item> items;
  std::unordered_multimap<uint64_t, size_t> index;  // hash of key -> position
};
struct FuncObj {
  std::string name;
  NativeFunction fn;
};
struct NsObj {
  std::string name;
  std::shared_ptr<const NameTable> names;
};
struct BigObj {
  BigInt i;
};
struct OpaqueObj {
  std::string type;
  std::shared_ptr<const void> payload;
};

template <typename T>
const T& Heap(const std::shared_ptr<const void>& p) {
  return *static_cast<const T*>(p.get());
}

const std::string kEmpty;
const std::vector<Value> kNoItems;
const std::vector<Value::Item> kNoDictItems;

uint64_t Mix(uint64_t h) {
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  return h;
}

}  // namespace

std::string_view ErrorKindName(Error::Kind kind) {
  switch (kind) {
    case Error::Kind::kSyntax: return "SyntaxError";
    case Error::Kind::kName: return "NameError";
    case Error::Kind::kType: return "TypeError";
    case Error::Kind::kValue: return "ValueError";
    case Error::Kind::kIndex: return "IndexError";
    case Error::Kind::kKey: return "KeyError";
    case Error::Kind::kZeroDivision: return "ZeroDivisionError";
    case Error::Kind::kOverflow: return "OverflowError";
    case Error::Kind::kAttribute: return "AttributeError";
    case Error::Kind::kLimit: return "LimitError";
    case Error::Kind::kUnsupported: return "UnsupportedError";
    case Error::Kind::kHost: return "HostError";
  }
  return "Error";
}

Value Value::Bool(bool b) {
  Value v;
  v.kind_ = Kind::kBool;
  v.scalar_.b = b;
  return v;
}

Value Value::Int(int64_t i) {
  Value v;
  v.kind_ = Kind::kInt;
  v.scalar_.i = i;
  return v;
}

Value Value::Big(BigInt i) {
  if (auto small = i.ToInt64()) return Int(*small);
  Value v;
  v.kind_ = Kind::kInt;
  v.scalar_.i = i.IsNegative() ? std::numeric_limits<int64_t>::min() : std::numeric_limits<int64_t>::max();
  v.heap_ = std::make_shared<const BigObj>(BigObj{std::move(i)});
  return v;
}

const BigInt& Value::big() const { return Heap<BigObj>(heap_).i; }

BigInt Value::AsBigInt() const { return IsBigInt() ? big() : BigInt::FromInt64(AsInt()); }

Value Value::Float(double d) {
  Value v;
  v.kind_ = Kind::kFloat;
  v.scalar_.d = d;
  return v;
}

Value Value::Str(std::string s) {
  Value v;
  v.kind_ = Kind::kStr;
  v.heap_ = std::make_shared<const StrObj>(StrObj{std::move(s)});
  return v;
}

Value Value::List(std::vector<Value> items) {
  Value v;
  v.kind_ = Kind::kList;
  v.heap_ = std::make_shared<const SeqObj>(SeqObj{std::move(items)});
  return v;
}

Value Value::Tuple(std::vector<Value> items) {
  Value v;
  v.kind_ = Kind::kTuple;
  v.heap_ = std::make_shared<const SeqObj>(SeqObj{std::move(items)});
  return v;
}

Value Value::Dict(std::vector<Item> items, bool attribute_access) {
  auto obj = std::make_shared<DictObj>();
  obj->items.reserve(items.size());
  for (auto& item : items) {
    std::optional<uint64_t> h = Hash(item.first);
    uint64_t key_hash = h ? *h : reinterpret_cast<uintptr_t>(item.first.identity());
    bool replaced = false;
    auto [lo, hi] = obj->index.equal_range(key_hash);
    for (auto it = lo; it != hi; ++it) {
      Value& existing = obj->items[it->second].first;
      if (h ? Equal(existing, item.first) : existing.identity() == item.first.identity()) {
        obj->items[it->second].second = std::move(item.second);
        replaced = true;
        break;
      }
    }
    if (replaced) continue;
    obj->index.emplace(key_hash, obj->items.size());
    obj->items.push_back(std::move(item));
  }
  Value v;
  v.kind_ = Kind::kDict;
  v.attribute_access_ = attribute_access;
  v.heap_ = std::move(obj);
  return v;
}

Value Value::Function(std::string name, NativeFunction fn) {
  Value v;
  v.kind_ = Kind::kFunction;
  v.heap_ = std::make_shared<const FuncObj>(FuncObj{std::move(name), std::move(fn)});
  return v;
}

Value Value::Namespace(std::string name, std::shared_ptr<const NameTable> names) {
  Value v;
  v.kind_ = Kind::kNamespace;
  if (!names) names = std::make_shared<const NameTable>();
  v.heap_ = std::make_shared<const NsObj>(NsObj{std::move(name), std::move(names)});
  return v;
}

Value Value::Opaque(std::string type_name, std::shared_ptr<const void> payload) {
  Value v;
  v.kind_ = Kind::kOpaque;
  v.heap_ = std::make_shared<const OpaqueObj>(OpaqueObj{std::move(type_name), std::move(payload)});
  return v;
}

int64_t Value::AsInt() const { return kind_ == Kind::kBool ? (scalar_.b ? 1 : 0) : scalar_.i; }

double Value::AsFloat() const {
  switch (kind_) {
    case Kind::kFloat: return scalar_.d;
    case Kind::kInt:
      if (heap_) {
        const BigInt& b = big();
        return b.ToDouble().value_or(b.IsNegative() ? -HUGE_VAL : HUGE_VAL);
      }
      return static_cast<double>(scalar_.i);
    case Kind::kBool: return scalar_.b ? 1.0 : 0.0;
    default: return 0.0;
  }
}

const std::string& Value::AsStr() const { return kind_ == Kind::kStr ? Heap<StrObj>(heap_).s : kEmpty; }

const std::vector<Value>& Value::items() const {
  return IsSequence() ? Heap<SeqObj>(heap_).items : kNoItems;
}

const std::vector<Value::Item>& Value::dict_items() const {
  return kind_ == Kind::kDict ? Heap<DictObj>(heap_).items : kNoDictItems;
}

const Value* Value::DictFind(const Value& key) const {
  if (kind_ != Kind::kDict) return nullptr;
  const DictObj& d = Heap<DictObj>(heap_);
  std::optional<uint64_t> h = Hash(key);
  if (!h) return nullptr;
  auto [lo, hi] = d.index.equal_range(*h);
  for (auto it = lo; it != hi; ++it)
    if (Equal(d.items[it->second].first, key)) return &d.items[it->second].second;
  return nullptr;
}

const Value* Value::DictFind(std::string_view key) const { return DictFind(Value::Str(std::string(key))); }

Value Value::WithAttributeAccess(bool on) const {
  Value v = *this;
  if (kind_ == Kind::kDict || kind_ == Kind::kList) v.attribute_access_ = on;
  return v;
}

const std::string& Value::name() const {
  if (kind_ == Kind::kFunction) return Heap<FuncObj>(heap_).name;
  if (kind_ == Kind::kNamespace) return Heap<NsObj>(heap_).name;
  return kEmpty;
}

const NativeFunction& Value::function() const { return Heap<FuncObj>(heap_).fn; }

const NameTable& Value::names() const { return *Heap<NsObj>(heap_).names; }

const std::string& Value::opaque_type() const {
  return kind_ == Kind::kOpaque ? Heap<OpaqueObj>(heap_).type : kEmpty;
}

const std::shared_ptr<const void>& Value::opaque_payload() const { return Heap<OpaqueObj>(heap_).payload; }

void NameTable::Set(std::string name, Value v) { names_[std::move(name)] = std::move(v); }

const Value* NameTable::Find(std::string_view name) const {
  auto it = names_.find(name);
  return it == names_.end() ? nullptr : &it->second;
}

std::vector<std::string> NameTable::Names() const {
  std::vector<std::string> out;
  out.reserve(names_.size());
  for (const auto& [name, value] : names_) out.push_back(name);
  return out;
}

std::string TypeName(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::kNone: return "NoneType";
    case Value::Kind::kBool: return "bool";
    case Value::Kind::kInt: return "int";
    case Value::Kind::kFloat: return "float";
    case Value::Kind::kStr: return "str";
    case Value::Kind::kList: return "list";
    case Value::Kind::kTuple: return "tuple";
    case Value::Kind::kDict: return "dict";
    case Value::Kind::kFunction: return v.name() == "<lambda>" ? "function" : "builtin_function_or_method";
    case Value::Kind::kNamespace: return "namespace";
    case Value::Kind::kOpaque: return v.opaque_type();
  }
  return "object";
}

namespace {

void AppendStrRepr(const std::string& s, std::string& out) {
  bool has_single = s.find('\'') != std::string::npos;
  bool has_double = s.find('"') != std::string::npos;
  char quote = has_single && !has_double ? '"' : '\'';
  out.push_back(quote);
  static const char* kHex = "0123456789abcdef";
  for (unsigned char c : s) {
    if (c == static_cast<unsigned char>(quote) || c == '\\') {
      out.push_back('\\');
      out.push_back(static_cast<char>(c));
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c < 0x20 || c == 0x7f) {
      out += "\\x";
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    } else {
      out.push_back(static_cast<char>(c));  // UTF-8 passes through (printable)
    }
  }
  out.push_back(quote);
}

void AppendRepr(const Value& v, std::string& out, int depth);

void AppendItems(const std::vector<Value>& items, std::string& out, int depth) {
  for (size_t i = 0; i < items.size(); ++i) {
    if (i) out += ", ";
    AppendRepr(items[i], out, depth + 1);
  }
}

void AppendRepr(const Value& v, std::string& out, int depth) {
  if (depth > 200) {  // values are immutable trees; this only bounds the stack
    out += "...";
    return;
  }
  switch (v.kind()) {
    case Value::Kind::kNone: out += "None"; break;
    case Value::Kind::kBool: out += v.AsBool() ? "True" : "False"; break;
    case Value::Kind::kInt: out += v.IsBigInt() ? v.big().ToString() : std::to_string(v.AsInt()); break;
    case Value::Kind::kFloat: out += FloatRepr(v.AsFloat()); break;
    case Value::Kind::kStr: AppendStrRepr(v.AsStr(), out); break;
    case Value::Kind::kList:
      out.push_back('[');
      AppendItems(v.items(), out, depth);
      out.push_back(']');
      break;
    case Value::Kind::kTuple:
      out.push_back('(');
      AppendItems(v.items(), out, depth);
      if (v.items().size() == 1) out.push_back(',');
      out.push_back(')');
      break;
    case Value::Kind::kDict: {
      out.push_back('{');
      bool first = true;
      for (const auto& [key, value] : v.dict_items()) {
        if (!first) out += ", ";
        first = false;
        AppendRepr(key, out, depth + 1);
        out += ": ";
        AppendRepr(value, out, depth + 1);
      }
      out.push_back('}');
      break;
    }
    case Value::Kind::kFunction:
      out += v.name() == "<lambda>" ? "<function <lambda>>" : "<built-in function " + v.name() + ">";
      break;
    case Value::Kind::kNamespace: out += "<namespace " + v.name() + ">"; break;
    case Value::Kind::kOpaque: out += "<" + v.opaque_type() + " object>"; break;
  }
}

// Exact comparison of an int with a double: -1, 0, 1; nullopt if d is nan.
std::optional<int> CompareIntDouble(int64_t i, double d) {
  if (std::isnan(d)) return std::nullopt;
  constexpr double kTwo63 = 9223372036854775808.0;
  if (d >= kTwo63) return -1;
  if (d < -kTwo63) return 1;
  double t = std::trunc(d);
  int64_t ti = static_cast<int64_t>(t);
  if (i < ti) return -1;
  if (i > ti) return 1;
  if (d > t) return -1;
  if (d < t) return 1;
  return 0;
}

// Numeric comparison: -1, 0, 1, nullopt for nan.
std::optional<int> CompareNumbers(const Value& a, const Value& b) {
  if (a.IsBigInt() || b.IsBigInt()) {
    if (a.IsIntegral() && b.IsIntegral()) return BigInt::Compare(a.AsBigInt(), b.AsBigInt());
    if (std::isnan(a.AsFloat()) || std::isnan(b.AsFloat())) return std::nullopt;
    if (a.IsIntegral()) return BigInt::CompareDouble(a.AsBigInt(), b.AsFloat());
    return -BigInt::CompareDouble(b.AsBigInt(), a.AsFloat());
  }
  if (a.IsIntegral() && b.IsIntegral()) {
    int64_t x = a.AsInt(), y = b.AsInt();
    return x < y ? -1 : (x > y ? 1 : 0);
  }
  if (a.IsIntegral()) return CompareIntDouble(a.AsInt(), b.AsFloat());
  if (b.IsIntegral()) {
    auto c = CompareIntDouble(b.AsInt(), a.AsFloat());
    if (!c) return c;
    return -*c;
  }
  double x = a.AsFloat(), y = b.AsFloat();
  if (std::isnan(x) || std::isnan(y)) return std::nullopt;
  return x < y ? -1 : (x > y ? 1 : 0);
}

bool Holds(CompareOp op, int c) {
  switch (op) {
    case CompareOp::kLt: return c < 0;
    case CompareOp::kLe: return c <= 0;
    case CompareOp::kGt: return c > 0;
    case CompareOp::kGe: return c >= 0;
  }
  return false;
}

const char* OpText(CompareOp op) {
  switch (op) {
    case CompareOp::kLt: return "<";
    case CompareOp::kLe: return "<=";
    case CompareOp::kGt: return ">";
    case CompareOp::kGe: return ">=";
  }
  return "?";
}

}  // namespace

std::string Str(const Value& v) {
  if (v.IsStr()) return v.AsStr();
  return Repr(v);
}

std::string Repr(const Value& v) {
  std::string out;
  AppendRepr(v, out, 0);
  return out;
}

bool Truthy(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::kNone: return false;
    case Value::Kind::kBool: return v.AsBool();
    case Value::Kind::kInt: return v.AsInt() != 0;
    case Value::Kind::kFloat: return v.AsFloat() != 0.0;
    case Value::Kind::kStr: return !v.AsStr().empty();
    case Value::Kind::kList:
    case Value::Kind::kTuple: return !v.items().empty();
    case Value::Kind::kDict: return !v.dict_items().empty();
    default: return true;
  }
}

bool Equal(const Value& a, const Value& b) {
  if (a.IsNumber() && b.IsNumber()) {
    auto c = CompareNumbers(a, b);
    return c && *c == 0;
  }
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case Value::Kind::kNone: return true;
    case Value::Kind::kStr: return a.AsStr() == b.AsStr();
    case Value::Kind::kList:
    case Value::Kind::kTuple: {
      const auto& x = a.items();
      const auto& y = b.items();
      if (x.size() != y.size()) return false;
      for (size_t i = 0; i < x.size(); ++i)
        if (x[i].identity() != y[i].identity() || x[i].identity() == nullptr)
          if (!Equal(x[i], y[i])) return false;
      return true;
    }
    case Value::Kind::kDict: {
      if (a.dict_items().size() != b.dict_items().size()) return false;
      for (const auto& [key, value] : a.dict_items()) {
        const Value* other = b.DictFind(key);
        if (!other || !Equal(value, *other)) return false;
      }
      return true;
    }
    case Value::Kind::kOpaque: return a.opaque_payload() == b.opaque_payload();
    default: return a.identity() == b.identity();
  }
}

std::optional<uint64_t> Hash(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::kNone: return 0x9e3779b97f4a7c15ULL;
    case Value::Kind::kBool:
    case Value::Kind::kInt:
      if (v.IsBigInt()) return v.big().Hash();
      return Mix(static_cast<uint64_t>(v.AsInt()));
    case Value::Kind::kFloat: {
      double d = v.AsFloat();
      if (std::isfinite(d) && d == std::trunc(d)) {  // as the equal int
        if (std::fabs(d) < 9223372036854775808.0) return Mix(static_cast<uint64_t>(static_cast<int64_t>(d)));
        return BigInt::FromDouble(d)->Hash();
      }
      if (d == 0) return Mix(0);
      uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      return Mix(bits ^ 0x5bd1e995ULL);
    }
    case Value::Kind::kStr: return Mix(std::hash<std::string>{}(v.AsStr()));
    case Value::Kind::kTuple: {
      uint64_t h = 0x345678;
      for (const Value& item : v.items()) {
        auto ih = Hash(item);
        if (!ih) return std::nullopt;
        h = Mix(h * 1000003 ^ *ih);
      }
      return h;
    }
    case Value::Kind::kList:
    case Value::Kind::kDict: return std::nullopt;
    case Value::Kind::kOpaque: return Mix(reinterpret_cast<uintptr_t>(v.opaque_payload().get()));
    default: return Mix(reinterpret_cast<uintptr_t>(v.identity()));
  }
}

Result<bool> Compare(const Value& a, CompareOp op, const Value& b) {
  if (a.IsNumber() && b.IsNumber()) {
    auto c = CompareNumbers(a, b);
    return c ? Holds(op, *c) : false;
  }
  if (a.IsStr() && b.IsStr()) return Holds(op, a.AsStr().compare(b.AsStr()));
  if ((a.IsList() && b.IsList()) || (a.IsTuple() && b.IsTuple())) {
    const auto& x = a.items();
    const auto& y = b.items();
    size_t n = std::min(x.size(), y.size());
    for (size_t i = 0; i < n; ++i) {
      if (Equal(x[i], y[i])) continue;
      return Compare(x[i], op, y[i]);
    }
    return Holds(op, x.size() < y.size() ? -1 : (x.size() > y.size() ? 1 : 0));
  }
  return Error{Error::Kind::kType, std::string("'") + OpText(op) + "' is not supported between '" + TypeName(a) +
                                       "' and '" + TypeName(b) + "'"};
}

}  // namespace mdlc::pyexpr
