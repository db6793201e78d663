// urdf_drake_joint.cc - <drake:joint> (EXT-001..003).
#include <fmt/format.h>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {

void UrdfReader::ReadDrakeJoint(const xml::XmlElement& e) {
  diags().Report(DiagKind::NotImplementedYet, e.GetLoc(),
                 "<drake:joint> is not implemented yet; the element is ignored");
}

}  // namespace mdlc::frontend::urdf
