// pyexpr's evaluator: literals, operators and precedence, short-circuits,
// indexing, attribute access, scope lookups, errors with offsets, limits
// (expected values checked against Python 3.11).
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "frontend/pyexpr/builtins.h"
#include "frontend/pyexpr/evaluate.h"

namespace mdlc::pyexpr {
namespace {

class EvalTestScope : public Scope {
 public:
  EvalTestScope() {
    names_["x"] = Value::Int(5);
    names_["f"] = Value::Float(2.5);
    names_["s"] = Value::Str("a,b;c d");
    names_["l"] = Value::List({Value::Int(3), Value::Int(1), Value::Int(2)});
    Value nested = Value::Dict({{Value::Str("m"), Value::Int(1)}});
    names_["d"] = Value::Dict({{Value::Str("k"), Value::Float(0.5)}, {Value::Str("n"), nested}});
    names_["y"] = Value::Dict({{Value::Str("k"), Value::Float(0.5)},
                               {Value::Str("n"), nested},
                               {Value::Str("v"), Value::List({nested})}},
                              /*attribute_access=*/true);
  }
  Result<std::optional<Value>> Lookup(std::string_view name) override {
    ++lookups;
    if (name == "broken") return Error{Error::Kind::kHost, "the property could not be evaluated", 0};
    auto it = names_.find(std::string(name));
    if (it == names_.end()) return std::optional<Value>();
    return std::optional<Value>(it->second);
  }
  int lookups = 0;

