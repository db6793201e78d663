// mass_matrix.cc - CRBA in Plücker coordinates about the world origin.
//
// Everything is expressed in W about W's origin (spatial.h), so composite
// inertias add without shifting and a joint's motion subspace S_j can be
// paired with any descendant's composite inertia directly:
//   Ic(b)   = I(b) + sum of Ic(children of b)
//   M(i, j) = S_i^T Ic(child of i) S_j   for j = i or j an ancestor joint of i
// and M is symmetric.
#include "backend/mass_matrix.h"

#include "backend/tree_sweep.h"

namespace mdlc::backend {

namespace {

/// Calls visit(j, column of j in the result, j's nv) for each joint with
/// velocities between `joint`'s parent and the world that is selected.
template <typename Visit>
void ForEachSelectedAncestor(const Plant& plant, const PlantJoint& joint,
                             const std::vector<int>& out_start, Visit&& visit) {
  for (BodyId b = joint.parent; !plant.body(b).is_world; b = plant.body(b).parent) {
    const JointId j = plant.body(b).inbound_joint;
    const int col = out_start[j.index()];
    const int nv_j = plant.joint(j).nv;
    if (col >= 0 && nv_j > 0) visit(j, col, nv_j);
  }
}

}  // namespace

Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q) {
  return CalcMassMatrix(plant, q, plant.joint_order);
}

Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q,
                               std::span<const JointId> joints) {
  RequireState(plant, q, nullptr);
  const TreeState s = SweepDown(plant, q, nullptr);  // poses, subspaces, inertias

  // where each selected joint's velocities go in the result (-1: not selected)
  std::vector<int> out_start(plant.joints.size(), -1);
  int size = 0;
  for (JointId j : joints) {
    out_start[j.index()] = size;
    size += plant.joint(j).nv;
  }

  // composite inertias, leaves first
  std::vector<CompactInertia> Ic = s.I;
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    Ic[joint.parent.index()] += Ic[joint.child.index()];
  }
  const auto S = [&](JointId j) -> const MotionSubspace& { return s.joint[j.index()].S; };

  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  for (JointId i : joints) {
    const PlantJoint& joint_i = plant.joint(i);
    if (joint_i.nv == 0) continue;
    const int row = out_start[i.index()];
    if (joint_i.nv == 1) {
      // most joints: F is one force vector and each entry one dot product
      const Vector6d F = Ic[joint_i.child.index()] * Vector6d(S(i).col(0));
      M(row, row) = S(i).col(0).dot(F);
      ForEachSelectedAncestor(plant, joint_i, out_start, [&](JointId j, int col, int nv_j) {
        if (nv_j == 1) {
          M(col, row) = M(row, col) = S(j).col(0).dot(F);
        } else {
          M.block(col, row, nv_j, 1) = S(j).transpose() * F;
          M.block(row, col, 1, nv_j) = M.block(col, row, nv_j, 1).transpose();
        }
      });
      continue;
    }
    const MotionSubspace F = Ic[joint_i.child.index()] * S(i);  // 6 x nv_i
    M.block(row, row, joint_i.nv, joint_i.nv) = S(i).transpose() * F;
    ForEachSelectedAncestor(plant, joint_i, out_start, [&](JointId j, int col, int nv_j) {
      M.block(col, row, nv_j, joint_i.nv) = S(j).transpose() * F;
      M.block(row, col, joint_i.nv, nv_j) = M.block(col, row, nv_j, joint_i.nv).transpose();
    });
  }
  return M;
}

}  // namespace mdlc::backend
