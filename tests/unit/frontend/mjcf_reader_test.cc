// mjcf_reader_test.cc - the MJCF frontend core: document and includes
// (MJCF-001), settings (MJCF-002..007), defaults (MJCF-011, MJCF-012), poses
// (MJCF-010), bodies and joints (MJCF-020..024, BEYOND-007), geoms
// (MJCF-040..043, BEYOND-002), sites and frames (BEYOND-004), cameras
// (MJCF-090). Numbers marked "MuJoCo 3.3.8" were read from mjModel/mjData
// compiled by mujoco-js 0.0.7 from the same XML.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "tests/unit/mjcf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc {
namespace {

using testing::kTol;
using testing::LoweredMjcf;
constexpr uint8_t kVisual = ir::kIllustrationRole | ir::kPerceptionRole;
constexpr uint8_t kCollision = ir::kProximityRole;

Eigen::Matrix3d Rx(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix(); }

std::string Model(std::string_view body) {
  return fmt::format("<mujoco model=\"m\">\n{}\n</mujoco>\n", body);
}

TEST(MjcfReader, Common021ModelNameAndBodyNames) {
  LoweredMjcf r(Model(R"(<worldbody><body><geom size="0.1"/><body><geom size="0.1"/></body></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_EQ(r.module.ModelName(*r.model), "m");
  // MJCF-020: Drake's body<N> counts the plant's bodies (world is 0)
  ASSERT_NE(r.Body("body1"), nullptr);
  ASSERT_NE(r.Body("body2"), nullptr);
  const ir::Joint* weld = r.Joint("body1_welds_to_body2");
  ASSERT_NE(weld, nullptr);
  EXPECT_TRUE(weld->unnamed);
}

TEST(MjcfReader, Common021MissingModelNameUsesFileStemWithWarning) {
  LoweredMjcf r("<mujoco><worldbody/></mujoco>");
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_EQ(r.module.ModelName(*r.model), "model");
  EXPECT_NE(r.Find(DiagKind::MissingModelName), nullptr);
}

TEST(MjcfReader, Mjcf001IncludeExpandsInPlaceRelativeToMainFile) {
  LoweredMjcf r(Model(R"(<worldbody><include file="parts/arm.xml"/></worldbody>)"),
                {{"parts/arm.xml", R"(<mujoco><body name="arm"><geom size="1"/>
                   <include file="parts/hand.xml"/></body></mujoco>)"},
                 {"parts/hand.xml", R"(<mujoco><body name="hand"><geom size="1"/></body></mujoco>)"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  ASSERT_NE(r.Body("arm"), nullptr);
  ASSERT_NE(r.Body("hand"), nullptr);
  EXPECT_NE(r.Joint("arm_welds_to_hand"), nullptr);
}

TEST(MjcfReader, Mjcf001NestedIncludeFallsBackToIncludingFilesDirectory) {
  LoweredMjcf r(Model(R"(<worldbody><include file="parts/arm.xml"/></worldbody>)"),
                {{"parts/arm.xml", R"(<mujoco><include file="hand.xml"/></mujoco>)"},
                 {"parts/hand.xml", R"(<mujoco><body name="hand"><geom size="1"/></body></mujoco>)"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Body("hand"), nullptr);
}

TEST(MjcfReader, Mjcf001IncludeCycleIsLocatedErrorWithChain) {
  LoweredMjcf r(Model(R"(<include file="a.xml"/>)"),
                {{"a.xml", "<mujoco><include file=\"b.xml\"/></mujoco>"},
                 {"b.xml", "<mujoco>\n  <include file=\"a.xml\"/></mujoco>"}});
  EXPECT_FALSE(r.ok());
  const Diagnostic* d = r.Find(DiagKind::IncludeCycle);
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_EQ(d->loc.column, 12u);  // at the file attribute
  EXPECT_EQ(d->notes.size(), 2u);  // model.xml -> a.xml -> b.xml
  EXPECT_TRUE(r.sources.IncludedFrom(d->loc.file).valid());
}

TEST(MjcfReader, Mjcf001RepeatedAndMissingIncludesAreErrors) {
  LoweredMjcf r(Model(R"(<include file="a.xml"/><include file="a.xml"/><include file="nope.xml"/>)"),
                {{"a.xml", "<mujoco><size/></mujoco>"}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.Find(DiagKind::DuplicateInclude, "already included"), nullptr) << r.Messages();
  EXPECT_NE(r.Find(DiagKind::FileNotFound, "nope.xml"), nullptr) << r.Messages();
}

// MJCF-020, MJCF-022, MJCF-040: a body, joint, geom or site name used twice
// is an error at the second, with a note at the first; a reference by that
// name (the motor's joint) finds the first.
TEST(MjcfReader, Mjcf020RepeatedNamesAreLocatedErrorsAndReferencesFindTheFirst) {
  LoweredMjcf r(Model(R"(<worldbody>
  <body name="a"><joint name="j"/><geom name="g" size="1"/><site name="s"/>
    <body name="a"><joint name="j"/><geom name="g" size="1"/><site name="s"/></body>
  </body>
</worldbody>
<actuator><motor joint="j"/></actuator>)"));
  EXPECT_FALSE(r.ok());
  for (std::string_view what : {"body name 'a'", "joint name 'j'", "geom name 'g'",
                                "site name 's'"}) {
    const Diagnostic* d = r.Find(DiagKind::DuplicateName, fmt::format("repeated {}", what));
    ASSERT_NE(d, nullptr) << what << "\n" << r.Messages();
    EXPECT_EQ(d->severity, Severity::Error) << what;
    EXPECT_EQ(d->loc.line, 4u) << what;  // the second, inner one
    ASSERT_EQ(d->notes.size(), 1u) << what;
    EXPECT_EQ(d->notes[0].loc.line, 3u) << what;  // the first
  }
  ASSERT_EQ(r.module.actuators.size(), 1u);
  const JointId motor_joint = r.module.actuators[0].joint.id;
  ASSERT_TRUE(motor_joint.valid());
  EXPECT_EQ(r.module[motor_joint].loc.line, 3u);
}

TEST(MjcfReader, Mjcf011DefaultsInheritAndChildclassApplies) {
  LoweredMjcf r(Model(R"(
  <default><geom type="box" size="1 2 3"/>
    <default class="a"><geom size="0.5"/></default>
  </default>
  <worldbody><body name="b" childclass="a"><geom name="g1"/><geom name="g2" class="main"/>
    <body name="c"><geom name="g3"/></body></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  auto box = [&](std::string_view name) {
    const ir::Geometry* g = r.Geometry(name, kCollision);
    EXPECT_NE(g, nullptr) << name;
    return g ? std::get<ir::Box>(g->shape).size : Eigen::Vector3d::Zero().eval();
  };
  // size="0.5" overwrites only the first value (MuJoCo reads it element-wise)
  EXPECT_TRUE(box("g1").isApprox(Eigen::Vector3d(1, 4, 6)));
  EXPECT_TRUE(box("g2").isApprox(Eigen::Vector3d(2, 4, 6)));
  EXPECT_TRUE(box("g3").isApprox(Eigen::Vector3d(1, 4, 6)));  // childclass reaches nested bodies
}

TEST(MjcfReader, Mjcf012DefaultAlternativeOrientationWinsOverOwnQuat) {
  // MuJoCo 3.3.8: geom_quat of both geoms is (0.7071, 0.7071, 0, 0)
  LoweredMjcf r(Model(R"(<default><geom euler="90 0 0" size="0.1"/></default>
  <worldbody><geom name="a" quat="1 0 0 0"/><geom name="b"/><geom name="c" zaxis="1 0 0"/></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_TRUE(r.Geometry("a", kVisual)->X_BG.R.isApprox(Rx(M_PI / 2), kTol));
  EXPECT_TRUE(r.Geometry("b", kVisual)->X_BG.R.isApprox(Rx(M_PI / 2), kTol));
  EXPECT_TRUE(r.Geometry("c", kVisual)->X_BG.R.col(2).isApprox(Eigen::Vector3d::UnitX(), kTol));
}

TEST(MjcfReader, Mjcf012UnknownClassIsLocatedError) {
  LoweredMjcf r(Model(R"(<worldbody><geom class="nope" size="1"/></worldbody>)"));
  const Diagnostic* d = r.Find(DiagKind::UnknownReference, "nope");
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_EQ(d->loc.column, 18u);
}

TEST(MjcfReader, Mjcf010MoreThanOneOrientationIsError) {
  LoweredMjcf r(Model(R"(<worldbody><body quat="1 0 0 0" euler="0 0 0"/></worldbody>)"));
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.Find(DiagKind::BadValue, "more than one orientation"), nullptr) << r.Messages();
}

TEST(MjcfReader, Mjcf002AngleUnitsApplyToEulerRangeAndRef) {
  for (const char* unit : {"degree", "radian"}) {
    const bool deg = std::string(unit) == "degree";
    const double a = deg ? 90 : M_PI / 2;
    LoweredMjcf r(Model(fmt::format(
        R"(<compiler angle="{0}"/><worldbody><body name="b" euler="{1} 0 0"><geom size="1"/>
           <joint name="j" range="-{1} {1}" ref="{1}"/></body></worldbody>)", unit, a)));
    ASSERT_TRUE(r.ok()) << r.Messages();
    const ir::Joint* j = r.Joint("j");
    ASSERT_NE(j, nullptr);
    EXPECT_NEAR(j->limits.upper[0], M_PI / 2, kTol) << unit;
    EXPECT_NEAR(j->default_positions[0], M_PI / 2, kTol) << unit;
    EXPECT_TRUE(j->X_PF.R.isApprox(Rx(M_PI / 2), kTol)) << unit;
  }
}

TEST(MjcfReader, Mjcf022JointNamesTypesLimitsAndDamping) {
  LoweredMjcf r(Model(R"(<worldbody><body name="p"><geom size="1"/>
    <body name="c"><geom size="1"/><joint type="slide" axis="0 2 0" range="0 1" damping="3"/></body>
    <body name="d"><geom size="1"/><joint name="ball" type="ball" damping="2"/></body>
  </body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Joint* slide = r.Joint("p-c");
  ASSERT_NE(slide, nullptr);
  EXPECT_TRUE(slide->unnamed);
  EXPECT_EQ(slide->type, ir::JointType::Prismatic);
  EXPECT_TRUE(slide->axis.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_EQ(slide->limits.lower[0], 0);
  EXPECT_EQ(slide->limits.upper[0], 1);
  EXPECT_EQ(slide->damping, std::vector<double>{3});
  const ir::Joint* ball = r.Joint("ball");
  ASSERT_NE(ball, nullptr);
  EXPECT_EQ(ball->type, ir::JointType::Ball);
  EXPECT_EQ(ball->damping, std::vector<double>(3, 2.0));
}

TEST(MjcfReader, Mjcf004AutolimitsOffWithRangeIsError) {
  LoweredMjcf r(Model(R"(<compiler autolimits="false"/><worldbody><body><geom size="1"/>
    <joint range="0 1"/></body></worldbody>)"));
  EXPECT_NE(r.Find(DiagKind::BadValue, "autolimits"), nullptr) << r.Messages();
}

/// X_PB(q) of a stacked chain from the IR: each joint X_PF * motion * X_CM^-1.
Transform ChainPose(const ir::Module& m, const std::vector<const ir::Joint*>& chain,
                    const std::vector<double>& q) {
  Transform X;
  for (size_t k = 0; k < chain.size(); ++k) {
    const ir::Joint& j = *chain[k];
    Transform motion;
    if (j.type == ir::JointType::Revolute) motion.R = RotationAboutAxis(j.axis, q[k]);
    if (j.type == ir::JointType::Prismatic) motion.p = j.axis * q[k];
    X = X * j.X_PF * motion * j.X_CM.inverse();
  }
  return X;
}

TEST(MjcfReader, Mjcf023StackedJointsFollowMuJoCo) {
  LoweredMjcf r(Model(R"(<worldbody><body name="p" pos="0 0 1"><geom size="0.1"/>
<body name="b" pos="1 0 0" euler="0 0 90"><geom size="0.1"/>
<joint type="hinge" axis="0 0 1" pos="0.5 0 0"/><joint type="hinge" axis="1 0 0" pos="0 0.2 0" ref="30"/><joint type="slide" axis="0 1 1" ref="0.1"/>
</body></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  // Drake's layout: massless b0, b1 between p and b, joints named parent-child
  const ir::Joint* j0 = r.Joint("p-b0");
  const ir::Joint* j1 = r.Joint("b0-b1");
  const ir::Joint* j2 = r.Joint("b1-b");
  ASSERT_TRUE(j0 && j1 && j2) << r.Messages();
  EXPECT_FALSE(r.Body("b0")->inertial.has_value());
  EXPECT_NEAR(j1->default_positions[0], M_PI / 6, kTol);
  EXPECT_NEAR(j2->default_positions[0], 0.1, kTol);
  // at qpos0 the body sits at its XML pose
  const Transform X0 = ChainPose(r.module, {j0, j1, j2}, {0, M_PI / 6, 0.1});
  EXPECT_TRUE(X0.p.isApprox(Eigen::Vector3d(1, 0, 0), kTol));
  // MuJoCo 3.3.8 at qpos = (0.3, 0.7, 0.25): body b's xpos and xquat
  const Transform X = Transform::FromTranslation({0, 0, 1}) * ChainPose(r.module, {j0, j1, j2}, {0.3, 0.7, 0.25});
  EXPECT_TRUE(X.p.isApprox(Eigen::Vector3d(1.0628207245961383, -0.0039430734247141545,
                                           1.0879357761487582), 1e-12));
  const Eigen::Quaterniond q(0.59119099977759426, 0.052279044093199806, 0.070894976564403633,
                             0.80170693250626335);
  EXPECT_TRUE(X.R.isApprox(q.toRotationMatrix(), 1e-12));
}

TEST(MjcfReader, Beyond007StiffnessBecomesJointSpring) {
  LoweredMjcf r(Model(R"(<worldbody><body><geom size="1"/>
    <joint name="j" stiffness="5" springref="90"/></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  ASSERT_EQ(r.module.force_elements.size(), 1u);
  ASSERT_EQ(r.module.force_elements[0].type(), ir::ForceElementType::JointSpring);
  const auto& f = r.module.force_elements[0].As<ir::JointSpring>();
  EXPECT_EQ(f.stiffness, 5);
  EXPECT_NEAR(f.nominal, M_PI / 2, kTol);
}

TEST(MjcfReader, Mjcf021FreeJointStartsAtWorldPose) {
  LoweredMjcf r(Model(R"(<worldbody><body name="base" pos="0 0 1"><freejoint/><geom size="1"/>
    <body name="free" pos="1 0 0"><joint type="free"/><geom size="1"/></body></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Joint* j = r.Joint("free");
  ASSERT_NE(j, nullptr);
  EXPECT_EQ(j->type, ir::JointType::QuaternionFloating);
  EXPECT_TRUE(j->unnamed);
  EXPECT_EQ(j->default_positions, (std::vector<double>{1, 0, 0, 0, 1, 0, 1}));
  ASSERT_TRUE(r.Body("free")->default_pose.has_value());
}

// A floating joint is named after its body, with '_' prefixed while another
// joint of the model bears the name: other floating joints renamed before it
// included, and never itself.
TEST(MjcfReader, Mjcf021FreeJointNamePrefixedWhileTaken) {
  LoweredMjcf r(Model(R"(<worldbody>
    <body name="a"><freejoint/><geom size="1"/></body>
    <body name="h" pos="0 0 2"><joint name="a"/><joint name="_a"/><geom size="1"/></body>
    <body name="b" pos="0 0 4"><freejoint/><geom size="1"/></body>
    <body name="k" pos="0 0 6"><joint name="b"/><geom size="1"/></body>
    <body name="_b" pos="0 0 8"><freejoint/><geom size="1"/></body>
    <body name="c" pos="0 0 9"><freejoint/><geom size="1"/></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Body* a = r.Body("a");
  const ir::Body* b = r.Body("b");
  const ir::Body* b2 = r.Body("_b");
  const ir::Body* c = r.Body("c");
  ASSERT_TRUE(a && b && b2 && c);
  auto floating_joint_of = [&](const ir::Body* body) {
    for (const ir::Joint& j : r.module.joints) {
      if (j.type == ir::JointType::QuaternionFloating && &r.module[j.child.id] == body) {
        return std::string(r.module.Text(j.name));
      }
    }
    return std::string();
  };
  EXPECT_EQ(floating_joint_of(a), "__a");
  EXPECT_EQ(floating_joint_of(b), "_b");
  EXPECT_EQ(floating_joint_of(b2), "__b");  // "_b" is b's floating joint by now
  EXPECT_EQ(floating_joint_of(c), "c");
}

TEST(MjcfReader, Mjcf021MocapBodyIsWeldedWithWarning) {
  LoweredMjcf r(Model(R"(<worldbody><body name="target" mocap="true" pos="1 2 3"><geom size="1"/></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Find(DiagKind::MocapBody), nullptr);
  const ir::Joint* weld = r.Joint("world_welds_to_target");
  ASSERT_NE(weld, nullptr);
  EXPECT_TRUE(weld->X_PF.p.isApprox(Eigen::Vector3d(1, 2, 3)));
}

TEST(MjcfReader, Mjcf040SizesFollowDrake) {
  LoweredMjcf r(Model(R"(<worldbody><body>
    <geom name="box" type="box" size="0.1 0.2 0.3"/>
    <geom name="cap" type="capsule" size="0.1 0.2"/>
    <geom name="cyl" type="cylinder" size="0.1 0.2"/>
    <geom name="ell" type="ellipsoid" size="0.1 0.2 0.3"/>
    <geom type="sphere" size="0.5"/><geom name="plane" type="plane" size="1 1 1"/>
  </body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_TRUE(std::get<ir::Box>(r.Geometry("box", kCollision)->shape).size.isApprox(Eigen::Vector3d(0.2, 0.4, 0.6)));
  EXPECT_DOUBLE_EQ(std::get<ir::Capsule>(r.Geometry("cap", kCollision)->shape).length, 0.4);
  EXPECT_DOUBLE_EQ(std::get<ir::Cylinder>(r.Geometry("cyl", kCollision)->shape).length, 0.4);
  EXPECT_DOUBLE_EQ(std::get<ir::Ellipsoid>(r.Geometry("ell", kCollision)->shape).c, 0.3);
  EXPECT_DOUBLE_EQ(std::get<ir::Sphere>(r.Geometry("geom4", kCollision)->shape).radius, 0.5);
  EXPECT_TRUE(std::holds_alternative<ir::HalfSpace>(r.Geometry("plane", kCollision)->shape));
  EXPECT_FALSE(r.Geometry("plane", kCollision)->mass_contribution.has_value());
}

TEST(MjcfReader, Mjcf041FromToCentresAndAlignsAsMuJoCo) {
  LoweredMjcf r(Model(R"(<worldbody><body>
    <geom name="c" type="capsule" fromto="0 0 0 0 0 1" size="0.1"/>
    <geom name="b" type="box" fromto="0 0 0 2 0 0" size="0.1 0.3"/>
  </body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Geometry* c = r.Geometry("c", kCollision);
  EXPECT_TRUE(c->X_BG.p.isApprox(Eigen::Vector3d(0, 0, 0.5)));
  EXPECT_DOUBLE_EQ(std::get<ir::Capsule>(c->shape).length, 1);
  // MuJoCo aligns +z with from - to
  EXPECT_TRUE(c->X_BG.R.col(2).isApprox(Eigen::Vector3d(0, 0, -1), kTol));
  // box: size (0.1, 0.1, half length) in MuJoCo's rule
  const ir::Geometry* b = r.Geometry("b", kCollision);
  EXPECT_TRUE(std::get<ir::Box>(b->shape).size.isApprox(Eigen::Vector3d(0.2, 0.2, 2)));
}

TEST(MjcfReader, Mjcf043RolesAndMassOnOneRegistration) {
  LoweredMjcf r(Model(R"(<worldbody><body>
    <geom name="both" size="1" friction="0.7" mass="2"/>
    <geom name="visual" size="1" contype="0" conaffinity="0"/>
    <geom name="collision" size="1" group="3"/>
  </body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_TRUE(r.Body("body1")->mass_from_geometry);
  const ir::Geometry* both_c = r.Geometry("both", kCollision);
  const ir::Geometry* both_v = r.Geometry("both", kVisual);
  ASSERT_TRUE(both_c && both_v);
  ASSERT_TRUE(both_c->mass_contribution.has_value());
  EXPECT_EQ(both_c->mass_contribution->mass, 2.0);
  EXPECT_FALSE(both_v->mass_contribution.has_value());
  ASSERT_EQ(both_c->properties.size(), 1u);
  EXPECT_EQ(both_c->properties[0].key, "material/coulomb_friction");
  EXPECT_EQ(r.Geometry("visual", kCollision), nullptr);
  ASSERT_NE(r.Geometry("visual", kVisual), nullptr);
  EXPECT_TRUE(r.Geometry("visual", kVisual)->mass_contribution.has_value());
  EXPECT_EQ(r.Geometry("collision", kVisual), nullptr);
}

TEST(MjcfReader, Mjcf005InertiaFromGeomFalseNeedsInertialOnMovingBodies) {
  LoweredMjcf r(Model(R"(<compiler inertiafromgeom="false"/><worldbody>
    <body name="static"><geom size="1"/></body>
    <body name="moving"><joint/><geom size="1"/></body>
    <body name="carried"><joint/><body><inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></body>
    <body name="two_joints"><joint/><joint/><geom size="1"/></body>
    <body name="deeply_carried"><joint/><body><geom size="1"/><body>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/></body></body></body>
  </worldbody>)"));
  EXPECT_NE(r.Find(DiagKind::MissingElement, "'moving'"), nullptr) << r.Messages();
  EXPECT_EQ(r.Find(DiagKind::MissingElement, "'static'"), nullptr);
  EXPECT_EQ(r.Find(DiagKind::MissingElement, "'carried'"), nullptr);
  // a body with two joints (a massless body between them) still needs one
  EXPECT_NE(r.Find(DiagKind::MissingElement, "'two_joints'"), nullptr);
  // mass two welded bodies down carries the moving body
  EXPECT_EQ(r.Find(DiagKind::MissingElement, "'deeply_carried'"), nullptr);
  // reported in document order
  const std::string messages = r.Messages();
  EXPECT_LT(messages.find("'moving'"), messages.find("'two_joints'")) << messages;
}

TEST(MjcfReader, Mjcf030InertialDiagAndFull) {
  LoweredMjcf r(Model(R"(<worldbody>
    <body name="a"><inertial pos="1 0 0" euler="90 0 0" mass="2" diaginertia="1 2 3"/></body>
    <body name="b"><inertial pos="0 0 0" mass="2" fullinertia="1 2 3 0.1 0.2 0.3"/></body>
  </worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Inertial& a = *r.Body("a")->inertial;
  EXPECT_EQ(a.mass, 2);
  EXPECT_TRUE(a.X_BI.R.isApprox(Rx(M_PI / 2), kTol));
  EXPECT_EQ(a.izz, 3);
  EXPECT_FALSE(r.Body("a")->mass_from_geometry);
  const ir::Inertial& b = *r.Body("b")->inertial;
  EXPECT_EQ(b.iyz, 0.3);
}

TEST(MjcfReader, Beyond002PrimitiveWithMeshIsFitted) {
  LoweredMjcf r(Model(R"(<asset><mesh file="part.obj" scale="2 2 2"/></asset>
    <worldbody><body><geom name="g" type="box" mesh="part"/><geom name="m" type="mesh" mesh="part"/></body></worldbody>)"),
                {{"part.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n"}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Geometry* g = r.Geometry("g", kCollision);
  ASSERT_TRUE(g->fit_to_mesh.has_value());
  EXPECT_TRUE(std::get<ir::Box>(g->shape).size.isZero());
  EXPECT_EQ(g->fit_to_mesh->mesh.scale, Eigen::Vector3d(2, 2, 2));
  const ir::Geometry* m = r.Geometry("m", kCollision);
  EXPECT_TRUE(std::get<ir::Mesh>(m->shape).resolved.ends_with("part.obj"));
  // MuJoCo 3.3's mesh inertia default is legacy
  EXPECT_EQ(m->mass_contribution->mesh_inertia, ir::MeshInertia::Legacy);
}

TEST(MjcfReader, Beyond004SitesAndFramesCompose) {
  LoweredMjcf r(Model(R"(<default><default class="big"><geom size="2"/></default></default>
  <worldbody><body name="b">
    <frame pos="0 0 1" euler="90 0 0" childclass="big">
      <site name="s" pos="0 1 0"/><geom name="g"/>
      <body name="c" pos="1 0 0"><geom name="h"/></body>
    </frame></body></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  ASSERT_EQ(r.module.frames.size(), 1u);
  EXPECT_TRUE(r.module.frames[0].X_BF.p.isApprox(Eigen::Vector3d(0, 0, 2), kTol));
  EXPECT_DOUBLE_EQ(std::get<ir::Sphere>(r.Geometry("g", kCollision)->shape).radius, 2);
  EXPECT_DOUBLE_EQ(std::get<ir::Sphere>(r.Geometry("h", kCollision)->shape).radius, 2);
  EXPECT_TRUE(r.Joint("b_welds_to_c")->X_PF.p.isApprox(Eigen::Vector3d(1, 0, 1), kTol));
}

TEST(MjcfReader, Mjcf090CameraNameAndDrakeFrame) {
  LoweredMjcf r(Model(R"(<worldbody><camera pos="0 0 1" fovy="90" resolution="320 240"/></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  ASSERT_EQ(r.module.cameras.size(), 1u);
  const ir::Camera& c = r.module.cameras[0];
  EXPECT_EQ(r.module.Text(c.name), "m/camera0");
  EXPECT_NEAR(c.fov_y, M_PI / 2, kTol);
  EXPECT_EQ(c.width, 320);
  // MuJoCo looks along -z: Drake's +z forward is the MuJoCo frame's -z
  EXPECT_TRUE(c.X_BC.R.col(2).isApprox(Eigen::Vector3d(0, 0, -1), kTol));
  EXPECT_TRUE(c.X_BC.R.col(1).isApprox(Eigen::Vector3d(0, -1, 0), kTol));
}

TEST(MjcfReader, UnknownAndUnsupportedAreDistinctWarnings) {
  LoweredMjcf r(Model(R"(<option timestep="0.01" viscosity="1"/><worldbody><body><geom size="1" colour="red"/>
    <light/><light/></body></worldbody><visual/>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Find(DiagKind::UnknownAttribute, "colour"), nullptr);
  EXPECT_NE(r.Find(DiagKind::UnsupportedAttribute, "viscosity"), nullptr);
  EXPECT_NE(r.Find(DiagKind::UnsupportedElement, "visual"), nullptr);
  size_t lights = 0;
  for (const auto& d : r.diags.diagnostics()) lights += d.message.find("<light>") != std::string::npos;
  EXPECT_EQ(lights, 1u);  // once per element kind
  r.ExpectDiagnostic(DiagKind::UnsupportedElement, "<light>");
  EXPECT_EQ(r.module.time_step, 0.01);
}

TEST(MjcfReader, DeepBodyNestingUsesNoCallStackPerLevel) {
  constexpr int kDepth = 10000;
  std::string xml = "<mujoco model=\"deep\"><worldbody>";
  for (int i = 0; i < kDepth; ++i) xml += "<body><geom size=\"0.1\"/>";
  for (int i = 0; i < kDepth; ++i) xml += "</body>";
  xml += "</worldbody></mujoco>";
  LoweredMjcf r(xml);
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_EQ(r.module.bodies.size(), kDepth + 1u);
}

}  // namespace
}  // namespace mdlc
