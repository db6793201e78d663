// The dynamics (backend/dynamics.h) against closed forms and against
// computations that share none of its spatial algebra: Jacobians and body
// accelerations by finite differences of forward kinematics, inverse
// dynamics by Kane's method (the sum over bodies of J^T times each body's
// Newton-Euler wrench, the accelerations taken by finite differences in
// time), gravity forces as the gradient of the potential energy, and the
// identities ID(FD(tau)) = tau, M vdot + C v - tau_g = ID and
// d(T + V)/dt = v . tau for a conservative model.
#include "backend/dynamics.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>
#include <variant>

#include "backend/kinematics.h"
#include "backend/mass_matrix.h"
#include "tests/unit/backend/backend_test_util.h"

namespace mdlc::backend {
namespace {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using Eigen::VectorXd;
using ir::JointType;
using test_util::ModelBuilder;

Eigen::Matrix3d Diag(double x, double y, double z) { return Vector3d(x, y, z).asDiagonal(); }

/// q moved along the joint velocities dv (a joint's angular part rotates
/// R_FM about an axis in F, as v = w_FM_F says; the rest adds): a smooth
/// path with q'(0) matching v, which is all a first derivative needs.
VectorXd Advance(const Plant& plant, const VectorXd& q, const VectorXd& dv) {
  VectorXd out = q;
  const auto rotate = [](const Vector3d& dw, const Eigen::Matrix3d& R) -> Eigen::Matrix3d {
    const double angle = dw.norm();
    if (angle == 0) return R;
    return Eigen::AngleAxisd(angle, dw / angle).toRotationMatrix() * R;
  };
  for (const PlantJoint& joint : plant.joints) {
    const auto qj = q.segment(joint.q_start, joint.nq);
    const auto dvj = dv.segment(joint.v_start, joint.nv);
    auto oj = out.segment(joint.q_start, joint.nq);
    switch (joint.type) {
      case JointType::Ball:
        oj = RpyFromRotation(rotate(dvj.head<3>(), RotationFromRpy(qj.head<3>())));
        break;
      case JointType::RpyFloating:
        oj.head<3>() = RpyFromRotation(rotate(dvj.head<3>(), RotationFromRpy(qj.head<3>())));
        oj.tail<3>() += dvj.tail<3>();
        break;
      case JointType::QuaternionFloating: {
        const Eigen::Quaterniond quat(qj[0], qj[1], qj[2], qj[3]);
        const Eigen::Quaterniond moved(rotate(dvj.head<3>(), quat.normalized().toRotationMatrix()));
        oj.head<4>() << moved.w(), moved.x(), moved.y(), moved.z();
        oj.tail<3>() += dvj.tail<3>();
        break;
      }
      default:
        oj += dvj;
    }
  }
  return out;
}

/// Per body: Jacobians of the COM's translational velocity and of the
/// angular velocity, by central differences of forward kinematics.
struct BodyJacobians {
  std::vector<MatrixXd> Jv, Jw;
};

BodyJacobians JacobiansByFiniteDifferences(const Plant& plant, const VectorXd& q) {
  const double h = 1e-5;
  const int nb = static_cast<int>(plant.bodies.size()), nv = plant.num_velocities;
  BodyJacobians J{std::vector<MatrixXd>(nb, MatrixXd::Zero(3, nv)),
                  std::vector<MatrixXd>(nb, MatrixXd::Zero(3, nv))};
  for (int k = 0; k < nv; ++k) {
    const VectorXd e = VectorXd::Unit(nv, k) * h;
    const std::vector<Transform> Xp = BodyPosesInWorld(plant, Advance(plant, q, e));
    const std::vector<Transform> Xm = BodyPosesInWorld(plant, Advance(plant, q, -e));
    for (int b = 0; b < nb; ++b) {
      const Vector3d& c = plant.bodies[b].p_BoBcm_B;
      J.Jv[b].col(k) = (Xp[b] * c - Xm[b] * c) / (2 * h);
      // [w]x = dR/dt R^T
      const Eigen::Matrix3d W = (Xp[b].R - Xm[b].R) / (2 * h) * Xp[b].R.transpose();
      J.Jw[b].col(k) = test_util::Vee(W);
    }
  }
  return J;
}

/// tau by Kane's method: sum over bodies of Jv^T m (a_cm - g) + Jw^T (I alpha
/// + w x I w), with a_cm and alpha differentiated in time along (q(t), v(t)).
VectorXd InverseDynamicsByKane(const Plant& plant, const VectorXd& q, const VectorXd& v,
                               const VectorXd& vdot) {
  const double h = 1e-5;
  const BodyJacobians J = JacobiansByFiniteDifferences(plant, q);
  const auto com_and_w = [&](double t) {
    const VectorXd qt = Advance(plant, q, t * v), vt = v + t * vdot;
    const std::vector<Transform> X = BodyPosesInWorld(plant, qt);
    const std::vector<Vector6d> V = BodySpatialVelocities(plant, qt, vt);
    std::vector<Vector6d> out(plant.bodies.size());
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      const Vector3d w = V[b].head<3>();
      out[b] << w, V[b].tail<3>() + w.cross(X[b].R * plant.bodies[b].p_BoBcm_B);
    }
    return out;
  };
  const std::vector<Vector6d> plus = com_and_w(h), minus = com_and_w(-h), now = com_and_w(0);
  const std::vector<Transform> X = BodyPosesInWorld(plant, q);
  VectorXd tau = VectorXd::Zero(plant.num_velocities);
  for (size_t b = 1; b < plant.bodies.size(); ++b) {
    const PlantBody& body = plant.bodies[b];
    const Vector6d a = (plus[b] - minus[b]) / (2 * h);
    const Vector3d w = now[b].head<3>();
    const Eigen::Matrix3d I_W = X[b].R * body.I_BBcm_B * X[b].R.transpose();
    tau += J.Jv[b].transpose() * (body.mass * (a.tail<3>() - plant.gravity));
    tau += J.Jw[b].transpose() * (I_W * a.head<3>() + w.cross(I_W * w));
  }
  return tau;
}

/// A floating tree over every joint type with rotated frames, offsets,
/// rotated inertias and a massless link in between; the last bodies keep
/// M regular.
ir::Module EveryJointTree(std::mt19937& rng) {
  ModelBuilder b;
  const auto body = [&](const std::string& name) { return test_util::AddRandomBody(b, rng, name); };
  const auto pose = [&] { return test_util::RandomPose(rng); };
  const auto axis = [&] { return test_util::RandomVector(rng, 1.0).normalized(); };
  const BodyId base = body("base");
  b.AddJoint("base", JointType::QuaternionFloating, ir::kWorldBody, base, {}, Vector3d::UnitZ(), pose());
  const struct { const char* name; JointType type; const char* parent; } chain[] = {
      {"shoulder", JointType::Ball, "base"},        {"elbow", JointType::Revolute, "shoulder"},
      {"slide", JointType::Prismatic, "elbow"},     {"screw", JointType::Screw, "slide"},
      {"wrist", JointType::Universal, "screw"},     {"table", JointType::Planar, "base"},
      {"flyer", JointType::RpyFloating, "table"},   {"track", JointType::Curvilinear, "base"},
  };
  std::map<std::string, BodyId> bodies{{"base", base}};
  for (const auto& link : chain) {
    const BodyId child = body(link.name);
    bodies[link.name] = child;
    const JointId j = b.AddJoint(link.name, link.type, bodies.at(link.parent), child, pose(), axis(), pose());
    b.module()[j].screw_thread_pitch = 0.05;
    if (link.type == JointType::Curvilinear) {
      ir::CurvilinearPath& path = b.module()[j].curvilinear_path;
      path.initial_tangent = Vector3d::UnitX();
      path.plane_normal = Vector3d::UnitZ();
      path.segments = {{0.5, 2.0}, {0.7, -1.0}, {0.4, 0.0}};
    }
  }
  const BodyId massless = b.AddMasslessBody("massless");
  b.AddJoint("mount", JointType::Weld, bodies.at("wrist"), massless, pose(), Vector3d::UnitZ(), pose());
  const BodyId tool = body("tool");
  b.AddJoint("tool", JointType::Revolute, massless, tool, pose(), axis(), pose());
  return std::move(b.module());
}

struct State {
  VectorXd q, v, vdot;
};

State RandomState(std::mt19937& rng, const Plant& plant) {
  std::uniform_real_distribution<double> u(-1, 1);
  State s{VectorXd(plant.num_positions), VectorXd(plant.num_velocities),
          VectorXd(plant.num_velocities)};
  for (auto* x : {&s.q, &s.v, &s.vdot}) {
    for (Eigen::Index i = 0; i < x->size(); ++i) (*x)[i] = u(rng);
  }
  for (const PlantJoint& joint : plant.joints) {
    if (joint.type == JointType::QuaternionFloating) s.q.segment<4>(joint.q_start).normalize();
  }
  return s;
}

double Scale(const VectorXd& x) { return 1 + x.cwiseAbs().maxCoeff(); }

class DynamicsOnEveryJoint : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937 rng(20261207);
    module_ = EveryJointTree(rng);
    model_ = test_util::InstantiateOk(module_);
    ASSERT_TRUE(model_);
    ASSERT_EQ(plant().num_velocities, 6 + 3 + 1 + 1 + 1 + 2 + 3 + 6 + 1 + 1);
  }
  const Plant& plant() const { return model_->plant; }
  ir::Module module_;
  std::optional<CompiledModel> model_;
};

