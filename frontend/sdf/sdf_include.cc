// sdf_include.cc - <include>: SDFormat and URDF files placed into a model or
// world, with name, pose, static and placement overrides, and merge-include
// (SDF-031..033).
#include <fmt/format.h>

#include "frontend/sdf/sdf_reader_detail.h"

namespace mdlc::frontend::sdf {

void SdfReader::ReadInclude(const xml::XmlElement& e, const SdfFile&, const ModelScope*) {
  diags().Report(DiagKind::NotImplemented, e.GetLoc(), "<include> is not implemented yet");
}

}  // namespace mdlc::frontend::sdf
