// floating_joint.h - the 6-dof joints the compiler adds, named as Drake names
// them: a free body's joint to the world (build-kinematic-tree) and a
// directive's default pose in a frame other than the world (apply-directives).
#pragma once

#include <optional>

#include "ir/module.h"

namespace mdlc::passes {

/// The body's name, prefixed with '_' until no joint of its instance has it
/// (Drake's rule for the joints it adds). `taken(name)` says whether a joint
/// of that instance is already called `name`.
template <typename Taken>
std::string FloatingJointName(std::string_view body_name, const Taken& taken) {
  std::string name(body_name);
  while (taken(name)) name = "_" + name;
  return name;
}

/// An unnamed quaternion_floating joint of `child`'s instance from frame F
/// (X_PF on `parent`) to frame M (X_CM on `child`), whose default pose X_FM
/// is `default_pose` (identity when absent).
ir::Joint MakeFloatingJoint(const ir::Module& m, Symbol name, Loc loc, BodyId parent,
                            const Transform& X_PF, BodyId child, const Transform& X_CM,
                            const std::optional<Transform>& default_pose);

}  // namespace mdlc::passes
