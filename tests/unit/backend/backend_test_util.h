// backend_test_util.h - builds small resolved IR modules by hand for the
// backend tests, plus an independent (finite-difference) mass matrix.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <random>
#include <string>

#include "backend/backend.h"
#include "ir/module.h"

namespace mdlc::backend::test_util {

/// A module with one model instance ("robot" by default) and helpers that add
/// entities with every reference already resolved.
class ModelBuilder {
 public:
  explicit ModelBuilder(std::string_view instance = "robot") { model_ = AddInstance(instance); }

  ir::Module& module() { return module_; }
  ModelId model() const { return model_; }

  ModelId AddInstance(std::string_view name) {
    return module_.Add(ir::ModelInstance{module_.Intern(name), {}, ir::SourceFormat::Internal, {}, {}});
  }
  void SetInstance(ModelId model) { model_ = model; }

  template <typename IdT>
  ir::Ref<IdT> Ref(IdT id, std::string_view name) {
    return {module_.Intern(name), {}, id};
  }
  /// A resolved reference to `id`; an out-of-range id (for error tests)
  /// gets the name "missing".
  ir::Ref<BodyId> BodyRef(BodyId id) {
    const bool in_range = id.index() < module_.bodies.size();
    return {in_range ? module_.bodies[id.index()].name : module_.Intern("missing"), {}, id};
  }

  BodyId AddMasslessBody(std::string_view name) {
    ir::Body body;
    body.name = module_.Intern(name);
    body.model = model_;
    return module_.Add(body);
  }

  /// A body of mass m whose COM is at `com` in B, with moments `I_I` about
  /// the COM expressed in an inertia frame rotated by R_BI.
  BodyId AddBody(std::string_view name, double mass, const Eigen::Vector3d& com,
                 const Eigen::Matrix3d& I_I,
                 const Eigen::Matrix3d& R_BI = Eigen::Matrix3d::Identity()) {
    ir::Body body;
    body.name = module_.Intern(name);
    body.model = model_;
    ir::Inertial in;
    in.mass = mass;
    in.X_BI = {R_BI, com};
    in.ixx = I_I(0, 0);
    in.iyy = I_I(1, 1);
    in.izz = I_I(2, 2);
    in.ixy = I_I(0, 1);
    in.ixz = I_I(0, 2);
    in.iyz = I_I(1, 2);
    body.inertial = in;
    return module_.Add(body);
  }

  JointId AddJoint(std::string_view name, ir::JointType type, BodyId parent, BodyId child,
                   const Transform& X_PF = {},
                   const Eigen::Vector3d& axis = Eigen::Vector3d::UnitZ(),
                   const Transform& X_CM = {}) {
    ir::Joint joint;
    joint.name = module_.Intern(name);
    joint.model = model_;
    joint.type = type;
    joint.parent = BodyRef(parent);
    joint.child = BodyRef(child);
    joint.X_PF = X_PF;
    joint.X_CM = X_CM;
    joint.axis = axis;
    return module_.Add(joint);
  }

  GeometryId AddGeometry(std::string_view name, BodyId body, ir::Shape shape, uint8_t roles,
                         const Transform& X_BG = {}) {
    ir::Geometry g;
    g.name = module_.Intern(name);
    g.model = model_;
    g.body = BodyRef(body);
    g.shape = std::move(shape);
    g.roles = roles;
    g.X_BG = X_BG;
    return module_.Add(g);
  }

 private:
  ir::Module module_;
  ModelId model_;
};

/// Instantiates and fails the test (returning nullopt) on any diagnostic error.
inline std::optional<CompiledModel> InstantiateOk(const ir::Module& module) {
  DiagnosticEngine diags;
  std::optional<CompiledModel> model = Instantiate(module, diags);
  for (const Diagnostic& d : diags.diagnostics()) ADD_FAILURE() << d.message;
  EXPECT_TRUE(model.has_value());
  return model;
}

inline Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-M_PI, M_PI);
  return RotationFromRpy(Eigen::Vector3d(u(rng), u(rng) / 2, u(rng)));
}

inline Eigen::Vector3d RandomVector(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  return {u(rng), u(rng), u(rng)};
}

/// A physically valid, non-diagonal inertia about the COM (box-like moments
/// in a random frame).
inline Eigen::Matrix3d RandomInertia(std::mt19937& rng, double mass) {
  std::uniform_real_distribution<double> u(0.05, 0.4);
  const double a = u(rng), b = u(rng), c = u(rng);
  const Eigen::Vector3d moments(b * b + c * c, a * a + c * c, a * a + b * b);
  const Eigen::Matrix3d R = RandomRotation(rng);
  return R * (mass / 12 * moments).asDiagonal() * R.transpose();
}

