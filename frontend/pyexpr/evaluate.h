// evaluate.h - evaluating one xacro `${...}` expression.
//
// Evaluate() lexes, parses and interprets the Python expression subset
// xacro's expressions use (literals, operators with Python's precedence and
// semantics, calls, attribute access, indexing and slicing, list and dict
// comprehensions, generator expressions, lambda). It runs no Python and
// touches no file: names resolve through the comprehension and lambda
// variables in force, then the host's Scope, then StandardGlobals()
// (builtins.h). A generator expression is evaluated to a list at once
// (any() and all() still stop at the first item that decides). A lambda may
// outlive its evaluation; called later, it reads global names from the
// Scope of the evaluation running then, or only StandardGlobals() outside
// one. Nesting, result sizes and work are bounded by Limits. No exception
// leaves the API; every failure is an Error.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {

// Where bare names come from: the host's property tables. Lookup may run
// host code (lazy properties) and fail; its error is passed on unchanged.
class Scope {
 public:
  virtual ~Scope() = default;
  // nullopt: not defined here (the interpreter then tries StandardGlobals(),
  // then reports kName)
  virtual Result<std::optional<Value>> Lookup(std::string_view name) = 0;
};

// A Scope with no names (only StandardGlobals() resolve).
class EmptyScope : public Scope {
 public:
  Result<std::optional<Value>> Lookup(std::string_view) override { return std::optional<Value>(); }
};

struct Limits {
  int max_depth = 100;                  // nesting levels of the expression
  size_t max_string_bytes = 16 << 20;   // largest str a result may build
  size_t max_items = 1 << 20;           // largest list/tuple/dict/range
  size_t max_steps = 4 << 20;           // comprehension iterations and lambda calls
  size_t max_int_digits = 10000;        // largest int an operation may build (about; in bits * log10(2))
};

Result<Value> Evaluate(std::string_view expression, Scope& scope, const Limits& limits = {});

// An expression parsed once, to evaluate many times: xacro evaluates the
// same text at every call of the macro that holds it.
struct ParsedExpression;
Result<std::shared_ptr<const ParsedExpression>> ParseExpression(std::string_view expression,
                                                                const Limits& limits = {});
Result<Value> Evaluate(const ParsedExpression& parsed, Scope& scope, const Limits& limits = {});

}  // namespace mdlc::pyexpr
