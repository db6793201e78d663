// dynamics.cc - velocities, accelerations, inverse dynamics, energies,
// Jacobians and the center of mass over the sweeps of tree_sweep.h (forward
// dynamics is forward_dynamics.cc).
#include "backend/dynamics.h"

#include <stdexcept>
#include <string>

#include "backend/applied_forces.h"
#include "backend/tree_sweep.h"

namespace mdlc::backend {

using Eigen::Vector3d;
using Eigen::VectorXd;

std::vector<Vector6d> BodySpatialVelocities(const Plant& plant, const VectorXd& q,
                                            const VectorXd& v) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  std::vector<Vector6d> V_WB(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    V_WB[b] = Spatial(Angular(s.V[b]), PointVelocity(s.V[b], s.X_WB[b].p));
  }
  return V_WB;
}

std::vector<Vector6d> BodySpatialAccelerations(const Plant& plant, const VectorXd& q,
                                               const VectorXd& v, const VectorXd& vdot) {
  RequireState(plant, q, &v, &vdot, "vdot");
  const TreeState s = SweepDown(plant, q, &v);
  const std::vector<Vector6d> A = Accelerations(plant, s, &vdot, Vector6d::Zero());
  // a_Bo = d/dt (v_O + w x p_WBo) = adot_O + alpha x p + w x v_Bo
  std::vector<Vector6d> A_WB(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const Vector3d& p = s.X_WB[b].p;
    const Vector3d v_Bo = PointVelocity(s.V[b], p);
    A_WB[b] = Spatial(Angular(A[b]), PointVelocity(A[b], p) + Angular(s.V[b]).cross(v_Bo));
  }
  return A_WB;
}

VectorXd ReflectedInertia(const Plant& plant) {
  VectorXd r = VectorXd::Zero(plant.num_velocities);
  for (const PlantActuator& actuator : plant.actuators) {
    const PlantJoint& joint = plant.joint(actuator.joint);
    if (joint.nv != 1) continue;  // actuators drive 1-dof joints
    r[joint.v_start] += actuator.rotor_inertia * actuator.gear_ratio * actuator.gear_ratio;
  }
  return r;
}

VectorXd InverseDynamics(const Plant& plant, const VectorXd& q, const VectorXd& v,
                         const VectorXd& vdot, const DynamicsOptions& options) {
  RequireState(plant, q, &v, &vdot, "vdot");
  const TreeState s = SweepDown(plant, q, &v);
  VectorXd tau_joint = VectorXd::Zero(plant.num_velocities);
  std::vector<Vector6d> f_ext;
  CollectAppliedForces(plant, s, q, v, options, tau_joint, f_ext);
  VectorXd tau = Rnea(plant, s, &vdot, GravityBaseAcceleration(plant, options.gravity), f_ext);
  tau -= tau_joint;
  if (options.reflected_inertia) tau += ReflectedInertia(plant).cwiseProduct(vdot);
  return tau;
}

VectorXd BiasTerm(const Plant& plant, const VectorXd& q, const VectorXd& v) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  return Rnea(plant, s, nullptr, Vector6d::Zero(), {});
}

VectorXd GravityForces(const Plant& plant, const VectorXd& q) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  return -Rnea(plant, s, nullptr, GravityBaseAcceleration(plant, true), {});
}

VectorXd AppliedForces(const Plant& plant, const VectorXd& q, const VectorXd& v,
                       const DynamicsOptions& options) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  return AppliedForcesAt(plant, s, q, v, options);
}

double KineticEnergy(const Plant& plant, const VectorXd& q, const VectorXd& v,
                     const DynamicsOptions& options) {
  RequireState(plant, q, &v);
  const TreeState s = SweepDown(plant, q, &v);
  double energy = 0;
  for (size_t b = 0; b < plant.bodies.size(); ++b) energy += s.V[b].dot(s.I[b] * s.V[b]);
  if (options.reflected_inertia) energy += ReflectedInertia(plant).dot(v.cwiseProduct(v));
  return energy / 2;
}

