// evaluate.cc - walks the syntax tree of one expression.
#include "frontend/pyexpr/evaluate.h"

#include <fmt/format.h>

#include <functional>
#include <memory>
#include <optional>
#include <unordered_set>

#include "frontend/pyexpr/builtins.h"
#include "frontend/pyexpr/internal.h"
#include "frontend/pyexpr/parser.h"

namespace mdlc::pyexpr {
namespace internal {
namespace {
thread_local const Limits* current_limits = nullptr;
thread_local size_t current_steps = 0;
}  // namespace

const Limits& CurrentLimits() {
  static const Limits kDefaults;
  return current_limits ? *current_limits : kDefaults;
}

LimitsScope::LimitsScope(const Limits& limits) : previous_(current_limits), previous_steps_(current_steps) {
  current_limits = &limits;
  current_steps = 0;
}
LimitsScope::~LimitsScope() {
  current_limits = previous_;
  current_steps = previous_steps_;
}

Result<bool> CheckIntBits(double bits) {
  size_t digits = CurrentLimits().max_int_digits;
  if (bits > static_cast<double>(digits) * 3.3219280948873623 + 64)
    return Fail(Error::Kind::kLimit, fmt::format("the int would have more than the limit of {} digits", digits));
  return true;
}

Result<Value> BigResult(BigInt i) {
  auto ok = CheckIntBits(static_cast<double>(i.BitLength()));
  if (!ok.ok()) return std::move(ok).error();
  return Value::Big(std::move(i));
}

Result<double> ToFloat(const Value& v) {
  if (v.IsBigInt()) {
    auto d = v.big().ToDouble();
    if (!d) return Fail(Error::Kind::kOverflow, "int too large to convert to float");
    return *d;
  }
  return v.AsFloat();
}

Result<bool> CountStep() {
  size_t limit = CurrentLimits().max_steps;
  if (++current_steps > limit)
    return Fail(Error::Kind::kLimit,
                fmt::format("the expression would take more than the limit of {} steps (comprehension iterations "
                            "and lambda calls)",
                            limit));
  return true;
}

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
    case Value::Kind::kInt:
      if (a.IsBigInt() || b.IsBigInt()) return a.identity() == b.identity();
      return a.AsInt() == b.AsInt();  // CPython shares small ints
    case Value::Kind::kFloat: return false;
    case Value::Kind::kOpaque: return a.opaque_payload() == b.opaque_payload();
    default: return a.identity() == b.identity();
  }
}

// The variables of one comprehension or lambda call, in front of the
// enclosing ones. A lambda keeps the frames it was created in, and reads a
// variable when it runs (Python's closures: `[lambda: i for i in
// range(3)]` all return 2). A name declared but not yet bound is a
// NameError, as in Python.
struct Frame {
  std::vector<std::pair<std::string, std::optional<Value>>> vars;
  std::shared_ptr<Frame> parent;

  std::optional<Value>* Find(std::string_view name) {
    for (auto& var : vars)
      if (var.first == name) return &var.second;
    return nullptr;
  }
  void Declare(const std::string& name) {
    if (!Find(name)) vars.emplace_back(name, std::nullopt);
  }
};
using FramePtr = std::shared_ptr<Frame>;

// The scope of the Evaluate() running on this thread: a lambda reads its
// global names there when it is called (xacro's globals are one live table),
// and only StandardGlobals() when called outside any evaluation.
thread_local Scope* current_scope = nullptr;
// Nesting of Eval() and comprehension clauses on this thread, lambda calls
// included.
thread_local int current_depth = 0;
// Where the outermost Evaluate() on this thread found the stack, and how much
// of it the evaluation may use below that. The depth count bounds nesting;
// this bounds the stack itself, whose frames are many times larger under
// AddressSanitizer and whose size a thread of an embedding program may set
// small (a runaway lambda recursion overflowed the stack under ASan).
thread_local const char* stack_start = nullptr;
constexpr size_t kMaxStackBytes = 1 << 20;

