// <drake:joint> in the URDF frontend (EXT-001..003) and its interplay with
// <joint> (URDF-011..014, URDF-042): types, counts, axes, screw pitch,
// curvilinear paths, errors, and the compiled plant's poses at given q.
// What the SDFormat spelling shares is tested in both in
// drake_spellings_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <tuple>

#include "backend/kinematics.h"
#include "backend/plant_json.h"
#include "backend/positions.h"
#include "tests/unit/test_values.h"
#include "tests/unit/urdf_test_util.h"
#include "tools/driver/compiler.h"

namespace mdlc {
namespace {

using testing::kInf;
using testing::Lowered;
constexpr double kPi = std::numbers::pi;

/// A robot with links a..f and `body` (joints, transmissions) inside.
std::string SixLinkRobot(std::string_view body) {
  return fmt::format(R"(<robot name='r'>
    <link name='a'/><link name='b'/><link name='c'/><link name='d'/><link name='e'/>
    <link name='f'/>
    {}
  </robot>)",
                     body);
}

Eigen::Matrix3d Rz(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// ---------------------------------------------------------------- EXT-001

TEST(UrdfDrakeJointTest, BallJointHasThreeRpyDofsAndSharedDamping) {  // EXT-001, URDF-014
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='ball' type='ball'><parent link='a'/><child link='b'/>
      <origin xyz='1 2 3'/><axis xyz='0 0 0'/><dynamics damping='0.1'/></drake:joint>)")))
      << l.Messages();
  const ir::Joint* ball = l.Joint("ball");
  ASSERT_NE(ball, nullptr);
  EXPECT_EQ(ball->type, ir::JointType::Ball);
  EXPECT_EQ(ir::JointPositionCount(ball->type), 3);  // roll, pitch, yaw (BallRpyJoint)
  EXPECT_EQ(ir::JointVelocityCount(ball->type), 3);
  EXPECT_EQ(ball->X_PF.p, Eigen::Vector3d(1, 2, 3));
  // Drake's BallRpyJoint applies its one damping value to every dof
  EXPECT_EQ(ball->damping, (std::vector<double>{0.1, 0.1, 0.1}));
  EXPECT_EQ(ball->limits.lower, (std::vector<double>(3, -kInf)));
  EXPECT_EQ(ball->limits.upper, (std::vector<double>(3, kInf)));
  EXPECT_EQ(ball->limits.effort, (std::vector<double>(3, kInf)));
  // the axis of a ball joint is not read at all (not even its zero check)
  EXPECT_EQ(l.diags.diagnostics().size(), 0u) << l.Messages();
}

TEST(UrdfDrakeJointTest, UniversalJointHasTwoDofsAndIgnoresItsAxis) {  // EXT-001, URDF-011
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='u' type='universal'><parent link='a'/><child link='b'/>
      <axis xyz='0 1 0'/><dynamics damping='0.25'/></drake:joint>)")))
      << l.Messages();
  const ir::Joint* u = l.Joint("u");
  ASSERT_NE(u, nullptr);
  EXPECT_EQ(u->type, ir::JointType::Universal);
  EXPECT_EQ(ir::JointPositionCount(u->type), 2);
  EXPECT_EQ(ir::JointVelocityCount(u->type), 2);
  EXPECT_EQ(u->damping, (std::vector<double>{0.25, 0.25}));
  EXPECT_EQ(u->limits.velocity_upper, (std::vector<double>(2, kInf)));
  EXPECT_EQ(u->axis, Eigen::Vector3d::UnitX());  // Drake ignores it: x then y
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::JointWarning, "<axis> of universal joint 'u' is ignored"));
  // ...but still rejects a zero axis, as Drake does
  Lowered zero;
  EXPECT_FALSE(zero.Read(SixLinkRobot(R"(<drake:joint name='u' type='universal'>
      <parent link='a'/><child link='b'/><axis xyz='0 0 0'/></drake:joint>)")));
  EXPECT_TRUE(zero.HasDiagnostic(DiagKind::ZeroAxis, "axis is zero"));
}

TEST(UrdfDrakeJointTest, PlanarIsAcceptedAsJointAndAsDrakeJoint) {  // EXT-001, URDF-012
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <joint name='p1' type='planar'><parent link='a'/><child link='b'/><axis xyz='1 0 0'/>
      <dynamics damping='1 2 3'/></joint>
    <drake:joint name='p2' type='planar'><parent link='a'/><child link='c'/><axis xyz='1 0 0'/>
      <dynamics damping='1 2 3'/></drake:joint>)")))
      << l.Messages();
  const ir::Joint* p1 = l.Joint("p1");
  const ir::Joint* p2 = l.Joint("p2");
  ASSERT_TRUE(p1 && p2);
  EXPECT_EQ(l.diags.diagnostics().size(), 0u) << l.Messages();
  for (const ir::Joint* p : {p1, p2}) {
    EXPECT_EQ(p->type, ir::JointType::Planar);
    // Drake's planar frame has z along the URDF axis
    EXPECT_TRUE((p->X_PF.R * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));
    EXPECT_TRUE(p->X_CM.R.isApprox(p->X_PF.R));
    EXPECT_EQ(p->damping, (std::vector<double>{1, 2, 3}));
  }
  EXPECT_TRUE(p1->X_PF.R.isApprox(p2->X_PF.R));
}

