// dmd_transform.h - Drake's YAML transform schema (DMD-013), as Model
// Directives write poses: an optional base frame, a translation and a
// rotation given as !Rpy {deg: [r, p, y]} or !AngleAxis {angle_deg, axis}.
// The schema also admits random distributions; a compiled scene must be
// deterministic, so they are errors (as Drake's directives require).
#pragma once

#include <optional>

#include "frontend/directives/yaml_schema.h"
#include "ir/transform.h"

namespace mdlc::frontend {

struct DirectiveTransform {
  std::optional<LocatedString> base_frame;
  Transform X;
  Loc loc;
};

/// Reads the transform at `node` (`what` names it in messages). nullopt
/// after reporting a problem.
std::optional<DirectiveTransform> ReadDirectiveTransform(YamlSchemaReader& reader,
                                                         const yaml::Node& node,
                                                         std::string_view what, Loc fallback);

}  // namespace mdlc::frontend
