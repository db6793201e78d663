// original_names.h - round-trip metadata of `mdlc convert`: the names the
// URDF and MJCF writers could not keep.
//
// URDF and MJCF hold one model, so a writer prefixes each entity of a
// multi-instance plant with its instance ("arm/link1"), turns "::" into "/"
// and renames a taken frame. Beside such an element it writes a comment
//
//   <link name="arm/link1">
//     <!-- mdlc:name model="arm" name="link1" -->
//
// (readers other than mdlc's ignore comments). mdlc's URDF and MJCF readers
// record each one as an OriginalName of the entity they read, and the
// restore-names pass gives the entity back its model instance and name, so a
// round trip restores the scoped names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
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

/// The comment's text: `mdlc:name model="M" name="N"`, each value
/// percent-encoded where XML comments or the quotes need it ('%', '"', and a
/// '-' after a '-').
std::string FormatOriginalNameComment(std::string_view model, std::string_view name);

/// The model and name a comment's text holds; nullopt for another comment.
struct ParsedOriginalName {
  std::string model, name;
};
std::optional<ParsedOriginalName> ParseOriginalNameComment(std::string_view text);

}  // namespace mdlc::ir
