// mass_matrix.h - the rigid-body mass matrix M(q) by the composite rigid body
// algorithm (CRBA).
//
// M is the matrix of the kinetic energy T = 1/2 v^T M v in the plant's
// velocity coordinates (kinematics.h says what v is for each joint type). It
// holds rigid-body inertia only: rotor (reflected) inertia is not included.
// Cost: O(n) for the composite inertias plus O(depth) per selected joint.
// Both functions require q.size() == plant.num_positions (else they throw
// std::invalid_argument).
#pragma once

#include <Eigen/Core>
#include <span>

#include "backend/plant.h"

namespace mdlc::backend {

/// The full nv x nv mass matrix, rows and columns in plant velocity order.
Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q);

/// M restricted to the velocities of `joints` (no repeats): rows and columns
/// are those joints' velocity slices, concatenated in the order given. Use
/// it when nv is too large for the full matrix.
Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q,
                               std::span<const JointId> joints);

}  // namespace mdlc::backend
