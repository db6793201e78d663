// topology.cc - inbound joints, tree levels, tree order and q/v layout.
#include "backend/topology.h"

#include <fmt/format.h>

#include <algorithm>

namespace mdlc::backend {

namespace {

/// Records each body's inbound joint; reports bodies with zero or several.
bool LinkChildren(const ir::Module& module, Plant& plant, DiagnosticEngine& diags) {
  bool ok = true;
  for (size_t j = 0; j < plant.joints.size(); ++j) {
    const PlantJoint& joint = plant.joints[j];
    const Loc loc = module.joints[j].loc;
    PlantBody& child = plant.bodies[joint.child.index()];
    if (joint.parent == joint.child) {
      diags.Report(DiagKind::SelfJoint, loc,
                   fmt::format("joint '{}' connects body '{}' to itself", plant.ScopedName(joint),
                               plant.ScopedName(child)));
      ok = false;
    } else if (child.is_world) {
      diags.Report(DiagKind::KinematicLoop, loc,
                   fmt::format("joint '{}' has the world as its child", plant.ScopedName(joint)));
      ok = false;
    } else if (child.inbound_joint.valid()) {
      const JointId first = child.inbound_joint;
      diags.Report(DiagKind::MultipleParents, loc,
                   fmt::format("body '{}' is the child of joints '{}' and '{}'",
                               plant.ScopedName(child), plant.ScopedName(plant.joint(first)),
                               plant.ScopedName(joint)))
          .Note(module.joints[first.index()].loc, "first joint declared here");
      ok = false;
    } else {
      child.inbound_joint = JointId(j);
      child.parent = joint.parent;
    }
  }
  for (size_t b = 0; b < plant.bodies.size(); ++b) {
    const PlantBody& body = plant.bodies[b];
    if (body.is_world || body.inbound_joint.valid()) continue;
    diags.Report(DiagKind::VerifierFailure, module.bodies[b].loc,
                 fmt::format("body '{}' is not the child of any joint (internal: a floating "
                             "joint should have been added)",
                             plant.ScopedName(body)));
    ok = false;
  }
  return ok;
}

/// Breadth-first from the world: sets levels; reports bodies it never reaches
/// (they hang on a cycle of joints that does not contain the world).
bool AssignLevels(const ir::Module& module, Plant& plant, DiagnosticEngine& diags) {
  const size_t num_bodies = plant.bodies.size();
  // joints by parent body, in IR order (compressed rows)
  std::vector<uint32_t> start(num_bodies + 1, 0);
  for (const PlantJoint& joint : plant.joints) ++start[joint.parent.index() + 1];
  for (size_t b = 0; b < num_bodies; ++b) start[b + 1] += start[b];
  std::vector<JointId> by_parent(plant.joints.size());
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t j = 0; j < plant.joints.size(); ++j) {
    by_parent[fill[plant.joints[j].parent.index()]++] = JointId(j);
  }

  std::vector<bool> reached(num_bodies, false);
  std::vector<BodyId> queue{ir::kWorldBody};
  reached[0] = true;
  for (size_t k = 0; k < queue.size(); ++k) {
    const size_t b = queue[k].index();
    for (uint32_t e = start[b]; e < start[b + 1]; ++e) {
      const BodyId c = plant.joint(by_parent[e]).child;
      plant.bodies[c.index()].level = plant.bodies[b].level + 1;
      reached[c.index()] = true;
      queue.push_back(c);
    }
  }
  if (queue.size() == num_bodies) return true;

  // every unreached body has one inbound joint, so they all sit on cycles
  std::vector<std::string> names;
  std::vector<JointId> joints;
  for (size_t b = 0; b < num_bodies; ++b) {
    if (reached[b]) continue;
    names.push_back("'" + plant.ScopedName(plant.bodies[b]) + "'");
    joints.push_back(plant.bodies[b].inbound_joint);
  }
  constexpr size_t kMaxListed = 8;
  const size_t listed = std::min(names.size(), kMaxListed);
  auto diag = diags.Report(
      DiagKind::KinematicLoop, module.joints[joints.front().index()].loc,
      fmt::format("kinematic loop: {} bod{} not connected to the world: {}{}", names.size(),
                  names.size() == 1 ? "y" : "ies",
                  fmt::join(names.begin(), names.begin() + listed, ", "),
                  names.size() > listed ? ", ..." : ""));
  for (size_t k = 0; k < listed; ++k) {
    diag.Note(module.joints[joints[k].index()].loc,
              fmt::format("joint '{}' is part of the loop",
                          plant.ScopedName(plant.joint(joints[k]))));
  }
  return false;
}

/// Joints by level (stable, so IR order within a level), then bodies and
/// q/v slices in that order.
void OrderByLevel(Plant& plant) {
  int max_level = 0;
  for (const PlantBody& body : plant.bodies) max_level = std::max(max_level, body.level);
  std::vector<uint32_t> start(max_level + 2, 0);
  for (const PlantJoint& joint : plant.joints) ++start[plant.body(joint.child).level + 1];
  for (int l = 0; l <= max_level; ++l) start[l + 1] += start[l];
  plant.joint_order.assign(plant.joints.size(), JointId());
  for (size_t j = 0; j < plant.joints.size(); ++j) {
    plant.joint_order[start[plant.body(plant.joints[j].child).level]++] = JointId(j);
  }

  plant.body_order.clear();
  plant.body_order.push_back(ir::kWorldBody);
  int q = 0, v = 0;
  for (JointId id : plant.joint_order) {
    PlantJoint& joint = plant.joints[id.index()];
    plant.body_order.push_back(joint.child);
    joint.q_start = q;
    joint.v_start = v;
    q += joint.nq;
    v += joint.nv;
  }
  plant.num_positions = q;
  plant.num_velocities = v;
}

}  // namespace

bool AssignTreeOrder(const ir::Module& module, Plant& plant, DiagnosticEngine& diags) {
  if (!LinkChildren(module, plant, diags)) return false;
  if (!AssignLevels(module, plant, diags)) return false;
  OrderByLevel(plant);
  return true;
}

}  // namespace mdlc::backend