TEST(UrdfDrakeJointTest, StandardTypeInDrakeJointIsAnError) {  // EXT-001
  for (std::string_view type : {"revolute", "continuous", "prismatic", "fixed", "floating"}) {
    Lowered l;
    EXPECT_FALSE(l.Read(SixLinkRobot(fmt::format(R"(<drake:joint name='j' type='{}'>
        <parent link='a'/><child link='b'/></drake:joint>)",
                                                 type))))
        << type;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "standard joint type")) << l.Messages();
    EXPECT_EQ(l.diags.error_count(), 1u) << l.Messages();
    if (type == "floating") {
      // TODO: the frontend still warns that the floating joint makes a free
      // body although it has just rejected the <drake:joint>; the warning
      // describes a joint that is never made.
      l.ExpectDiagnostic(DiagKind::FloatingJoint, "creates no joint");
    }
  }
}

TEST(UrdfDrakeJointTest, CustomTypeInPlainJointIsAnError) {  // EXT-001
  for (std::string_view type : {"ball", "universal", "screw", "curvilinear"}) {
    Lowered l;
    EXPECT_FALSE(l.Read(SixLinkRobot(fmt::format(R"(<joint name='j' type='{}'>
        <parent link='a'/><child link='b'/>
        <drake:screw_thread_pitch value='0.1'/>
        <drake:curves><drake:line_segment length='1'/></drake:curves></joint>)",
                                                 type))))
        << type;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "custom joint type")) << l.Messages();
    EXPECT_EQ(l.diags.error_count(), 1u) << l.Messages();
    // the children that do not belong to this type are ignored with a warning
    l.ExpectDiagnostic(DiagKind::UnknownElement, "applies only to");
    // as in Drake, the joint is still made, so references to it resolve
    ASSERT_NE(l.Joint("j"), nullptr);
    EXPECT_EQ(ir::JointTypeName(l.Joint("j")->type), type);
  }
}

