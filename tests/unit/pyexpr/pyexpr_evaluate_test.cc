// pyexpr's evaluator: literals, operators and precedence, short-circuits,
// indexing, attribute access, scope lookups, errors with offsets, limits
// (expected values checked against Python 3.11).
#include <gtest/gtest.h>

#include <limits>
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
  EXPECT_EQ(EvalRepr("123456789012345678901234"), "123456789012345678901234");
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
  EXPECT_EQ(EvalRepr("float(2**1024)"), "ERR OverflowError");
  EXPECT_EQ(EvalRepr("2**2000 + 1.0"), "ERR OverflowError");
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
  EXPECT_EQ(EvalError("{v for v in l}").kind, Error::Kind::kUnsupported);  // sets
  EXPECT_EQ(EvalError("[x for x.a in l]").kind, Error::Kind::kUnsupported);
  EXPECT_EQ(EvalError("[__v for __v in l]").kind, Error::Kind::kUnsupported);
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

// Comprehensions and generator expressions (expected values from Python 3.11).
TEST(PyExprEvaluate, Comprehensions) {
  EXPECT_EQ(EvalRepr("[i * 2 for i in python.range(3)]"), "[0, 2, 4]");
  EXPECT_EQ(EvalRepr("dict(a=dict(b=1))['a']['b']"), "1");
  EXPECT_EQ(EvalRepr("[x*y for x in range(3) for y in range(3) if x != y]"), "[0, 0, 0, 2, 0, 2]");
  EXPECT_EQ(EvalRepr("[x for x in range(10) if x % 2 if x > 3]"), "[5, 7, 9]");
  EXPECT_EQ(EvalRepr("[(k, v) for k, v in d.items()]"), "[('k', 0.5), ('n', {'m': 1})]");
  EXPECT_EQ(EvalRepr("[k for k in d]"), "['k', 'n']");
  EXPECT_EQ(EvalRepr("[y for x in l for y in range(x)]"), "[0, 1, 2, 0, 0, 1]");
  EXPECT_EQ(EvalRepr("[[j for j in range(i)] for i in range(4)]"), "[[], [0], [0, 1], [0, 1, 2]]");
  EXPECT_EQ(EvalRepr("[x if x > 1 else -x for x in l]"), "[3, -1, 2]");
  EXPECT_EQ(EvalRepr("[x + y for x in 'ab' for y in 'cd']"), "['ac', 'ad', 'bc', 'bd']");
  EXPECT_EQ(EvalRepr("[(i, c) for i, c in python.enumerate('ab')]"), "[(0, 'a'), (1, 'b')]");
  EXPECT_EQ(EvalRepr("[i for i in range(3) for i in range(i)]"), "[0, 0, 1]");
  EXPECT_EQ(EvalRepr("[x for x in y.n]"), "['m']");
  EXPECT_EQ(EvalRepr("[() for () in [()]]"), "[()]");
  // dict comprehensions; a repeated key keeps its first place and last value
  EXPECT_EQ(EvalRepr("{k: v for k, v in python.zip('abc', range(3))}"), "{'a': 0, 'b': 1, 'c': 2}");
  EXPECT_EQ(EvalRepr("{k: v for k, v in [(1, 2), (1, 3)]}"), "{1: 3}");
  EXPECT_EQ(EvalRepr("{k: [v for v in range(k)] for k in range(3)}"), "{0: [], 1: [0], 2: [0, 1]}");
  EXPECT_EQ(EvalRepr("{[k]: v for k, v in [(1, 2)]}"), "ERR TypeError");
  // unpacking targets
  EXPECT_EQ(EvalRepr("[a for a, *b in [(1, 2, 3), (4,)]]"), "[1, 4]");
  EXPECT_EQ(EvalRepr("[b for a, *b in [(1, 2, 3), (4,)]]"), "[[2, 3], []]");
  EXPECT_EQ(EvalRepr("[c for a, *b, c in [(1, 2, 3, 4)]]"), "[4]");
  EXPECT_EQ(EvalRepr("[(a, b, c) for a, (b, c) in [(1, (2, 3))]]"), "[(1, 2, 3)]");
  EXPECT_EQ(EvalRepr("[(a, b) for [a, b] in ['xy', 'zw']]"), "[('x', 'y'), ('z', 'w')]");
  EXPECT_EQ(EvalRepr("[a for a, b in [(1, 2, 3)]]"), "ERR ValueError");
  EXPECT_EQ(EvalRepr("[a for a, b, c in [(1, 2)]]"), "ERR ValueError");
  EXPECT_EQ(EvalRepr("[a for a, *b, c in [(1,)]]"), "ERR ValueError");
  EXPECT_EQ(EvalRepr("[a for a, b in [1]]"), "ERR TypeError");
  EXPECT_EQ(EvalRepr("[x for x in 5]"), "ERR TypeError");
  // the variables are local: they shadow the scope's names and do not leak;
  // the first iterable is evaluated outside
  EXPECT_EQ(EvalRepr("([x for x in range(3)], x)"), "([0, 1, 2], 5)");
  EXPECT_EQ(EvalRepr("[x for x in [x, x + 1]]"), "[5, 6]");
  EXPECT_EQ(EvalRepr("[x for x in range(3)][-1] + x"), "7");
  EXPECT_EQ(EvalRepr("[y for x in l if y for y in l]"), "ERR NameError");  // UnboundLocalError
  // generator expressions (as lists)
  EXPECT_EQ(EvalRepr("python.sum(x*x for x in l)"), "14");
  EXPECT_EQ(EvalRepr("python.sum(x for x in range(101))"), "5050");
  EXPECT_EQ(EvalRepr("python.sum((x for x in l), 10)"), "16");
  EXPECT_EQ(EvalRepr("python.any(x > 2 for x in l)"), "True");
  EXPECT_EQ(EvalRepr("python.all(x > 2 for x in l)"), "False");
  EXPECT_EQ(EvalRepr("max(x % 3 for x in l)"), "2");
  EXPECT_EQ(EvalRepr("min(-x for x in l)"), "-3");
  EXPECT_EQ(EvalRepr("python.tuple(x for x in l)"), "(3, 1, 2)");
  EXPECT_EQ(EvalRepr("list(x for x in 'abc')"), "['a', 'b', 'c']");
  EXPECT_EQ(EvalRepr("','.join(str(x) for x in l)"), "'3,1,2'");
  EXPECT_EQ(EvalRepr("sorted(x for x in l)"), "[1, 2, 3]");
  EXPECT_EQ(EvalRepr("(x for x in l)"), "[3, 1, 2]");
  // any() and all() stop where Python's lazy generator would
  EXPECT_EQ(EvalRepr("python.any(1/x for x in [1, 0])"), "True");
  EXPECT_EQ(EvalRepr("python.all(1/x - 1 for x in [1, 0])"), "False");
  EXPECT_EQ(EvalRepr("python.all(1/x for x in [1, 0])"), "ERR ZeroDivisionError");
}