bool StackNearlyFull() {
  const char here = 0;
  return stack_start && stack_start - &here > static_cast<ptrdiff_t>(kMaxStackBytes);
}

struct LambdaCode {
  std::vector<std::string> names;
  std::vector<std::string> kinds;  // as Node::arg_names of a kLambda
  std::shared_ptr<const Node> body;
};

Result<Value> CallLambda(const LambdaCode& code, const std::vector<std::optional<Value>>& defaults,
                         const FramePtr& closure, internal::Positional positional, internal::Keywords keywords);

// The function a lambda expression creates (a named type, so that
// BreakCycles can see the frames it keeps).
struct LambdaFunction {
  std::shared_ptr<const LambdaCode> code;
  std::shared_ptr<const std::vector<std::optional<Value>>> defaults;
  FramePtr closure;
  Result<Value> operator()(internal::Positional positional, internal::Keywords keywords) const {
    return CallLambda(*code, *defaults, closure, positional, keywords);
  }
};

// Whether `target` is reachable from v through containers, lambdas' defaults
// and closures, and frames.
bool Reaches(const Value& v, const Frame* target) {
  std::vector<const Value*> values{&v};
  std::vector<const Frame*> frames;
  std::unordered_set<const void*> seen;
  while (!values.empty() || !frames.empty()) {
    if (!frames.empty()) {
      const Frame* f = frames.back();
      frames.pop_back();
      if (f == target) return true;
      if (!seen.insert(f).second) continue;
      for (const auto& var : f->vars)
        if (var.second) values.push_back(&*var.second);
      if (f->parent) frames.push_back(f->parent.get());
      continue;
    }
    const Value* x = values.back();
    values.pop_back();
    if (!x->identity() || !seen.insert(x->identity()).second) continue;
    if (x->IsSequence()) {
      for (const Value& item : x->items()) values.push_back(&item);
    } else if (x->IsDict()) {
      for (const auto& [key, value] : x->dict_items()) {
        values.push_back(&key);
        values.push_back(&value);
      }
    } else if (x->IsFunction()) {
      if (const auto* fn = x->function().target<LambdaFunction>()) {
        for (const auto& d : *fn->defaults)
          if (d) values.push_back(&*d);
        if (fn->closure) frames.push_back(fn->closure.get());
      }
    }
  }
  return false;
}

// A comprehension's frame that holds (say) a lambda made in it, which keeps
// the frame, would never be freed: once the comprehension is done, such
// variables are unbound (a lambda reading one later gets a NameError, where
// Python would find the value).
void BreakCycles(Frame& frame) {
  for (auto& var : frame.vars)
    if (var.second && Reaches(*var.second, &frame)) var.second.reset();
}

class Evaluator {
 public:
  Evaluator(Scope& scope, const Limits& limits, FramePtr frame = nullptr)
      : scope_(scope), limits_(limits), frame_(std::move(frame)) {}

  Result<Value> Eval(const Node& n) {
    if (++current_depth > MaxDepth() || StackNearlyFull()) {
      --current_depth;
      return TooDeep(n.offset);
    }
    auto r = EvalNode(n);
    --current_depth;
    return r;
  }

