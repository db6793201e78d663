// mujoco_eigen.h - a mesh's principal axes as MuJoCo 3.3.8 finds them.
//
// A symmetric 3x3 matrix has its eigenvectors only up to sign (and order
// among equal eigenvalues); which signs a solver returns is its own choice.
// MuJoCo turns a mesh into its principal frame with the frame its Jacobi
// eigen-solver accumulates (as a quaternion, from the identity, then
// reordered for decreasing moments), and a primitive fitted to the mesh
// takes that frame: a box or a capsule fitted by another solver can come
// out turned by a half turn, the same shape in another frame. This is the
// cyclic Jacobi method with the pivot, rotation and ordering conventions
// MuJoCo's compiler uses, so fitted primitives get MuJoCo's frames, and the
// eigenvalues its tolerance (1e-12 off the diagonal) leaves.
#pragma once

#include <Eigen/Core>

namespace mdlc::mesh {

/// Eigenvalues of the symmetric `A` in decreasing order (up to MuJoCo's
/// tolerance: equal ones are not swapped) and the rotation whose columns
/// are their axes, as MuJoCo's compiler computes them.
void MujocoEigen(const Eigen::Matrix3d& A, Eigen::Vector3d* values, Eigen::Matrix3d* axes);

}  // namespace mdlc::mesh