TEST(UrdfDrakeJointTest, UnknownTypeAndMissingPartsAreLocatedErrors) {  // EXT-001
  Lowered l;
  EXPECT_FALSE(l.Read(SixLinkRobot(R"(
    <drake:joint name='j1' type='hinge'><parent link='a'/><child link='b'/></drake:joint>
    <drake:joint type='ball'><parent link='a'/><child link='b'/></drake:joint>
    <drake:joint name='j3'><parent link='a'/><child link='b'/></drake:joint>
    <drake:joint name='j4' type='ball'><child link='b'/></drake:joint>
    <drake:joint name='j5' type='ball'><parent link='a'/></drake:joint>
    <drake:joint name='j6' type='ball'><parent/><child link='b'/></drake:joint>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "joint 'j1' has unrecognized type 'hinge'"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "'name'"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "'type'"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "<drake:joint> is missing its <parent>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement, "<drake:joint> is missing its <child>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "<parent> is missing required"));
  EXPECT_EQ(l.diags.error_count(), 6u) << l.Messages();
  EXPECT_TRUE(l.module.joints.empty());
  for (const auto& d : l.diags.diagnostics()) EXPECT_TRUE(d.loc.valid()) << d.message;
}

TEST(UrdfDrakeJointTest, ZeroOrNanAxisIsAnError) {  // EXT-001, URDF-011
  Lowered l;
  EXPECT_FALSE(l.Read(SixLinkRobot(R"(
    <drake:joint name='s' type='screw'><parent link='a'/><child link='b'/>
      <axis xyz='0 0 1e-9'/><drake:screw_thread_pitch value='1'/></drake:joint>
    <drake:joint name='t' type='screw'><parent link='a'/><child link='c'/>
      <axis xyz='nan 0 1'/><drake:screw_thread_pitch value='1'/></drake:joint>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::ZeroAxis, "joint 's': axis is zero"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonFinite, "'xyz'"));
}

// URDF-042: joints are made in document order across both elements, share one
// name space, and transmissions and mimics may name a drake:joint.
TEST(UrdfDrakeJointTest, JointsAreMadeInDocumentOrderAcrossBothElements) {  // URDF-042
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <transmission><type>SimpleTransmission</type><joint name='s'/><actuator name='m'/>
    </transmission>
    <joint name='r1' type='revolute'><parent link='a'/><child link='b'/>
      <mimic joint='s' multiplier='2'/></joint>
    <drake:joint name='s' type='screw'><parent link='b'/><child link='c'/>
      <drake:screw_thread_pitch value='0.01'/></drake:joint>
    <joint name='r2' type='continuous'><parent link='c'/><child link='d'/></joint>
    <drake:joint name='u' type='universal'><parent link='d'/><child link='e'/></drake:joint>)")))
      << l.Messages();
  ASSERT_EQ(l.module.joints.size(), 4u);
  std::vector<std::string_view> order;
  for (const auto& j : l.module.joints) order.push_back(l.module.Text(j.name));
  EXPECT_EQ(order, (std::vector<std::string_view>{"r1", "s", "r2", "u"}));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  ASSERT_EQ(l.module.actuators.size(), 1u);
  EXPECT_EQ(l.module.Text(l.module[l.module.actuators[0].joint.id].name), "s");
  // Drake reads no effort for a screw joint: the actuator is unbounded
  EXPECT_EQ(l.module.actuators[0].effort_limit, kInf);
  ASSERT_EQ(l.module.constraints.size(), 1u);
  // r1 follows the drake:joint s (Drake's orientation: joint0 follows joint1)
  EXPECT_EQ(l.module.Text(l.module[l.module.constraints[0].As<ir::CouplerConstraint>().joint0.id].name), "r1");
  EXPECT_EQ(l.module.Text(l.module[l.module.constraints[0].As<ir::CouplerConstraint>().joint1.id].name), "s");

  Lowered dup;
  EXPECT_FALSE(dup.Read(SixLinkRobot(R"(
    <joint name='x' type='fixed'><parent link='a'/><child link='b'/></joint>
    <drake:joint name='x' type='ball'><parent link='a'/><child link='c'/></drake:joint>)")));
  EXPECT_TRUE(dup.HasDiagnostic(DiagKind::DuplicateName, "joint 'x' is already defined"));
}

TEST(UrdfDrakeJointTest, DrakeJointHonoursDrakeIgnoreAndMimic) {  // EXT-001, URDF-002, URDF-018
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='gone' type='ball' drake_ignore='true'><parent link='a'/>
      <child link='b'/></drake:joint>
    <joint name='lead' type='revolute'><parent link='a'/><child link='c'/></joint>
    <drake:joint name='follow' type='screw'><parent link='a'/><child link='d'/>
      <drake:screw_thread_pitch value='0.5'/><mimic joint='lead' offset='1'/></drake:joint>)")))
      << l.Messages();
  EXPECT_EQ(l.Joint("gone"), nullptr);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  ASSERT_EQ(l.module.constraints.size(), 1u);
  EXPECT_EQ(l.module.Text(l.module[l.module.constraints[0].As<ir::CouplerConstraint>().joint0.id].name), "follow");
  EXPECT_EQ(l.module.Text(l.module[l.module.constraints[0].As<ir::CouplerConstraint>().joint1.id].name), "lead");
  EXPECT_EQ(l.module.constraints[0].As<ir::CouplerConstraint>().offset, 1);
}

TEST(UrdfDrakeJointTest, LimitsOfCustomTypesAreIgnoredWithAWarning) {  // EXT-001, URDF-013
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='s' type='screw'><parent link='a'/><child link='b'/>
      <drake:screw_thread_pitch value='0.5'/>
      <limit lower='-1' upper='1' effort='5' velocity='2'/></drake:joint>
    <drake:joint name='p' type='planar'><parent link='a'/><child link='c'/>
      <limit lower='-1' upper='1'/></drake:joint>)")))
      << l.Messages();
  const ir::Joint* s = l.Joint("s");
  EXPECT_EQ(s->limits.lower[0], -kInf);
  EXPECT_EQ(s->limits.upper[0], kInf);
  EXPECT_EQ(s->limits.effort[0], kInf);
  EXPECT_EQ(s->limits.velocity_upper[0], kInf);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "<limit> of screw joint 's'"));
  // planar ignores <limit> silently, as for <joint type='planar'>
  EXPECT_EQ(l.diags.diagnostics().size(), 1u) << l.Messages();
}

