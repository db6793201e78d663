// original_name.h - round-trip metadata of `mdlc convert`: the names the
// URDF and MJCF writers could not keep.
//
// URDF and MJCF hold one model, so a writer prefixes each entity of a
// multi-instance plant with its instance ("arm/link1"), turns "::" into "/"
// and renames a taken frame. Beside such an element it writes a comment
// (its text: ir/syntax/original_name_comment.h). mdlc's URDF and MJCF
// readers record each one as an OriginalName of the entity they read, and
// the restore-names pass gives the entity back its model instance and name,
// so a round trip restores the scoped names.
#pragma once

#include <string>
#include <variant>

#include "ir/ids.h"
#include "ir/location.h"

namespace mdlc::ir {

struct OriginalName {
  std::variant<BodyId, JointId, FrameId, GeometryId, ActuatorId, CameraId> entity;
  std::string model;  // the model instance's full name ("arm::hand")
  std::string name;   // the entity's local name
  Loc loc;            // the element the comment is in
};

}  // namespace mdlc::ir
