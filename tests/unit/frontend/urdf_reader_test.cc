// The URDF frontend: what each element lowers to (URDF-001..041).
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/urdf_test_util.h"

namespace mdlc {
namespace {

using testing::Lowered;

TEST(UrdfReaderTest, RobotNameIsTheModelInstance) {  // COMMON-020, COMMON-021
  Lowered l;
  ASSERT_TRUE(l.Read("<robot name='arm'><link name='a'/></robot>")) << l.Messages();
  ASSERT_EQ(l.module.models.size(), 3u);
  EXPECT_EQ(l.module.ModelName(ModelId(uint32_t{0})), "WorldModelInstance");
  EXPECT_EQ(l.module.ModelName(ModelId(uint32_t{1})), "DefaultModelInstance");
  EXPECT_EQ(l.module.ModelName(ModelId(uint32_t{2})), "arm");
}

TEST(UrdfReaderTest, InstanceNameCollisionIsAnErrorUnlessAutoRenamed) {  // COMMON-022
  Lowered l;
  ASSERT_TRUE(l.Read("<robot name='arm'><link name='a'/></robot>"));
  EXPECT_FALSE(l.Read("<robot name='arm'><link name='a'/></robot>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::DuplicateName, "already exists"));
  Lowered r;
  frontend::FrontendOptions rename;
  rename.auto_rename = true;
  ASSERT_TRUE(r.Read("<robot name='arm'><link name='a'/></robot>", rename));
  ASSERT_TRUE(r.Read("<robot name='arm'><link name='a'/></robot>", rename));
  ASSERT_TRUE(r.Read("<robot name='arm'><link name='a'/></robot>", rename));
  EXPECT_EQ(r.module.ModelName(ModelId(uint32_t{3})), "arm_1");
  EXPECT_EQ(r.module.ModelName(ModelId(uint32_t{4})), "arm_2");
}

TEST(UrdfReaderTest, InertialKeepsItsFrameForTheBackend) {  // URDF-004, URDF-005
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'><inertial>
      <origin xyz='1 2 3' rpy='0.1 0.2 0.3'/><mass value='4'/>
      <inertia ixx='1' iyy='2' izz='2.5' ixy='0.1' ixz='0.2' iyz='0.3'/>
    </inertial></link></robot>)"))
      << l.Messages();
  const ir::Body* a = l.Body("a");
  ASSERT_TRUE(a && a->inertial);
  EXPECT_EQ(a->inertial->mass, 4);
  EXPECT_EQ(a->inertial->X_BI.p, Eigen::Vector3d(1, 2, 3));
  // fixed-axis rpy: R = Rz(yaw) Ry(pitch) Rx(roll)
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                                       .toRotationMatrix();
  EXPECT_TRUE(a->inertial->X_BI.R.isApprox(expected, 1e-15));
  EXPECT_EQ(a->inertial->ixy, 0.1);
  EXPECT_EQ(a->inertial->iyz, 0.3);
}

TEST(UrdfReaderTest, MissingInertialMeansMassless) {  // URDF-004
  Lowered l;
  ASSERT_TRUE(l.Read("<robot name='r'><link name='a'/></robot>"));
  EXPECT_FALSE(l.Body("a")->inertial.has_value());
}

TEST(UrdfReaderTest, WorldLinkIsTheWorldBody) {  // URDF-003
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
    <link name='world'><visual><geometry><box size='1 1 1'/></geometry></visual></link>
    <link name='a'/>
    <joint name='j' type='fixed'><parent link='world'/><child link='a'/></joint>
  </robot>)"));
  EXPECT_EQ(l.module.bodies.size(), 2u);  // world + a
  ASSERT_EQ(l.module.geometries.size(), 1u);
  EXPECT_EQ(l.module.geometries[0].body.id, ir::kWorldBody);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_EQ(l.Joint("j")->parent.id, ir::kWorldBody);
}

TEST(UrdfReaderTest, JointTypesAndDefaults) {  // URDF-011..014
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
    <link name='a'/><link name='b'/><link name='c'/><link name='d'/><link name='e'/>
    <joint name='rev' type='revolute'><parent link='a'/><child link='b'/>
      <axis xyz='0 0 2'/><limit lower='-1' upper='1' effort='3' velocity='4'/></joint>
    <joint name='cont' type='continuous'><parent link='a'/><child link='c'/>
      <limit lower='-1' upper='1' velocity='7'/><dynamics damping='0.25'/></joint>
    <joint name='pri' type='prismatic'><parent link='a'/><child link='d'/></joint>
    <joint name='fix' type='fixed'><parent link='a'/><child link='e'/><axis xyz='0 0 0'/></joint>
  </robot>)"))
      << l.Messages();
  const ir::Joint* rev = l.Joint("rev");
  EXPECT_EQ(rev->type, ir::JointType::Revolute);
  EXPECT_EQ(rev->axis, Eigen::Vector3d(0, 0, 1));  // normalised
  EXPECT_EQ(rev->limits.lower[0], -1);
  EXPECT_EQ(rev->limits.effort[0], 3);
  EXPECT_EQ(rev->limits.velocity_upper[0], 4);
  const ir::Joint* cont = l.Joint("cont");
  EXPECT_EQ(cont->type, ir::JointType::Revolute);
  EXPECT_TRUE(std::isinf(cont->limits.lower[0]));  // continuous: bounds ignored
  EXPECT_EQ(cont->limits.velocity_upper[0], 7);
  EXPECT_EQ(cont->damping[0], 0.25);
  EXPECT_EQ(l.Joint("pri")->axis, Eigen::Vector3d(1, 0, 0));  // default axis
  EXPECT_TRUE(std::isinf(l.Joint("pri")->limits.upper[0]));   // no <limit>: unbounded
  EXPECT_EQ(l.Joint("fix")->type, ir::JointType::Weld);       // axis ignored for fixed
}

TEST(UrdfReaderTest, FloatingJointLeavesAFreeBody) {  // URDF-012
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/>
    <joint name='float' type='floating'><parent link='a'/><child link='b'/></joint></robot>)"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::FloatingJoint, "free body"));
  EXPECT_EQ(l.Joint("float"), nullptr);
  ASSERT_TRUE(l.RunPasses());
  // both roots get a quaternion floating joint named after the body (URDF-017)
  ASSERT_NE(l.Joint("b"), nullptr);
  EXPECT_EQ(l.Joint("b")->type, ir::JointType::QuaternionFloating);
  EXPECT_TRUE(l.Joint("b")->unnamed);
}

