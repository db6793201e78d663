// forward_dynamics.cc - vdot by the articulated-body algorithm (ABA), O(n)
// in the bodies, in Plücker coordinates about the world origin like the
// other sweeps (tree_sweep.h). Per joint j with child c and parent p:
//   up the tree:   U = I^A_c S, D = S^T U (+ reflected inertia),
//                  u = tau_j - S^T p^A_c,
//                  I^A_p += I^A_c - U D^-1 U^T,
//                  p^A_p += p^A_c + (I^A_c - U D^-1 U^T) c_j + U D^-1 u
//   down the tree: a' = A_p + c_j, vdot_j = D^-1 (u - U^T a'), A_c = a' + S vdot_j
// where c_j is the velocity product of the RNEA (JointState) and
// p^A_c starts as V_c x* I_c V_c minus the applied body forces.
#include <Eigen/Cholesky>
#include <stdexcept>
#include <string>

#include "backend/applied_forces.h"
#include "backend/dynamics.h"
#include "backend/tree_sweep.h"

namespace mdlc::backend {

using Eigen::VectorXd;

namespace {

using JointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;

/// What the sweep up the tree leaves for the sweep down, per joint.
struct ArticulatedJoint {
  MotionSubspace U;    // I^A S
  JointMatrix D_inv;   // (S^T I^A S + reflected)^-1
  JointVector u;       // tau - S^T p^A
};

[[noreturn]] void ThrowMassless(const Plant& plant, const PlantJoint& joint) {
  throw std::domain_error("joint '" + plant.ScopedName(joint) +
                          "' has no inertia along its own motion (it moves only massless bodies, "
                          "or point masses on its axis), so the accelerations are undefined");
}

JointMatrix InvertJointInertia(const Plant& plant, const PlantJoint& joint, const JointMatrix& D) {
  const Eigen::LDLT<JointMatrix> ldlt(D);
  const JointVector d = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || !(d.minCoeff() > 1e-12 * std::max(1e-300, d.maxCoeff()))) {
    ThrowMassless(plant, joint);
  }
  return ldlt.solve(JointMatrix::Identity(joint.nv, joint.nv));
}

}  // namespace

VectorXd ForwardDynamics(const Plant& plant, const VectorXd& q, const VectorXd& v,
                         const VectorXd& tau, const DynamicsOptions& options) {
  RequireState(plant, q, &v, &tau, "tau");
  const TreeState s = SweepDown(plant, q, &v);
  VectorXd tau_total = tau;
  std::vector<Vector6d> f_ext;
  CollectAppliedForces(plant, s, q, v, options, tau_total, f_ext);
  const VectorXd reflected = options.reflected_inertia ? ReflectedInertia(plant)
                                                       : VectorXd::Zero(plant.num_velocities);

  std::vector<Matrix6d> IA(plant.bodies.size());
  std::vector<Vector6d> pA(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    if (s.I[b].is_zero) {
      IA[b].setZero();
      pA[b].setZero();
    } else {
      IA[b] = s.I[b].Matrix();
      pA[b] = CrossForce(s.V[b], s.I[b] * s.V[b]);
    }
    if (!f_ext.empty()) pA[b] -= f_ext[b];
  }
  std::vector<ArticulatedJoint> art(plant.joints.size());
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    const MotionSubspace& S = s.joint[it->index()].S;
    ArticulatedJoint& aj = art[it->index()];
    const int p = joint.parent.index(), c = joint.child.index();
    Matrix6d Ia = IA[c];
    Vector6d pa = pA[c];
    if (joint.nv == 1) {
      // most joints: D is a number and U D^-1 U^T an outer product
      const Vector6d s_col = S.col(0), U = IA[c] * s_col;
      const double D = s_col.dot(U) + reflected[joint.v_start];
      // below round-off of the product it came from, D is zero: a joint
      // moving only massless bodies, or point masses on its own axis
      const double round_off = 1e-13 * IA[c].cwiseAbs().maxCoeff() * s_col.squaredNorm();
      if (!(D > round_off)) ThrowMassless(plant, joint);
      aj.U = U;
      aj.D_inv = JointMatrix::Constant(1, 1, 1 / D);
      aj.u = JointVector::Constant(1, tau_total[joint.v_start] - s_col.dot(pA[c]));
      Ia.noalias() -= U * (U.transpose() / D);
      pa += U * (aj.u[0] / D);
    } else if (joint.nv > 1) {
      aj.U = IA[c] * S;
      JointMatrix D = S.transpose() * aj.U;
      D.diagonal() += reflected.segment(joint.v_start, joint.nv);
      aj.D_inv = InvertJointInertia(plant, joint, D);
      aj.u = tau_total.segment(joint.v_start, joint.nv) - S.transpose() * pA[c];
      Ia -= aj.U * aj.D_inv * aj.U.transpose();
      pa += aj.U * (aj.D_inv * aj.u);
    }
    pa += Ia * s.joint[it->index()].velocity_product;
    IA[p] += Ia;
    pA[p] += pa;
  }

  VectorXd vdot = VectorXd::Zero(plant.num_velocities);
  std::vector<Vector6d> A(plant.bodies.size(), Vector6d::Zero());
  A[0] = GravityBaseAcceleration(plant, options.gravity);
  for (JointId id : plant.joint_order) {
    const PlantJoint& joint = plant.joint(id);
    const ArticulatedJoint& aj = art[id.index()];
    const Vector6d a = A[joint.parent.index()] + s.joint[id.index()].velocity_product;
    A[joint.child.index()] = a;
    if (joint.nv == 0) continue;
    if (joint.nv == 1) {
      const double vdot_j = aj.D_inv(0, 0) * (aj.u[0] - aj.U.col(0).dot(a));
      vdot[joint.v_start] = vdot_j;
      A[joint.child.index()] += s.joint[id.index()].S.col(0) * vdot_j;
      continue;
    }
    const JointVector vdot_j = aj.D_inv * (aj.u - aj.U.transpose() * a);
    vdot.segment(joint.v_start, joint.nv) = vdot_j;
    A[joint.child.index()] += s.joint[id.index()].S * vdot_j;
  }
  return vdot;
}

}  // namespace mdlc::backend
