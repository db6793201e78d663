// The scopes the SDFormat writer gives model instances (issue 16: found by
// fuzz_urdf, tests/fuzz/regressions/urdf/robot_name_with_empty_scope). A
// URDF robot's name becomes its model instance's name, "::" and all. The
// writer nests a model per "::"; an empty part ("::a") looked up the world's
// scope as a model and threw, and "a:::b" was split at different colons
// when the scopes were made and when they were looked up.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "tests/unit/compile_test_util.h"
#include "tests/unit/writers/written.h"

namespace mdlc {
namespace {

using testing::CompiledText;
using testing::Written;

struct Case {
  std::string robot;                 // the URDF robot's name
  std::string written;               // the scope its link is written in
  std::vector<std::string> warning;  // the writer's lossy warning, if any
};

class InstanceScopes : public ::testing::TestWithParam<Case> {};

TEST_P(InstanceScopes, ARobotNamedWithScopesWritesAndReadsBack) {
  const Case& c = GetParam();
  CompiledText original("robot.urdf", "<robot name='" + c.robot +
                                          "'><link name='l'><inertial><mass value='2'/>"
                                          "<inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' "
                                          "iyz='0'/></inertial></link></robot>");
  ASSERT_TRUE(original.ok()) << original.Messages();
  DiagnosticEngine diags;
  const std::string text = Written(original, Format::Sdf, diags);
  std::vector<std::string> messages;
  for (const Diagnostic& d : diags.diagnostics()) {
    EXPECT_EQ(d.kind, DiagKind::Lossy) << d.message;
    EXPECT_TRUE(d.loc.valid()) << d.message;
    messages.push_back(d.message);
  }
  EXPECT_EQ(messages, c.warning);

  CompiledText reread("robot.sdf", text);
  ASSERT_TRUE(reread.ok()) << reread.Messages() << "\n" << text;
  const nlohmann::json bodies = reread.Json()["bodies"];
  ASSERT_EQ(bodies.size(), 1u);
  EXPECT_EQ(bodies[0]["name"], "l");
  EXPECT_EQ(bodies[0]["model_instance"], c.written);
  EXPECT_EQ(bodies[0]["mass"], 2);
}

std::string EmptyPart(const std::string& name, const std::string& written) {
  return "model instance '" + name + "' has an empty name in its scope; it is written as '" +
         written + "'";
}

INSTANTIATE_TEST_SUITE_P(
    Writers, InstanceScopes,
    ::testing::Values(Case{"a::b", "a::b", {}},
                      // split at each "::" from the left, as written and as read
                      Case{"a:::b", "a:::b", {}},
                      Case{"::a", "model::a", {EmptyPart("::a", "model::a")}},
                      Case{"a::", "a::model", {EmptyPart("a::", "a::model")}},
                      Case{"::", "model::model", {EmptyPart("::", "model::model")}},
                      Case{"a::::b", "a::model::b", {EmptyPart("a::::b", "a::model::b")}}));

}  // namespace
}  // namespace mdlc
