// LoadYaml: PyYAML safe_load's YAML 1.1 types, xacro's unit tags and the
// attribute access xacro gives loaded dicts (expected values checked with
// PyYAML 6 under Python 3.11).
#include <gtest/gtest.h>

#include <string>

#include "frontend/pyexpr/evaluate.h"
#include "frontend/pyexpr/yaml_values.h"

namespace mdlc::pyexpr {
namespace {

// repr() of the value of `v: <scalar>`
std::string YamlScalarRepr(const std::string& scalar) {
  auto r = LoadYaml("v: " + scalar + "\n");
  if (!r.ok()) return "ERR " + r.error().message;
  const Value* v = r->DictFind("v");
  return v ? Repr(*v) : "missing";
}

TEST(PyExprYaml, Yaml11ImplicitTypes) {
  EXPECT_EQ(YamlScalarRepr("yes"), "True");
  EXPECT_EQ(YamlScalarRepr("Yes"), "True");
  EXPECT_EQ(YamlScalarRepr("ON"), "True");
  EXPECT_EQ(YamlScalarRepr("off"), "False");
  EXPECT_EQ(YamlScalarRepr("No"), "False");
  EXPECT_EQ(YamlScalarRepr("oFF"), "'oFF'");
  EXPECT_EQ(YamlScalarRepr("y"), "'y'");
  EXPECT_EQ(YamlScalarRepr("true"), "True");
  EXPECT_EQ(YamlScalarRepr("1e-3"), "'1e-3'");
  EXPECT_EQ(YamlScalarRepr("1.0e-3"), "0.001");
  EXPECT_EQ(YamlScalarRepr("1.0e3"), "'1.0e3'");
  EXPECT_EQ(YamlScalarRepr("1.0E+3"), "1000.0");
  EXPECT_EQ(YamlScalarRepr("1.e-3"), "0.001");
  EXPECT_EQ(YamlScalarRepr(".5"), "0.5");
  EXPECT_EQ(YamlScalarRepr("-.5"), "'-.5'");
  EXPECT_EQ(YamlScalarRepr("0."), "0.0");
  EXPECT_EQ(YamlScalarRepr("1.5_0"), "1.5");
  EXPECT_EQ(YamlScalarRepr(".inf"), "inf");
  EXPECT_EQ(YamlScalarRepr("-.Inf"), "-inf");
  EXPECT_EQ(YamlScalarRepr(".NaN"), "nan");
  EXPECT_EQ(YamlScalarRepr("1:30.5"), "90.5");
  EXPECT_EQ(YamlScalarRepr("0x1f"), "31");
  EXPECT_EQ(YamlScalarRepr("010"), "8");
  EXPECT_EQ(YamlScalarRepr("08"), "'08'");
  EXPECT_EQ(YamlScalarRepr("0o10"), "'0o10'");
  EXPECT_EQ(YamlScalarRepr("0b101"), "5");
  EXPECT_EQ(YamlScalarRepr("1_000"), "1000");
  EXPECT_EQ(YamlScalarRepr("1__0"), "10");
  EXPECT_EQ(YamlScalarRepr("_1"), "'_1'");
  EXPECT_EQ(YamlScalarRepr("190:20:30"), "685230");
  EXPECT_EQ(YamlScalarRepr("-0"), "0");
  EXPECT_EQ(YamlScalarRepr("+12"), "12");
  EXPECT_EQ(YamlScalarRepr("~"), "None");
  EXPECT_EQ(YamlScalarRepr(""), "None");
  EXPECT_EQ(YamlScalarRepr("NULL"), "None");
  EXPECT_EQ(YamlScalarRepr("2001-12-14"), "'2001-12-14'");  // a date in PyYAML; its str() is the same text
}

TEST(PyExprYaml, QuotedAndExplicitlyTaggedScalars) {
  EXPECT_EQ(YamlScalarRepr("'1'"), "'1'");
  EXPECT_EQ(YamlScalarRepr("\"yes\""), "'yes'");
  EXPECT_EQ(YamlScalarRepr("!!str 12"), "'12'");
  EXPECT_EQ(YamlScalarRepr("!!float 1"), "1.0");
  EXPECT_EQ(YamlScalarRepr("!!int '7'"), "7");
}

TEST(PyExprYaml, UnitTags) {
  EXPECT_EQ(YamlScalarRepr("!degrees 90"), "1.5707963267948966");
  EXPECT_EQ(YamlScalarRepr("!radians pi/2"), "1.5707963267948966");
  EXPECT_EQ(YamlScalarRepr("!millimeters 5"), "0.005");
  EXPECT_EQ(YamlScalarRepr("!meters 2"), "2.0");
  EXPECT_EQ(YamlScalarRepr("!foot 1"), "0.3048");
  EXPECT_EQ(YamlScalarRepr("!inches 2*5"), "0.254");
  auto bad = LoadYaml("a: !degrees foo(\n");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message.find("line 1"), std::string::npos);
  auto unknown = LoadYaml("a: !unknown 1\n");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.error().kind, Error::Kind::kUnsupported);
}

TEST(PyExprYaml, MapsAndListsWithAttributeAccess) {
  auto r = LoadYaml("robot:\n  arm: {length: 0.5, joints: [a, b]}\n  mass: 2\nlist: [1, 2.5, off]\n1: int key\n");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(Str(*r), "{'robot': {'arm': {'length': 0.5, 'joints': ['a', 'b']}, 'mass': 2}, 'list': [1, 2.5, False], 1: 'int key'}");
  EXPECT_TRUE(r->attribute_access());

  class YamlScope : public Scope {
   public:
    explicit YamlScope(Value v) : v_(std::move(v)) {}
    Result<std::optional<Value>> Lookup(std::string_view name) override {
      if (name == "props") return std::optional<Value>(v_);
      return std::optional<Value>();
    }

   private:
    Value v_;
  } scope(*r);
  EXPECT_EQ(Str(*Evaluate("props.robot.arm.length * 2", scope)), "1.0");
  EXPECT_EQ(Str(*Evaluate("props['robot'].arm.joints[1]", scope)), "b");
  EXPECT_EQ(Str(*Evaluate("props.robot['mass']", scope)), "2");
  auto missing = Evaluate("props.robot.wheel", scope);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().kind, Error::Kind::kAttribute);
  EXPECT_EQ(missing.error().missing_name, "wheel");
}

TEST(PyExprYaml, MergeKeysDocumentsAndErrors) {
  auto merged = LoadYaml("base: &b {x: 1, y: 2}\nderived:\n  <<: *b\n  y: 3\n");
  ASSERT_TRUE(merged.ok());
  EXPECT_EQ(Str(*merged), "{'base': {'x': 1, 'y': 2}, 'derived': {'x': 1, 'y': 3}}");
  EXPECT_EQ(Str(*LoadYaml("")), "None");
  EXPECT_EQ(Str(*LoadYaml("[1, 2]")), "[1, 2]");
  auto syntax = LoadYaml("a: [1, 2\nb: 3\n");
  ASSERT_FALSE(syntax.ok());
  EXPECT_EQ(syntax.error().kind, Error::Kind::kSyntax);
  EXPECT_NE(syntax.error().message.find("line 2"), std::string::npos);
  EXPECT_FALSE(LoadYaml("---\na: 1\n---\nb: 2\n").ok());
  auto cyclic = LoadYaml("a: &a [*a]\n");
  ASSERT_FALSE(cyclic.ok());
  EXPECT_EQ(cyclic.error().kind, Error::Kind::kLimit);
}

}  // namespace
}  // namespace mdlc::pyexpr
