// evaluate.cc - walks the syntax tree of one expression.
#include "frontend/pyexpr/evaluate.h"

#include <fmt/format.h>

#include "frontend/pyexpr/builtins.h"
#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/parser.h"

namespace mdlc::pyexpr {
namespace internal {
namespace {
thread_local const Limits* current_limits = nullptr;
}  // namespace

const Limits& CurrentLimits() {
  static const Limits kDefaults;
  return current_limits ? *current_limits : kDefaults;
}

LimitsScope::LimitsScope(const Limits& limits) : previous_(current_limits) { current_limits = &limits; }
LimitsScope::~LimitsScope() { current_limits = previous_; }

Result<bool> CheckStringSize(size_t bytes) {
  size_t limit = CurrentLimits().max_string_bytes;
  if (bytes > limit)
    return Fail(Error::Kind::kLimit, fmt::format("the string would be longer than the limit of {} bytes", limit));
  return true;
}

Result<bool> CheckItemCount(size_t items) {
  size_t limit = CurrentLimits().max_items;
  if (items > limit)
    return Fail(Error::Kind::kLimit, fmt::format("the result would hold more than the limit of {} items", limit));
  return true;
}

Result<Value> Call(const Value& callee, Positional positional, Keywords keywords) {
  if (!callee.IsFunction())
    return Fail(Error::Kind::kType, fmt::format("'{}' values cannot be called", TypeName(callee)));
  if (!callee.function()) return Fail(Error::Kind::kType, fmt::format("'{}' cannot be called", callee.name()));
  return callee.function()(positional, keywords);
}

Result<std::vector<Value>> Iterate(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::kList:
    case Value::Kind::kTuple: {
      if (!v.attribute_access()) return v.items();
      std::vector<Value> out;
      out.reserve(v.items().size());
      for (const Value& item : v.items()) out.push_back(WrapChild(v, item));
      return out;
    }
    case Value::Kind::kStr: {
      std::vector<Value> out;
      if (IsAscii(v.AsStr())) {
        for (char c : v.AsStr()) out.push_back(Value::Str(std::string(1, c)));
      } else {
        for (auto& cp : SplitCodePoints(v.AsStr())) out.push_back(Value::Str(std::move(cp)));
      }
      return out;
    }
    case Value::Kind::kDict: {
      std::vector<Value> out;
      out.reserve(v.dict_items().size());
      for (const auto& item : v.dict_items()) out.push_back(item.first);
      return out;
    }
    case Value::Kind::kNamespace: {
      std::vector<Value> out;
      for (auto& name : v.names().Names()) out.push_back(Value::Str(std::move(name)));
      return out;
    }
    default: return Fail(Error::Kind::kType, fmt::format("'{}' values are not iterable", TypeName(v)));
  }
}

}  // namespace internal

namespace {

using internal::Fail;

template <typename T>
Result<T> At(Result<T> r, size_t offset) {
  if (!r.ok() && r.error().offset == 0) r.error().offset = offset;
  return r;
}

internal::BinOp BinOpOf(std::string_view op) {
  using internal::BinOp;
  if (op == "+") return BinOp::kAdd;
  if (op == "-") return BinOp::kSub;
  if (op == "*") return BinOp::kMul;
  if (op == "/") return BinOp::kDiv;
  if (op == "//") return BinOp::kFloorDiv;
  if (op == "%") return BinOp::kMod;
  if (op == "@") return BinOp::kMatMul;
  if (op == "<<") return BinOp::kLShift;
  if (op == ">>") return BinOp::kRShift;
  if (op == "&") return BinOp::kBitAnd;
  if (op == "|") return BinOp::kBitOr;
  return BinOp::kBitXor;
}

bool Identical(const Value& a, const Value& b) {
  if (a.kind() != b.kind()) return false;
  switch (a.kind()) {
    case Value::Kind::kNone: return true;
    case Value::Kind::kBool:
    case Value::Kind::kInt: return a.AsInt() == b.AsInt();  // CPython shares small ints
    case Value::Kind::kFloat: return false;
    case Value::Kind::kOpaque: return a.opaque_payload() == b.opaque_payload();
    default: return a.identity() == b.identity();
  }
}

class Evaluator {
 public:
  Evaluator(Scope& scope, const Limits& limits) : scope_(scope), limits_(limits) {}

  Result<Value> Eval(const Node& n) {
    if (++depth_ > limits_.max_depth * 4 + 16) {
      --depth_;
      return Error{Error::Kind::kLimit,
                   fmt::format("expression nested deeper than the limit of {} levels", limits_.max_depth), n.offset};
    }
    auto r = EvalNode(n);
    --depth_;
    return r;
  }