TEST_F(DynamicsOnEveryJoint, InverseDynamicsMatchesKanesMethod) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 4; ++trial) {
    const State s = RandomState(rng, plant());
    const VectorXd tau = InverseDynamics(plant(), s.q, s.v, s.vdot);
    const VectorXd expected = InverseDynamicsByKane(plant(), s.q, s.v, s.vdot);
    EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-6 * Scale(expected))
        << "trial " << trial << "\n" << tau.transpose() << "\n" << expected.transpose();
  }
}

TEST_F(DynamicsOnEveryJoint, InverseDynamicsIsMassMatrixTimesVdotPlusBiasMinusGravity) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 4; ++trial) {
    const State s = RandomState(rng, plant());
    const VectorXd expected = CalcMassMatrix(plant(), s.q) * s.vdot + BiasTerm(plant(), s.q, s.v) -
                              GravityForces(plant(), s.q);
    const VectorXd tau = InverseDynamics(plant(), s.q, s.v, s.vdot);
    EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-10 * Scale(expected));
  }
}

TEST_F(DynamicsOnEveryJoint, GravityForcesAreMinusThePotentialGradient) {
  std::mt19937 rng(3);
  const double h = 1e-6;
  const State s = RandomState(rng, plant());
  const VectorXd tau_g = GravityForces(plant(), s.q);
  for (int k = 0; k < plant().num_velocities; ++k) {
    const VectorXd e = VectorXd::Unit(plant().num_velocities, k) * h;
    const double dV = PotentialEnergy(plant(), Advance(plant(), s.q, e)) -
                      PotentialEnergy(plant(), Advance(plant(), s.q, -e));
    EXPECT_NEAR(tau_g[k], -dV / (2 * h), 1e-6 * Scale(tau_g)) << "velocity " << k;
  }
}

