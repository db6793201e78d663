// mjcf_lowering.h - what the worldbody walk (mjcf_body.cc) hands to the
// element lowerings (mjcf_joint.cc, mjcf_geom.cc). Private to frontend/mjcf.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "frontend/mjcf/mjcf_reader_detail.h"
#include "frontend/original_names.h"

namespace mdlc::frontend::mjcf {

/// One child element of a body, with the <frame>s it sits in folded in:
/// X_BF is the pose of the innermost enclosing frame in the body frame
/// (identity outside frames), `childclass` the class its elements default to.
struct BodyItem {
  xml::XmlElement e;
  Transform X_BF;
  std::string childclass;
};

/// A body being lowered: its MJCF element, its id, its parent's id and the
/// pose MuJoCo gives it in the parent frame at qpos0 (X_PB0).
struct BodyContext {
  xml::XmlElement e;
  BodyId body;
  BodyId parent;
  std::string name;
  Transform X_PB0;
  Transform X_WB0;  // world pose at qpos0 (free joints start there)
  bool mass_from_geometry = false;
  /// MuJoCo's "simple" body structure, as far as the tree decides it: no
  /// child bodies, and a parent that is the world or a joint-less child of
  /// it (the joints and the inertia frame decide the rest)
  bool simple_position = false;
  /// The body's name before `mdlc convert` wrote it (round-trip metadata):
  /// the massless bodies between its stacked joints are named after it.
  std::optional<syntax::ParsedOriginalName> original;
};

/// MJCF-021..024, BEYOND-007: the body's joints, or a weld to its parent
/// when it has none. Adds the intermediate bodies of stacked joints.
void LowerJoints(MjcfReader& r, const BodyContext& b, std::span<const BodyItem> joints,
                 bool mocap);

/// MJCF-040..043, BEYOND-002: one geom; `index` numbers the body's geoms for
/// default names. Returns false when the geom is skipped (no index used).
bool LowerGeom(MjcfReader& r, const BodyItem& item, BodyId body, bool is_world,
               bool mass_from_geometry, int index);
/// BEYOND-004: a site becomes a frame on its body.
void LowerSite(MjcfReader& r, const BodyItem& item, BodyId body);
/// MJCF-090: a camera.
void LowerCamera(MjcfReader& r, const BodyItem& item, BodyId body);

}  // namespace mdlc::frontend::mjcf
