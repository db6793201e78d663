// option_names_test.cc - the one checker of option names and values
// (mdlc/option_names.h) that the command line and the Python module share
// (issue 59: a misspelt -W group, pass, limit or value is refused with the
// nearest known name, instead of quietly doing nothing).
#include "mdlc/option_names.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace mdlc {
namespace {

bool Has(const std::vector<std::string_view>& names, std::string_view name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(OptionNames, KnowsTheGroupsOfTheDiagnosticsAndThePasses) {
  EXPECT_TRUE(Has(WarningGroupNames(), "joint"));
  EXPECT_TRUE(Has(WarningGroupNames(), "mesh-axes"));
  EXPECT_TRUE(std::is_sorted(WarningGroupNames().begin(), WarningGroupNames().end()));
  EXPECT_TRUE(Has(PassNames(), "resolve-names"));
  EXPECT_TRUE(Has(PassNames(), "check-inertia"));
}

TEST(OptionNames, WarningFlagsSetThePolicy) {
  DiagnosticPolicy policy;
  EXPECT_EQ(ApplyWarningFlag(policy, "no-joint", "-Wno-joint"), std::nullopt);
  EXPECT_EQ(ApplyWarningFlag(policy, "error=names", "-Werror=names"), std::nullopt);
  EXPECT_EQ(ApplyWarningFlag(policy, "unknown", "-Wunknown"), std::nullopt);  // the default
  EXPECT_FALSE(policy.warnings_as_errors);
  EXPECT_EQ(ApplyWarningFlag(policy, "error", "-Werror"), std::nullopt);
  EXPECT_TRUE(policy.warnings_as_errors);
  EXPECT_TRUE(policy.disabled_groups.contains("joint"));
  EXPECT_TRUE(policy.error_groups.contains("names"));
  EXPECT_EQ(policy.disabled_groups.size() + policy.error_groups.size(), 2u);
}

TEST(OptionNames, AMisspeltWarningGroupIsRefusedWithTheNearest) {
  DiagnosticPolicy policy;
  EXPECT_EQ(ApplyWarningFlag(policy, "no-jiont", "-Wno-jiont"),
            "unknown warning group 'jiont' in -Wno-jiont; did you mean 'joint'?");
  EXPECT_EQ(ApplyWarningFlag(policy, "error=inertai", "-Werror=inertai"),
            "unknown warning group 'inertai' in -Werror=inertai; did you mean 'inertia'?");
  EXPECT_EQ(ApplyWarningFlag(policy, "typo", "-Wtypo"),
            "unknown warning group 'typo' in -Wtypo; mdlc --list-warnings lists the groups");
  EXPECT_EQ(ApplyWarningFlag(policy, "", "-W"), "-W needs a value");
  EXPECT_TRUE(policy.disabled_groups.empty());
  EXPECT_TRUE(policy.error_groups.empty());
}

TEST(OptionNames, AMisspeltPassIsRefusedWithTheNearest) {
  EXPECT_EQ(CheckPassName("resolve-names", "--passes"), std::nullopt);
  EXPECT_EQ(CheckPassName("resolve-nmes", "--passes"),
            "unknown pass 'resolve-nmes' in --passes; did you mean 'resolve-names'?");
  EXPECT_EQ(CheckPassName("typo", "--print-after"),
            "unknown pass 'typo' in --print-after; mdlc --list-passes lists the passes");
}

TEST(OptionNames, LimitsAndChoices) {
  Limits limits;
  EXPECT_EQ(ApplyLimitSetting(limits, "depth=7", "--limit"), std::nullopt);
  EXPECT_EQ(limits.depth, 7u);
  EXPECT_EQ(ApplyLimitSetting(limits, "dept=7", "--limit"),
            "unknown limit 'dept' in --limit; did you mean 'depth'?");
  // the rest of SetLimit's messages, named by where the setting came from
  EXPECT_EQ(ApplyLimitSetting(limits, "depth=lots", "limits").value_or("").rfind("limits: ", 0),
            0u);
  MeshReader reader = MeshReader::Process;
  EXPECT_EQ(ParseMeshReader("in-process", "--mesh-reader", reader), std::nullopt);
  EXPECT_EQ(reader, MeshReader::InProcess);
  EXPECT_EQ(ParseMeshReader("in-proces", "--mesh-reader", reader),
            "unknown value 'in-proces' for --mesh-reader; did you mean 'in-process'?");
  EXPECT_EQ(ParseMeshReader("thread", "--mesh-reader", reader),
            "unknown value 'thread' for --mesh-reader; expected 'process' or 'in-process'");
  ColladaUpAxis axis = ColladaUpAxis::AsWritten;
  EXPECT_EQ(ParseColladaUpAxis("apply", "collada_up_axis", axis), std::nullopt);
  EXPECT_EQ(axis, ColladaUpAxis::Apply);
  EXPECT_EQ(ParseColladaUpAxis("aply", "collada_up_axis", axis),
            "unknown value 'aply' for collada_up_axis; did you mean 'apply'?");
}

TEST(OptionNames, PythonKeywords) {
  EXPECT_EQ(CheckOptionKeyword("strict", "mdlc.compile"), std::nullopt);
  EXPECT_EQ(CheckOptionKeyword("strcit", "mdlc.compile"),
            "unknown keyword 'strcit' for mdlc.compile; did you mean 'strict'?");
  const auto& names = CompileOptionNames();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end(), [](const auto& a, const auto& b) {
    return a.keyword < b.keyword;
  }));
}

}  // namespace
}  // namespace mdlc