double PotentialEnergy(const Plant& plant, const VectorXd& q, const DynamicsOptions& options) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  double energy = 0;
  if (options.gravity) {
    for (size_t b = 0; b < plant.bodies.size(); ++b) {
      energy -= plant.bodies[b].mass * plant.gravity.dot(CenterOfMassInWorld(plant, s, b));
    }
  }
  if (options.force_elements) energy += ForceElementsPotentialEnergy(plant, s, q);
  return energy;
}

Eigen::MatrixXd JacobianSpatialVelocity(const Plant& plant, const VectorXd& q,
                                        const BodyFixedFrame& B, const Vector3d& p_BoBp_B,
                                        const BodyFixedFrame& A, const BodyFixedFrame& E) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);
  const Vector3d p_WBp = s.X_WB[B.body.index()] * (B.X_BF * p_BoBp_B);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, plant.num_velocities);
  AddPointJacobian(plant, s, B.body, p_WBp, +1, J);
  // measured in A: minus the motion of A's point that coincides with Bp
  AddPointJacobian(plant, s, A.body, p_WBp, -1, J);
  const Eigen::Matrix3d R_EW = (s.X_WB[E.body.index()].R * E.X_BF.R).transpose();
  J.topRows<3>() = R_EW * J.topRows<3>();
  J.bottomRows<3>() = R_EW * J.bottomRows<3>();
  return J;
}

Eigen::MatrixXd JacobianTranslationalVelocity(const Plant& plant, const VectorXd& q,
                                              const BodyFixedFrame& B, const Vector3d& p_BoBp_B,
                                              const BodyFixedFrame& A, const BodyFixedFrame& E) {
  return JacobianSpatialVelocity(plant, q, B, p_BoBp_B, A, E).bottomRows<3>();
}

CenterOfMass CalcCenterOfMass(const Plant& plant, const VectorXd& q, const VectorXd& v,
                              const std::vector<ModelId>& models) {
  const bool with_v = v.size() > 0;
  RequireState(plant, q, with_v ? &v : nullptr);
  const TreeState s = SweepDown(plant, q, with_v ? &v : nullptr);
  auto selected = [&](size_t b) {
    if (plant.bodies[b].is_world) return false;
    if (models.empty()) return true;
    for (ModelId m : models) {
      if (plant.bodies[b].model == m) return true;
    }
    return false;
  };
  // per body: its selected mass and first moment, then summed over subtrees
  std::vector<double> mass(plant.bodies.size(), 0);
  std::vector<Vector3d> moment(plant.bodies.size(), Vector3d::Zero());
  CenterOfMass com;
  Vector3d momentum = Vector3d::Zero();
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    if (!selected(b)) continue;
    const Vector3d c = CenterOfMassInWorld(plant, s, b);
    mass[b] = plant.bodies[b].mass;
    moment[b] = mass[b] * c;
    com.mass += mass[b];
    com.position += moment[b];
    if (with_v) momentum += mass[b] * PointVelocity(s.V[b], c);
  }
  if (!(com.mass > 0)) {
    throw std::domain_error("the selected bodies have no mass, so they have no center of mass");
  }
  com.position /= com.mass;
  com.velocity = momentum / com.mass;
  // column of joint j: sum over its subtree of m (S_lin + S_ang x c)
  com.jacobian = Eigen::MatrixXd::Zero(3, plant.num_velocities);
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    const int c = joint.child.index();
    const MotionSubspace& S = s.joint[it->index()].S;
    for (int k = 0; k < joint.nv; ++k) {
      com.jacobian.col(joint.v_start + k) =
          (mass[c] * Linear(S.col(k)) + Angular(S.col(k)).cross(moment[c])) / com.mass;
    }
    mass[joint.parent.index()] += mass[c];
    moment[joint.parent.index()] += moment[c];
  }
  return com;
}
}  // namespace mdlc::backend
