// The URDF and SDFormat writers' -Wlossy warnings for joint state neither
// format holds: velocity or acceleration limits that are not symmetric (both
// formats hold one bound) and nonzero default positions. No reader makes
// such limits, so the tests set them on a compiled plant, as an embedder
// building a plant could.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backend/writers/writer.h"
#include "frontend/frontend.h"
#include "tools/driver/compiler.h"

namespace mdlc {
namespace {

constexpr const char* kArm = R"(<robot name='r'>
  <link name='base'/>
  <link name='arm'>
    <inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial>
  </link>
  <joint name='shoulder' type='revolute'><parent link='base'/><child link='arm'/>
    <axis xyz='0 0 1'/><limit effort='5' lower='-1' upper='1' velocity='2'/></joint>
</robot>)";

class AsymmetricLimitsTest : public ::testing::TestWithParam<Format> {
 protected:
  // kArm compiled; each test edits its shoulder joint before writing
  void SetUp() override {
    frontend::FrontendContext ctx{c_.sources, c_.diags, c_.module, c_.options.frontend};
    frontend::ReadUrdf(c_.sources.AddBuffer("arm.urdf", kArm), ctx);
    ASSERT_TRUE(c_.RunPasses());
    ASSERT_TRUE(c_.RunBackend());
    for (backend::PlantJoint& j : c_.model->plant.joints) {
      if (j.name == "shoulder") shoulder_ = &j;
    }
    ASSERT_NE(shoulder_, nullptr);
  }
  /// The plant written in the format under test; the writer's diagnostics.
  std::vector<Diagnostic> Write() {
    DiagnosticEngine diags;
    writers::WriteOptions options;
    options.to = GetParam();
    EXPECT_TRUE(writers::Write(*c_.model, c_.module, options, diags).has_value());
    return diags.diagnostics();
  }

  Compilation c_;
  backend::PlantJoint* shoulder_ = nullptr;
};

TEST_P(AsymmetricLimitsTest, EachAsymmetricLimitIsALossyWarning) {
  shoulder_->velocity_lower.set(0, -1);  // upper stays 2
  shoulder_->acceleration_lower.set(0, -3);
  shoulder_->acceleration_upper.set(0, 4);
  const std::vector<Diagnostic> diagnostics = Write();
  const std::string format = GetParam() == Format::Urdf ? "URDF" : "SDFormat";
  std::vector<std::string> lossy;
  for (const Diagnostic& d : diagnostics) {
    if (d.kind == DiagKind::Lossy && d.message.find("limits [") != std::string::npos) {
      lossy.push_back(d.message);
      EXPECT_TRUE(d.loc.valid()) << d.message;
    }
  }
  ASSERT_EQ(lossy.size(), 2u);
  EXPECT_EQ(lossy[0], "joint 'shoulder' has velocity limits [-1, 2]; " + format +
                          "'s are symmetric, so +-2 is written");
  EXPECT_EQ(lossy[1], "joint 'shoulder' has acceleration limits [-3, 4]; " + format +
                          "'s are symmetric, so +-4 is written");
}

TEST_P(AsymmetricLimitsTest, NonzeroDefaultPositionIsALossyWarning) {
  shoulder_->default_positions = {0.5};
  const std::vector<Diagnostic> diagnostics = Write();
  const std::string why = GetParam() == Format::Urdf
                              ? "URDF has no initial positions"
                              : "mdlc's SDFormat reader takes no initial positions";
  int found = 0;
  for (const Diagnostic& d : diagnostics) {
    if (d.kind != DiagKind::Lossy || d.message.find("default position") == std::string::npos) {
      continue;
    }
    ++found;
    EXPECT_EQ(d.message,
              "the default position of joint 'shoulder' (0.5) is not written (" + why + ")");
  }
  EXPECT_EQ(found, 1);
}

INSTANTIATE_TEST_SUITE_P(Writers, AsymmetricLimitsTest,
                         ::testing::Values(Format::Urdf, Format::Sdf),
                         [](const auto& info) { return info.param == Format::Urdf ? "Urdf" : "Sdf"; });

}  // namespace
}  // namespace mdlc
