// sdf_drake_elements.cc - drake: elements of an SDFormat model and joint
// (EXT-001, EXT-004, EXT-010, EXT-012..014, EXT-040, EXT-050..054, EXT-070).
#include <fmt/format.h>

#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {

void SdfReader::ReadDrakeModelElement(const xml::XmlElement& e, ModelScope&) {
  diags().Report(DiagKind::NotImplementedYet, e.GetLoc(),
                 fmt::format("<{}> in SDFormat is not read yet", e.Name()));
}

void SdfReader::ReadJointDrakeChildren(const xml::XmlElement& joint_element, ModelScope&, JointId,
                                       std::optional<ActuatorId>) {
  for (auto child = joint_element.FirstChild(); child; child = child.NextSibling()) {
    if (child.Name().starts_with("drake:")) {
      diags().Report(DiagKind::NotImplementedYet, child.GetLoc(),
                     fmt::format("<{}> in SDFormat is not read yet", child.Name()));
    }
  }
}

void SdfReader::ReadDeformableProperties(const xml::XmlElement& link, ModelScope&, BodyId) {
  diags().Report(DiagKind::NotImplementedYet, link.GetLoc(),
                 "drake:deformable_properties is not read yet");
}

}  // namespace mdlc::frontend::sdf
