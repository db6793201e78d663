// Joint motion X_FM(q), motion subspaces, forward kinematics, default
// positions and joints by name (backend/kinematics.h, backend/positions.h).
#include "backend/kinematics.h"

#include <gtest/gtest.h>

#include <numbers>

#include "backend/positions.h"
#include "tests/unit/backend/backend_test_util.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using test_util::ModelBuilder;
using std::numbers::pi;

PlantJoint MakeJoint(JointType type, const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ(),
                     double pitch = 0) {
  PlantJoint joint;
  joint.type = type;
  joint.axis = axis;
  joint.screw_thread_pitch = pitch;
  joint.nq = ir::JointPositionCount(type);
  joint.nv = ir::JointVelocityCount(type);
  return joint;
}

Eigen::VectorXd Q(std::initializer_list<double> values) {
  Eigen::VectorXd q(values.size());
  int i = 0;
  for (double x : values) q[i++] = x;
  return q;
}

Eigen::Matrix3d Rot(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

void ExpectPose(const Transform& X, const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  EXPECT_TRUE(X.R.isApprox(R, 1e-12)) << X.R << "\nexpected\n" << R;
  EXPECT_TRUE(X.p.isApprox(p, 1e-12) || (X.p - p).norm() < 1e-12) << X.p.transpose();
}

TEST(Kinematics, RevoluteRotatesAboutAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  ExpectPose(JointPose(MakeJoint(JointType::Revolute, axis), Q({0.7})), Rot(axis, 0.7),
             Eigen::Vector3d::Zero());
  const Transform X = JointPose(MakeJoint(JointType::Revolute), Q({pi / 2}));
  EXPECT_TRUE((X.R * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY(), 1e-15));
}

TEST(Kinematics, PrismaticTranslatesAlongAxis) {
  ExpectPose(JointPose(MakeJoint(JointType::Prismatic, Eigen::Vector3d::UnitY()), Q({0.3})),
             Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0.3, 0));
}

TEST(Kinematics, ScrewAdvancesPitchPerRevolution) {
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  // half a turn advances half the pitch
  ExpectPose(JointPose(MakeJoint(JointType::Screw, axis, 0.1), Q({pi})), Rot(axis, pi),
             Eigen::Vector3d(0, 0, 0.05));
}

TEST(Kinematics, UniversalIsRxThenRy) {
  ExpectPose(JointPose(MakeJoint(JointType::Universal), Q({0.3, -0.8})),
             Rot(Eigen::Vector3d::UnitX(), 0.3) * Rot(Eigen::Vector3d::UnitY(), -0.8),
             Eigen::Vector3d::Zero());
}

TEST(Kinematics, BallIsRollPitchYaw) {
  ExpectPose(JointPose(MakeJoint(JointType::Ball), Q({0.1, 0.2, 0.3})),
             Rot(Eigen::Vector3d::UnitZ(), 0.3) * Rot(Eigen::Vector3d::UnitY(), 0.2) *
                 Rot(Eigen::Vector3d::UnitX(), 0.1),
             Eigen::Vector3d::Zero());
}

TEST(Kinematics, PlanarTranslatesThenRotatesAboutZ) {
  ExpectPose(JointPose(MakeJoint(JointType::Planar), Q({0.5, -0.25, 1.1})),
             Rot(Eigen::Vector3d::UnitZ(), 1.1), Eigen::Vector3d(0.5, -0.25, 0));
}