 private:
  std::map<std::string, Value> names_;
};

// repr() of the result, or "ERR <Python exception name>"
std::string EvalRepr(std::string_view expression, const Limits& limits = {}) {
  EvalTestScope scope;
  auto r = Evaluate(expression, scope, limits);
  if (!r.ok()) return "ERR " + std::string(ErrorKindName(r.error().kind));
  return Repr(*r);
}

Error EvalError(std::string_view expression, const Limits& limits = {}) {
  EvalTestScope scope;
  auto r = Evaluate(expression, scope, limits);
  EXPECT_FALSE(r.ok()) << expression;
  return r.ok() ? Error{} : r.error();
}

TEST(PyExprEvaluate, Literals) {
  EXPECT_EQ(EvalRepr("0x1f"), "31");
  EXPECT_EQ(EvalRepr("0o17"), "15");
  EXPECT_EQ(EvalRepr("0b101"), "5");
  EXPECT_EQ(EvalRepr("1_000_000"), "1000000");
  EXPECT_EQ(EvalRepr("1e3"), "1000.0");
  EXPECT_EQ(EvalRepr("1e-3"), "0.001");
  EXPECT_EQ(EvalRepr(".5"), "0.5");
  EXPECT_EQ(EvalRepr("5."), "5.0");
  EXPECT_EQ(EvalRepr("1e16"), "1e+16");
  EXPECT_EQ(EvalRepr("'a' 'b'"), "'ab'");
  EXPECT_EQ(EvalRepr("'\\x41\\u00e9'"), "'Aé'");
  EXPECT_EQ(EvalRepr("r'a\\nb'"), "'a\\\\nb'");
  EXPECT_EQ(EvalRepr("'it\\'s'"), "\"it's\"");
  EXPECT_EQ(EvalRepr("\"say \\\"hi\\\"\""), "'say \"hi\"'");
  EXPECT_EQ(EvalRepr("'a\\tb\\n'"), "'a\\tb\\n'");
  EXPECT_EQ(EvalRepr("True"), "True");
  EXPECT_EQ(EvalRepr("None"), "None");
  EXPECT_EQ(EvalRepr("(1,)"), "(1,)");
  EXPECT_EQ(EvalRepr("()"), "()");
  EXPECT_EQ(EvalRepr("[1, 'a', 2.0, None, True,]"), "[1, 'a', 2.0, None, True]");
  EXPECT_EQ(EvalRepr("{'k': 'v'}"), "{'k': 'v'}");
  EXPECT_EQ(EvalRepr("{1: 2, 'a': [1, 2.0]}"), "{1: 2, 'a': [1, 2.0]}");
  EXPECT_EQ(EvalRepr("1, 2"), "(1, 2)");
  EXPECT_EQ(EvalRepr("  x  "), "5");
  EXPECT_EQ(EvalRepr("007"), "ERR SyntaxError");
  EXPECT_EQ(EvalRepr("123456789012345678901234"), "ERR OverflowError");
}

TEST(PyExprEvaluate, Arithmetic) {
  EXPECT_EQ(EvalRepr("1+2"), "3");
  EXPECT_EQ(EvalRepr("0.1+0.2"), "0.30000000000000004");
  EXPECT_EQ(EvalRepr("2**62"), "4611686018427387904");
  EXPECT_EQ(EvalRepr("-2**2"), "-4");
  EXPECT_EQ(EvalRepr("(-2)**2"), "4");
  EXPECT_EQ(EvalRepr("2**-1"), "0.5");
  EXPECT_EQ(EvalRepr("2**3**2"), "512");
  EXPECT_EQ(EvalRepr("2**0.5"), "1.4142135623730951");
  EXPECT_EQ(EvalRepr("7//2"), "3");
  EXPECT_EQ(EvalRepr("-7//2"), "-4");
  EXPECT_EQ(EvalRepr("7%-3"), "-2");
  EXPECT_EQ(EvalRepr("-7%3"), "2");
  EXPECT_EQ(EvalRepr("7.5%-2"), "-0.5");
  EXPECT_EQ(EvalRepr("-7.5//2"), "-4.0");
  EXPECT_EQ(EvalRepr("1/3"), "0.3333333333333333");
  EXPECT_EQ(EvalRepr("4/2"), "2.0");
  EXPECT_EQ(EvalRepr("True+1"), "2");
  EXPECT_EQ(EvalRepr("str(True+1)"), "'2'");
  EXPECT_EQ(EvalRepr("True & False"), "False");
  EXPECT_EQ(EvalRepr("True | 1"), "1");
  EXPECT_EQ(EvalRepr("~True"), "-2");
  EXPECT_EQ(EvalRepr("2 << 3"), "16");
  EXPECT_EQ(EvalRepr("-8 >> 1"), "-4");
  EXPECT_EQ(EvalRepr("5 ^ 3"), "6");
  EXPECT_EQ(EvalRepr("6 & 3"), "2");
  EXPECT_EQ(EvalRepr("4 | 1"), "5");
  EXPECT_EQ(EvalRepr("1 + 2 * 3 - 4 / 2"), "5.0");
  EXPECT_EQ(EvalRepr("(1 + 2) * 3"), "9");
  EXPECT_EQ(EvalRepr("x * f"), "12.5");
  EXPECT_EQ(EvalRepr("1e308*10"), "inf");
  EXPECT_EQ(EvalRepr("-1e308*10"), "-inf");
  EXPECT_EQ(EvalRepr("5e-324"), "5e-324");
}

TEST(PyExprEvaluate, ArithmeticErrors) {
  EXPECT_EQ(EvalRepr("5/0"), "ERR ZeroDivisionError");
  EXPECT_EQ(EvalRepr("5.0//0"), "ERR ZeroDivisionError");
  EXPECT_EQ(EvalRepr("5%0"), "ERR ZeroDivisionError");
  EXPECT_EQ(EvalRepr("0**-1"), "ERR ZeroDivisionError");
  EXPECT_EQ(EvalRepr("2**63"), "ERR OverflowError");
  EXPECT_EQ(EvalRepr("1 << 70"), "ERR OverflowError");
  EXPECT_EQ(EvalRepr("9223372036854775807 + 1"), "ERR OverflowError");
  EXPECT_EQ(EvalRepr("(-8)**(1/3)"), "ERR UnsupportedError");
  EXPECT_EQ(EvalRepr("'a'+1"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("-'a'"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("1 @ 2"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("1 >> -1"), "ERR ValueError");
  Error e = EvalError("1 + 'a'");
  EXPECT_EQ(e.message, "unsupported operand types for +: 'int' and 'str'");
  EXPECT_EQ(e.offset, 2u);
}

TEST(PyExprEvaluate, Sequences) {
  EXPECT_EQ(EvalRepr("(1,2)+(3,)"), "(1, 2, 3)");
  EXPECT_EQ(EvalRepr("[1]+[2]"), "[1, 2]");
  EXPECT_EQ(EvalRepr("'a'*3"), "'aaa'");
  EXPECT_EQ(EvalRepr("3*'ab'"), "'ababab'");
  EXPECT_EQ(EvalRepr("[0]*3"), "[0, 0, 0]");
  EXPECT_EQ(EvalRepr("'a'*-1"), "''");
  EXPECT_EQ(EvalRepr("[*l, 4]"), "[3, 1, 2, 4]");
}

TEST(PyExprEvaluate, ComparisonsAndLogic) {
  EXPECT_EQ(EvalRepr("1 < 2 < 3"), "True");
  EXPECT_EQ(EvalRepr("1 < 3 < 2"), "False");
  EXPECT_EQ(EvalRepr("0 < x <= 5"), "True");
  EXPECT_EQ(EvalRepr("1 == 1.0"), "True");
  EXPECT_EQ(EvalRepr("1 == '1'"), "False");
  EXPECT_EQ(EvalRepr("1 != '1'"), "True");
  EXPECT_EQ(EvalRepr("1 < '1'"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("'a' < 'b'"), "True");
  EXPECT_EQ(EvalRepr("[1,2] < [1,3]"), "True");
  EXPECT_EQ(EvalRepr("(1,2) == (1,2)"), "True");
  EXPECT_EQ(EvalRepr("1 in [1,2]"), "True");
  EXPECT_EQ(EvalRepr("'b' in 'abc'"), "True");
  EXPECT_EQ(EvalRepr("'k' in d"), "True");
  EXPECT_EQ(EvalRepr("'z' not in d"), "True");
  EXPECT_EQ(EvalRepr("1 in 'abc'"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("None is None"), "True");
  EXPECT_EQ(EvalRepr("x is not None"), "True");
  EXPECT_EQ(EvalRepr("1 and 2"), "2");
  EXPECT_EQ(EvalRepr("0 or 'z'"), "'z'");
  EXPECT_EQ(EvalRepr("not 0"), "True");
  EXPECT_EQ(EvalRepr("not []"), "True");
  EXPECT_EQ(EvalRepr("not x == 5"), "False");
  EXPECT_EQ(EvalRepr("x > 1 and x < 10 or False"), "True");
  EXPECT_EQ(EvalRepr("2**53 + 1 == 2.0**53"), "False");
  EXPECT_EQ(EvalRepr("0.5 == 1/2"), "True");
}

TEST(PyExprEvaluate, ShortCircuitSkipsUndefinedNames) {
  EXPECT_EQ(EvalRepr("False and undefined_name"), "False");
  EXPECT_EQ(EvalRepr("True or undefined_name"), "True");
  EXPECT_EQ(EvalRepr("1 if True else undefined_name"), "1");
  EXPECT_EQ(EvalRepr("1 > 2 > undefined_name"), "False");
  EXPECT_EQ(EvalRepr("True and undefined_name"), "ERR NameError");
}

TEST(PyExprEvaluate, Conditional) {
  EXPECT_EQ(EvalRepr("3 if x > 4 else 4"), "3");
  EXPECT_EQ(EvalRepr("'a' if 0 else 'b' if 1 else 'c'"), "'b'");
  EXPECT_EQ(EvalRepr("(1 if x else 2) + 1"), "2");
}

TEST(PyExprEvaluate, IndexingAndSlicing) {
  EXPECT_EQ(EvalRepr("l[0]"), "3");
  EXPECT_EQ(EvalRepr("l[-1]"), "2");
  EXPECT_EQ(EvalRepr("l[3]"), "ERR IndexError");
  EXPECT_EQ(EvalRepr("l[::-1]"), "[2, 1, 3]");
  EXPECT_EQ(EvalRepr("l[1:]"), "[1, 2]");
  EXPECT_EQ(EvalRepr("l[:-1]"), "[3, 1]");
  EXPECT_EQ(EvalRepr("l[::2]"), "[3, 2]");
  EXPECT_EQ(EvalRepr("l[5:1:-1]"), "[2]");
  EXPECT_EQ(EvalRepr("l[::0]"), "ERR ValueError");
  EXPECT_EQ(EvalRepr("'hello'[1:3]"), "'el'");
  EXPECT_EQ(EvalRepr("'hello'[::-1]"), "'olleh'");
  EXPECT_EQ(EvalRepr("'hello'[-2]"), "'l'");
  EXPECT_EQ(EvalRepr("'héllo'[1:3]"), "'él'");
  EXPECT_EQ(EvalRepr("'é'[0]"), "'é'");
  EXPECT_EQ(EvalRepr("(1, 2)[5]"), "ERR IndexError");
  EXPECT_EQ(EvalRepr("[1, 2][1.0]"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("d['k']"), "0.5");
  EXPECT_EQ(EvalRepr("d['n']['m']"), "1");
  EXPECT_EQ(EvalRepr("d['zz']"), "ERR KeyError");
  EXPECT_EQ(EvalRepr("d[[1]]"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("x[0]"), "ERR TypeError");
}

TEST(PyExprEvaluate, AttributeAccess) {
  EXPECT_EQ(EvalRepr("y.k"), "0.5");
  EXPECT_EQ(EvalRepr("y.n.m"), "1");
  EXPECT_EQ(EvalRepr("y['n'].m"), "1");
  EXPECT_EQ(EvalRepr("y.v[0].m"), "1");
  EXPECT_EQ(EvalRepr("y.keys()"), "['k', 'n', 'v']");
  EXPECT_EQ(EvalRepr("str(y.n)"), "\"{'m': 1}\"");
  EXPECT_EQ(EvalRepr("d.k"), "ERR AttributeError");
  EXPECT_EQ(EvalRepr("math.pi"), "3.141592653589793");
  EXPECT_EQ(EvalRepr("x.y"), "ERR AttributeError");
  Error e = EvalError("y.zz");
  EXPECT_EQ(e.kind, Error::Kind::kAttribute);
  EXPECT_EQ(e.missing_name, "zz");
  EXPECT_EQ(e.offset, 2u);
  e = EvalError("y['zz']");
  EXPECT_EQ(e.kind, Error::Kind::kAttribute);  // xacro's YamlDictWrapper raises AttributeError for [] too
  EXPECT_EQ(e.missing_name, "zz");
  e = EvalError("d['zz']");
  EXPECT_EQ(e.kind, Error::Kind::kKey);
  EXPECT_EQ(e.missing_name, "zz");
  e = EvalError("math.nope");
  EXPECT_EQ(e.kind, Error::Kind::kName);
  EXPECT_EQ(e.missing_name, "nope");
  EXPECT_EQ(e.message, "name 'nope' is not defined");
}

TEST(PyExprEvaluate, DotifyWrapsDicts) {
  Value plain = Value::Dict({{Value::Str("a"), Value::Dict({{Value::Str("b"), Value::Int(2)}})}});
  Value dotted = Dotify(plain);
  EXPECT_TRUE(dotted.attribute_access());
  EXPECT_FALSE(plain.attribute_access());
  EXPECT_EQ(Str(dotted), "{'a': {'b': 2}}");
  EXPECT_EQ(Str(Dotify(Value::Int(1))), "1");
}

TEST(PyExprEvaluate, CallsWithKeywordsAndUnpacking) {
  EXPECT_EQ(EvalRepr("dict(a=1, b=2)"), "{'a': 1, 'b': 2}");
  EXPECT_EQ(EvalRepr("str(dict(a=1, b=0.5))"), "\"{'a': 1, 'b': 0.5}\"");
  EXPECT_EQ(EvalRepr("sorted(l, reverse=True)"), "[3, 2, 1]");
  EXPECT_EQ(EvalRepr("max(*l)"), "3");
  EXPECT_EQ(EvalRepr("dict(**{'a': 1}, b=2)"), "{'a': 1, 'b': 2}");
  EXPECT_EQ(EvalRepr("round(f, ndigits=None)"), "2");
  EXPECT_EQ(EvalRepr("len(5)"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("f(1)"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("dict(a=1, a=2)"), "ERR SyntaxError");
  EXPECT_EQ(EvalRepr("sorted(reverse=True, l)"), "ERR SyntaxError");
}

TEST(PyExprEvaluate, ScopeFirstThenStandardGlobals) {
  EvalTestScope scope;
  auto r = Evaluate("x + pi", scope);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(Str(*r), "8.141592653589793");
  EXPECT_EQ(scope.lookups, 2);  // x and pi both asked of the host first
}

TEST(PyExprEvaluate, UnknownNameReportsNameAndOffset) {
  Error e = EvalError("1 +  widht");
  EXPECT_EQ(e.kind, Error::Kind::kName);
  EXPECT_EQ(e.missing_name, "widht");
  EXPECT_EQ(e.offset, 5u);
  EXPECT_EQ(e.message, "name 'widht' is not defined");
}

TEST(PyExprEvaluate, HostLookupErrorsPassThrough) {
  Error e = EvalError("1 + broken");
  EXPECT_EQ(e.kind, Error::Kind::kHost);
  EXPECT_EQ(e.message, "the property could not be evaluated");
}

TEST(PyExprEvaluate, HostFunctionsAndOpaqueValues) {
  class FnScope : public Scope {
   public:
    Result<std::optional<Value>> Lookup(std::string_view name) override {
      if (name == "twice")
        return std::optional<Value>(Value::Function("twice", [](std::span<const Value> a, auto kw) -> Result<Value> {
          if (a.size() != 1) return Error{Error::Kind::kType, "twice() takes one argument"};
          return Value::Int(a[0].AsInt() * 2);
        }));
      if (name == "fail")
        return std::optional<Value>(Value::Function("fail", [](std::span<const Value>, auto) -> Result<Value> {
          Error e{Error::Kind::kHost, "stopped"};
          e.fatal = true;
          return e;
        }));
      if (name == "blob") return std::optional<Value>(Value::Opaque("blob", payload));
      return std::optional<Value>();
    }
    std::shared_ptr<const void> payload = std::make_shared<int>(1);
  } scope;
  EXPECT_EQ(Str(*Evaluate("twice(21)", scope)), "42");
  auto r = Evaluate("1 + fail()", scope);
  ASSERT_FALSE(r.ok());
  EXPECT_TRUE(r.error().fatal);
  EXPECT_EQ(r.error().offset, 4u);
  EXPECT_EQ(Str(*Evaluate("blob == blob", scope)), "True");
  EXPECT_FALSE(Evaluate("blob + 1", scope).ok());
}

TEST(PyExprEvaluate, SyntaxErrorsWithOffsets) {
  Error e = EvalError("1 +");
  EXPECT_EQ(e.kind, Error::Kind::kSyntax);
  EXPECT_EQ(e.offset, 3u);
  e = EvalError("(1, 2");
  EXPECT_EQ(e.kind, Error::Kind::kSyntax);
  EXPECT_EQ(e.offset, 0u);
  e = EvalError("1 + )");
  EXPECT_EQ(e.offset, 4u);
  e = EvalError("a b");
  EXPECT_EQ(e.offset, 2u);
  e = EvalError("x = 1");
  EXPECT_EQ(e.offset, 2u);
  e = EvalError("1 $ 2");
  EXPECT_EQ(e.offset, 2u);
  e = EvalError("'abc");
  EXPECT_EQ(e.kind, Error::Kind::kSyntax);
  e = EvalError("1 if 2");
  EXPECT_EQ(e.kind, Error::Kind::kSyntax);
  e = EvalError("");
  EXPECT_EQ(e.kind, Error::Kind::kSyntax);
}

TEST(PyExprEvaluate, UnsupportedConstructs) {
  EXPECT_EQ(EvalError("[v for v in l]").kind, Error::Kind::kUnsupported);
  EXPECT_EQ(EvalError("lambda: 1").kind, Error::Kind::kUnsupported);
  EXPECT_EQ(EvalError("f'{x}'").kind, Error::Kind::kUnsupported);
  EXPECT_EQ(EvalError("1j").kind, Error::Kind::kUnsupported);
  EXPECT_EQ(EvalError("{1, 2}").kind, Error::Kind::kUnsupported);
  Error e = EvalError("__import__('os')");
  EXPECT_EQ(e.kind, Error::Kind::kUnsupported);
  EXPECT_EQ(e.offset, 0u);
  e = EvalError("x.__class__");
  EXPECT_EQ(e.kind, Error::Kind::kUnsupported);
  EXPECT_EQ(e.offset, 2u);
  // like xacro, even in a branch that is never taken
  EXPECT_EQ(EvalError("False and __builtins__").kind, Error::Kind::kUnsupported);
}

TEST(PyExprEvaluate, DepthLimit) {
  std::string ok = std::string(40, '(') + "1" + std::string(40, ')');
  EXPECT_EQ(EvalRepr(ok), "1");
  std::string deep = std::string(300, '[') + std::string(300, ']');
  Error e = EvalError(deep);
  EXPECT_EQ(e.kind, Error::Kind::kLimit);
  EXPECT_NE(e.message.find("100"), std::string::npos);
  EXPECT_EQ(EvalError(std::string(200, '-') + "1").kind, Error::Kind::kLimit);
  EXPECT_EQ(EvalError(std::string(200, '(') + "1" + std::string(200, ')')).kind, Error::Kind::kLimit);
  Limits tight;
  tight.max_depth = 5;
  EXPECT_EQ(EvalError("((((((1))))))", tight).kind, Error::Kind::kLimit);
  // long flat chains are not nesting
  std::string chain = "1";
  for (int i = 0; i < 5000; ++i) chain += "+1";
  EXPECT_EQ(EvalRepr(chain), "5001");
}

TEST(PyExprEvaluate, SizeLimits) {
  Error e = EvalError("'a' * 10**9");
  EXPECT_EQ(e.kind, Error::Kind::kLimit);
  EXPECT_EQ(e.offset, 4u);
  EXPECT_EQ(EvalError("range(10**9)").kind, Error::Kind::kLimit);
  EXPECT_EQ(EvalError("[0] * 10**8").kind, Error::Kind::kLimit);
  EXPECT_EQ(EvalError("'{:1000000000}'.format(1)").kind, Error::Kind::kLimit);
  EXPECT_EQ(EvalError("'ab'.center(10**9)").kind, Error::Kind::kLimit);
  Limits small;
  small.max_string_bytes = 10;
  small.max_items = 10;
  EXPECT_EQ(EvalRepr("'a' * 10", small), "'aaaaaaaaaa'");
  EXPECT_EQ(EvalRepr("'a' * 11", small), "ERR LimitError");
  EXPECT_EQ(EvalRepr("range(11)", small), "ERR LimitError");
  EXPECT_EQ(EvalRepr("[1] * 5 + [2] * 6", small), "ERR LimitError");
}

}  // namespace
}  // namespace mdlc::pyexpr
