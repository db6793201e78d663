// proximity_keys.h - the keys of the proximity properties a geometry holds
// (ir::Property), as Drake's ProximityProperties name them: "group/name".
// The frontends set them and the scene graph and writers carry them,
// whatever a format calls them (Drake's tags: ir/syntax/drake_proximity_tags.h).
#pragma once

#include <string_view>

namespace mdlc::ir {

inline constexpr std::string_view kResolutionHintKey = "hydroelastic/resolution_hint";
inline constexpr std::string_view kHydroelasticModulusKey = "hydroelastic/hydroelastic_modulus";
inline constexpr std::string_view kHuntCrossleyDissipationKey =
    "material/hunt_crossley_dissipation";
inline constexpr std::string_view kPointContactStiffnessKey = "material/point_contact_stiffness";
inline constexpr std::string_view kRelaxationTimeKey = "material/relaxation_time";
inline constexpr std::string_view kHydroelasticMarginKey = "hydroelastic/margin";
/// [static, dynamic] (EXT-021).
inline constexpr std::string_view kCoulombFrictionKey = "material/coulomb_friction";
/// "rigid" or "compliant".
inline constexpr std::string_view kComplianceTypeKey = "hydroelastic/compliance_type";

}  // namespace mdlc::ir
