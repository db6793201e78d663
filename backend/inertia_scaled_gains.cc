// inertia_scaled_gains.cc - springdamper and dampratio from M(qpos0).
#include "backend/inertia_scaled_gains.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "backend/mass_matrix.h"
#include "backend/positions.h"

namespace mdlc::backend {

namespace {

constexpr double kMinVal = 1e-15;  // MuJoCo's mjMINVAL

/// MuJoCo's "same frame" test of a body's inertia frame against the body
/// frame, on what the plant keeps: the COM at the origin (1e-6 per
/// coordinate, as MuJoCo compares frames) and no products of inertia.
bool InertiaFrameIsBodyFrame(const PlantBody& body) {
  if ((body.p_BoBcm_B.array().abs() >= 1e-6).any()) return false;
  const Eigen::Matrix3d& I = body.I_BBcm_B;
  const double largest = I.diagonal().cwiseAbs().maxCoeff();
  const double off = std::max({std::abs(I(0, 1)), std::abs(I(0, 2)), std::abs(I(1, 2))});
  return off <= 1e-6 * largest;
}

class ModelGains {
 public:
  ModelGains(const ir::Module& module, const ir::InertiaScaledGains& request, Plant& plant,
             DiagnosticEngine& diags)
      : m_(module), g_(request), plant_(plant), diags_(diags) {}

  bool Apply() {
    JointSpace();
    bool ok = true;
    if (!g_.spring_dampers.empty()) ok = SpringDampers();
    for (const auto& d : g_.damp_ratios) DampRatio(d);
    return ok;
  }

 private:
  // M at qpos0 over the model's joints, armature on the diagonal
  void JointSpace() {
    Eigen::VectorXd q = DefaultPositions(plant_);
    std::vector<double> armature;
    for (const auto& s : g_.joints) {
      if (s.joint.index() >= plant_.joints.size()) continue;
      const PlantJoint& j = plant_.joint(s.joint);
      if (j.nv == 0) continue;
      if (j.type == ir::JointType::Revolute || j.type == ir::JointType::Prismatic) {
        q[j.q_start] = s.qpos0;
      } else if (j.type == ir::JointType::Ball) {
        q.segment(j.q_start, j.nq).setZero();  // roll-pitch-yaw 0: MuJoCo's unit quaternion
      }
      // a free joint anywhere: M^-1 on the other joints does not depend on it
      start_[s.joint.index()] = size_;
      joints_.push_back(s.joint);
      size_ += j.nv;
      armature.insert(armature.end(), static_cast<size_t>(j.nv), s.armature);
    }
    M_ = CalcMassMatrix(plant_, q, joints_);
    for (int k = 0; k < size_; ++k) M_(k, k) += armature[static_cast<size_t>(k)];
  }

  int Start(JointId joint) const {
    auto it = start_.find(joint.index());
    return it == start_.end() ? -1 : it->second;
  }

  // Cholesky pivots, relative to M's diagonal, at least this (else M is
  // singular up to rounding: MuJoCo's own factorization then divides by ~0)
  static constexpr double kMinRelativePivot = 1e-12;

  bool PositiveDefinite(const Eigen::LLT<Eigen::MatrixXd>& llt) const {
    if (llt.info() != Eigen::Success) return false;
    const Eigen::MatrixXd& L = llt.matrixLLT();
    for (int k = 0; k < size_; ++k) {
      if (!(L(k, k) * L(k, k) > kMinRelativePivot * M_(k, k))) return false;
    }
    return true;
  }

  bool SpringDampers() {
    const Eigen::LLT<Eigen::MatrixXd> llt(M_);
    if (!PositiveDefinite(llt)) {
      diags_.Report(DiagKind::BadMassProperties, g_.spring_dampers.front().loc,
                    fmt::format("the joint-space inertia of model '{}' at qpos0 is singular "
                                "(two joints move it alike, or a moving body has no mass): "
                                "springdamper cannot be computed",
                                m_.ModelName(g_.model)));
      return false;
    }
    for (const auto& s : g_.spring_dampers) {
      const int start = Start(s.joint);
      if (start < 0) continue;
      PlantJoint& joint = plant_.joints[s.joint.index()];
      const int n = joint.nv;
      // (M^-1)_kk over the joint's dofs: MuJoCo's dof_invweight0
      Eigen::MatrixXd E = Eigen::MatrixXd::Zero(size_, n);
      for (int k = 0; k < n; ++k) E(start + k, k) = 1;
      const Eigen::MatrixXd X = llt.solve(E);
      double sum = 0;
      for (int k = 0; k < n; ++k) sum += X(start + k, k);
      if (s.simple_body.valid() && s.simple_body.index() < plant_.bodies.size()) {
        const PlantBody& body = plant_.body(s.simple_body);
        if (InertiaFrameIsBodyFrame(body)) sum = n / std::max(kMinVal, body.mass);
      }
      const double inertia = n / std::max(kMinVal, sum);
      const double stiffness =
          inertia / std::max(kMinVal, s.timeconst * s.timeconst * s.dampratio * s.dampratio);
      const double damping = 2 * inertia / std::max(kMinVal, s.timeconst);
      joint.damping.assign(static_cast<size_t>(n), damping);
      if (joint.type == ir::JointType::Revolute || joint.type == ir::JointType::Prismatic) {
        plant_.force_elements.emplace_back(JointSpring{.joint = s.joint, .nominal = s.springref, .stiffness = stiffness});
      }
    }
    return true;
  }

  void DampRatio(const ir::InertiaScaledGains::DampRatio& d) {
    if (d.actuator.index() >= plant_.actuators.size()) return;
    PlantActuator& a = plant_.actuators[d.actuator.index()];
    const int k = Start(a.joint);
    if (k < 0 || plant_.joint(a.joint).nv != 1) return;
    // MuJoCo's dof_M0 reflected through the transmission (moment = gear)
    const double trn2 = a.gear_ratio * a.gear_ratio;
    const double mass = trn2 > kMinVal ? M_(k, k) / trn2 : 0.0;
    const double kp = a.kp.value_or(0);
    a.kd = d.dampratio * 2 * std::sqrt(kp * mass);
  }

  const ir::Module& m_;
  const ir::InertiaScaledGains& g_;
  Plant& plant_;
  DiagnosticEngine& diags_;
  std::vector<JointId> joints_;
  std::unordered_map<size_t, int> start_;  // joint index -> first row in M_
  int size_ = 0;
  Eigen::MatrixXd M_;
};

}  // namespace

bool ApplyInertiaScaledGains(const ir::Module& module, Plant& plant, DiagnosticEngine& diags) {
  bool ok = true;
  for (const ir::InertiaScaledGains& g : module.inertia_scaled_gains) {
    if (g.empty()) continue;
    ok = ModelGains(module, g, plant, diags).Apply() && ok;
  }
  return ok;
}

}  // namespace mdlc::backend
