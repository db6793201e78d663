// dart_coordinates.h - pairs an mdlc plant with the DART skeletons read from
// the same file, and converts mdlc's generalized coordinates to DART's.
//
// Joints are paired through their child bodies (every tree joint has one),
// bodies by model and link name. Where the two disagree on what a joint
// is, the pairing fails with a reason and nothing is compared.
//
// Coordinates (checked against DART 6.12's FreeJoint, BallJoint and
// PlanarJoint, and against its body velocities and accelerations):
//   revolute, prismatic, universal   DART's q and v are mdlc's
//   quaternion_floating / FreeJoint  DART's joint motion is X_JpJc = Q =
//       K X_FM L (K = X_JpF, L = X_MJc: DART's joint frames Jp, Jc need not
//       be F and M); DART q = [log(R_Q); p_Q] (rotation vector, translation);
//       DART v = [w; v] of Jc relative to Jp expressed in Jc, i.e.
//       Ad_L^-1 [R_FM^T w_FM_F; R_FM^T v_FM_F]; mdlc's v is in F
//   ball / BallJoint                 the same with K, L rotations: DART
//       q = log(R_Q) (mdlc: roll-pitch-yaw), DART v = R_L^T R_FM^T w_FM_F
//   planar / PlanarJoint             DART translates along its own axes t1, t2
//       of the plane: [x; y] = A [q0; q1], theta = q2; v likewise
// So v_mdlc = T v_dart with T block diagonal (diag(R_FM, R_FM) Ad_L for a
// floating joint, R_FM R_L for a ball joint, A^-1 for a planar joint, 1
// otherwise), and since DART's accelerations are d/dt of its velocities,
// vdot_mdlc = T vdot_dart + a with a = w_FM_F x v_FM_F in a floating joint's
// translational rows (d/dt R_FM = [w_FM_F]x R_FM; Ad_L is constant), zero
// elsewhere. Generalized forces keep power tau . v invariant:
// tau_dart = T^T tau_mdlc; a mass matrix is M_mdlc = T^-T M_dart T^-1 and a
// Jacobian J_mdlc = J_dart T^-1.
#pragma once

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Joint.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "backend/plant.h"

namespace mdlc::oracle {

/// An mdlc joint with velocities and the DART joint moving the same body.
struct JointPair {
  JointId joint;
  dart::dynamics::Joint* dart = nullptr;
  int dart_v_start = 0;  // its first velocity in DART's stacked v
  // DART's joint frames Jp (on the parent) and Jc (on the child) against
  // mdlc's F and M: K = X_JpF, L = X_MJc, constant; DART's joint motion is
  // X_JpJc = K X_FM(q) L.
  Transform K, L;
};

/// The pairing of a plant with DART skeletons. DART's vectors are stacked
/// skeleton after skeleton (`skeleton_v_start`).
struct DartPairing {
  std::vector<dart::dynamics::SkeletonPtr> skeletons;
  std::vector<int> skeleton_v_start;
  std::vector<dart::dynamics::BodyNode*> bodies;  // by BodyId; null for the world
  std::vector<JointPair> joints;
  int nv = 0;
};

/// Pairs `plant` with `skeletons`; returns why not ("" when paired).
std::string PairWithDart(const backend::Plant& plant,
                         const std::vector<dart::dynamics::SkeletonPtr>& skeletons,
                         DartPairing* pairing);

/// DART's coordinates for mdlc's state (q, v), with the maps of the header
/// comment: v_mdlc = T v_dart, vdot_mdlc = T vdot_dart + a.
struct DartState {
  Eigen::VectorXd q, v;
  Eigen::MatrixXd T;
  Eigen::VectorXd a;
};

/// The one conversion of mdlc's coordinates to DART's (header comment).
DartState ToDartState(const backend::Plant& plant, const DartPairing& pairing,
                      const Eigen::VectorXd& q, const Eigen::VectorXd& v);

/// Sets DART's stacked positions, velocities, accelerations or forces.
void SetDartPositions(const DartPairing& pairing, const Eigen::VectorXd& q);
void SetDartVelocities(const DartPairing& pairing, const Eigen::VectorXd& v);
void SetDartAccelerations(const DartPairing& pairing, const Eigen::VectorXd& vdot);
void SetDartForces(const DartPairing& pairing, const Eigen::VectorXd& tau);

}  // namespace mdlc::oracle
