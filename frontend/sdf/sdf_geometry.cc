// sdf_geometry.cc - <visual>, <collision>, shapes, materials and sensors of
// a link (SDF-040, SDF-041, SDF-043, SDF-044, EXT-020..035).
#include <fmt/format.h>

#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {

void SdfReader::ReadVisual(const xml::XmlElement& e, ModelScope&, BodyId, Symbol) {
  diags().Report(DiagKind::NotImplementedYet, e.GetLoc(), "SDFormat <visual> is not read yet");
}

void SdfReader::ReadCollision(const xml::XmlElement& e, ModelScope&, BodyId, Symbol) {
  diags().Report(DiagKind::NotImplementedYet, e.GetLoc(), "SDFormat <collision> is not read yet");
}

void SdfReader::ReadSensor(const xml::XmlElement& e, ModelScope&, BodyId, Symbol) {
  diags().Report(DiagKind::NotImplementedYet, e.GetLoc(), "SDFormat <sensor> is not read yet");
}

}  // namespace mdlc::frontend::sdf
