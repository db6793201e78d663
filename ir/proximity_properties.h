// proximity_properties.h - the children of Drake's
// <drake:proximity_properties> (EXT-020) and the geometry properties they
// stand for. One table for both directions: the URDF and SDFormat readers
// (frontend/drake_proximity.cc) read these tags into these keys, and the
// URDF and SDFormat writers (backend/writers/drake_out.cc) write the keys
// back as the same tags.
#pragma once

#include <array>
#include <string_view>

namespace mdlc::ir {

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
    {"drake:mesh_resolution_hint", false, "mesh resolution hint", "hydroelastic/resolution_hint"},
    {"drake:hydroelastic_modulus", false, "hydroelastic modulus",
     "hydroelastic/hydroelastic_modulus"},
    {"drake:hunt_crossley_dissipation", true, "Hunt-Crossley dissipation",
     "material/hunt_crossley_dissipation"},
    {"drake:point_contact_stiffness", false, "point contact stiffness",
     "material/point_contact_stiffness"},
    {"drake:mu_dynamic", true, "dynamic friction coefficient", ""},
    {"drake:mu_static", true, "static friction coefficient", ""},
    {"drake:relaxation_time", true, "relaxation time", "material/relaxation_time"},
    {"drake:hydroelastic_margin", true, "hydroelastic margin", "hydroelastic/margin"},
}};

/// drake:mu_static and drake:mu_dynamic together: [static, dynamic] (EXT-021).
inline constexpr std::string_view kCoulombFrictionKey = "material/coulomb_friction";
/// drake:rigid_hydroelastic / drake:compliant_hydroelastic: "rigid" or "compliant".
inline constexpr std::string_view kComplianceTypeKey = "hydroelastic/compliance_type";
inline constexpr std::string_view kRigidHydroelasticTag = "drake:rigid_hydroelastic";
inline constexpr std::string_view kCompliantHydroelasticTag = "drake:compliant_hydroelastic";
inline constexpr std::string_view kProximityPropertiesTag = "drake:proximity_properties";

}  // namespace mdlc::ir