 private:
  int MaxDepth() const { return limits_.max_depth * 4 + 16; }
  Error TooDeep(size_t offset) const {
    return Error{Error::Kind::kLimit,
                 fmt::format("expression nested deeper than the limit of {} levels", limits_.max_depth), offset};
  }

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
      case Node::Type::kListComp:
      case Node::Type::kGenExp: {
        std::vector<Value> out;
        PYEXPR_TRY(done, RunComprehension(n, 1, [&]() -> Result<bool> {
          PYEXPR_TRY(v, Eval(*n.kids[0]));
          out.push_back(std::move(v));
          PYEXPR_TRY(ok, At(internal::CheckItemCount(out.size()), n.offset));
          return ok;
        }));
        (void)done;
        return Value::List(std::move(out));
      }
      case Node::Type::kDictComp: {
        std::vector<Value::Item> out;
        PYEXPR_TRY(done, RunComprehension(n, 2, [&]() -> Result<bool> {
          PYEXPR_TRY(key, Eval(*n.kids[0]));
          PYEXPR_TRY(value, Eval(*n.kids[1]));
          if (!Hash(key))
            return Error{Error::Kind::kType, fmt::format("unhashable type: '{}'", TypeName(key)), n.kids[0]->offset};
          out.emplace_back(std::move(key), std::move(value));
          PYEXPR_TRY(ok, At(internal::CheckItemCount(out.size()), n.offset));
          return ok;
        }));
        (void)done;
        return Value::Dict(std::move(out));
      }
      case Node::Type::kCompFor:
      case Node::Type::kCompIf:
        return Error{Error::Kind::kSyntax, "a comprehension clause outside a comprehension", n.offset};
      case Node::Type::kLambda: return MakeLambda(n);
    }
    return Error{Error::Kind::kSyntax, "unknown expression", n.offset};
  }

  Result<Value> LookupName(const Node& n) {
    for (Frame* f = frame_.get(); f; f = f->parent.get()) {
      if (std::optional<Value>* slot = f->Find(n.name)) {
        if (*slot) return **slot;
        Error e{Error::Kind::kName,
                fmt::format("cannot access local variable '{}' where it is not associated with a value", n.name),
                n.offset};
        e.missing_name = n.name;
        return e;
      }
    }
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

  // Makes the current frame `frame` until destroyed.
  class FrameSwap {
   public:
    FrameSwap(Evaluator& e, FramePtr frame) : e_(e), saved_(std::move(e.frame_)) { e_.frame_ = std::move(frame); }
    ~FrameSwap() { e_.frame_ = std::move(saved_); }
    FrameSwap(const FrameSwap&) = delete;
    FrameSwap& operator=(const FrameSwap&) = delete;

   private:
    Evaluator& e_;
    FramePtr saved_;
  };

  // Called once per combination of the comprehension's variables that passes
  // its conditions; false stops the comprehension.
  using Emit = std::function<Result<bool>()>;

  static void DeclareTargets(const Node& target, Frame& frame) {
    if (target.type == Node::Type::kName) {
      frame.Declare(target.name);
      return;
    }
    for (const auto& kid : target.kids) DeclareTargets(*kid, frame);
  }

  // Runs the clauses n.kids[first_clause...] in a new frame holding the
  // comprehension's variables; the first iterable is evaluated outside it,
  // as in Python. false if emit stopped it.
  Result<bool> RunComprehension(const Node& n, size_t first_clause, const Emit& emit) {
    auto frame = std::make_shared<Frame>();
    frame->parent = frame_;
    for (size_t i = first_clause; i < n.kids.size(); ++i)
      if (n.kids[i]->type == Node::Type::kCompFor) DeclareTargets(*n.kids[i]->kids[0], *frame);
    PYEXPR_TRY(first, Eval(*n.kids[first_clause]->kids[1]));
    Result<bool> result = false;
    {
      FrameSwap swap(*this, frame);
      result = Clauses(n, first_clause, &first, emit);
    }
    if (frame.use_count() > 1) BreakCycles(*frame);  // some lambda keeps it
    return result;
  }

  Result<bool> Clauses(const Node& n, size_t i, const Value* first, const Emit& emit) {
    if (i == n.kids.size()) return emit();
    if (++current_depth > MaxDepth() || StackNearlyFull()) {
      --current_depth;
      return TooDeep(n.kids[i]->offset);
    }
    auto r = Clause(n, i, first, emit);
    --current_depth;
    return r;
  }

  Result<bool> Clause(const Node& n, size_t i, const Value* first, const Emit& emit) {
    const Node& c = *n.kids[i];
    if (c.type == Node::Type::kCompIf) {
      PYEXPR_TRY(cond, Eval(*c.kids[0]));
      if (!Truthy(cond)) return true;
      return Clauses(n, i + 1, nullptr, emit);
    }
    Value iterable;
    if (first) {
      iterable = *first;
    } else {
      PYEXPR_TRY(v, Eval(*c.kids[1]));
      iterable = std::move(v);
    }
    PYEXPR_TRY(items, At(internal::Iterate(iterable), c.kids[1]->offset));
    for (const Value& item : items) {
      PYEXPR_TRY(step, At(internal::CountStep(), c.offset));
      (void)step;
      PYEXPR_TRY(bound, At(Bind(*c.kids[0], item), c.kids[0]->offset));
      (void)bound;
      PYEXPR_TRY(more, Clauses(n, i + 1, nullptr, emit));
      if (!more) return false;
    }
    return true;
  }

  // Assigns v to a comprehension's target (a declared name, or a tuple or
  // list of targets with at most one starred).
  Result<bool> Bind(const Node& target, const Value& v) {
    if (target.type == Node::Type::kName) {
      std::optional<Value>* slot = frame_ ? frame_->Find(target.name) : nullptr;
      if (!slot) return Error{Error::Kind::kSyntax, "assignment to an undeclared name", target.offset};
      *slot = v;
      return true;
    }
    auto unpacked = internal::Iterate(v);
    if (!unpacked.ok())
      return Error{Error::Kind::kType, fmt::format("cannot unpack non-iterable {} object", TypeName(v)), target.offset};
    const std::vector<Value>& items = *unpacked;
    const auto& kids = target.kids;
    size_t star = kids.size();
    for (size_t k = 0; k < kids.size(); ++k)
      if (kids[k]->type == Node::Type::kStarred) star = k;
    if (star == kids.size()) {
      if (items.size() > kids.size())
        return Error{Error::Kind::kValue, fmt::format("too many values to unpack (expected {})", kids.size()),
                     target.offset};
      if (items.size() < kids.size())
        return Error{Error::Kind::kValue,
                     fmt::format("not enough values to unpack (expected {}, got {})", kids.size(), items.size()),
                     target.offset};
      for (size_t k = 0; k < kids.size(); ++k) {
        PYEXPR_TRY(ok, Bind(*kids[k], items[k]));
        (void)ok;
      }
      return true;
    }
    size_t after = kids.size() - star - 1;
    if (items.size() < kids.size() - 1)
      return Error{Error::Kind::kValue,
                   fmt::format("not enough values to unpack (expected at least {}, got {})", kids.size() - 1,
                               items.size()),
                   target.offset};
    for (size_t k = 0; k < star; ++k) {
      PYEXPR_TRY(ok, Bind(*kids[k], items[k]));
      (void)ok;
    }
    size_t rest_end = items.size() - after;
    PYEXPR_TRY(ok, Bind(*kids[star]->kids[0], Value::List(std::vector<Value>(items.begin() + static_cast<ptrdiff_t>(star),
                                                                            items.begin() + static_cast<ptrdiff_t>(rest_end)))));
    (void)ok;
    for (size_t k = 0; k < after; ++k) {
      PYEXPR_TRY(ok2, Bind(*kids[star + 1 + k], items[rest_end + k]));
      (void)ok2;
    }
    return true;
  }

  Result<Value> MakeLambda(const Node& n) {
    auto code = std::make_shared<LambdaCode>();
    code->names = n.ops;
    code->kinds = n.arg_names;
    code->body = n.body;
    std::vector<std::optional<Value>> defaults;
    for (const auto& d : n.kids) {
      if (!d) {
        defaults.emplace_back();
        continue;
      }
      PYEXPR_TRY(v, Eval(*d));
      defaults.emplace_back(std::move(v));
    }
    return Value::Function(
        "<lambda>", LambdaFunction{std::move(code),
                                   std::make_shared<const std::vector<std::optional<Value>>>(std::move(defaults)),
                                   frame_});
  }

  static bool IsBuiltin(const Value& callee, std::string_view name) {
    const Value* python = StandardGlobals().Find("python");
    const Value* f = python ? python->names().Find(name) : nullptr;
    return f && callee.IsFunction() && f->identity() == callee.identity();
  }

  Result<Value> CallNode(const Node& n) {
    PYEXPR_TRY(callee, Eval(*n.kids[0]));
    // any() and all() of a generator expression stop at the first item that
    // decides, as Python's lazy generator does
    if (n.kids.size() == 2 && n.arg_names[0].empty() && n.kids[1]->type == Node::Type::kGenExp &&
        (IsBuiltin(callee, "any") || IsBuiltin(callee, "all"))) {
      const Node& gen = *n.kids[1];
      bool is_any = IsBuiltin(callee, "any");
      bool decided = false;
      PYEXPR_TRY(done, RunComprehension(gen, 1, [&]() -> Result<bool> {
        PYEXPR_TRY(v, Eval(*gen.kids[0]));
        if (Truthy(v) == is_any) decided = true;
        return !decided;
      }));
      (void)done;
      return Value::Bool(is_any ? decided : !decided);
    }
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
  FramePtr frame_;
};

std::string QuotedList(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += names.size() == 2 ? " and " : (i + 1 == names.size() ? ", and " : ", ");
    out += "'" + names[i] + "'";
  }
  return out;
}