TEST(PyExprEvaluate, ComprehensionSyntax) {
  for (const char* bad : {"[x for x in l, 1]", "python.sum(x for x in l, )", "python.sum(1, x for x in l)",
                          "len(k=x for x in l)", "(x, y for x in l)", "[*x for x in l]", "{**d for x in l}",
                          "[x for x in l if x else 1]", "[x for *x in l]", "[x for a, *b, *c in l]",
                          "[x for x in l for]", "[x for x in]", "[x for in l]", "[x for x in l if]",
                          "[x for x in l if lambda: 1]", "[x async for x in l]", "[x for x in l] for x in l"}) {
    EXPECT_EQ(EvalError(bad).kind, Error::Kind::kSyntax) << bad;
  }
  EXPECT_EQ(EvalError("python.sum(1, x for x in l)").offset, 14u);
}

TEST(PyExprEvaluate, Lambda) {
  EXPECT_EQ(EvalRepr("(lambda: 1)()"), "1");
  EXPECT_EQ(EvalRepr("lambda a: a"), "<function <lambda>>");
  EXPECT_EQ(EvalRepr("(lambda a, b=1: a + b)(2)"), "3");
  EXPECT_EQ(EvalRepr("(lambda a, b=1: a + b)(2, 3)"), "5");
  EXPECT_EQ(EvalRepr("(lambda a, b=1: a + b)(b=5, a=2)"), "7");
  EXPECT_EQ(EvalRepr("(lambda *a: a)(1, 2)"), "(1, 2)");
  EXPECT_EQ(EvalRepr("(lambda **k: k)(a=1, b=2)"), "{'a': 1, 'b': 2}");
  EXPECT_EQ(EvalRepr("(lambda a, *r, k=3, **kw: (a, r, k, kw))(1, 2, 3, k=4, z=5)"), "(1, (2, 3), 4, {'z': 5})");
  EXPECT_EQ(EvalRepr("(lambda a, /, b: a + b)(1, b=2)"), "3");
  EXPECT_EQ(EvalRepr("(lambda *, a=1: a)()"), "1");
  EXPECT_EQ(EvalRepr("(lambda a=x: a)()"), "5");
  EXPECT_EQ(EvalRepr("(lambda: lambda: 3)()()"), "3");
  EXPECT_EQ(EvalRepr("(lambda a: lambda b: a + b)(1)(2)"), "3");
  EXPECT_EQ(EvalRepr("(lambda a, b: a if a > b else b)(3, 4)"), "4");
  EXPECT_EQ(EvalRepr("(lambda x: x)(x) + x"), "10");
  EXPECT_EQ(EvalRepr("(lambda x: [x for x in range(x)])(3)"), "[0, 1, 2]");
  EXPECT_EQ(EvalRepr("(lambda n: [n * k for k in range(n)])(4)"), "[0, 4, 8, 12]");
  EXPECT_EQ(EvalRepr("(lambda f: f(f, 5))(lambda g, n: 1 if n == 0 else n * g(g, n - 1))"), "120");
  EXPECT_EQ(EvalRepr("[lambda: 1][0]()"), "1");
  // closures read the variable when called, as in Python
  EXPECT_EQ(EvalRepr("[f() for f in [lambda: i for i in range(3)]]"), "[2, 2, 2]");
  EXPECT_EQ(EvalRepr("[f() for f in [lambda i=i: i for i in range(3)]]"), "[0, 1, 2]");
  EXPECT_EQ(EvalRepr("[h() for x in [1] for h in [lambda: x]]"), "[1]");
  // with the builtins that take functions
  EXPECT_EQ(EvalRepr("list(map(lambda v: v * 2, l))"), "[6, 2, 4]");
  EXPECT_EQ(EvalRepr("list(map(lambda a, b: a + b, l, [10, 20, 30]))"), "[13, 21, 32]");
  EXPECT_EQ(EvalRepr("list(python.filter(lambda v: v > 1, l))"), "[3, 2]");
  EXPECT_EQ(EvalRepr("sorted(l, key=lambda v: -v)"), "[3, 2, 1]");
  EXPECT_EQ(EvalRepr("sorted(['bb', 'a', 'ccc'], key=lambda s: len(s))"), "['a', 'bb', 'ccc']");
  EXPECT_EQ(EvalRepr("max(l, key=lambda v: (v - 2) ** 2)"), "3");
  EXPECT_EQ(EvalRepr("min(l, key=lambda v: python.abs(v - 2))"), "2");
  // argument errors
  for (const char* bad : {"(lambda a, /, b: a + b)(a=1, b=2)", "(lambda a, *, b: a + b)(1, 2)",
                          "(lambda a, *, b: a + b)(1)", "(lambda a, b: a)(1)", "(lambda a, b: a)(1, 2, 3)",
                          "(lambda: 0)(1)", "(lambda a: a)(1, a=2)", "(lambda a: a)(b=2)"}) {
    EXPECT_EQ(EvalError(bad).kind, Error::Kind::kType) << bad;
  }
  EXPECT_EQ(EvalError("(lambda a, b, c: a)(1)").message, "<lambda>() missing 2 required positional arguments: 'b' and 'c'");
  EXPECT_EQ(EvalError("(lambda a, b=2: a)(1, 2, 3)").message,
            "<lambda>() takes from 1 to 2 positional arguments but 3 were given");
  for (const char* bad : {"lambda a=1, b: 0", "lambda a, a: 0", "lambda *: 0", "lambda *, **k: 0", "1 + lambda: 2",
                          "lambda a, /, b, /: 1", "lambda /: 1", "lambda **k, a: 1", "lambda *a, *b: 1"}) {
    EXPECT_EQ(EvalError(bad).kind, Error::Kind::kSyntax) << bad;
  }
  // unbounded recursion is a depth error
  EXPECT_EQ(EvalError("(lambda f: f(f))(lambda f: f(f))").kind, Error::Kind::kLimit);
}

