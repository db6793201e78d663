// positions.cc - default configuration and joint lookup by name.
#include "backend/positions.h"

namespace mdlc::backend {

Eigen::VectorXd DefaultPositions(const Plant& plant) {
  Eigen::VectorXd q(plant.num_positions);
  for (const PlantJoint& joint : plant.joints) {
    for (int k = 0; k < joint.nq; ++k) q[joint.q_start + k] = joint.default_positions[k];
  }
  return q;
}

JointLookup FindJointByName(const Plant& plant, std::string_view name) {
  // a scoped name is unique; a local name may repeat across instances
  for (int pass = 0; pass < 2; ++pass) {
    JointLookup found;
    for (size_t j = 0; j < plant.joints.size(); ++j) {
      const PlantJoint& joint = plant.joints[j];
      if (pass == 0 ? !name.ends_with(joint.name) || plant.ScopedName(joint) != name
                    : joint.name != name) {
        continue;
      }
      if (found.status == JointLookupStatus::Found) return {JointLookupStatus::Ambiguous, {}};
      found = {JointLookupStatus::Found, JointId(j)};
    }
    if (found.status == JointLookupStatus::Found) return found;
  }
  return {};
}

bool SetJointPositionByName(const Plant& plant, Eigen::VectorXd& q, std::string_view name,
                            double value) {
  const JointLookup lookup = FindJointByName(plant, name);
  if (lookup.status != JointLookupStatus::Found) return false;
  const PlantJoint& joint = plant.joint(lookup.joint);
  if (joint.nq != 1 || q.size() != plant.num_positions) return false;
  q[joint.q_start] = value;
  return true;
}

}  // namespace mdlc::backend
