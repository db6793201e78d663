// tree_sweep.h - the sweeps over the plant's tree that the dynamics share
// (dynamics.cc, applied_forces.cc, forward_dynamics.cc): kinematics down the
// tree, the recursive Newton-Euler algorithm, and body forces up to
// generalized forces. Everything is in Plücker coordinates about the world
// origin (spatial.h).
//
// A joint's motion subspace S_j is H_FM(q) (kinematics.h: columns [w;
// velocity of M's origin] in F) moved to F's origin and re-expressed in W,
// and the recursions are Featherstone's:
//   V_c = V_p + S_j v_j
//   A_c = A_p + S_j vdot_j + V_p x (S_j v_j) + X_WF (dS'_F/dt v_j)
//   f_c = I_c A_c + V_c x* (I_c V_c) - f_ext,c
//   tau_j = S_j^T (f_c + the f of c's descendants)
// with A_world = -gravity so the weights come out of the same sweep. The
// term dS'_F/dt v_j is the rate of the subspace as F sees it: only universal
// and curvilinear joints have an H that turns with q, and every joint whose
// M origin moves off F's origin (planar, floating, curvilinear, screw)
// shifts its angular columns as it goes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "backend/plant.h"
#include "backend/spatial.h"
#include "ir/transform.h"

namespace mdlc::backend {

/// Throws std::invalid_argument unless q has num_positions entries and v
/// and v_like (when given) num_velocities.
void RequireState(const Plant& plant, const Eigen::VectorXd& q, const Eigen::VectorXd* v,
                  const Eigen::VectorXd* v_like = nullptr, const char* v_like_name = "");

/// What one sweep down the tree knows about a joint at (q, v).
struct JointState {
  MotionSubspace S;  // world Plücker columns
  /// c_j = V_p x (S v_j) + X_WF (dS'_F/dt v_j): the child's acceleration
  /// over its parent's when vdot_j = 0 (zero without v).
  Vector6d velocity_product = Vector6d::Zero();
};

/// Poses, velocities and joint subspaces of the whole tree at (q, v).
struct TreeState {
  std::vector<Transform> X_WB;
  std::vector<Vector6d> V;        // by body, world Plücker
  std::vector<JointState> joint;  // by JointId
  std::vector<CompactInertia> I;  // by body, about the world origin in W
};

/// Poses, subspaces and body inertias at q; velocities and the velocity
/// products too when v is given (else zero).
TreeState SweepDown(const Plant& plant, const Eigen::VectorXd& q, const Eigen::VectorXd* v);

/// Every body's Plücker acceleration for vdot (null: zero) from the base
/// acceleration A_world: A_c = A_p + S vdot_j + c_j (c_j counts only when
/// the state has velocities).
std::vector<Vector6d> Accelerations(const Plant& plant, const TreeState& s,
                                    const Eigen::VectorXd* vdot, const Vector6d& A_world);

/// The RNEA with body forces f_ext (world Plücker, by body; may be empty)
/// acting on the bodies: tau for vdot (null: zero) and base acceleration
/// A_world, at the state's velocities (zero when it has none).
Eigen::VectorXd Rnea(const Plant& plant, const TreeState& s, const Eigen::VectorXd* vdot,
                     const Vector6d& A_world, const std::vector<Vector6d>& f_ext);

/// Generalized forces of body forces f (world Plücker, by body; empty:
/// none): tau_j = S_j^T (the sum of f over j's subtree).
Eigen::VectorXd GeneralizedFromBodyForces(const Plant& plant, const TreeState& s,
                                   std::vector<Vector6d> f);

/// A_world for the RNEA: minus the plant's gravity, or zero.
Vector6d GravityBaseAcceleration(const Plant& plant, bool gravity);

/// p_WBcm of body b.
Eigen::Vector3d CenterOfMassInWorld(const Plant& plant, const TreeState& s, size_t b);

/// Translational Jacobian columns of the point p_W fixed on `body`, added
/// (sign +1) or subtracted (-1) into the 6-row J, for every joint between
/// the body and the world.
void AddPointJacobian(const Plant& plant, const TreeState& s, BodyId body, const Eigen::Vector3d& p_W,
                      double sign, Eigen::MatrixXd& J);

}  // namespace mdlc::backend