/// A body of random mass (0.5 to 2.5), COM offset and rotated inertia.
inline BodyId AddRandomBody(ModelBuilder& b, std::mt19937& rng, const std::string& name) {
  const double m = 0.5 + std::abs(RandomVector(rng, 2.0).x());
  return b.AddBody(name, m, RandomVector(rng, 0.2), RandomInertia(rng, m), RandomRotation(rng));
}

/// A random rotation with an offset of up to 0.4 per axis.
inline Transform RandomPose(std::mt19937& rng) {
  return Transform{RandomRotation(rng), RandomVector(rng, 0.4)};
}

inline Eigen::Vector3d Vee(const Eigen::Matrix3d& S) {
  return {0.5 * (S(2, 1) - S(1, 2)), 0.5 * (S(0, 2) - S(2, 0)), 0.5 * (S(1, 0) - S(0, 1))};
}

/// The joint's positions after moving by `eps` along velocity coordinate k,
/// from `q_joint`. For joints with qdot = v that is q + eps e_k; for the
/// rotation parameterizations the rotation is advanced by an angular
/// velocity e_k expressed in F (R_FM <- exp(eps [e_k]) R_FM).
inline Eigen::VectorXd MoveAlongVelocity(const PlantJoint& joint,
                                         const Eigen::VectorXd& q_joint, int k, double eps) {
  Eigen::VectorXd q = q_joint;
  const auto rotated = [&](const Eigen::Matrix3d& R) -> Eigen::Matrix3d {
    return Eigen::AngleAxisd(eps, Eigen::Vector3d::Unit(k)).toRotationMatrix() * R;
  };
  switch (joint.type) {
    case ir::JointType::Ball:
      q = RpyFromRotation(rotated(RotationFromRpy(q_joint.head<3>())));
      return q;
    case ir::JointType::RpyFloating:
      if (k < 3) q.head<3>() = RpyFromRotation(rotated(RotationFromRpy(q_joint.head<3>())));
      else q[k] += eps;
      return q;
    case ir::JointType::QuaternionFloating:
      if (k < 3) {
        const Eigen::Quaterniond quat(q_joint[0], q_joint[1], q_joint[2], q_joint[3]);
        const Eigen::Quaterniond moved(rotated(quat.normalized().toRotationMatrix()));
        q.head<4>() << moved.w(), moved.x(), moved.y(), moved.z();
      } else {
        q[k + 1] += eps;
      }
      return q;
    default:
      q[k] += eps;
      return q;
  }
}

/// M = sum over bodies of Jv^T m Jv + Jw^T I_W Jw, with the COM and angular
/// velocity Jacobians taken by 5-point central differences of forward
/// kinematics. Independent of the spatial algebra in mass_matrix.cc.
inline Eigen::MatrixXd MassMatrixByFiniteDifferences(const Plant& plant,
                                                     const Eigen::VectorXd& q) {
  const double h = 1e-3;
  const int nb = static_cast<int>(plant.bodies.size());
  const int nv = plant.num_velocities;
  std::vector<Eigen::MatrixXd> Jv(nb, Eigen::MatrixXd::Zero(3, nv));
  std::vector<Eigen::MatrixXd> Jw(nb, Eigen::MatrixXd::Zero(3, nv));
  const std::vector<Transform> X0 = BodyPosesInWorld(plant, q);
  for (const PlantJoint& joint : plant.joints) {
    const Eigen::VectorXd qj = q.segment(joint.q_start, joint.nq);
    for (int k = 0; k < joint.nv; ++k) {
      std::vector<std::vector<Transform>> X;
      for (double step : {-2.0, -1.0, 1.0, 2.0}) {
        Eigen::VectorXd qs = q;
        qs.segment(joint.q_start, joint.nq) = MoveAlongVelocity(joint, qj, k, step * h);
        X.push_back(BodyPosesInWorld(plant, qs));
      }
      const auto d = [&](const auto& f) {
        return ((f(X[0]) - 8 * f(X[1]) + 8 * f(X[2]) - f(X[3])) / (12 * h)).eval();
      };
      for (int b = 0; b < nb; ++b) {
        const PlantBody& body = plant.bodies[b];
        const int col = joint.v_start + k;
        Jv[b].col(col) = d([&](const std::vector<Transform>& Xs) -> Eigen::Vector3d {
          return Xs[b] * body.p_BoBcm_B;
        });
        const Eigen::Matrix3d dR = d([&](const std::vector<Transform>& Xs) -> Eigen::Matrix3d {
          return Xs[b].R;
        });
        Jw[b].col(col) = Vee(dR * X0[b].R.transpose());
      }
    }
  }
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(nv, nv);
  for (int b = 0; b < nb; ++b) {
    const PlantBody& body = plant.bodies[b];
    const Eigen::Matrix3d I_W = X0[b].R * body.I_BBcm_B * X0[b].R.transpose();
    M += body.mass * Jv[b].transpose() * Jv[b] + Jw[b].transpose() * I_W * Jw[b];
  }
  return M;
}

}  // namespace mdlc::backend::test_util
