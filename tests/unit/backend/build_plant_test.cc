// BuildPlant / Instantiate: instances, mass properties, normalization, tree
// order, and the defensive precondition checks (backend/build_plant.h).
#include "backend/build_plant.h"

#include <gtest/gtest.h>

#include <limits>

#include "tests/unit/backend/backend_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using test_util::ModelBuilder;

using testing::kInf;

std::vector<DiagKind> Kinds(const DiagnosticEngine& diags) {
  std::vector<DiagKind> kinds;
  for (const Diagnostic& d : diags.diagnostics()) kinds.push_back(d.kind);
  return kinds;
}

// COMMON-020: instance 0 is WorldModelInstance (owning the world body), 1 is
// DefaultModelInstance, then one per model.
TEST(BackendBuildPlant, Common020ModelInstancesAndWorldBody) {
  ModelBuilder b;
  b.AddJoint("j", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("link"));
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  EXPECT_EQ(plant.model_instances.ToVector(),
            (std::vector<std::string>{"WorldModelInstance", "DefaultModelInstance", "robot"}));
  ASSERT_EQ(plant.bodies.size(), 2u);
  EXPECT_TRUE(plant.bodies[0].is_world);
  EXPECT_EQ(plant.ScopedName(plant.bodies[0]), "world");
  EXPECT_EQ(plant.bodies[0].model, ir::kWorldModel);
  EXPECT_EQ(plant.ScopedName(plant.bodies[1]), "robot::link");
  EXPECT_EQ(plant.ScopedName(plant.joints[0]), "robot::j");
}

// COMMON-042: mass properties end up about the COM, expressed in B.
TEST(BackendBuildPlant, Common042InertiaReexpressedInBodyFrame) {
  ModelBuilder b;
  Eigen::Matrix3d I_I;
  I_I << 0.3, 0.01, -0.02,
         0.01, 0.4, 0.03,
         -0.02, 0.03, 0.5;
  const Eigen::Matrix3d R_BI = RotationFromRpy(Eigen::Vector3d(0.5, -0.3, 2.0));
  const BodyId link = b.AddBody("link", 2.5, Eigen::Vector3d(0.1, 0.2, 0.3), I_I, R_BI);
  const BodyId massless = b.AddMasslessBody("massless");
  b.AddJoint("j1", JointType::Revolute, ir::kWorldBody, link);
  b.AddJoint("j2", JointType::Revolute, link, massless);
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const PlantBody& body = model->plant.body(link);
  EXPECT_EQ(body.mass, 2.5);
  EXPECT_EQ(body.p_BoBcm_B, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_TRUE(body.I_BBcm_B.isApprox(R_BI * I_I * R_BI.transpose(), 1e-15));
  EXPECT_TRUE(body.I_BBcm_B.isApprox(body.I_BBcm_B.transpose(), 1e-15));
  EXPECT_EQ(model->plant.body(massless).mass, 0);
  EXPECT_TRUE(model->plant.body(massless).I_BBcm_B.isZero(0));
}

TEST(BackendBuildPlant, JointVectorsAreNormalizedToTheirSizes) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId c = b.AddMasslessBody("c");
  b.AddJoint("free", JointType::QuaternionFloating, ir::kWorldBody, a);
  const JointId hinge =
      b.AddJoint("hinge", JointType::Revolute, a, c, {}, Eigen::Vector3d(0, 0, 2));
  b.module()[hinge].limits.lower = {-1};
  b.module()[hinge].limits.upper = {1};
  b.module()[hinge].damping = {0.5};
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const PlantJoint& free = model->plant.joints[0];
  EXPECT_EQ(free.nq, 7);
  EXPECT_EQ(free.nv, 6);
  EXPECT_EQ(free.lower, std::vector<double>(6, -kInf));
  EXPECT_EQ(free.effort, std::vector<double>(6, kInf));
  EXPECT_EQ(free.damping, std::vector<double>(6, 0.0));
  EXPECT_EQ(free.default_positions, (std::vector<double>{1, 0, 0, 0, 0, 0, 0}));
  const PlantJoint& h = model->plant.joint(hinge);
  EXPECT_EQ(h.lower, std::vector<double>{-1});
  EXPECT_EQ(h.velocity_upper, std::vector<double>{kInf});
  EXPECT_EQ(h.damping, std::vector<double>{0.5});
  EXPECT_EQ(h.axis, Eigen::Vector3d::UnitZ());  // normalized
}

// q/v are laid out breadth-first by tree level, IR order within a level,
// whatever order the IR lists the joints in.
TEST(BackendBuildPlant, TreeOrderIsByLevelThenIrOrder) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId a1 = b.AddMasslessBody("a1");
  const BodyId a2 = b.AddMasslessBody("a2");
  const BodyId c = b.AddMasslessBody("c");
  const JointId j_a1 = b.AddJoint("a1", JointType::Ball, a, a1);        // level 2
  const JointId j_c = b.AddJoint("c", JointType::Prismatic, ir::kWorldBody, c);  // level 1
  const JointId j_a2 = b.AddJoint("a2", JointType::Revolute, a, a2);    // level 2
  const JointId j_a = b.AddJoint("a", JointType::Weld, ir::kWorldBody, a);       // level 1
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  EXPECT_EQ(plant.joint_order, (std::vector<JointId>{j_c, j_a, j_a1, j_a2}));
  EXPECT_EQ(plant.body_order, (std::vector<BodyId>{ir::kWorldBody, c, a, a1, a2}));
  EXPECT_EQ(plant.joint(j_c).q_start, 0);
  EXPECT_EQ(plant.joint(j_a).q_start, 1);
  EXPECT_EQ(plant.joint(j_a1).q_start, 1);
  EXPECT_EQ(plant.joint(j_a2).q_start, 4);
  EXPECT_EQ(plant.num_positions, 5);
  EXPECT_EQ(plant.num_velocities, 5);
  EXPECT_EQ(plant.body(a1).parent, a);
  EXPECT_EQ(plant.body(a1).inbound_joint, j_a1);
  EXPECT_EQ(plant.body(a1).level, 2);
}