TEST(UrdfDrakeJointTest, NegativeOrNanDampingIsAnError) {  // URDF-014
  Lowered l;
  EXPECT_FALSE(l.Read(SixLinkRobot(R"(
    <drake:joint name='b' type='ball'><parent link='a'/><child link='b'/>
      <dynamics damping='-1'/></drake:joint>
    <drake:joint name='u' type='universal'><parent link='a'/><child link='c'/>
      <dynamics damping='nan'/></drake:joint>
    <drake:joint name='p' type='planar'><parent link='a'/><child link='d'/>
      <dynamics damping='1 -2 3'/></drake:joint>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "joint 'b': damping must not be negative"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::NonFinite, "'damping'"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "joint 'p': damping must not be negative"));
}

TEST(UrdfDrakeJointTest, ParametersOfAnotherTypeAreIgnoredWithAWarning) {  // EXT-002, EXT-003
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='b' type='ball'><parent link='a'/><child link='b'/>
      <drake:screw_thread_pitch value='1'/><drake:curves/><foo/></drake:joint>)")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "unknown element <foo> in <drake:joint>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "<drake:screw_thread_pitch> applies only to screw joints"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "<drake:curves> applies only to curvilinear joints"));
}

// ---------------------------------------------------------------- EXT-002

TEST(UrdfDrakeJointTest, ScrewJointReadsAxisAndThreadPitch) {  // EXT-001, EXT-002
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='s' type='screw'><parent link='a'/><child link='b'/>
      <axis xyz='0 0 2'/><drake:screw_thread_pitch value='-0.04'/>
      <dynamics damping='0.1'/></drake:joint>)")))
      << l.Messages();
  const ir::Joint* s = l.Joint("s");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->type, ir::JointType::Screw);
  EXPECT_EQ(ir::JointPositionCount(s->type), 1);
  EXPECT_EQ(ir::JointVelocityCount(s->type), 1);
  EXPECT_EQ(s->axis, Eigen::Vector3d::UnitZ());  // normalised
  EXPECT_EQ(s->screw_thread_pitch, -0.04);       // a left-handed thread is fine
  EXPECT_EQ(s->damping, (std::vector<double>{0.1}));
  EXPECT_EQ(s->limits.lower, (std::vector<double>{-kInf}));
}

