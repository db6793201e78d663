// The CRBA mass matrix (backend/mass_matrix.h) against closed forms and an
// independent finite-difference Jacobian computation.
#include "backend/mass_matrix.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "backend/positions.h"
#include "tests/unit/backend/backend_test_util.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using test_util::ModelBuilder;

Eigen::Matrix3d Diag(double x, double y, double z) { return Eigen::Vector3d(x, y, z).asDiagonal(); }

TEST(MassMatrix, SinglePendulumIsMlSquaredPlusI) {
  ModelBuilder b;
  const double m = 1.5, l = 0.8;
  // a full inertia tensor, in a rotated inertia frame: only the component
  // about the joint axis (y of B) counts
  std::mt19937 rng(7);
  const Eigen::Matrix3d I_I = test_util::RandomInertia(rng, m);
  const Eigen::Matrix3d R_BI = RotationFromRpy(Eigen::Vector3d(0.3, -0.4, 1.2));
  const BodyId link = b.AddBody("link", m, Eigen::Vector3d(0, 0, -l), I_I, R_BI);
  b.AddJoint("pivot", JointType::Revolute, ir::kWorldBody, link, {}, Eigen::Vector3d::UnitY());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const double I_yy = (R_BI * I_I * R_BI.transpose())(1, 1);
  for (double q : {0.0, 0.7, -2.0}) {
    const Eigen::MatrixXd M = CalcMassMatrix(model->plant, Eigen::VectorXd::Constant(1, q));
    ASSERT_EQ(M.rows(), 1);
    EXPECT_NEAR(M(0, 0), m * l * l + I_yy, 1e-14);
  }
}

TEST(MassMatrix, DoublePendulumClosedForm) {
  ModelBuilder b;
  const double m1 = 1.0, m2 = 2.0, l1 = 1.1, lc1 = 0.5, lc2 = 0.6, I1 = 0.05, I2 = 0.08;
  const BodyId link1 = b.AddBody("link1", m1, Eigen::Vector3d(0, 0, -lc1), Diag(0.01, I1, 0.02));
  const BodyId link2 = b.AddBody("link2", m2, Eigen::Vector3d(0, 0, -lc2), Diag(0.03, I2, 0.04));
  b.AddJoint("shoulder", JointType::Revolute, ir::kWorldBody, link1, {}, Eigen::Vector3d::UnitY());
  b.AddJoint("elbow", JointType::Revolute, link1, link2,
             Transform::FromTranslation(Eigen::Vector3d(0, 0, -l1)), Eigen::Vector3d::UnitY());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  for (const auto& [q1, q2] : {std::pair{0.0, 0.0}, {0.3, 1.2}, {-1.0, 2.5}, {2.0, -0.7}}) {
    const double c2 = std::cos(q2);
    Eigen::Matrix2d expected;
    expected(0, 0) = I1 + I2 + m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2);
    expected(0, 1) = expected(1, 0) = I2 + m2 * (lc2 * lc2 + l1 * lc2 * c2);
    expected(1, 1) = I2 + m2 * lc2 * lc2;
    const Eigen::MatrixXd M = CalcMassMatrix(model->plant, Eigen::Vector2d(q1, q2));
    EXPECT_LT((M - expected).norm(), 1e-13) << "q = " << q1 << ", " << q2 << "\n" << M;
  }
}

TEST(MassMatrix, CartPoleClosedForm) {
  ModelBuilder b;
  const double mc = 3.0, mp = 0.4, lp = 0.9, Ip = 0.02;
  const BodyId cart = b.AddBody("cart", mc, Eigen::Vector3d::Zero(), Diag(0.1, 0.2, 0.3));
  const BodyId pole = b.AddBody("pole", mp, Eigen::Vector3d(0, 0, lp), Diag(0.01, Ip, 0.001));
  b.AddJoint("slider", JointType::Prismatic, ir::kWorldBody, cart, {}, Eigen::Vector3d::UnitX());
  b.AddJoint("hinge", JointType::Revolute, cart, pole, {}, Eigen::Vector3d::UnitY());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  for (double theta : {0.0, 0.4, 2.0, -2.9}) {
    Eigen::Matrix2d expected;
    expected << mc + mp, mp * lp * std::cos(theta), mp * lp * std::cos(theta), Ip + mp * lp * lp;
    const Eigen::MatrixXd M = CalcMassMatrix(model->plant, Eigen::Vector2d(1.7, theta));
    EXPECT_LT((M - expected).norm(), 1e-13) << "theta = " << theta << "\n" << M;
  }
}

