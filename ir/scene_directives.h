// scene_directives.h - the scene-level edits of Model Directives (DMD-030,
// DMD-040, DMD-011, DMD-012), as the directives file states them.
//
// Drake applies each directive the moment it reads it, looking frames up in
// the plant built so far. The frontend cannot: a model's frames are only
// known once resolve-frames has run. It records each edit here, in directive
// order, with every name already carrying its namespace, and the
// apply-directives pass performs them in that order. `visible_models` is how
// many model instances existed when the directive ran: a lookup never sees an
// instance added later, as in Drake.
#pragma once

#include <optional>
#include <variant>
#include <vector>

#include "ir/ids.h"
#include "ir/location.h"
#include "ir/symbol.h"
#include "ir/transform.h"

namespace mdlc::ir {

/// A frame named in a directive: "world", "frame" (any instance, if unique)
/// or "instance::frame" (a body frame or an explicit frame).
struct DirectiveFrameName {
  Symbol name;
  Loc loc;
};

/// add_frame: a frame fixed at X_PF in the base frame. `instance` is the
/// instance the name's scope selects; empty: the base frame's instance.
struct AddFrameEdit {
  Loc loc;
  Symbol name;  // the element name
  Loc name_loc;
  Symbol instance;
  DirectiveFrameName base_frame;
  Transform X_PF;
};

/// add_weld: a weld joint from the parent frame to the child frame at X_PC,
/// named "{parent}_welds_to_{child}" in the child's instance (DMD-070).
struct AddWeldEdit {
  Loc loc;
  DirectiveFrameName parent, child;
  Transform X_PC;
};

/// add_model's default_joint_positions: one joint of the model.
struct DefaultJointPositionsEdit {
  Loc loc;  // the joint's key
  ModelId model;
  Symbol joint;
  Loc values_loc;
  std::vector<double> positions;
};

/// add_model's default_free_body_pose: `frame` (unscoped, in the model; empty
/// means the model's only body) is posed at X_PC in `base_frame` (world when
/// absent).
struct DefaultFreeBodyPoseEdit {
  Loc loc;  // the frame's key
  ModelId model;
  Symbol frame;
  std::optional<DirectiveFrameName> base_frame;
  Transform X_PC;
};

struct SceneEdit {
  using Variant =
      std::variant<AddFrameEdit, AddWeldEdit, DefaultJointPositionsEdit, DefaultFreeBodyPoseEdit>;
  Variant edit;
  uint32_t visible_models = 0;
};

}  // namespace mdlc::ir
