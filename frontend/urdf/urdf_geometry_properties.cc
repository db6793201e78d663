// urdf_geometry_properties.cc - drake: children of <collision> and <visual>
// (EXT-020, EXT-021, EXT-030, EXT-031, URDF-033).
#include <fmt/format.h>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {

bool UrdfReader::ReadCollisionExtension(const xml::XmlElement& child, ir::Geometry& geometry) {
  if (!child.Name().starts_with("drake:")) return false;
  diags().Report(DiagKind::NotImplementedYet, child.GetLoc(),
                 fmt::format("<{}> is not implemented yet; the element is ignored", child.Name()));
  return true;
}

bool UrdfReader::ReadVisualExtension(const xml::XmlElement& child, ir::Geometry& geometry) {
  if (!child.Name().starts_with("drake:")) return false;
  diags().Report(DiagKind::NotImplementedYet, child.GetLoc(),
                 fmt::format("<{}> is not implemented yet; the element is ignored", child.Name()));
  return true;
}

bool UrdfReader::FinishVisual(const xml::XmlElement& visual, ir::Geometry& geometry) {
  return true;
}

}  // namespace mdlc::frontend::urdf