TEST(UrdfReaderTest, PlanarJointMovesInThePlaneNormalToItsAxis) {  // URDF-012
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/>
    <joint name='p' type='planar'><parent link='a'/><child link='b'/><axis xyz='1 0 0'/>
    <dynamics damping='1 2 3'/></joint></robot>)"))
      << l.Messages();
  const ir::Joint* p = l.Joint("p");
  EXPECT_EQ(p->type, ir::JointType::Planar);
  // Drake's planar frame has z along the URDF axis
  EXPECT_TRUE((p->X_PF.R * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(p->X_CM.R.isApprox(p->X_PF.R));
  EXPECT_EQ(p->damping, (std::vector<double>{1, 2, 3}));
}

TEST(UrdfReaderTest, GeometryRolesShapesAndNames) {  // URDF-031, URDF-032, URDF-040
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'>
    <visual><geometry><box size='1 2 3'/></geometry></visual>
    <visual><geometry><box size='1 1 1'/></geometry></visual>
    <collision><geometry><box size='1 1 1'/></geometry></collision>
    <collision><geometry><capsule radius='0.1' length='0.5'/></geometry></collision>
    <collision><geometry><drake:ellipsoid a='1' b='2' c='3'/></geometry></collision>
    <visual name='m'><geometry><mesh filename='x.obj' scale='2'/></geometry></visual>
    <collision><geometry><mesh filename='y.obj' scale='1 2 3'/><drake:declare_convex/></geometry></collision>
  </link></robot>)"))
      << l.Messages();
  const auto& g = l.module.geometries;
  ASSERT_EQ(g.size(), 7u);
  EXPECT_EQ(l.module.Text(g[0].name), "Box");
  EXPECT_EQ(l.module.Text(g[1].name), "Box_1");  // same link and role
  EXPECT_EQ(l.module.Text(g[2].name), "Box");    // other role: no clash
  EXPECT_EQ(g[0].roles, ir::kIllustrationRole | ir::kPerceptionRole);
  EXPECT_EQ(g[2].roles, ir::kProximityRole);
  EXPECT_EQ(std::get<ir::Box>(g[0].shape).size, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(std::get<ir::Capsule>(g[3].shape).length, 0.5);
  EXPECT_EQ(std::get<ir::Ellipsoid>(g[4].shape).c, 3);
  EXPECT_EQ(std::get<ir::Mesh>(g[5].shape).scale, Eigen::Vector3d(2, 2, 2));
  EXPECT_EQ(l.module.Text(g[5].name), "m");
  EXPECT_TRUE(std::get<ir::Mesh>(g[6].shape).convex);
  EXPECT_EQ(ir::ShapeTypeName(g[6].shape), "convex");
}

// pybullet's racecar writes <material> inside <geometry>: urdfdom and Drake
// read the shape beside it, and so does mdlc, with a warning
TEST(UrdfReaderTest, AnElementBesideTheShapeIsIgnoredAndTheShapeRead) {  // issue 55, URDF-031
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'>
    <visual><geometry><box size='1 2 3'/><material name='grey'/></geometry></visual>
    <collision><geometry><origin xyz='0 0 1'/><sphere radius='0.5'/></geometry></collision>
  </link></robot>)"))
      << l.Messages();
  const auto& g = l.module.geometries;
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(std::get<ir::Box>(g[0].shape).size, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(std::get<ir::Sphere>(g[1].shape).radius, 0.5);
  // the misplaced <origin> does not move the geometry
  EXPECT_EQ(g[1].X_BG.p, Eigen::Vector3d::Zero());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "element <material> in <geometry> is ignored"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "element <origin> in <geometry> is ignored"));
}

