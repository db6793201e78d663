// mjcf_elements_qpos0.cc - body poses at MuJoCo's reference configuration.
//
// MuJoCo completes connect and weld constraints at qpos0 (mj_setConst): the
// point a connect anchors on body2, and a weld's relative pose when relpose
// is not given, are read off the bodies' world poses with every joint at its
// `ref`. Drake's AddBallConstraint does the same at the plant's default
// configuration. The frontend has the joints' X_PF, X_CM and default
// positions, so it composes X_WC = X_WP * X_PF * X_FM(q0) * X_CM^-1 itself,
// walking each body's chain up to a body already placed (no recursion).
#include <Eigen/Geometry>

#include "frontend/mjcf/mjcf_elements.h"

namespace mdlc::frontend::mjcf {

namespace {

// X_FM of a joint at its default positions (empty: zero / identity)
Transform JointMotionAtDefault(const ir::Joint& j) {
  const ir::DofValues& q = j.default_positions;
  auto at = [&q](size_t i) { return i < q.size() ? q[i] : 0.0; };
  switch (j.type) {
    case ir::JointType::Revolute:
      return Transform::FromRotation(RotationAboutAxis(j.axis, at(0)));
    case ir::JointType::Prismatic:
      return Transform::FromTranslation(j.axis * at(0));
    case ir::JointType::Ball:
      return Transform::FromRotation(RotationFromRpy({at(0), at(1), at(2)}));
    case ir::JointType::QuaternionFloating: {
      if (q.size() < 7) return Transform::Identity();
      Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
      if (quat.norm() == 0) quat = Eigen::Quaterniond::Identity();
      return {quat.normalized().toRotationMatrix(), Eigen::Vector3d(q[4], q[5], q[6])};
    }
    default:
      return Transform::Identity();  // weld, and types MJCF never produces
  }
}

}  // namespace

void ElementsLowering::ComputeQpos0Poses() {
  const ir::Module& m = module();
  const size_t n = m.bodies.size();
  X_WB0_.assign(n, Transform::Identity());
  std::vector<char> placed(n, 0);
  placed[ir::kWorldBody.index()] = 1;

  // the joint that places each body (its inboard joint)
  std::vector<int> inboard(n, -1);
  std::vector<BodyId> parent_of(n);
  for (size_t j = 0; j < m.joints.size(); ++j) {
    std::optional<BodyId> child = BodyOf(m.joints[j].child);
    std::optional<BodyId> parent = BodyOf(m.joints[j].parent);
    if (!child || !parent || child->index() >= n) continue;
    inboard[child->index()] = static_cast<int>(j);
    parent_of[child->index()] = *parent;
  }

  std::vector<size_t> chain;
  for (size_t b = 0; b < n; ++b) {
    // walk up to a placed body (or a root), then place the chain downwards
    chain.clear();
    size_t at = b;
    while (!placed[at] && chain.size() <= n) {
      chain.push_back(at);
      if (inboard[at] < 0) break;
      at = parent_of[at].index();
    }
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const size_t c = *it;
      if (placed[c]) continue;
      if (inboard[c] < 0) {
        // a free (or unattached) body: where the file places it
        X_WB0_[c] = m.bodies[c].default_pose.value_or(Transform::Identity());
      } else {
        const ir::Joint& j = m.joints[inboard[c]];
        const size_t p = parent_of[c].index();
        X_WB0_[c] = X_WB0_[p] * j.X_PF * JointMotionAtDefault(j) * j.X_CM.inverse();
      }
      placed[c] = 1;
    }
  }
  have_qpos0_ = true;
}

const Transform& ElementsLowering::PoseAtQpos0(BodyId body) {
  if (!have_qpos0_) ComputeQpos0Poses();
  return X_WB0_[body.index()];
}

double ElementsLowering::JointQpos0(JointId joint) const {
  const ir::Joint& j = r.ctx.module[joint];
  return j.default_positions.empty() ? 0.0 : j.default_positions[0];
}

}  // namespace mdlc::frontend::mjcf
