// URDF transmissions as Drake reads them: what makes an actuator, and which
// parts are ignored with a warning or silently (URDF-022..024).
#include <gtest/gtest.h>

#include "../urdf_test_util.h"

namespace mdlc::testing {
namespace {

constexpr const char* kTwoLinks = R"(<link name='a'/><link name='b'/>
    <joint name='j' type='revolute'><parent link='a'/><child link='b'/>
      <limit lower='-1' upper='1' effort='7' velocity='1'/></joint>)";

size_t CountWarnings(const Lowered& l) {
  size_t n = 0;
  for (const Diagnostic& d : l.diags.diagnostics()) n += d.severity == Severity::Warning;
  return n;
}

TEST(UrdfTransmissionTest, JointsGetNoActuatorWithoutATransmission) {  // URDF-024
  Lowered l;
  ASSERT_TRUE(l.Read(std::string("<robot name='r'>") + kTwoLinks + "</robot>")) << l.Messages();
  EXPECT_TRUE(l.module.actuators.empty());
}

TEST(UrdfTransmissionTest, ReductionOfOneIsSilentAnyOtherWarns) {  // URDF-022
  Lowered one;
  ASSERT_TRUE(one.Read(std::string("<robot name='r'>") + kTwoLinks + R"(
    <transmission><type>transmission_interface/SimpleTransmission</type><joint name='j'/>
      <actuator name='m'><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  </robot>)"))
      << one.Messages();
  ASSERT_EQ(one.module.actuators.size(), 1u);
  EXPECT_EQ(CountWarnings(one), 0u) << one.Messages();

  Lowered other;
  ASSERT_TRUE(other.Read(std::string("<robot name='r'>") + kTwoLinks + R"(
    <transmission><type>SimpleTransmission</type><joint name='j'/>
      <mechanicalReduction>100</mechanicalReduction><actuator name='m'/></transmission>
  </robot>)"))
      << other.Messages();
  ASSERT_EQ(other.module.actuators.size(), 1u);
  EXPECT_EQ(other.module.actuators[0].gear_ratio, 1);  // not applied
  EXPECT_TRUE(other.HasDiagnostic(DiagKind::UnsupportedValue, "mechanicalReduction '100'"));
}

TEST(UrdfTransmissionTest, GripperAndNamingPartsWarnHardwareInterfacesAreSilent) {  // URDF-023
  Lowered l;
  ASSERT_TRUE(l.Read(std::string("<robot name='r'>") + kTwoLinks + R"(
    <transmission name='t'><type>SimpleTransmission</type>
      <joint name='j'><hardwareInterface>EffortJointInterface</hardwareInterface></joint>
      <actuator name='m'><hardwareInterface>EffortJointInterface</hardwareInterface></actuator>
      <leftActuator name='l'/><rightActuator name='r'/><flexJoint name='f'/>
      <rollJoint name='o'/><gap_joint name='g'/><passive_joint name='p'/>
      <use_simulated_gripper_joint/>
    </transmission>
    <gazebo reference='a'><material>Gazebo/Grey</material></gazebo>
  </robot>)"))
      << l.Messages();
  ASSERT_EQ(l.module.actuators.size(), 1u);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedAttribute, "'name' of <transmission>"));
  for (const char* tag : {"leftActuator", "rightActuator", "flexJoint", "rollJoint", "gap_joint",
                          "passive_joint", "use_simulated_gripper_joint"}) {
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, std::string("<") + tag + ">"))
        << tag << "\n" << l.Messages();
  }
  // the name and the seven gripper tags; nothing for hardwareInterface or gazebo
  EXPECT_EQ(CountWarnings(l), 8u) << l.Messages();
}

}  // namespace
}  // namespace mdlc::testing