TEST(UrdfReaderTest, ExplicitDuplicateGeometryNameIsRenamedWithAWarning) {  // URDF-040
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'>
    <collision name='c'><geometry><sphere radius='1'/></geometry></collision>
    <collision name='c'><geometry><sphere radius='1'/></geometry></collision>
  </link></robot>)"));
  EXPECT_EQ(l.module.Text(l.module.geometries[1].name), "c_1");
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::RenamedDuplicate, "renamed to 'c_1'"));
}

TEST(UrdfReaderTest, MaterialsByNameInlineAndReused) {  // URDF-030
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
    <link name='a'>
      <visual><geometry><sphere radius='1'/></geometry><material name='late'/></visual>
      <visual><geometry><sphere radius='1'/></geometry>
        <material name='inline'><color rgba='0 1 0 1'/></material></visual>
      <visual><geometry><sphere radius='1'/></geometry><material name='inline'/></visual>
    </link>
    <material name='late'><color rgba='1 0 0 0.5'/></material>
    <material name='late'><color rgba='1 0 0 0.5'/></material>
  </robot>)"))
      << l.Messages();
  const auto& g = l.module.geometries;
  EXPECT_EQ(*g[0].rgba, Eigen::Vector4d(1, 0, 0, 0.5));  // defined later in the file
  EXPECT_EQ(*g[1].rgba, Eigen::Vector4d(0, 1, 0, 1));
  EXPECT_EQ(*g[2].rgba, Eigen::Vector4d(0, 1, 0, 1));    // inline definition reused
  EXPECT_EQ(l.diags.error_count(), 0u);                  // identical redefinition is fine
}

TEST(UrdfReaderTest, RgbaOutsideUnitIntervalIsAnError) {  // URDF-030
  Lowered l;
  EXPECT_FALSE(l.Read(R"(<robot name='r'><material name='m'><color rgba='2 0 0 1'/></material>
    <link name='a'/></robot>)"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "within [0, 1]"));
}

TEST(UrdfReaderTest, DrakeIgnoreSkipsLinksAndJoints) {  // URDF-002
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b' drake_ignore='true'/>
    <joint name='j' type='fixed' drake_ignore='true'><parent link='a'/><child link='b'/></joint>
  </robot>)"));
  EXPECT_EQ(l.Body("b"), nullptr);
  EXPECT_EQ(l.Joint("j"), nullptr);
  EXPECT_EQ(l.diags.diagnostics().size(), 0u);
}

TEST(UrdfReaderTest, FramesAttachToLinks) {  // URDF-041
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/>
    <frame name='tool' link='a' xyz='0 0 1' rpy='0 0 1.5'/></robot>)"));
  ASSERT_EQ(l.module.frames.size(), 1u);
  EXPECT_EQ(l.module.frames[0].X_BF.p, Eigen::Vector3d(0, 0, 1));
  ASSERT_TRUE(l.RunPasses());
  EXPECT_EQ(l.module.frames[0].body.id, BodyId(uint32_t{1}));
  Lowered bad;
  EXPECT_FALSE(bad.Read("<robot name='r'><link name='a'/><frame name='f'/></robot>"));
  EXPECT_TRUE(bad.HasDiagnostic(DiagKind::MissingAttribute, "'link'"));
}