TEST(UrdfDrakeJointTest, ScrewThreadPitchErrors) {  // EXT-002
  struct Case {
    std::string_view pitch;
    DiagKind kind;
    std::string_view message;
  };
  for (const Case& c : {
           Case{"", DiagKind::MissingElement, "missing its <drake:screw_thread_pitch> element"},
           Case{"<drake:screw_thread_pitch/>", DiagKind::MissingAttribute,
                "<drake:screw_thread_pitch> is missing required attribute 'value'"},
           Case{"<drake:screw_thread_pitch value='0'/>", DiagKind::BadValue,
                "thread pitch must not be zero"},
           Case{"<drake:screw_thread_pitch value='nan'/>", DiagKind::NonFinite, "'value'"},
           Case{"<drake:screw_thread_pitch value='inf'/>", DiagKind::NonFinite, "'value'"},
           Case{"<drake:screw_thread_pitch value='x'/>", DiagKind::BadValue, "must be numbers"},
       }) {
    Lowered l;
    EXPECT_FALSE(l.Read(SixLinkRobot(fmt::format(R"(<drake:joint name='s' type='screw'>
        <parent link='a'/><child link='b'/>{}</drake:joint>)",
                                                 c.pitch))))
        << c.pitch;
    EXPECT_TRUE(l.HasDiagnostic(c.kind, c.message)) << c.pitch << "\n" << l.Messages();
    EXPECT_EQ(l.diags.error_count(), 1u) << l.Messages();
    for (const auto& d : l.diags.diagnostics()) EXPECT_TRUE(d.loc.valid()) << d.message;
  }
}

// ---------------------------------------------------------------- EXT-003

// a path's segments, its default plane and its limits are tested in both
// spellings in drake_spellings_test.cc

