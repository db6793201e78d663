// drake_proximity_tags.h - the children of Drake's
// <drake:proximity_properties> (EXT-020) and the geometry properties they
// stand for (ir/proximity_keys.h). One table for both directions: the URDF
// and SDFormat readers (frontend/drake_proximity.cc) read these tags into
// these keys, and the URDF and SDFormat writers (backend/writers/drake_out.cc)
// write the keys back as the same tags.
#pragma once

#include <array>
#include <string_view>

#include "ir/proximity_keys.h"

namespace mdlc::syntax {

/// Where a value of one of Drake's XML extensions is written: URDF puts it
/// in an attribute (<drake:x value="1"/>, <drake:frame name="a"/>),
/// SDFormat in the element's text (<drake:x>1</drake:x>).
enum class ValueSpelling {
  Attribute,  // URDF: @value for numbers, @name (or @link) for names
  Text,       // SDFormat: the element's text
};

/// A child of <drake:proximity_properties> that carries one number.
struct ProximityValueTag {
  std::string_view tag;   // "drake:mesh_resolution_hint"
  bool zero_allowed;      // else the value must be positive; never negative
  std::string_view what;  // for messages
  std::string_view key;   // the property; empty for friction (two tags, one key)
};

/// Indices into kProximityValueTags, which is in Drake's order of properties.
enum ProximityValueIndex {
  kResolutionHint,
  kModulus,
  kDissipation,
  kStiffness,
  kMuDynamic,
  kMuStatic,
  kRelaxationTime,
  kMargin,
  kProximityValueTagCount
};

inline constexpr std::array<ProximityValueTag, kProximityValueTagCount> kProximityValueTags = {{
    {"drake:mesh_resolution_hint", false, "mesh resolution hint", ir::kResolutionHintKey},
    {"drake:hydroelastic_modulus", false, "hydroelastic modulus", ir::kHydroelasticModulusKey},
    {"drake:hunt_crossley_dissipation", true, "Hunt-Crossley dissipation",
     ir::kHuntCrossleyDissipationKey},
    {"drake:point_contact_stiffness", false, "point contact stiffness",
     ir::kPointContactStiffnessKey},
    {"drake:mu_dynamic", true, "dynamic friction coefficient", ""},
    {"drake:mu_static", true, "static friction coefficient", ""},
    {"drake:relaxation_time", true, "relaxation time", ir::kRelaxationTimeKey},
    {"drake:hydroelastic_margin", true, "hydroelastic margin", ir::kHydroelasticMarginKey},
}};

/// drake:mu_static and drake:mu_dynamic together: ir::kCoulombFrictionKey.
/// drake:rigid_hydroelastic / drake:compliant_hydroelastic: ir::kComplianceTypeKey.
inline constexpr std::string_view kRigidHydroelasticTag = "drake:rigid_hydroelastic";
inline constexpr std::string_view kCompliantHydroelasticTag = "drake:compliant_hydroelastic";
inline constexpr std::string_view kProximityPropertiesTag = "drake:proximity_properties";

}  // namespace mdlc::syntax