TEST_F(DynamicsOnEveryJoint, ForwardDynamicsInvertsInverseDynamics) {
  std::mt19937 rng(4);
  DynamicsOptions all;
  all.joint_damping = all.force_elements = all.reflected_inertia = true;
  for (int trial = 0; trial < 4; ++trial) {
    const State s = RandomState(rng, plant());
    const VectorXd tau = s.vdot * 10;
    const VectorXd vdot = ForwardDynamics(plant(), s.q, s.v, tau, all);
    EXPECT_LT((InverseDynamics(plant(), s.q, s.v, vdot, all) - tau).cwiseAbs().maxCoeff(),
              1e-9 * Scale(tau));
  }
}

TEST_F(DynamicsOnEveryJoint, BodyAccelerationsAreTheRateOfBodyVelocities) {
  std::mt19937 rng(5);
  const double h = 1e-5;
  const State s = RandomState(rng, plant());
  const std::vector<Vector6d> A = BodySpatialAccelerations(plant(), s.q, s.v, s.vdot);
  const auto V = [&](double t) {
    return BodySpatialVelocities(plant(), Advance(plant(), s.q, t * s.v), s.v + t * s.vdot);
  };
  const std::vector<Vector6d> plus = V(h), minus = V(-h);
  for (size_t b = 0; b < plant().bodies.size(); ++b) {
    const Vector6d expected = (plus[b] - minus[b]) / (2 * h);
    EXPECT_LT((A[b] - expected).cwiseAbs().maxCoeff(), 1e-6 * (1 + expected.norm()))
        << "body " << plant().bodies[b].name << "\n" << A[b].transpose() << "\n" << expected.transpose();
  }
}