// Python's argument binding for a lambda's parameters, into frame.
Result<bool> BindArguments(const LambdaCode& code, const std::vector<std::optional<Value>>& defaults,
                           internal::Positional positional, internal::Keywords keywords, Frame& frame) {
  const auto& names = code.names;
  const auto& kinds = code.kinds;
  std::vector<std::optional<Value>> bound(names.size());
  std::vector<size_t> positional_params;
  size_t var_args = names.size(), var_keywords = names.size();
  for (size_t i = 0; i < names.size(); ++i) {
    if (kinds[i] == "" || kinds[i] == "/") positional_params.push_back(i);
    if (kinds[i] == "*") var_args = i;
    if (kinds[i] == "**") var_keywords = i;
  }
  std::vector<Value> extra;
  for (size_t k = 0; k < positional.size(); ++k) {
    if (k < positional_params.size()) {
      bound[positional_params[k]] = positional[k];
    } else if (var_args < names.size()) {
      extra.push_back(positional[k]);
    } else {
      size_t required = 0;
      for (size_t i : positional_params) required += !defaults[i];
      size_t most = positional_params.size();
      std::string takes = required == most ? fmt::format("{} positional argument{}", most, most == 1 ? "" : "s")
                                           : fmt::format("from {} to {} positional arguments", required, most);
      return Fail(Error::Kind::kType, fmt::format("<lambda>() takes {} but {} {} given", takes, positional.size(),
                                                  positional.size() == 1 ? "was" : "were"));
    }
  }
  if (var_args < names.size()) bound[var_args] = Value::Tuple(std::move(extra));
  std::vector<Value::Item> extra_keywords;
  std::vector<std::string> positional_only_as_keyword;
  for (const auto& [key, value] : keywords) {
    size_t i = 0;
    while (i < names.size() && !(names[i] == key && (kinds[i] == "" || kinds[i] == "kw"))) ++i;
    if (i < names.size()) {
      if (bound[i]) return Fail(Error::Kind::kType, fmt::format("<lambda>() got multiple values for argument '{}'", key));
      bound[i] = value;
      continue;
    }
    if (var_keywords < names.size()) {
      extra_keywords.emplace_back(Value::Str(key), value);
      continue;
    }
    bool positional_only = false;
    for (size_t j = 0; j < names.size(); ++j) positional_only = positional_only || (names[j] == key && kinds[j] == "/");
    if (positional_only) {
      positional_only_as_keyword.push_back(key);
      continue;
    }
    return Fail(Error::Kind::kType, fmt::format("<lambda>() got an unexpected keyword argument '{}'", key));
  }
  if (!positional_only_as_keyword.empty()) {
    std::string list;
    for (const auto& k : positional_only_as_keyword) list += (list.empty() ? "'" : ", '") + k + "'";
    return Fail(Error::Kind::kType,
                fmt::format("<lambda>() got some positional-only arguments passed as keyword arguments: {}", list));
  }
  if (var_keywords < names.size()) bound[var_keywords] = Value::Dict(std::move(extra_keywords));
  std::vector<std::string> missing, missing_keyword_only;
  for (size_t i = 0; i < names.size(); ++i) {
    if (bound[i]) continue;
    if (defaults[i]) {
      bound[i] = defaults[i];
    } else {
      (kinds[i] == "kw" ? missing_keyword_only : missing).push_back(names[i]);
    }
  }
  if (!missing.empty())
    return Fail(Error::Kind::kType, fmt::format("<lambda>() missing {} required positional argument{}: {}",
                                                missing.size(), missing.size() == 1 ? "" : "s", QuotedList(missing)));
  if (!missing_keyword_only.empty())
    return Fail(Error::Kind::kType,
                fmt::format("<lambda>() missing {} required keyword-only argument{}: {}", missing_keyword_only.size(),
                            missing_keyword_only.size() == 1 ? "" : "s", QuotedList(missing_keyword_only)));
  for (size_t i = 0; i < names.size(); ++i) frame.vars.emplace_back(names[i], std::move(bound[i]));
  return true;
}

