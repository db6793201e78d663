// mass_matrix.cc - CRBA in Plücker coordinates about the world origin.
//
// Everything is expressed in W about W's origin (spatial.h), so composite
// inertias add without shifting and a joint's motion subspace S_j can be
// paired with any descendant's composite inertia directly:
//   Ic(b)   = I(b) + sum of Ic(children of b)
//   M(i, j) = S_i^T Ic(child of i) S_j   for j = i or j an ancestor joint of i
// and M is symmetric.
#include "backend/mass_matrix.h"


#include "backend/kinematics.h"
#include "backend/spatial.h"

namespace mdlc::backend {

Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q) {
  return CalcMassMatrix(plant, q, plant.joint_order);
}

Eigen::MatrixXd CalcMassMatrix(const Plant& plant, const Eigen::VectorXd& q,
                               std::span<const JointId> joints) {
  const std::vector<Transform> X_WB = BodyPosesInWorld(plant, q);

  // where each selected joint's velocities go in the result (-1: not selected)
  std::vector<int> out_start(plant.joints.size(), -1);
  int size = 0;
  for (JointId j : joints) {
    out_start[j.index()] = size;
    size += plant.joint(j).nv;
  }

  // each body's own spatial inertia, then composites, leaves first
  std::vector<Matrix6d> Ic(plant.bodies.size());
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const PlantBody& body = plant.bodies[b];
    const Eigen::Matrix3d& R_WB = X_WB[b].R;
    Ic[b] = SpatialInertiaAboutOrigin(body.mass, X_WB[b] * body.p_BoBcm_B,
                                      R_WB * body.I_BBcm_B * R_WB.transpose());
  }
  for (auto it = plant.joint_order.rbegin(); it != plant.joint_order.rend(); ++it) {
    const PlantJoint& joint = plant.joint(*it);
    Ic[joint.parent.index()] += Ic[joint.child.index()];
  }

  // motion subspaces of the selected joints, in world Plücker coordinates
  std::vector<MotionSubspace> S(plant.joints.size());
  for (JointId j : joints) {
    const PlantJoint& joint = plant.joint(j);
    const Transform X_WF = JointFrameInWorld(plant, X_WB, j);
    const Eigen::Vector3d p_WMo = X_WB[joint.child.index()] * joint.X_CM.p;
    S[j.index()] = ToWorldPlucker(
        JointMotionSubspace(joint, q.segment(joint.q_start, joint.nq)), X_WF.R, p_WMo);
  }

  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(size, size);
  for (JointId i : joints) {
    const PlantJoint& joint_i = plant.joint(i);
    if (joint_i.nv == 0) continue;
    const MotionSubspace F = Ic[joint_i.child.index()] * S[i.index()];  // 6 x nv_i
    const int row = out_start[i.index()];
    M.block(row, row, joint_i.nv, joint_i.nv) = S[i.index()].transpose() * F;
    // walk up to the world, filling the blocks with selected ancestor joints
    for (BodyId b = joint_i.parent; !plant.body(b).is_world; b = plant.body(b).parent) {
      const JointId j = plant.body(b).inbound_joint;
      const int col = out_start[j.index()];
      const int nv_j = plant.joint(j).nv;
      if (col < 0 || nv_j == 0) continue;
      M.block(col, row, nv_j, joint_i.nv) = S[j.index()].transpose() * F;
      M.block(row, col, joint_i.nv, nv_j) = M.block(col, row, nv_j, joint_i.nv).transpose();
    }
  }
  return M;
}

}  // namespace mdlc::backend