 private:
  Result<Value> EvalNode(const Node& n) {
    switch (n.type) {
      case Node::Type::kConst: return n.constant;
      case Node::Type::kName: return LookupName(n);
      case Node::Type::kTuple:
      case Node::Type::kList: {
        auto items = Items(n.kids);
        if (!items.ok()) return std::move(items).error();
        return n.type == Node::Type::kList ? Value::List(std::move(*items)) : Value::Tuple(std::move(*items));
      }
      case Node::Type::kDict: return DictDisplay(n);
      case Node::Type::kBinary: {
        PYEXPR_TRY(acc, Eval(*n.kids[0]));
        for (size_t i = 0; i < n.ops.size(); ++i) {
          PYEXPR_TRY(rhs, Eval(*n.kids[i + 1]));
          PYEXPR_TRY(next, At(internal::ApplyBinary(BinOpOf(n.ops[i]), acc, rhs), n.op_offsets[i]));
          acc = std::move(next);
        }
        return acc;
      }
      case Node::Type::kPower: {
        PYEXPR_TRY(base, Eval(*n.kids[0]));
        PYEXPR_TRY(exponent, Eval(*n.kids[1]));
        return At(internal::ApplyBinary(internal::BinOp::kPow, base, exponent), n.offset);
      }
      case Node::Type::kUnary: {
        PYEXPR_TRY(v, Eval(*n.kids[0]));
        internal::UnOp op = n.ops[0] == "-" ? internal::UnOp::kNeg
                            : n.ops[0] == "+" ? internal::UnOp::kPos
                                              : internal::UnOp::kInvert;
        return At(internal::ApplyUnary(op, v), n.offset);
      }
      case Node::Type::kNot: {
        PYEXPR_TRY(v, Eval(*n.kids[0]));
        return Value::Bool(!Truthy(v));
      }
      case Node::Type::kAnd:
      case Node::Type::kOr: {
        bool is_or = n.type == Node::Type::kOr;
        Value v;
        for (size_t i = 0; i < n.kids.size(); ++i) {
          PYEXPR_TRY(x, Eval(*n.kids[i]));
          v = std::move(x);
          if (Truthy(v) == is_or) break;
        }
        return v;
      }
      case Node::Type::kCompare: return CompareChain(n);
      case Node::Type::kIfElse: {
        PYEXPR_TRY(cond, Eval(*n.kids[1]));
        return Eval(*n.kids[Truthy(cond) ? 0 : 2]);
      }
      case Node::Type::kAttribute: {
        PYEXPR_TRY(obj, Eval(*n.kids[0]));
        return At(Attribute(obj, n.name), n.offset + 1);
      }
      case Node::Type::kSubscript: {
        PYEXPR_TRY(obj, Eval(*n.kids[0]));
        const Node& index = *n.kids[1];
        if (index.type == Node::Type::kSlice) {
          Value parts[3];
          for (int k = 0; k < 3; ++k) {
            if (!index.kids[k]) continue;
            PYEXPR_TRY(part, Eval(*index.kids[k]));
            parts[k] = std::move(part);
          }
          return At(internal::Slice(obj, parts[0], parts[1], parts[2]), index.offset);
        }
        PYEXPR_TRY(key, Eval(index));
        return At(internal::Subscript(obj, key), index.offset);
      }
      case Node::Type::kSlice:
        return Error{Error::Kind::kUnsupported, "slices are only supported directly inside []", n.offset};
      case Node::Type::kCall: return CallNode(n);
      case Node::Type::kStarred:
        return Error{Error::Kind::kSyntax, "a starred expression is not allowed here", n.offset};
    }
    return Error{Error::Kind::kSyntax, "unknown expression", n.offset};
  }

  Result<Value> LookupName(const Node& n) {
    auto found = scope_.Lookup(n.name);
    if (!found.ok()) return std::move(found).error();
    if (*found) return **found;
    if (const Value* v = StandardGlobals().Find(n.name)) return *v;
    Error e{Error::Kind::kName, fmt::format("name '{}' is not defined", n.name), n.offset};
    e.missing_name = n.name;
    return e;
  }

  Result<std::vector<Value>> Items(const std::vector<NodePtr>& kids) {
    std::vector<Value> out;
    out.reserve(kids.size());
    for (const auto& kid : kids) {
      if (kid->type == Node::Type::kStarred) {
        PYEXPR_TRY(v, Eval(*kid->kids[0]));
        PYEXPR_TRY(items, At(internal::Iterate(v), kid->offset));
        out.insert(out.end(), items.begin(), items.end());
        auto ok = At(internal::CheckItemCount(out.size()), kid->offset);
        if (!ok.ok()) return std::move(ok).error();
      } else {
        PYEXPR_TRY(v, Eval(*kid));
        out.push_back(std::move(v));
      }
    }
    return out;
  }

