// mjcf_layout.h - which plant bodies the MJCF writer writes as <body>
// elements, which joints each holds, and where the content of the others
// goes.
//
// Every plant body is a <body> nested by the kinematic tree, holding its
// inbound joint, except:
//   - Stacked joints. mdlc and Drake read an MJCF body with several joints
//     as a chain of massless bodies joined by those joints, the last one
//     ending on the body (frontend/mjcf/mjcf_joint.cc). MuJoCo refuses a
//     moving body without mass, so such a chain is written back as one
//     <body> with several <joint>s: a massless body with nothing on it (no
//     geometry, frame, camera, constraint or force element) whose inbound
//     joint is a hinge or slide and whose only child hangs on a hinge or
//     slide is "merged": its joint moves the next written body instead.
//     The motion is the same (mjcf_writer.cc writes each joint's pos and
//     axis in that body's frame); the massless body is not written.
//   - --fuse-fixed. A body welded to its parent (not to the world: its mass
//     would be lost there) is "fused" into the written body it hangs on:
//     its mass properties are combined with that body's exactly (parallel-
//     axis theorem), and its geometry, frames and cameras are re-posed there.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "backend/plant.h"
#include "backend/scene_graph.h"

namespace mdlc::writers {

struct MjcfBodyLayout {
  enum class Role {
    Written,  // a <body> of its own
    Merged,   // a massless body between stacked joints: not written
    Fused,    // welded and fused into another body (--fuse-fixed)
  };
  /// Per plant body (world: Written).
  std::vector<Role> role;
  /// The written body that holds a body's content: itself, the body it is
  /// fused into, or, for a merged body, the body its joint moves.
  std::vector<BodyId> owner;
  /// A fused body's pose in its owner's frame (identity for the others).
  std::vector<Transform> X_OB;
  /// For a written body: the plant body its joints start on (written, or
  /// fused: the <body> is nested in that body's owner), and those joints,
  /// parent side first (one, or several for stacked joints; a weld when the
  /// body is fixed to its parent).
  std::vector<BodyId> parent;
  std::vector<std::vector<JointId>> joints;
  /// For a written body: its mass properties with those of the bodies fused
  /// into it, in its own frame (the plant's, bit for bit, when none is).
  std::vector<double> mass;
  std::vector<Eigen::Vector3d> p_BoBcm_B;
  std::vector<Eigen::Matrix3d> I_BBcm_B;
  /// The fused bodies of each written body, in plant body order.
  std::vector<std::vector<BodyId>> fused;

  bool written(BodyId b) const { return role[b.index()] == Role::Written; }
};

/// The layout of `plant`; `fuse_fixed` fuses welded bodies.
MjcfBodyLayout PlanMjcfBodies(const backend::Plant& plant, const backend::SceneGraph& scene,
                              bool fuse_fixed);

}  // namespace mdlc::writers
