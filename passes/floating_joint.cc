#include "passes/floating_joint.h"

namespace mdlc::passes {

ir::Joint MakeFloatingJoint(const ir::Module& m, Symbol name, Loc loc, BodyId parent,
                            const Transform& X_PF, BodyId child, const Transform& X_CM,
                            const std::optional<Transform>& default_pose) {
  ir::Joint j;
  j.name = name;
  j.model = m[child].model;
  j.loc = loc;
  j.type = ir::JointType::QuaternionFloating;
  j.parent = {m[parent].name, {}, parent};
  j.child = {m[child].name, m[child].loc, child};
  j.X_PF = X_PF;
  j.X_CM = X_CM;
  j.limits = ir::JointLimits::Unbounded(6);
  j.damping.assign(6, 0.0);
  if (default_pose) {
    const Eigen::Quaterniond q = CanonicalQuaternion(default_pose->R);
    const Eigen::Vector3d& p = default_pose->p;
    j.default_positions = {q.w(), q.x(), q.y(), q.z(), p.x(), p.y(), p.z()};
  }
  j.unnamed = true;
  return j;
}

}  // namespace mdlc::passes