TEST(UrdfReaderTest, TransmissionsMakeActuators) {  // URDF-020..024
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/><link name='c'/>
    <transmission name='t1' type='SimpleTransmission'>
      <joint name='j'/><actuator name='motor'><mechanicalReduction>50</mechanicalReduction></actuator>
    </transmission>
    <transmission><type>Differential</type><joint name='j'/><actuator name='x'/></transmission>
    <transmission><type>SimpleTransmission</type><joint name='w'/><actuator name='y'/></transmission>
    <joint name='j' type='revolute'><parent link='a'/><child link='b'/>
      <limit lower='-1' upper='1' effort='12' velocity='1'/></joint>
    <joint name='w' type='fixed'><parent link='a'/><child link='c'/></joint>
  </robot>)"))
      << l.Messages();
  ASSERT_EQ(l.module.actuators.size(), 1u);
  EXPECT_EQ(l.module.Text(l.module.actuators[0].name), "motor");
  EXPECT_EQ(l.module.actuators[0].effort_limit, 12);
  EXPECT_EQ(l.module.actuators[0].gear_ratio, 1);  // mechanicalReduction is not applied
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "mechanicalReduction"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "Differential"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::ActuatorWarning, "fixed joint 'w'"));
  // the actuator takes its name from <actuator>, as in Drake
  l.ExpectDiagnostic(DiagKind::UnsupportedAttribute, "attribute 'name' of <transmission>");
}

TEST(UrdfReaderTest, ZeroEffortMakesNoActuator) {  // URDF-021
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/>
    <joint name='j' type='continuous'><parent link='a'/><child link='b'/><limit effort='0'/></joint>
    <transmission><type>SimpleTransmission</type><joint name='j'/><actuator name='m'/></transmission>
  </robot>)"));
  EXPECT_TRUE(l.module.actuators.empty());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::ActuatorWarning, "effort limit of zero"));
}

TEST(UrdfReaderTest, MimicBecomesACouplerConstraint) {  // URDF-018
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/><link name='c'/>
    <joint name='follower' type='continuous'><parent link='a'/><child link='c'/>
      <mimic joint='leader' multiplier='2' offset='0.5'/></joint>
    <joint name='leader' type='continuous'><parent link='a'/><child link='b'/></joint>
  </robot>)"));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();  // forward reference resolved
  ASSERT_EQ(l.module.constraints.size(), 1u);
  ASSERT_EQ(l.module.constraints[0].type(), ir::ConstraintType::Coupler);
  const auto& c = l.module.constraints[0].As<ir::CouplerConstraint>();
  // Drake's AddCouplerConstraint(joint0, joint1): q0 = gear * q1 + offset, and
  // Drake passes the joint holding <mimic> as joint0
  EXPECT_EQ(l.module.Text(l.module[c.joint0.id].name), "follower");
  EXPECT_EQ(l.module.Text(l.module[c.joint1.id].name), "leader");
  EXPECT_EQ(c.gear_ratio, 2);
  EXPECT_EQ(c.offset, 0.5);
}

TEST(UrdfReaderTest, MimicOnAFixedJointIsIgnoredWithAWarning) {  // URDF-018
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'><link name='a'/><link name='b'/><link name='c'/>
    <joint name='leader' type='continuous'><parent link='a'/><child link='b'/></joint>
    <joint name='follower' type='fixed'><parent link='a'/><child link='c'/>
      <mimic joint='leader'/></joint>
  </robot>)"));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_TRUE(l.module.constraints.empty());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::JointWarning, "single-dof"));
}

TEST(UrdfReaderTest, ManyIndependentErrorsInOneRun) {
  Lowered l;
  EXPECT_FALSE(l.Read(R"(<robot name='r'>
    <link/>
    <link name='a'><inertial><mass value='x'/></inertial></link>
    <joint name='j' type='bogus'><parent link='a'/><child link='a'/></joint>
    <joint type='fixed'/>
  </robot>)"));
  EXPECT_GE(l.diags.error_count(), 4u) << l.Messages();
  l.ExpectDiagnostic(DiagKind::MissingAttribute, "<link> is missing required attribute 'name'");
  l.ExpectDiagnostic(DiagKind::BadValue, "attribute 'value' of <mass>");
  l.ExpectDiagnostic(DiagKind::BadValue, "unrecognized type 'bogus'");
  l.ExpectDiagnostic(DiagKind::MissingAttribute, "<joint> is missing required attribute 'name'");
  l.ExpectDiagnostic(DiagKind::MissingElement, "missing its <parent> element");
  l.ExpectDiagnostic(DiagKind::MissingElement, "missing its <child> element");
}

}  // namespace
}  // namespace mdlc