  Result<Value> DictDisplay(const Node& n) {
    std::vector<Value::Item> items;
    for (size_t i = 0; i + 1 < n.kids.size(); i += 2) {
      if (!n.kids[i]) {
        PYEXPR_TRY(mapping, Eval(*n.kids[i + 1]));
        if (!mapping.IsDict())
          return Error{Error::Kind::kType, fmt::format("'{}' values are not mappings", TypeName(mapping)),
                       n.kids[i + 1]->offset};
        for (const auto& item : mapping.dict_items()) items.push_back(item);
        continue;
      }
      PYEXPR_TRY(key, Eval(*n.kids[i]));
      if (!Hash(key))
        return Error{Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(key)), n.kids[i]->offset};
      PYEXPR_TRY(value, Eval(*n.kids[i + 1]));
      items.emplace_back(std::move(key), std::move(value));
    }
    return Value::Dict(std::move(items));
  }

  Result<Value> CompareChain(const Node& n) {
    PYEXPR_TRY(left, Eval(*n.kids[0]));
    Value result = Value::Bool(true);
    for (size_t i = 0; i < n.ops.size(); ++i) {
      PYEXPR_TRY(right, Eval(*n.kids[i + 1]));
      PYEXPR_TRY(holds, At(CompareOnce(n.ops[i], left, right), n.op_offsets[i]));
      if (!holds) return Value::Bool(false);
      left = std::move(right);
    }
    return result;
  }

  static Result<bool> CompareOnce(const std::string& op, const Value& a, const Value& b) {
    if (op == "==") return Equal(a, b);
    if (op == "!=") return !Equal(a, b);
    if (op == "<") return Compare(a, CompareOp::kLt, b);
    if (op == "<=") return Compare(a, CompareOp::kLe, b);
    if (op == ">") return Compare(a, CompareOp::kGt, b);
    if (op == ">=") return Compare(a, CompareOp::kGe, b);
    if (op == "in") return internal::Contains(b, a);
    if (op == "not in") {
      auto r = internal::Contains(b, a);
      if (!r.ok()) return r;
      return !*r;
    }
    if (op == "is") return Identical(a, b);
    return !Identical(a, b);  // is not
  }

  static Result<Value> Attribute(const Value& obj, const std::string& name) {
    if (obj.IsNamespace()) {
      if (const Value* v = obj.names().Find(name)) return *v;
      Error e{Error::Kind::kName, fmt::format("name '{}' is not defined", name)};
      e.missing_name = name;
      return e;
    }
    if (obj.IsStr() || obj.IsSequence() || obj.IsDict()) {
      auto method = internal::Method(obj, name);
      if (method.ok() || !obj.IsDict() || !obj.attribute_access()) return method;
      if (const Value* v = obj.DictFind(name)) return internal::WrapChild(obj, *v);
      Error e{Error::Kind::kAttribute, fmt::format("the yaml dictionary has no key '{}'", name)};
      e.missing_name = name;
      return e;
    }
    Error e{Error::Kind::kAttribute, fmt::format("'{}' values have no attribute '{}'", TypeName(obj), name)};
    e.missing_name = name;
    return e;
  }

  Result<Value> CallNode(const Node& n) {
    PYEXPR_TRY(callee, Eval(*n.kids[0]));
    std::vector<Value> positional;
    std::vector<std::pair<std::string, Value>> keywords;
    for (size_t i = 0; i < n.arg_names.size(); ++i) {
      const Node& arg = *n.kids[i + 1];
      const std::string& kw = n.arg_names[i];
      PYEXPR_TRY(v, Eval(arg));
      if (kw.empty()) {
        positional.push_back(std::move(v));
      } else if (kw == "*") {
        PYEXPR_TRY(items, At(internal::Iterate(v), arg.offset));
        positional.insert(positional.end(), items.begin(), items.end());
      } else if (kw == "**") {
        if (!v.IsDict())
          return Error{Error::Kind::kType, fmt::format("argument after ** must be a mapping, not {}", TypeName(v)),
                       arg.offset};
        for (const auto& [key, value] : v.dict_items()) {
          if (!key.IsStr()) return Error{Error::Kind::kType, "keywords must be strings", arg.offset};
          for (const auto& existing : keywords)
            if (existing.first == key.AsStr())
              return Error{Error::Kind::kType, fmt::format("keyword argument '{}' given twice", key.AsStr()),
                           arg.offset};
          keywords.emplace_back(key.AsStr(), value);
        }
      } else {
        keywords.emplace_back(kw, std::move(v));
      }
    }
    return At(internal::Call(callee, positional, keywords), n.kids[0]->offset);
  }

  Scope& scope_;
  const Limits& limits_;
  int depth_ = 0;
};

}  // namespace

Result<Value> Evaluate(std::string_view expression, Scope& scope, const Limits& limits) {
  internal::LimitsScope limits_scope(limits);
  size_t first = expression.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return Error{Error::Kind::kSyntax, "empty expression", expression.size()};
  auto tree = Parse(expression, limits.max_depth);
  if (!tree.ok()) return std::move(tree).error();
  return Evaluator(scope, limits).Eval(**tree);
}

}  // namespace mdlc::pyexpr