TEST(PyExprEvaluate, LambdaOutlivesItsEvaluation) {
  EvalTestScope scope;
  auto f = Evaluate("lambda a, k=x: [a * k + v for v in range(3)]", scope);
  ASSERT_TRUE(f.ok());
  std::vector<Value> args = {Value::Int(2)};
  auto r = f->function()(args, {});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(Repr(*r), "[10, 11, 12]");
  // called outside any evaluation, only the standard globals resolve
  auto g = Evaluate("lambda: x", scope);
  ASSERT_TRUE(g.ok());
  r = g->function()({}, {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, Error::Kind::kName);
}

TEST(PyExprEvaluate, ComprehensionLimits) {
  EXPECT_EQ(EvalError("[x for x in range(10**7)]").kind, Error::Kind::kLimit);
  Limits small;
  small.max_items = 10;
  EXPECT_EQ(EvalRepr("[x for x in range(10)]", small), "[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]");
  EXPECT_EQ(EvalRepr("[(x, y) for x in range(4) for y in range(3)]", small), "ERR LimitError");
  EXPECT_EQ(EvalRepr("{x: y for x in range(4) for y in range(3)}", small), "ERR LimitError");
  Limits few_steps;
  few_steps.max_steps = 100;
  EXPECT_EQ(EvalRepr("len([1 for x in range(10) for y in range(9)])", few_steps), "90");
  EXPECT_EQ(EvalRepr("[1 for x in range(10) for y in range(10) if 0]", few_steps), "ERR LimitError");
  EXPECT_EQ(EvalRepr("list(map(lambda v: v, range(101)))", few_steps), "ERR LimitError");
  few_steps.max_steps = 1000;
  EXPECT_EQ(EvalRepr("[[j for j in range(100)] for i in range(100)]", few_steps), "ERR LimitError");
}

TEST(PyExprEvaluate, BigInts) {
  // expected values from Python 3.11
  EXPECT_EQ(EvalRepr("2 ** 70"), "1180591620717411303424");
  EXPECT_EQ(EvalRepr("2**63"), "9223372036854775808");
  EXPECT_EQ(EvalRepr("-2**63 - 1"), "-9223372036854775809");
  EXPECT_EQ(EvalRepr("(-2)**63"), "-9223372036854775808");
  EXPECT_EQ(EvalRepr("9223372036854775807 + 1"), "9223372036854775808");
  EXPECT_EQ(EvalRepr("1 << 70"), "1180591620717411303424");
  EXPECT_EQ(EvalRepr("str(2**70)"), "'1180591620717411303424'");
  EXPECT_EQ(EvalRepr("123456789012345678901234567890 * 987654321098765432109876543210"), "121932631137021795226185032733622923332237463801111263526900");
  EXPECT_EQ(EvalRepr("-2**100 // 3"), "-422550200076076467165567735126");
  EXPECT_EQ(EvalRepr("2**100 % -7"), "-5");
  EXPECT_EQ(EvalRepr("(2**200 + 12345) % (2**70 + 1)"), "1152921504606859321");
  EXPECT_EQ(EvalRepr("-(2**200 + 12345) // (2**70 + 1)"), "-1361129467683753853852345508222465998849");
  EXPECT_EQ(EvalRepr("python.divmod(-2**80, 10**9)"), "(-1208925819614630, 825293824)");
  EXPECT_EQ(EvalRepr("python.abs(-2**70)"), "1180591620717411303424");
  EXPECT_EQ(EvalRepr("~(2**70)"), "-1180591620717411303425");
  EXPECT_EQ(EvalRepr("2**63 // -1"), "-9223372036854775808");
  EXPECT_EQ(EvalRepr("-9223372036854775808 // -1"), "9223372036854775808");
  EXPECT_EQ(EvalRepr("2**70 == 2.0**70"), "True");
  EXPECT_EQ(EvalRepr("2**70 + 1 == 2.0**70"), "False");
  EXPECT_EQ(EvalRepr("2**70 + 1 > 2.0**70"), "True");
  EXPECT_EQ(EvalRepr("2**1100 > 1e308"), "True");
  EXPECT_EQ(EvalRepr("-2**1100 < -1e308"), "True");
  EXPECT_EQ(EvalRepr("int(1e30)"), "1000000000000000019884624838656");
  EXPECT_EQ(EvalRepr("int(-1e30)"), "-1000000000000000019884624838656");
  EXPECT_EQ(EvalRepr("float(2**70)"), "1.1805916207174113e+21");
  EXPECT_EQ(EvalRepr("float(2**80 + 2**27)"), "1.2089258196146292e+24");
  EXPECT_EQ(EvalRepr("float(2**80 + 2**27 + 1)"), "1.2089258196146294e+24");
  EXPECT_EQ(EvalRepr("2**70 / 3"), "3.935305402391371e+20");
  EXPECT_EQ(EvalRepr("1 / 2**70"), "8.470329472543003e-22");
  EXPECT_EQ(EvalRepr("10**400 / 10**399"), "10.0");
  EXPECT_EQ(EvalRepr("(2**64+1) / 3"), "6.148914691236517e+18");
  EXPECT_EQ(EvalRepr("2**70 + 0.5"), "1.1805916207174113e+21");
  EXPECT_EQ(EvalRepr("{2**70: 1}[2.0**70]"), "1");
  EXPECT_EQ(EvalRepr("{2**70: 'a', 2**70: 'b'}"), "{1180591620717411303424: 'b'}");
  EXPECT_EQ(EvalRepr("int('123456789012345678901234567890')"), "123456789012345678901234567890");
  EXPECT_EQ(EvalRepr("int('-123456789012345678901234567890')"), "-123456789012345678901234567890");
  EXPECT_EQ(EvalRepr("int('f' * 30, 16)"), "1329227995784915872903807060280344575");
  EXPECT_EQ(EvalRepr("math.factorial(30)"), "265252859812191058636308480000000");
  EXPECT_EQ(EvalRepr("math.comb(100, 50)"), "100891344545564193334812497256");
  EXPECT_EQ(EvalRepr("math.perm(30, 20)"), "73096577329197271449600000");
  EXPECT_EQ(EvalRepr("math.perm(2**70, 2)"), "1393796574908163946344801800419805182820352");
  EXPECT_EQ(EvalRepr("math.gcd(2**100 * 3, -(2**70) * 9, 6)"), "6");
  EXPECT_EQ(EvalRepr("math.lcm(2**70, 3**40)"), "14353237968448109868972222216943775514624");
  EXPECT_EQ(EvalRepr("math.isqrt(10**50 - 1)"), "9999999999999999999999999");
  EXPECT_EQ(EvalRepr("math.isqrt(2**127)"), "13043817825332782212");
  EXPECT_EQ(EvalRepr("round(2**70 + 5, -1)"), "1180591620717411303430");
  EXPECT_EQ(EvalRepr("round(2**70 + 15, -1)"), "1180591620717411303440");
  EXPECT_EQ(EvalRepr("round(123456789012345678901250000000, -23)"), "123456800000000000000000000000");
  EXPECT_EQ(EvalRepr("round(1e30)"), "1000000000000000019884624838656");
  EXPECT_EQ(EvalRepr("-2**70 & 0xffff"), "0");
  EXPECT_EQ(EvalRepr("-2**70 | 5"), "-1180591620717411303419");
  EXPECT_EQ(EvalRepr("(2**70 - 1) & -2**68"), "885443715538058477568");
  EXPECT_EQ(EvalRepr("2**70 ^ 2**69"), "1770887431076116955136");
  EXPECT_EQ(EvalRepr("-(2**70 + 1) >> 3"), "-147573952589676412929");
  EXPECT_EQ(EvalRepr("-2**70 >> 100"), "-1");
  EXPECT_EQ(EvalRepr("-1 << 100"), "-1267650600228229401496703205376");
  EXPECT_EQ(EvalRepr("'%d' % 2**70"), "'1180591620717411303424'");
  EXPECT_EQ(EvalRepr("'{:#X}'.format(-2**70)"), "'-0X400000000000000000'");
  EXPECT_EQ(EvalRepr("'{:,}'.format(2**70)"), "'1,180,591,620,717,411,303,424'");
  EXPECT_EQ(EvalRepr("(-3) ** 41"), "-36472996377170786403");
  EXPECT_EQ(EvalRepr("(2**70) ** -1"), "8.470329472543003e-22");
  EXPECT_EQ(EvalRepr("(-1) ** (2**70 + 1)"), "-1");
  EXPECT_EQ(EvalRepr("2**70 - 2**70"), "0");
  EXPECT_EQ(EvalRepr("sorted([2**70, -2**70, 0, 2.0**71])"), "[-1180591620717411303424, 0, 1180591620717411303424, 2.3611832414348226e+21]");
  EXPECT_EQ(EvalRepr("0x10000000000000000"), "18446744073709551616");
  EXPECT_EQ(EvalRepr("math.floor(1e20)"), "100000000000000000000");
  EXPECT_EQ(EvalRepr("2**70 // 1.5"), "7.870610804782742e+20");
  EXPECT_EQ(EvalRepr("int('1' * 5000)"), "ERR ValueError");
  // a Value holds a small int inline and demotes results that fit
  EvalTestScope scope;
  auto v = Evaluate("2**70 - 2**70 + 7", scope);
  ASSERT_TRUE(v.ok());
  EXPECT_FALSE(v->IsBigInt());
  EXPECT_EQ(v->AsInt(), 7);
  v = Evaluate("-2**70", scope);
  ASSERT_TRUE(v.ok());
  EXPECT_TRUE(v->IsBigInt());
  EXPECT_EQ(v->AsInt(), std::numeric_limits<int64_t>::min());  // saturated
  EXPECT_EQ(Str(*v), "-1180591620717411303424");
}

TEST(PyExprEvaluate, BigIntLimits) {
  EXPECT_EQ(EvalRepr("10**10**6"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("2**(2**70)"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("math.factorial(10**6)"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("1 << 10**6"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("10**5000 * 10**5050"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("math.comb(60000, 30000)"), "ERR LimitError");
  EXPECT_EQ(EvalRepr("len(str(2**33000))"), "9934");
  EXPECT_EQ(EvalRepr("[1] * 2**70"), "ERR LimitError");
  Limits small;
  small.max_int_digits = 30;
  EXPECT_EQ(EvalRepr("10**25", small), "10000000000000000000000000");
  EXPECT_EQ(EvalRepr("10**60", small), "ERR LimitError");
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