/// A random chain with rotated joint frames (X_PF and X_CM), random axes and
/// offset, rotated inertias, over joint types whose qdot = v.
ir::Module RandomChain(std::mt19937& rng, int num_joints) {
  const JointType types[] = {JointType::Revolute, JointType::Prismatic, JointType::Screw,
                             JointType::Universal, JointType::Planar, JointType::Revolute};
  ModelBuilder b;
  std::uniform_real_distribution<double> mass(0.3, 5.0);
  BodyId parent = ir::kWorldBody;
  for (int i = 0; i < num_joints; ++i) {
    const double m = mass(rng);
    const BodyId body =
        b.AddBody("link" + std::to_string(i), m, test_util::RandomVector(rng, 0.2),
                  test_util::RandomInertia(rng, m), test_util::RandomRotation(rng));
    const JointId j = b.AddJoint(
        "joint" + std::to_string(i), types[i % 6], parent, body,
        {test_util::RandomRotation(rng), test_util::RandomVector(rng, 0.5)},
        test_util::RandomVector(rng, 1.0).normalized(),
        {test_util::RandomRotation(rng), test_util::RandomVector(rng, 0.3)});
    b.module()[j].screw_thread_pitch = 0.07;
    parent = body;
  }
  return std::move(b.module());
}

Eigen::VectorXd RandomQ(std::mt19937& rng, const Plant& plant) {
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  Eigen::VectorXd q(plant.num_positions);
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = u(rng);
  return q;
}

TEST(MassMatrix, CrbaMatchesFiniteDifferenceJacobiansOnRandomChain) {
  std::mt19937 rng(20240611);
  for (int trial = 0; trial < 3; ++trial) {
    const ir::Module module = RandomChain(rng, 6);
    auto model = test_util::InstantiateOk(module);
    ASSERT_TRUE(model);
    ASSERT_EQ(model->plant.num_velocities, 1 + 1 + 1 + 2 + 3 + 1);
    for (int k = 0; k < 4; ++k) {
      const Eigen::VectorXd q = RandomQ(rng, model->plant);
      const Eigen::MatrixXd M = CalcMassMatrix(model->plant, q);
      const Eigen::MatrixXd expected = test_util::MassMatrixByFiniteDifferences(model->plant, q);
      EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-9)
          << "trial " << trial << "\n" << M << "\n\n" << expected;
      EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

// A tree: floating base (quaternion), a ball joint, an rpy-floating body, a
// branch behind a weld, and massless bodies in between.
TEST(MassMatrix, CrbaMatchesFiniteDifferenceJacobiansOnFloatingTree) {
  std::mt19937 rng(42);
  ModelBuilder b;
  const auto body = [&](const std::string& name) { return test_util::AddRandomBody(b, rng, name); };
  const auto pose = [&] { return test_util::RandomPose(rng); };
  const BodyId base = body("base");
  const BodyId shoulder = body("shoulder");
  const BodyId hand = body("hand");
  const BodyId massless = b.AddMasslessBody("massless");
  const BodyId tool = body("tool");
  const BodyId flyer = body("flyer");
  const BodyId finger = body("finger");
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();  // unused by these joint types
  b.AddJoint("base", JointType::QuaternionFloating, ir::kWorldBody, base, {}, z, pose());
  b.AddJoint("shoulder", JointType::Ball, base, shoulder, pose(), z, pose());
  b.AddJoint("wrist", JointType::Revolute, shoulder, hand, pose(), Eigen::Vector3d::UnitZ(),
             pose());
  b.AddJoint("mount", JointType::Weld, hand, massless, pose(), z, pose());
  b.AddJoint("tool", JointType::Prismatic, massless, tool, pose(), Eigen::Vector3d::UnitY(),
             pose());
  b.AddJoint("flyer", JointType::RpyFloating, base, flyer, pose(), z, pose());
  b.AddJoint("finger", JointType::Revolute, hand, finger, pose(), Eigen::Vector3d::UnitX(), pose());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  ASSERT_EQ(model->plant.num_velocities, 6 + 3 + 1 + 1 + 6 + 1);
  for (int k = 0; k < 4; ++k) {
    Eigen::VectorXd q = RandomQ(rng, model->plant);
    const PlantJoint& floating = model->plant.joint(JointId(size_t{0}));
    q.segment<4>(floating.q_start).normalize();
    const Eigen::MatrixXd M = CalcMassMatrix(model->plant, q);
    const Eigen::MatrixXd expected = test_util::MassMatrixByFiniteDifferences(model->plant, q);
    EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-9) << M << "\n\n" << expected;
  }
}

TEST(MassMatrix, RestrictedToJointsIsTheMatchingSubmatrix) {
  std::mt19937 rng(5);
  const ir::Module module = RandomChain(rng, 6);
  auto model = test_util::InstantiateOk(module);
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  const Eigen::VectorXd q = RandomQ(rng, plant);
  const Eigen::MatrixXd full = CalcMassMatrix(plant, q);
  // joints 5 (1 dof), 0 (1 dof), 4 (planar, 3 dofs), in that order
  const std::vector<JointId> joints = {JointId(size_t{5}), JointId(size_t{0}), JointId(size_t{4})};
  std::vector<int> rows;
  for (JointId j : joints) {
    for (int k = 0; k < plant.joint(j).nv; ++k) rows.push_back(plant.joint(j).v_start + k);
  }
  const Eigen::MatrixXd sub = CalcMassMatrix(plant, q, joints);
  ASSERT_EQ(sub.rows(), 5);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 5; ++c) EXPECT_NEAR(sub(r, c), full(rows[r], rows[c]), 1e-14);
  }
}

}  // namespace
}  // namespace mdlc::backend