TEST(BackendBuildPlant, UnresolvedReferenceIsAnErrorNotACrash) {
  ModelBuilder b;
  const JointId j = b.AddJoint("j", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("a"));
  b.module()[j].child.id = BodyId();  // name but no id
  ir::Geometry g;
  g.name = b.module().Intern("g");
  g.model = b.model();
  g.body = b.Ref(BodyId(size_t{99}), "nowhere");  // out of range
  b.module().Add(g);
  DiagnosticEngine diags;
  EXPECT_FALSE(Instantiate(b.module(), diags));
  EXPECT_TRUE(diags.has_errors());
  EXPECT_EQ(Kinds(diags)[0], DiagKind::VerifierFailure);
}

TEST(BackendBuildPlant, GeometryReferenceOutOfRangeIsAnError) {
  ModelBuilder b;
  b.AddJoint("j", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("a"));
  b.AddGeometry("g", BodyId(size_t{42}), ir::Sphere{1}, ir::kProximityRole);
  DiagnosticEngine diags;
  EXPECT_FALSE(Instantiate(b.module(), diags));
  EXPECT_EQ(Kinds(diags), std::vector<DiagKind>{DiagKind::VerifierFailure});
}

TEST(BackendBuildPlant, TwoParentsAreReported) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId c = b.AddMasslessBody("c");
  b.AddJoint("j1", JointType::Revolute, ir::kWorldBody, a);
  b.AddJoint("j2", JointType::Revolute, ir::kWorldBody, c);
  b.AddJoint("j3", JointType::Revolute, a, c);
  DiagnosticEngine diags;
  EXPECT_FALSE(BuildPlant(b.module(), diags));
  ASSERT_EQ(Kinds(diags), std::vector<DiagKind>{DiagKind::MultipleParents});
  EXPECT_NE(diags.diagnostics()[0].message.find("'robot::c'"), std::string::npos);
}

TEST(BackendBuildPlant, LoopNotThroughWorldIsReported) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  const BodyId c = b.AddMasslessBody("c");
  b.AddJoint("j1", JointType::Revolute, a, c);
  b.AddJoint("j2", JointType::Revolute, c, a);
  DiagnosticEngine diags;
  EXPECT_FALSE(BuildPlant(b.module(), diags));
  ASSERT_EQ(Kinds(diags), std::vector<DiagKind>{DiagKind::KinematicLoop});
  EXPECT_EQ(diags.diagnostics()[0].notes.size(), 2u);
}

TEST(BackendBuildPlant, BodyWithoutInboundJointIsReported) {
  ModelBuilder b;
  b.AddMasslessBody("orphan");
  DiagnosticEngine diags;
  EXPECT_FALSE(BuildPlant(b.module(), diags));
  // build-kinematic-tree gives every root a floating joint: this is a bug, not bad input
  EXPECT_EQ(Kinds(diags), std::vector<DiagKind>{DiagKind::VerifierFailure});
}

TEST(BackendBuildPlant, SelfJointWorldChildAndZeroAxisAreReported) {
  ModelBuilder b;
  const BodyId a = b.AddMasslessBody("a");
  b.AddJoint("ok", JointType::Revolute, ir::kWorldBody, a);
  b.AddJoint("self", JointType::Revolute, a, a);
  b.AddJoint("to_world", JointType::Revolute, a, ir::kWorldBody);
  const BodyId c = b.AddMasslessBody("c");
  b.AddJoint("zero", JointType::Prismatic, a, c, {}, Eigen::Vector3d::Zero());
  DiagnosticEngine diags;
  EXPECT_FALSE(BuildPlant(b.module(), diags));
  // one run reports all three
  EXPECT_EQ(Kinds(diags), (std::vector<DiagKind>{DiagKind::ZeroAxis, DiagKind::SelfJoint,
                                                 DiagKind::KinematicLoop}));
}

TEST(BackendBuildPlant, WrongSizedJointVectorsAreReported) {
  ModelBuilder b;
  const JointId j = b.AddJoint("j", JointType::Revolute, ir::kWorldBody, b.AddMasslessBody("a"));
  b.module()[j].limits.lower = {-1, -2};
  b.module()[j].default_positions = {0, 0, 0};
  DiagnosticEngine diags;
  EXPECT_FALSE(BuildPlant(b.module(), diags));
  EXPECT_EQ(Kinds(diags), (std::vector<DiagKind>{DiagKind::BadLimits, DiagKind::BadValue}));
}

}  // namespace
}  // namespace mdlc::backend