TEST(UrdfDrakeJointTest, CurvilinearPlaneTangentAndPeriodic) {  // EXT-003
  // the corpus's joint_parsing_test.urdf curvilinear_periodic joint
  Lowered l;
  ASSERT_TRUE(l.Read(SixLinkRobot(R"(
    <drake:joint name='c' type='curvilinear'><parent link='a'/><child link='b'/>
      <origin xyz='3 2 1' rpy='0 0 0'/>
      <drake:initial_tangent xyz='0 0 1'/><drake:plane_normal xyz='2 0 0'/>
      <drake:is_periodic value='true'/>
      <drake:curves>
        <drake:line_segment length='1.0'/>
        <drake:circular_arc radius='2.0' angle='1.57079632679489661923'/>
        <drake:circular_arc radius='2.0' angle='-1.57079632679489661923'/>
      </drake:curves></drake:joint>)")))
      << l.Messages();
  const ir::Joint* c = l.Joint("c");
  const ir::CurvilinearPath& path = c->curvilinear_path;
  EXPECT_EQ(path.initial_tangent, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(path.plane_normal, Eigen::Vector3d(2, 0, 0));
  EXPECT_TRUE(path.periodic);
  EXPECT_EQ(c->X_PF.p, Eigen::Vector3d(3, 2, 1));
  // a periodic path does not limit the joint
  EXPECT_EQ(c->limits.lower[0], -kInf);
  EXPECT_EQ(c->limits.upper[0], kInf);
  // Drake's expected breaks {0, 1, 1+pi, 1+2pi} and turning rates {0, .5, -.5}
  EXPECT_DOUBLE_EQ(path.TotalLength(), 1 + 2 * kPi);
  EXPECT_DOUBLE_EQ(path.segments[1].curvature, 0.5);
  EXPECT_DOUBLE_EQ(path.segments[2].curvature, -0.5);
  // at s = 0 the path frame A has x = tangent, z = normal, y = z x x = -Fy
  const Transform X0 = path.PoseAt(0);
  EXPECT_TRUE(X0.R.col(0).isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE(X0.R.col(1).isApprox(-Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(X0.R.col(2).isApprox(Eigen::Vector3d::UnitX()));
}

TEST(UrdfDrakeJointTest, IsPeriodicTakesOnlyTrueAsTrue) {  // EXT-003
  for (auto [value, periodic, warns] :
       {std::tuple{"'true'", true, false}, {"'false'", false, false}, {"'1'", false, true},
        {"'True'", false, true}}) {
    Lowered l;
    ASSERT_TRUE(l.Read(SixLinkRobot(fmt::format(R"(<drake:joint name='c' type='curvilinear'>
        <parent link='a'/><child link='b'/><drake:is_periodic value={}/>
        <drake:curves><drake:line_segment length='1'/></drake:curves></drake:joint>)",
                                                value))))
        << l.Messages();
    EXPECT_EQ(l.Joint("c")->curvilinear_path.periodic, periodic) << value;
    EXPECT_EQ(l.HasDiagnostic(DiagKind::JointWarning, "is not periodic"), warns) << value;
  }
}

TEST(UrdfDrakeJointTest, CurvilinearPathErrors) {  // EXT-003
  struct Case {
    std::string_view body;
    DiagKind kind;
    std::string_view message;
  };
  const std::string_view line = "<drake:curves><drake:line_segment length='1'/></drake:curves>";
  for (const Case& c : {
           Case{"", DiagKind::MissingElement, "missing its <drake:curves> list"},
           Case{"<drake:curves/>", DiagKind::MissingElement, "empty <drake:curves> list"},
           Case{"<drake:curves><!-- nothing --></drake:curves>", DiagKind::MissingElement,
                "empty <drake:curves> list"},
           Case{"<drake:curves><drake:spline/></drake:curves>", DiagKind::BadValue,
                "may hold only <drake:line_segment> and <drake:circular_arc>, not <drake:spline>"},
           Case{"<drake:curves><drake:line_segment/></drake:curves>", DiagKind::MissingAttribute,
                "'length'"},
           Case{"<drake:curves><drake:line_segment length='0'/></drake:curves>",
                DiagKind::BadValue, "length must be positive"},
           Case{"<drake:curves><drake:line_segment length='-1'/></drake:curves>",
                DiagKind::BadValue, "length must be positive"},
           Case{"<drake:curves><drake:line_segment length='nan'/></drake:curves>",
                DiagKind::NonFinite, "'length'"},
           Case{"<drake:curves><drake:circular_arc angle='1'/></drake:curves>",
                DiagKind::MissingAttribute, "'radius'"},
           Case{"<drake:curves><drake:circular_arc radius='1'/></drake:curves>",
                DiagKind::MissingAttribute, "'angle'"},
           Case{"<drake:curves><drake:circular_arc radius='0' angle='1'/></drake:curves>",
                DiagKind::BadValue, "radius must be positive"},
           Case{"<drake:curves><drake:circular_arc radius='1' angle='0'/></drake:curves>",
                DiagKind::BadValue, "angle must not be zero"},
           Case{"<drake:curves><drake:circular_arc radius='1e300' angle='1e300'/></drake:curves>",
                DiagKind::BadValue, "must be positive and finite"},
           Case{"<drake:plane_normal xyz='0 0 0'/>", DiagKind::ZeroAxis,
                "<drake:plane_normal> is zero"},
           Case{"<drake:initial_tangent xyz='0 0 0'/>", DiagKind::ZeroAxis,
                "<drake:initial_tangent> is zero"},
           Case{"<drake:initial_tangent/>", DiagKind::MissingAttribute, "'xyz'"},
           Case{"<drake:initial_tangent xyz='1 0 0.001'/>", DiagKind::BadValue,
                "is not perpendicular to the plane normal"},
           Case{"<drake:plane_normal xyz='1 0 0'/>", DiagKind::BadValue,
                "is not perpendicular to the plane normal"},
       }) {
    Lowered l;
    const bool has_curves = c.body.find("drake:curves") != std::string_view::npos;
    EXPECT_FALSE(
        l.Read(SixLinkRobot(fmt::format(R"(<drake:joint name='c' type='curvilinear'>
        <parent link='a'/><child link='b'/>{}{}</drake:joint>)",
                                        c.body, has_curves || c.body.empty() ? "" : line))))
        << c.body;
    EXPECT_TRUE(l.HasDiagnostic(c.kind, c.message)) << c.body << "\n" << l.Messages();
    EXPECT_EQ(l.diags.error_count(), 1u) << c.body << "\n" << l.Messages();
    for (const auto& d : l.diags.diagnostics()) EXPECT_TRUE(d.loc.valid()) << d.message;
    // the joint is still declared (no cascading errors), with no path
    ASSERT_NE(l.Joint("c"), nullptr);
    EXPECT_TRUE(l.Joint("c")->curvilinear_path.segments.empty());
  }
}

TEST(UrdfDrakeJointTest, EveryCurveErrorIsReportedInOneRun) {  // EXT-003
  Lowered l;
  EXPECT_FALSE(l.Read(SixLinkRobot(R"(<drake:joint name='c' type='curvilinear'>
      <parent link='a'/><child link='b'/>
      <drake:curves>
        <drake:line_segment length='-1'/>
        <drake:circular_arc radius='-1' angle='0'/>
        <drake:bezier/>
      </drake:curves></drake:joint>)")));
  EXPECT_EQ(l.diags.error_count(), 4u) << l.Messages();
  l.ExpectDiagnostic(DiagKind::BadValue, "");  // the four errors, counted above
}

// ------------------------------------------- compiled plant, poses at q

/// Compiles URDF text through the whole pipeline (frontend, passes, backend).
class CompiledUrdf {
 public:
  explicit CompiledUrdf(const std::string& text) {
    path_ = std::filesystem::temp_directory_path() /
            fmt::format("mdlc_drake_joint_{}_{}.urdf", ::getpid(),
                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::ofstream(path_) << text;
    c_.options.inputs = {Input::File(path_.string())};
    ok_ = c_.Run();
  }
  ~CompiledUrdf() { std::filesystem::remove(path_); }

  bool ok() const { return ok_; }
  std::string Messages() const {
    std::string out;
    for (const auto& d : c_.diags.diagnostics()) out += d.message + "\n";
    return out;
  }
  const backend::Plant& plant() const { return c_.model->plant; }
  /// The plant-json dump at q, with `positions` set by joint name.
  nlohmann::json PlantJson(std::initializer_list<std::pair<std::string_view, double>> positions) {
    Eigen::VectorXd q = backend::DefaultPositions(plant());
    for (auto [name, value] : positions) {
      EXPECT_TRUE(backend::SetJointPositionByName(plant(), q, name, value)) << name;
    }
    return nlohmann::json::parse(backend::EmitPlantJson(*c_.model, q));
  }

 private:
  std::filesystem::path path_;
  Compilation c_;
  bool ok_ = false;
};

/// X_WB of body `name` from a plant-json dump.
Transform BodyPose(const nlohmann::json& json, std::string_view name) {
  for (const auto& body : json["bodies"]) {
    if (body["name"] == name) {
      const auto& p = body["X_WB"]["p"];
      const auto& q = body["X_WB"]["q"];
      Transform X;
      X.p = Eigen::Vector3d(p[0], p[1], p[2]);
      X.R = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
      return X;
    }
  }
  ADD_FAILURE() << "no body " << name;
  return {};
}

constexpr std::string_view kMovingJoints = R"(<?xml version="1.0"?>
<robot name="moving">
  <link name="nut"/>
  <link name="cart"/>
  <link name="slider"/>
  <drake:joint name="screw" type="screw">
    <parent link="world"/><child link="nut"/>
    <origin xyz="0 0 1"/>
    <axis xyz="0 0 1"/>
    <drake:screw_thread_pitch value="0.04"/>
  </drake:joint>
  <drake:joint name="track" type="curvilinear">
    <parent link="world"/><child link="cart"/>
    <origin xyz="0 0 0.5"/>
    <drake:curves>
      <drake:line_segment length="1"/>
      <drake:circular_arc radius="0.5" angle="1.5707963267948966"/>
    </drake:curves>
  </drake:joint>
  <drake:joint name="rail" type="curvilinear">
    <parent link="world"/><child link="slider"/>
    <origin xyz="3 2 1"/>
    <drake:initial_tangent xyz="0 0 1"/>
    <drake:plane_normal xyz="1 0 0"/>
    <drake:curves>
      <drake:line_segment length="1"/>
      <drake:circular_arc radius="2" angle="-1.5707963267948966"/>
    </drake:curves>
  </drake:joint>
</robot>
)";

TEST(UrdfDrakeJointTest, ScrewJointPoseInThePlant) {  // EXT-001, EXT-002
  CompiledUrdf c{std::string(kMovingJoints)};
  ASSERT_TRUE(c.ok()) << c.Messages();
  // a quarter turn of a 0.04 m/rev thread advances 0.01 m along the axis
  const Transform X = BodyPose(c.PlantJson({{"screw", kPi / 2}}), "nut");
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(0, 0, 1.01), 1e-12)) << X.p.transpose();
  EXPECT_TRUE(X.R.isApprox(Rz(kPi / 2), 1e-12));
  const nlohmann::json json = c.PlantJson({});
  for (const auto& joint : json["joints"]) {
    if (joint["name"] == "screw") {
      EXPECT_EQ(joint["screw_thread_pitch"], 0.04);
    }
  }
}

TEST(UrdfDrakeJointTest, CurvilinearJointPoseInThePlant) {  // EXT-001, EXT-003
  CompiledUrdf c{std::string(kMovingJoints)};
  ASSERT_TRUE(c.ok()) << c.Messages();
  // q = 0: at the joint origin, unrotated (default tangent x, normal z)
  Transform X = BodyPose(c.PlantJson({}), "cart");
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(0, 0, 0.5), 1e-12));
  EXPECT_TRUE(X.R.isApprox(Eigen::Matrix3d::Identity(), 1e-12));
  // after the 1 m line and half of the quarter arc (radius 0.5, turning
  // left about +z, centre at (1, 0.5)): 45 degrees round the arc
  X = BodyPose(c.PlantJson({{"track", 1 + 0.5 * kPi / 4}}), "cart");
  const double h = std::sqrt(0.5) * 0.5;
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(1 + h, 0.5 - h, 0.5), 1e-12)) << X.p.transpose();
  EXPECT_TRUE(X.R.isApprox(Rz(kPi / 4), 1e-12));
  // at the end of the quarter arc: at (1.5, 0.5), heading +y
  X = BodyPose(c.PlantJson({{"track", 1 + 0.5 * kPi / 2}}), "cart");
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(1.5, 0.5, 0.5), 1e-12)) << X.p.transpose();
  EXPECT_TRUE(X.R.isApprox(Rz(kPi / 2), 1e-12));
  // an open path limits q to [0, length]
  const auto json = c.PlantJson({});  // kept: the loop reads into it
  for (const auto& joint : json["joints"]) {
    if (joint["name"] != "track") continue;
    EXPECT_EQ(joint["lower"][0], 0.0);
    EXPECT_DOUBLE_EQ(joint["upper"][0].get<double>(), 1 + 0.5 * kPi / 2);
  }
}

TEST(UrdfDrakeJointTest, CurvilinearJointInATiltedPlane) {  // EXT-003
  CompiledUrdf c{std::string(kMovingJoints)};
  ASSERT_TRUE(c.ok()) << c.Messages();
  // tangent +z, normal +x: the path frame starts as [x y z] = [Fz, -Fy, Fx].
  // A 1 m line then a right turn (angle < 0) of radius 2 through 90 degrees
  // ends 1 + 2 along the start tangent and 2 to the right (-(-Fy) = +Fy)...
  // in F: (0, 2, 3); heading along +Fy, so the frame is [Fy, Fz, Fx].
  const Transform X = BodyPose(c.PlantJson({{"rail", 1 + kPi}}), "slider");
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(3, 2 + 2, 1 + 3), 1e-12)) << X.p.transpose();
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d::UnitY();
  R.col(1) = Eigen::Vector3d::UnitZ();
  R.col(2) = Eigen::Vector3d::UnitX();
  EXPECT_TRUE(X.R.isApprox(R, 1e-12)) << X.R;
}

}  // namespace
}  // namespace mdlc
