// pyexpr values: Python's str()/repr() of numbers and containers, equality,
// ordering, and the number texts of int()/float() (expected values checked
// against Python 3.11).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "frontend/pyexpr/number_text.h"
#include "frontend/pyexpr/value.h"

namespace mdlc::pyexpr {
namespace {

TEST(PyExprFloatRepr, ShortestRoundTripLikePython) {
  EXPECT_EQ(FloatRepr(0.1 + 0.2), "0.30000000000000004");
  EXPECT_EQ(FloatRepr(116.0), "116.0");
  EXPECT_EQ(FloatRepr(-0.7853981633974483), "-0.7853981633974483");
  EXPECT_EQ(FloatRepr(2.8900000000000004e-08), "2.8900000000000004e-08");
  EXPECT_EQ(FloatRepr(2.89e-08), "2.89e-08");
  EXPECT_EQ(FloatRepr(1e16), "1e+16");
  EXPECT_EQ(FloatRepr(1e15), "1000000000000000.0");
  EXPECT_EQ(FloatRepr(1.5e16), "1.5e+16");
  EXPECT_EQ(FloatRepr(1e-5), "1e-05");
  EXPECT_EQ(FloatRepr(0.0001), "0.0001");
  EXPECT_EQ(FloatRepr(1e100), "1e+100");
  EXPECT_EQ(FloatRepr(-0.0), "-0.0");
  EXPECT_EQ(FloatRepr(0.0), "0.0");
  EXPECT_EQ(FloatRepr(5e-324), "5e-324");
  EXPECT_EQ(FloatRepr(1.0 / 3), "0.3333333333333333");
  EXPECT_EQ(FloatRepr(9.223372036854776e18), "9.223372036854776e+18");
  EXPECT_EQ(FloatRepr(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(FloatRepr(-std::numeric_limits<double>::infinity()), "-inf");
  EXPECT_EQ(FloatRepr(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(PyExprStr, ScalarsAndContainers) {
  EXPECT_EQ(Str(Value()), "None");
  EXPECT_EQ(Str(Value::Bool(true)), "True");
  EXPECT_EQ(Str(Value::Bool(false)), "False");
  EXPECT_EQ(Str(Value::Int(-42)), "-42");
  EXPECT_EQ(Str(Value::Int(123456789012345678)), "123456789012345678");
  EXPECT_EQ(Str(Value::Float(1.0)), "1.0");
  EXPECT_EQ(Str(Value::Str("a'b")), "a'b");
  EXPECT_EQ(Str(Value::List({Value::Str("a"), Value::Int(1)})), "['a', 1]");
  EXPECT_EQ(Str(Value::List({Value::Float(0.1), Value::Str("x"), Value::Float(-0.0)})), "[0.1, 'x', -0.0]");
  EXPECT_EQ(Str(Value::Tuple({Value::Int(1)})), "(1,)");
  EXPECT_EQ(Str(Value::Tuple({})), "()");
  EXPECT_EQ(Str(Value::Dict({{Value::Str("k"), Value::Float(0.5)}})), "{'k': 0.5}");
  EXPECT_EQ(Str(Value::Dict({{Value::Int(1), Value::Int(2)}, {Value::Str("a"), Value::List({Value::Int(1), Value::Float(2.0)})}})),
            "{1: 2, 'a': [1, 2.0]}");
  EXPECT_EQ(Str(Value::List({Value::Int(1), Value::List({Value::Int(2), Value::Tuple({Value::Int(3)})}),
                             Value::Dict({{Value::Str("a"), Value()}})})),
            "[1, [2, (3,)], {'a': None}]");
}

TEST(PyExprRepr, StringQuotingAndEscapes) {
  EXPECT_EQ(Repr(Value::Str("a")), "'a'");
  EXPECT_EQ(Repr(Value::Str("it's")), "\"it's\"");
  EXPECT_EQ(Repr(Value::Str("say \"hi\"")), "'say \"hi\"'");
  EXPECT_EQ(Repr(Value::Str("both ' and \"")), "'both \\' and \"'");
  EXPECT_EQ(Repr(Value::Str("a\tb\n")), "'a\\tb\\n'");
  EXPECT_EQ(Repr(Value::Str("\\")), "'\\\\'");
  EXPECT_EQ(Repr(Value::Str("\x01")), "'\\x01'");
  EXPECT_EQ(Repr(Value::Str("Aé")), "'Aé'");
}

TEST(PyExprDict, FirstPlaceLastValueAndLookup) {
  Value d = Value::Dict({{Value::Str("a"), Value::Int(1)}, {Value::Str("b"), Value::Int(2)}, {Value::Str("a"), Value::Int(3)}});
  EXPECT_EQ(Str(d), "{'a': 3, 'b': 2}");
  ASSERT_NE(d.DictFind("b"), nullptr);
  EXPECT_EQ(d.DictFind("b")->AsInt(), 2);
  EXPECT_EQ(d.DictFind("z"), nullptr);
  // 1, 1.0 and True are one key
  Value n = Value::Dict({{Value::Int(1), Value::Str("int")}});
  ASSERT_NE(n.DictFind(Value::Float(1.0)), nullptr);
  ASSERT_NE(n.DictFind(Value::Bool(true)), nullptr);
  EXPECT_FALSE(d.attribute_access());
  EXPECT_TRUE(d.WithAttributeAccess(true).attribute_access());
}

TEST(PyExprEquality, NumbersAcrossKindsAndNothingElse) {
  EXPECT_TRUE(Equal(Value::Int(1), Value::Float(1.0)));
  EXPECT_TRUE(Equal(Value::Bool(true), Value::Int(1)));
  EXPECT_FALSE(Equal(Value::Int(1), Value::Str("1")));
  EXPECT_FALSE(Equal(Value::Float(std::nan("")), Value::Float(std::nan(""))));
  // exact comparison of a big int with a float: 2**53 + 1 != 2.0**53
  EXPECT_FALSE(Equal(Value::Int((int64_t{1} << 53) + 1), Value::Float(9007199254740992.0)));
  EXPECT_TRUE(Equal(Value::Int(int64_t{1} << 53), Value::Float(9007199254740992.0)));
  EXPECT_TRUE(Equal(Value::Tuple({Value::Int(1), Value::Int(2)}), Value::Tuple({Value::Int(1), Value::Float(2.0)})));
  EXPECT_FALSE(Equal(Value::Tuple({}), Value::List({})));
  EXPECT_TRUE(Equal(Value(), Value()));
}

TEST(PyExprCompare, OrderingAndIncomparableKinds) {
  EXPECT_TRUE(*Compare(Value::Str("a"), CompareOp::kLt, Value::Str("b")));
  EXPECT_TRUE(*Compare(Value::List({Value::Int(1), Value::Int(2)}), CompareOp::kLt,
                       Value::List({Value::Int(1), Value::Int(3)})));
  EXPECT_TRUE(*Compare(Value::Int(2), CompareOp::kGe, Value::Float(1.5)));
  auto r = Compare(Value::Int(1), CompareOp::kLt, Value::Str("1"));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, Error::Kind::kType);
}

TEST(PyExprTruthy, PythonBool) {
  EXPECT_FALSE(Truthy(Value()));
  EXPECT_FALSE(Truthy(Value::Int(0)));
  EXPECT_FALSE(Truthy(Value::Float(0.0)));
  EXPECT_FALSE(Truthy(Value::Str("")));
  EXPECT_FALSE(Truthy(Value::List({})));
  EXPECT_FALSE(Truthy(Value::Dict({})));
  EXPECT_TRUE(Truthy(Value::Str("0")));
  EXPECT_TRUE(Truthy(Value::Float(std::nan(""))));
}

TEST(PyExprNumberText, IntLikePython) {
  EXPECT_EQ(ParsePythonInt("12"), 12);
  EXPECT_EQ(ParsePythonInt(" -12 "), -12);
  EXPECT_EQ(ParsePythonInt("+7"), 7);
  EXPECT_EQ(ParsePythonInt("1_000"), 1000);
  EXPECT_EQ(ParsePythonInt("007"), 7);
  EXPECT_EQ(ParsePythonInt("-9223372036854775808"), std::numeric_limits<int64_t>::min());
  EXPECT_FALSE(ParsePythonInt("9223372036854775808"));
  EXPECT_FALSE(ParsePythonInt("1.5"));
  EXPECT_FALSE(ParsePythonInt("0x1f"));
  EXPECT_FALSE(ParsePythonInt("1__0"));
  EXPECT_FALSE(ParsePythonInt("_1"));
  EXPECT_FALSE(ParsePythonInt(""));
  EXPECT_FALSE(ParsePythonInt("1 2"));
}

TEST(PyExprNumberText, FloatLikePython) {
  EXPECT_EQ(ParsePythonFloat("1.5"), 1.5);
  EXPECT_EQ(ParsePythonFloat(" 1.5 "), 1.5);
  EXPECT_EQ(ParsePythonFloat("1e-3"), 0.001);
  EXPECT_EQ(ParsePythonFloat(".5"), 0.5);
  EXPECT_EQ(ParsePythonFloat("5."), 5.0);
  EXPECT_EQ(ParsePythonFloat("-2"), -2.0);
  EXPECT_EQ(ParsePythonFloat("1_0.5e1_0"), 105000000000.0);
  EXPECT_EQ(ParsePythonFloat("1e400"), std::numeric_limits<double>::infinity());
  EXPECT_EQ(ParsePythonFloat("-Infinity"), -std::numeric_limits<double>::infinity());
  EXPECT_EQ(ParsePythonFloat("inf"), std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(*ParsePythonFloat("NaN")));
  EXPECT_FALSE(ParsePythonFloat("abc"));
  EXPECT_FALSE(ParsePythonFloat("1e"));
  EXPECT_FALSE(ParsePythonFloat("."));
  EXPECT_FALSE(ParsePythonFloat("0x10"));
}

TEST(PyExprNumberText, FormatCodes) {
  EXPECT_EQ(FormatFloatFixed(3.14159, 2), "3.14");
  EXPECT_EQ(FormatFloatFixed(2.5, 0), "2");
  EXPECT_EQ(FormatFloatFixed(0.05, 1), "0.1");
  EXPECT_EQ(FormatFloatExp(12345.678, 6), "1.234568e+04");
  EXPECT_EQ(FormatFloatGeneral(0.0001234, 6), "0.0001234");
  EXPECT_EQ(FormatFloatGeneral(1234567.0, 6), "1.23457e+06");
}

}  // namespace
}  // namespace mdlc::pyexpr
