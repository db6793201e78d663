// SDFormat joint limits, dynamics and actuators as lowered by the frontend
// (SDF-013, SDF-020, EXT-011).
#include <gtest/gtest.h>

#include <limits>

#include "tests/unit/sdf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {
namespace {

using testing::kInf;

std::string Joint(std::string_view limit) {
  return fmt::format(R"(<model name='m'><link name='a'/><link name='b'/>
    <joint name='j' type='revolute'><parent>a</parent><child>b</child>
      <axis><xyz>0 0 1</xyz><limit>{}</limit><dynamics><damping>0.5</damping></dynamics></axis>
    </joint></model>)",
                     limit);
}

TEST(SdfJoint, LimitsAccelerationAndEffort) {  // SDF-013, EXT-011, SDF-020
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(Joint("<lower>-1</lower><upper>2</upper><velocity>3</velocity>"
                           "<effort>4</effort><drake:acceleration>5</drake:acceleration>")))
      << r.Messages();
  const ir::Joint& j = r.module.joints.back();
  EXPECT_EQ(j.limits.lower[0], -1);
  EXPECT_EQ(j.limits.upper[0], 2);
  EXPECT_EQ(j.limits.velocity_upper[0], 3);
  EXPECT_EQ(j.limits.velocity_lower[0], -3);
  EXPECT_EQ(j.limits.acceleration_upper[0], 5);  // EXT-011: symmetric
  EXPECT_EQ(j.limits.acceleration_lower[0], -5);
  EXPECT_EQ(j.damping[0], 0.5);
  ASSERT_EQ(r.module.actuators.size(), 1u);  // SDF-020: actuated by default
  EXPECT_EQ(r.module.actuators[0].effort_limit, 4);
}

TEST(SdfJoint, NegativeVelocityAndEffortMeanUnlimited) {  // SDF-013
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(Joint("<velocity>-1</velocity><effort>-1</effort>"))) << r.Messages();
  EXPECT_EQ(r.module.joints.back().limits.velocity_upper[0], kInf);
  EXPECT_EQ(r.module.actuators[0].effort_limit, kInf);
  EXPECT_EQ(r.module.joints.back().limits.acceleration_upper[0], kInf);
}

TEST(SdfJoint, ZeroEffortMeansNoActuator) {  // SDF-020
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(Joint("<effort>0</effort>"))) << r.Messages();
  EXPECT_TRUE(r.module.actuators.empty());
}

TEST(SdfJoint, NegativeAccelerationIsAnError) {  // EXT-011
  SdfFrontendResult r;
  EXPECT_FALSE(r.Read(Joint("<drake:acceleration>-1</drake:acceleration>")));
  EXPECT_TRUE(r.HasDiagnostic(DiagKind::BadLimits, "acceleration limit of joint 'j' must not be negative"))
      << r.Messages();
}

}  // namespace
}  // namespace mdlc::testing
