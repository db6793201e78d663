// Scoped names through nested SDFormat models (COMMON-030, COMMON-031,
// SDF-030), with instance names kept as parent + local name (issue 16): deep
// nesting resolves, the plant prints full names, and unknown names keep
// their diagnostics.
#include <gtest/gtest.h>

#include <string>

#include "tests/unit/sdf_test_util.h"

namespace mdlc::testing {
namespace {

// models top > m1 > ... > m{depth-1}, each with a link "link"; the top
// model's joint reaches the innermost link through the whole scoped name
std::string Nested(int depth, std::string_view child) {
  std::string out = "<model name='top'><link name='link'/>";
  out += fmt::format("<joint name='deep' type='revolute'><parent>link</parent><child>{}</child>"
                     "<axis><xyz>0 0 1</xyz></axis></joint>",
                     child);
  for (int i = 1; i < depth; ++i) out += fmt::format("<model name='m{}'><link name='link'/>", i);
  for (int i = 1; i < depth; ++i) out += "</model>";
  out += "</model>";
  return out;
}

std::string InnermostLink(int depth) {
  std::string name;
  for (int i = 1; i < depth; ++i) name += fmt::format("m{}::", i);
  return name + "link";
}

TEST(SdfNestedNames, DeepNestingResolvesAndPrintsFullNames) {  // COMMON-030, issue 16
  constexpr int kDepth = 60;  // SDFormat files nest deeper still; this is enough to walk
  SdfCompileResult r(Nested(kDepth, InnermostLink(kDepth)));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const nlohmann::json plant = r.PlantJson();
  std::string full = "top";
  for (int i = 1; i < kDepth; ++i) full += fmt::format("::m{}", i);
  const auto& instances = plant["model_instances"];
  ASSERT_EQ(instances.size(), static_cast<size_t>(kDepth) + 2);
  EXPECT_EQ(instances.back(), full);
  EXPECT_EQ(instances[3], "top::m1");
  bool found = false;
  for (const auto& j : plant["joints"]) {
    if (j["name"] == "deep") {
      found = true;
      EXPECT_EQ(j["model_instance"], "top");
      EXPECT_EQ(j["child"], full + "::link");
    }
  }
  EXPECT_TRUE(found);
}

TEST(SdfNestedNames, UnknownNestedInstanceIsReported) {  // COMMON-030
  SdfCompileResult r(Nested(4, "m1::mX::link"));
  EXPECT_FALSE(r.ok());
  r.ExpectDiagnostic(DiagKind::UnknownReference,
                     "child frame 'mX' does not match a nested model, link, joint, or frame "
                     "name in model 'm1'");
}

TEST(SdfNestedNames, UnknownLinkInAKnownInstanceIsReported) {  // COMMON-030
  SdfCompileResult r(Nested(4, "m1::m2::lnk"));
  EXPECT_FALSE(r.ok());
  r.ExpectDiagnostic(DiagKind::UnknownReference, "m1::m2::lnk");
}

}  // namespace
}  // namespace mdlc::testing
