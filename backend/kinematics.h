// kinematics.h - joint motion and forward kinematics (Drake's conventions).
//
// For a joint with positions q_j (its slice of q) and velocities v_j:
//   revolute      X_FM = rotation about `axis` by q                     v = qdot
//   prismatic     X_FM = translation axis * q                           v = qdot
//   screw         rotation about axis by q, translation axis * q * pitch / 2pi
//   universal     R_FM = Rx(q0) * Ry(q1)                                v = qdot
//   ball          R_FM = RotationFromRpy(q0, q1, q2)     v = w_FM expressed in F
//   planar        translation (q0, q1, 0), then Rz(q2)   v = (vx, vy, wz) in F
//   weld          identity                                              no q, no v
//   quaternion_floating  q = [qw qx qy qz px py pz]      v = [w_FM_F, v_FM_F]
//   rpy_floating         q = [roll pitch yaw px py pz]    v = [w_FM_F, v_FM_F]
//   curvilinear   X_FM = the pose at arc length q along the joint's planar path
//                 (ir/curvilinear_path.h)     v = qdot: V = [curvature * normal; tangent]
// A child's pose is X_WC = X_WP * X_PF * X_FM(q) * X_CM^-1.
//
// Everything here iterates the plant's topological order; nothing recurses.
// Functions taking a full `q` require q.size() == plant.num_positions and
// throw std::invalid_argument otherwise.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "backend/plant.h"
#include "backend/spatial.h"
#include "ir/transform.h"

namespace mdlc::backend {

/// X_FM for `joint` at its own positions `q_joint` (precondition: size
/// joint.nq). A quaternion is normalized first; an all-zero one counts as the
/// identity.
Transform JointPose(const PlantJoint& joint, const Eigen::Ref<const Eigen::VectorXd>& q_joint);

/// The joint's motion subspace H_FM(q) in F: V_FM_F = H * v_joint, one
/// column [w; v_Mo] per joint velocity (6 x joint.nv).
MotionSubspace JointMotionSubspace(const PlantJoint& joint,
                                   const Eigen::Ref<const Eigen::VectorXd>& q_joint);

/// X_WB of every body (indexed by BodyId) at configuration q.
std::vector<Transform> BodyPosesInWorld(const Plant& plant, const Eigen::VectorXd& q);

/// X_WF of a joint's frame F, given the body poses at some q.
Transform JointFrameInWorld(const Plant& plant, const std::vector<Transform>& X_WB,
                            JointId joint);

}  // namespace mdlc::backend