Result<Value> CallLambda(const LambdaCode& code, const std::vector<std::optional<Value>>& defaults,
                         const FramePtr& closure, internal::Positional positional, internal::Keywords keywords) {
  PYEXPR_TRY(step, internal::CountStep());
  (void)step;
  auto frame = std::make_shared<Frame>();
  frame->parent = closure;
  PYEXPR_TRY(ok, BindArguments(code, defaults, positional, keywords, *frame));
  (void)ok;
  static EmptyScope no_names;
  Scope& scope = current_scope ? *current_scope : no_names;
  return Evaluator(scope, internal::CurrentLimits(), std::move(frame)).Eval(*code.body);
}

}  // namespace

struct ParsedExpression {
  NodePtr tree;
};

Result<std::shared_ptr<const ParsedExpression>> ParseExpression(std::string_view expression,
                                                                const Limits& limits) {
  internal::LimitsScope limits_scope(limits);
  size_t first = expression.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) {
    return Error{Error::Kind::kSyntax, "empty expression", expression.size()};
  }
  auto tree = Parse(expression, limits.max_depth);
  if (!tree.ok()) return std::move(tree).error();
  auto parsed = std::make_shared<ParsedExpression>();
  parsed->tree = std::move(*tree);
  return std::shared_ptr<const ParsedExpression>(std::move(parsed));
}

Result<Value> Evaluate(const ParsedExpression& parsed, Scope& scope, const Limits& limits) {
  internal::LimitsScope limits_scope(limits);
  Scope* saved_scope = current_scope;
  int saved_depth = current_depth;
  const char* saved_stack_start = stack_start;
  const char here = 0;
  if (!stack_start) stack_start = &here;  // nested evaluations share the outermost budget
  current_scope = &scope;
  current_depth = 0;
  auto result = Evaluator(scope, limits).Eval(*parsed.tree);
  current_scope = saved_scope;
  current_depth = saved_depth;
  stack_start = saved_stack_start;
  return result;
}

Result<Value> Evaluate(std::string_view expression, Scope& scope, const Limits& limits) {
  auto parsed = ParseExpression(expression, limits);
  if (!parsed.ok()) return std::move(parsed).error();
  return Evaluate(**parsed, scope, limits);
}

}  // namespace mdlc::pyexpr