TEST_F(DynamicsOnEveryJoint, JacobianMatchesFiniteDifferencesOfAFramePoint) {
  std::mt19937 rng(6);
  const double h = 1e-6;
  const State s = RandomState(rng, plant());
  const BodyId tool(plant().bodies.size() - 1), shoulder(size_t{2});
  const BodyFixedFrame B{tool, {test_util::RandomRotation(rng), test_util::RandomVector(rng, 0.3)}};
  const BodyFixedFrame world{BodyId(size_t{0})};
  const Vector3d p_BoBp_B = test_util::RandomVector(rng, 0.2);
  const auto point = [&](const VectorXd& q) {
    const Transform X_WB = BodyPosesInWorld(plant(), q)[tool.index()] * B.X_BF;
    return std::pair{X_WB * p_BoBp_B, X_WB.R};
  };
  const MatrixXd J = JacobianSpatialVelocity(plant(), s.q, B, p_BoBp_B, world, world);
  for (int k = 0; k < plant().num_velocities; ++k) {
    const VectorXd e = VectorXd::Unit(plant().num_velocities, k) * h;
    const auto [p_plus, R_plus] = point(Advance(plant(), s.q, e));
    const auto [p_minus, R_minus] = point(Advance(plant(), s.q, -e));
    Vector6d expected;
    expected << test_util::Vee((R_plus - R_minus) / (2 * h) * R_plus.transpose()),
        (p_plus - p_minus) / (2 * h);
    EXPECT_LT((J.col(k) - expected).cwiseAbs().maxCoeff(), 1e-6) << "velocity " << k;
  }
  // J v is the point's spatial velocity; measured in and expressed in other
  // frames: V_ABp_E = R_EW (V_WBp - V_WAp), Ap the point of A at Bp
  const BodyFixedFrame A{shoulder, {test_util::RandomRotation(rng), test_util::RandomVector(rng, 0.3)}};
  const BodyFixedFrame E{tool, B.X_BF};
  const MatrixXd J_A = JacobianSpatialVelocity(plant(), s.q, B, p_BoBp_B, A, world);
  const std::vector<Vector6d> V = BodySpatialVelocities(plant(), s.q, s.v);
  const std::vector<Transform> X = BodyPosesInWorld(plant(), s.q);
  const Vector3d p_WBp = point(s.q).first;
  const auto at = [&](BodyId b) {
    Vector6d x;
    x << V[b.index()].head<3>(), V[b.index()].tail<3>() + V[b.index()].head<3>().cross(p_WBp - X[b.index()].p);
    return x;
  };
  EXPECT_LT((J_A * s.v - (at(tool) - at(shoulder))).cwiseAbs().maxCoeff(), 1e-12);
  const MatrixXd J_AE = JacobianSpatialVelocity(plant(), s.q, B, p_BoBp_B, A, E);
  const Eigen::Matrix3d R_EW = (X[tool.index()].R * E.X_BF.R).transpose();
  EXPECT_LT((J_AE.topRows<3>() - R_EW * J_A.topRows<3>()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((J_AE.bottomRows<3>() - R_EW * J_A.bottomRows<3>()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(JacobianTranslationalVelocity(plant(), s.q, B, p_BoBp_B, A, E), J_AE.bottomRows<3>());
}

TEST_F(DynamicsOnEveryJoint, CenterOfMassJacobianAndVelocity) {
  std::mt19937 rng(7);
  const double h = 1e-6;
  const State s = RandomState(rng, plant());
  const CenterOfMass com = CalcCenterOfMass(plant(), s.q, s.v);
  double mass = 0;
  for (const PlantBody& body : plant().bodies) mass += body.mass;
  EXPECT_NEAR(com.mass, mass, 1e-12);
  for (int k = 0; k < plant().num_velocities; ++k) {
    const VectorXd e = VectorXd::Unit(plant().num_velocities, k) * h;
    const Vector3d expected = (CalcCenterOfMass(plant(), Advance(plant(), s.q, e), {}).position -
                               CalcCenterOfMass(plant(), Advance(plant(), s.q, -e), {}).position) /
                              (2 * h);
    EXPECT_LT((com.jacobian.col(k) - expected).cwiseAbs().maxCoeff(), 1e-7) << "velocity " << k;
  }
  EXPECT_LT((com.velocity - com.jacobian * s.v).cwiseAbs().maxCoeff(), 1e-12);
  // one model instance: the only one here, so the same center
  const CenterOfMass robot = CalcCenterOfMass(plant(), s.q, {}, {plant().bodies[1].model});
  EXPECT_LT((robot.position - com.position).norm(), 1e-12);
  EXPECT_THROW(CalcCenterOfMass(plant(), s.q, {}, {ModelId(size_t{0})}), std::domain_error);
}

// With springs and no damping the model is conservative: d(T + V)/dt = v . tau.
TEST_F(DynamicsOnEveryJoint, EnergyRateIsThePowerOfTheActuation) {
  ir::ForceElement spring;
  spring.model = module_.bodies[1].model;
  ir::JointSpring joint_spring;
  joint_spring.joint = {module_.Intern("elbow"), {}, JointId(size_t{2})};
  joint_spring.nominal = 0.3;
  joint_spring.stiffness = 4;
  spring.payload = joint_spring;
  module_.Add(spring);
  ir::LinearSpringDamper rope;
  rope.body_A = {module_.Intern("world"), {}, BodyId(size_t{0})};
  rope.body_B = {module_.Intern("tool"), {}, BodyId(module_.bodies.size() - 1)};
  rope.p_AP = Vector3d(0.1, 0.2, 2.0);
  rope.p_BQ = Vector3d(0.05, 0, 0);
  rope.free_length = 0.5;
  rope.stiffness = 30;
  spring.payload = rope;
  module_.Add(spring);
  model_ = test_util::InstantiateOk(module_);
  ASSERT_TRUE(model_);
  // a bushing between the base and the tool, its frames named as bodies
  LinearBushingRpy bushing;
  bushing.frame_A = "robot::base";
  bushing.frame_C = "robot::tool";
  bushing.torque_stiffness = Vector3d(3, 4, 5);
  bushing.force_stiffness = Vector3d(20, 30, 40);
  model_->plant.force_elements.push_back(bushing);
  ASSERT_EQ(plant().force_elements.size(), 3u);

  DynamicsOptions conservative;
  conservative.force_elements = true;
  std::mt19937 rng(8);
  const double h = 1e-5;
  for (int trial = 0; trial < 3; ++trial) {
    const State s = RandomState(rng, plant());
    const VectorXd tau = s.vdot;
    const VectorXd vdot = ForwardDynamics(plant(), s.q, s.v, tau, conservative);
    const auto energy = [&](double t) {
      const VectorXd qt = Advance(plant(), s.q, t * s.v), vt = s.v + t * vdot;
      return KineticEnergy(plant(), qt, vt, conservative) + PotentialEnergy(plant(), qt, conservative);
    };
    const double rate = (energy(h) - energy(-h)) / (2 * h);
    EXPECT_NEAR(rate, s.v.dot(tau), 1e-6 * (1 + std::abs(s.v.dot(tau))));
  }
  // the springs' generalized forces are minus their energy's gradient
  const State s = RandomState(rng, plant());
  DynamicsOptions springs_only;
  springs_only.gravity = false;
  springs_only.force_elements = true;
  const VectorXd zero_v = VectorXd::Zero(plant().num_velocities);
  const VectorXd applied = AppliedForces(plant(), s.q, zero_v, springs_only);
  for (int k = 0; k < plant().num_velocities; ++k) {
    const VectorXd e = VectorXd::Unit(plant().num_velocities, k) * 1e-6;
    const double dV = PotentialEnergy(plant(), Advance(plant(), s.q, e), springs_only) -
                      PotentialEnergy(plant(), Advance(plant(), s.q, -e), springs_only);
    EXPECT_NEAR(applied[k], -dV / 2e-6, 1e-5 * Scale(applied)) << "velocity " << k;
  }
  // dampers only: their power is minus twice the dissipation function, so
  // it is negative whatever v is
  Plant& damped = model_->plant;
  for (ForceElement& element : damped.force_elements) {
    if (auto* b = std::get_if<LinearBushingRpy>(&element)) {
      b->torque_stiffness.setZero();
      b->force_stiffness.setZero();
      b->torque_damping = Vector3d(1, 2, 3);
      b->force_damping = Vector3d(4, 5, 6);
    } else if (auto* rope = std::get_if<LinearSpringDamper>(&element)) {
      rope->stiffness = 0;
      rope->damping = 7;
    } else {
      std::get<JointSpring>(element).stiffness = 0;
    }
  }
  for (int trial = 0; trial < 3; ++trial) {
    const State t = RandomState(rng, plant());
    EXPECT_LT(AppliedForces(plant(), t.q, t.v, springs_only).dot(t.v), 0);
    EXPECT_NEAR(AppliedForces(plant(), t.q, VectorXd::Zero(plant().num_velocities), springs_only).norm(), 0, 1e-12);
  }
}

TEST(Dynamics, PendulumClosedForm) {
  ModelBuilder b;
  const double m = 2.0, l = 0.7, I_c = 0.03, d = 0.4;
  const BodyId link = b.AddBody("link", m, Vector3d(0, 0, -l), Diag(I_c, I_c, I_c));
  const JointId pivot = b.AddJoint("pivot", JointType::Revolute, ir::kWorldBody, link, {}, Vector3d::UnitY());
  b.module()[pivot].damping = {d};
  ir::Actuator motor;
  motor.name = b.module().Intern("motor");
  motor.model = b.model();
  motor.joint = b.Ref(pivot, "pivot");
  motor.gear_ratio = 20;
  motor.rotor_inertia = 1e-4;
  b.module().Add(motor);
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  const double g = 9.81, reflected = 1e-4 * 20 * 20, I = m * l * l + I_c;
  for (const auto& [q, v, vdot] : {std::tuple{0.0, 0.0, 0.0}, {0.6, -1.5, 2.0}, {-2.5, 3.0, -1.0}}) {
    const Eigen::VectorXd Q = VectorXd::Constant(1, q), V = VectorXd::Constant(1, v),
                          A = VectorXd::Constant(1, vdot);
    // the COM at (-l sin q, 0, -l cos q) (rotation about +y): gravity pulls q back to 0
    EXPECT_NEAR(GravityForces(plant, Q)[0], -m * g * l * std::sin(q), 1e-12);
    EXPECT_NEAR(BiasTerm(plant, Q, V)[0], 0, 1e-12);
    DynamicsOptions options;
    options.joint_damping = true;
    const double tau = (I + reflected) * vdot + m * g * l * std::sin(q) + d * v;
    EXPECT_NEAR(InverseDynamics(plant, Q, V, A, options)[0], tau, 1e-12);
    EXPECT_NEAR(ForwardDynamics(plant, Q, V, VectorXd::Constant(1, tau), options)[0], vdot, 1e-12);
    options.reflected_inertia = false;
    EXPECT_NEAR(InverseDynamics(plant, Q, V, A, options)[0], tau - reflected * vdot, 1e-12);
    EXPECT_NEAR(KineticEnergy(plant, Q, V, options), I * v * v / 2, 1e-12);
    EXPECT_NEAR(PotentialEnergy(plant, Q), -m * g * l * std::cos(q), 1e-12);
    const std::vector<Vector6d> V_WB = BodySpatialVelocities(plant, Q, V);
    EXPECT_LT((V_WB[1] - (Vector6d() << 0, v, 0, 0, 0, 0).finished()).norm(), 1e-12);
  }
}

TEST(Dynamics, RejectsWrongSizesAndSingularMass) {
  ModelBuilder b;
  const BodyId massless = b.AddMasslessBody("massless");
  b.AddJoint("pivot", JointType::Revolute, ir::kWorldBody, massless, {}, Vector3d::UnitY());
  auto model = test_util::InstantiateOk(b.module());
  ASSERT_TRUE(model);
  const Plant& plant = model->plant;
  const VectorXd one = VectorXd::Zero(1), two = VectorXd::Zero(2);
  EXPECT_THROW(InverseDynamics(plant, two, one, one), std::invalid_argument);
  EXPECT_THROW(InverseDynamics(plant, one, two, one), std::invalid_argument);
  EXPECT_THROW(InverseDynamics(plant, one, one, two), std::invalid_argument);
  EXPECT_THROW(ForwardDynamics(plant, one, one, two), std::invalid_argument);
  EXPECT_THROW(GravityForces(plant, two), std::invalid_argument);
  EXPECT_THROW(ForwardDynamics(plant, one, one, one), std::domain_error);
  EXPECT_THROW(CalcCenterOfMass(plant, one, {}), std::domain_error);
  EXPECT_EQ(InverseDynamics(plant, one, one, one).size(), 1);
}

// A point mass on its joint's axis has no inertia along the joint's motion:
// M is singular though the body has mass, and the round-off of M's entry
// must not pass for an inertia. A small but real inertia, away from the
// world origin, still counts.
TEST(Dynamics, PointMassOnItsAxisIsSingularButASmallInertiaIsNot) {
  for (const bool point_mass : {true, false}) {
    ModelBuilder b;
    const Eigen::Matrix3d I = point_mass ? Eigen::Matrix3d::Zero() : Diag(1e-9, 1e-9, 1e-9);
    const BodyId link = b.AddBody("link", point_mass ? 0.5 : 1e-3, Vector3d::Zero(), I);
    const Transform X_PF{RotationFromRpy(Vector3d(0.3, 0.2, 0.1)), Vector3d(3, -2, 1)};
    b.AddJoint("spin", JointType::Revolute, ir::kWorldBody, link, X_PF, Vector3d(0.6, 0.8, 0));
    auto model = test_util::InstantiateOk(b.module());
    ASSERT_TRUE(model);
    const VectorXd q = VectorXd::Constant(1, 2.7), v = VectorXd::Constant(1, 0.3),
                   tau = VectorXd::Constant(1, 1e-9);
    if (point_mass) {
      EXPECT_THROW(ForwardDynamics(model->plant, q, v, tau), std::domain_error);
    } else {
      EXPECT_NEAR(ForwardDynamics(model->plant, q, v, tau)[0], 1.0, 1e-6);
    }
  }
}

}  // namespace
}  // namespace mdlc::backend