TEST(Kinematics, WeldIsIdentity) {
  ExpectPose(JointPose(MakeJoint(JointType::Weld), Eigen::VectorXd(0)),
             Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

TEST(Kinematics, QuaternionFloatingNormalizesItsQuaternion) {
  const double c = std::cos(0.4), s = std::sin(0.4);
  // [qw qx qy qz px py pz], quaternion scaled by 3: a rotation of 0.8 about z
  ExpectPose(JointPose(MakeJoint(JointType::QuaternionFloating), Q({3 * c, 0, 0, 3 * s, 1, 2, 3})),
             Rot(Eigen::Vector3d::UnitZ(), 0.8), Eigen::Vector3d(1, 2, 3));
  ExpectPose(JointPose(MakeJoint(JointType::QuaternionFloating), Q({0, 0, 0, 0, 0, 0, 0})),
             Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

TEST(Kinematics, RpyFloatingIsRpyThenTranslation) {
  ExpectPose(JointPose(MakeJoint(JointType::RpyFloating), Q({0.1, -0.2, 0.3, 4, 5, 6})),
             RotationFromRpy(Eigen::Vector3d(0.1, -0.2, 0.3)), Eigen::Vector3d(4, 5, 6));
}

// a line of 1 m along a tilted tangent, then a left arc of radius 0.5 m turning
// through pi/2, in a plane whose normal is not z
PlantJoint CurvedJoint(bool periodic) {
  PlantJoint j = MakeJoint(JointType::Curvilinear);
  j.curvilinear_path.initial_tangent = Eigen::Vector3d(1, 1, 0).normalized();
  j.curvilinear_path.plane_normal = Eigen::Vector3d(0, 0, 1);
  j.curvilinear_path.segments = {{1.0, 0.0}, {0.25 * M_PI, 2.0}};
  if (periodic) {
    // four lines and four quarter circles: a closed rounded square
    j.curvilinear_path.segments = {{1.0, 0}, {0.25 * M_PI, 2}, {1.0, 0}, {0.25 * M_PI, 2},
                                   {1.0, 0}, {0.25 * M_PI, 2}, {1.0, 0}, {0.25 * M_PI, 2}};
    j.curvilinear_path.periodic = true;
  }
  return j;
}

TEST(Kinematics, CurvilinearFollowsLinesAndArcs) {
  const PlantJoint j = CurvedJoint(false);
  const Eigen::Vector3d t = Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d n = Eigen::Vector3d::UnitZ().cross(t);  // the side the arc turns to
  // along the line: translation only, the frame's x along the tangent
  const Transform X_line = JointPose(j, Q({0.6}));
  EXPECT_TRUE(X_line.p.isApprox(0.6 * t, 1e-12));
  EXPECT_TRUE(X_line.R.col(0).isApprox(t, 1e-12));
  // end of the quarter arc: one radius along t and one along n, turned by 90 degrees
  const Transform X_end = JointPose(j, Q({1.0 + 0.25 * M_PI}));
  EXPECT_TRUE(X_end.p.isApprox(1.0 * t + 0.5 * t + 0.5 * n, 1e-12)) << X_end.p.transpose();
  EXPECT_TRUE(X_end.R.col(0).isApprox(n, 1e-12));
  EXPECT_TRUE(X_end.R.col(2).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  // a closed loop comes back to its start after its length
  const PlantJoint loop = CurvedJoint(true);
  const double length = loop.curvilinear_path.TotalLength();
  const Transform X0 = JointPose(loop, Q({0.2})), X1 = JointPose(loop, Q({0.2 + length}));
  EXPECT_TRUE(X0.p.isApprox(X1.p, 1e-12));
  EXPECT_TRUE(X0.R.isApprox(X1.R, 1e-12));
}

TEST(Kinematics, CurvilinearWithoutSegmentsStaysAtItsStart) {
  // an empty path has no length: the child stays at the path's start
  ExpectPose(JointPose(MakeJoint(JointType::Curvilinear), Q({0.4})),
             Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

// For joints with qdot = v, H's columns are the derivatives of X_FM(q):
// angular part vee(dR/dq R^T), linear part dp/dq, both in F.
TEST(Kinematics, MotionSubspaceMatchesDerivativeOfJointPose) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const std::vector<std::pair<PlantJoint, Eigen::VectorXd>> cases = {
      {MakeJoint(JointType::Revolute, axis), Q({0.7})},
      {MakeJoint(JointType::Prismatic, axis), Q({0.2})},
      {MakeJoint(JointType::Screw, axis, 0.03), Q({1.3})},
      {MakeJoint(JointType::Universal), Q({0.4, -1.1})},
      {MakeJoint(JointType::Planar), Q({0.3, 0.6, -2.1})},
      {MakeJoint(JointType::Curvilinear), Q({0.1})},
      {CurvedJoint(false), Q({0.3})},   // inside the first (straight) piece
      {CurvedJoint(false), Q({1.7})},   // inside the arc
      {CurvedJoint(false), Q({-0.4})},  // before the start: the first piece continues
      {CurvedJoint(true), Q({7.9})},    // a closed loop wraps around
  };
  const double h = 1e-6;
  for (const auto& [joint, q] : cases) {
    SCOPED_TRACE(std::string(ir::JointTypeName(joint.type)));
    const MotionSubspace H = JointMotionSubspace(joint, q);
    ASSERT_EQ(H.cols(), joint.nv);
    const Transform X = JointPose(joint, q);
    for (int k = 0; k < joint.nv; ++k) {
      Eigen::VectorXd qp = q, qm = q;
      qp[k] += h;
      qm[k] -= h;
      const Transform Xp = JointPose(joint, qp), Xm = JointPose(joint, qm);
      const Eigen::Vector3d w = test_util::Vee((Xp.R - Xm.R) / (2 * h) * X.R.transpose());
      const Eigen::Vector3d v = (Xp.p - Xm.p) / (2 * h);
      EXPECT_LT((H.col(k).head<3>() - w).norm(), 1e-8) << k;
      EXPECT_LT((H.col(k).tail<3>() - v).norm(), 1e-8) << k;
    }
  }
}

TEST(Kinematics, SinglePendulumForwardKinematics) {
  ModelBuilder b;
  const double l = 0.7;
  const BodyId link =
      b.AddBody("link", 2.0, Eigen::Vector3d(0, 0, -l), Eigen::Matrix3d::Identity());
  b.AddJoint("pivot", JointType::Revolute, ir::kWorldBody, link,
             Transform::FromTranslation(Eigen::Vector3d(0, 0, 1)), Eigen::Vector3d::UnitY());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const std::vector<Transform> X_WB = BodyPosesInWorld(model->plant, Q({0.5}));
  ExpectPose(X_WB[link.index()], Rot(Eigen::Vector3d::UnitY(), 0.5), Eigen::Vector3d(0, 0, 1));
  const Eigen::Vector3d com = X_WB[link.index()] * model->plant.body(link).p_BoBcm_B;
  EXPECT_TRUE(com.isApprox(Eigen::Vector3d(-l * std::sin(0.5), 0, 1 - l * std::cos(0.5)), 1e-14));
}

// X_WC = X_WP * X_PF * X_FM(q) * X_CM^-1 along a chain.
TEST(Kinematics, ChainComposesJointFrames) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId c = b.AddMasslessBody("c");
  const Transform X_PF1{Rot(Eigen::Vector3d::UnitX(), 0.3), Eigen::Vector3d(1, 0, 0)};
  const Transform X_CM1{Rot(Eigen::Vector3d::UnitZ(), -0.2), Eigen::Vector3d(0, 0.5, 0)};
  const Transform X_PF2{Rot(Eigen::Vector3d::UnitY(), 1.0), Eigen::Vector3d(0, 0, 2)};
  b.AddJoint("j1", JointType::Revolute, ir::kWorldBody, a, X_PF1, Eigen::Vector3d::UnitZ(), X_CM1);
  b.AddJoint("j2", JointType::Prismatic, a, c, X_PF2, Eigen::Vector3d::UnitX());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const std::vector<Transform> X_WB = BodyPosesInWorld(model->plant, Q({0.4, 0.25}));
  const Transform X_WA = X_PF1 * Transform::FromRotation(Rot(Eigen::Vector3d::UnitZ(), 0.4)) *
                         X_CM1.inverse();
  const Transform X_WC =
      X_WA * X_PF2 * Transform::FromTranslation(Eigen::Vector3d(0.25, 0, 0));
  ExpectPose(X_WB[a.index()], X_WA.R, X_WA.p);
  ExpectPose(X_WB[c.index()], X_WC.R, X_WC.p);
  ExpectPose(X_WB[0], Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero());
}

TEST(Kinematics, ForwardKinematicsRejectsWrongSizeQ) {
  ModelBuilder b;
  b.AddJoint("j", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("a"));
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  EXPECT_THROW(BodyPosesInWorld(model->plant, Q({1, 2})), std::invalid_argument);
}

TEST(Kinematics, DefaultPositionsUseModelValuesElseZeroOrIdentity) {
  ModelBuilder b;
  const BodyId base = b.AddMasslessBody("base");
  const BodyId arm = b.AddMasslessBody("arm");
  b.AddJoint("base", JointType::QuaternionFloating, ir::kWorldBody, base);
  const JointId elbow = b.AddJoint("elbow", JointType::Revolute, base, arm);
  b.module()[elbow].default_positions = {0.25};
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Eigen::VectorXd q = DefaultPositions(model->plant);
  ASSERT_EQ(q.size(), 8);
  EXPECT_EQ(q, Q({1, 0, 0, 0, 0, 0, 0, 0.25}));
}

TEST(Kinematics, SetJointPositionByScopedOrUnambiguousLocalName) {
  ModelBuilder b("left");
  b.AddJoint("shoulder", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("l1"));
  b.AddJoint("wrist", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("l2"));
  b.AddJoint("ball", JointType::Ball, ir::kWorldBody, b.AddMasslessBody("l3"));
  b.SetInstance(b.AddInstance("right"));
  b.AddJoint("shoulder", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("r1"));
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  Eigen::VectorXd q = DefaultPositions(plant);

  EXPECT_TRUE(SetJointPositionByName(plant, q, "right::shoulder", 0.5));
  EXPECT_TRUE(SetJointPositionByName(plant, q, "wrist", -0.5));
  EXPECT_FALSE(SetJointPositionByName(plant, q, "shoulder", 1.0));  // ambiguous
  EXPECT_FALSE(SetJointPositionByName(plant, q, "elbow", 1.0));     // unknown
  EXPECT_FALSE(SetJointPositionByName(plant, q, "ball", 1.0));      // 3 positions
  EXPECT_EQ(FindJointByName(plant, "shoulder").status, JointLookupStatus::Ambiguous);
  EXPECT_EQ(FindJointByName(plant, "left::shoulder").status, JointLookupStatus::Found);

  const PlantJoint& right = plant.joint(FindJointByName(plant, "right::shoulder").joint);
  const PlantJoint& wrist = plant.joint(FindJointByName(plant, "wrist").joint);
  EXPECT_EQ(q[right.q_start], 0.5);
  EXPECT_EQ(q[wrist.q_start], -0.5);
  EXPECT_EQ(q.cwiseAbs().sum(), 1.0);  // nothing else changed
}

}  // namespace
}  // namespace mdlc::backend
