// urdf_drake_elements.cc - model-level drake: elements: collision filter
// groups, force elements and constraints (EXT-040, EXT-050..054).
#include <fmt/format.h>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
void NotYet(DiagnosticEngine& diags, const xml::XmlElement& e) {
  diags.Report(DiagKind::NotImplementedYet, e.GetLoc(),
               fmt::format("<{}> is not implemented yet; the element is ignored", e.Name()));
}
}  // namespace

void UrdfReader::ReadCollisionFilterGroup(const xml::XmlElement& e) { NotYet(diags(), e); }
void UrdfReader::ReadLinearBushing(const xml::XmlElement& e) { NotYet(diags(), e); }
void UrdfReader::ReadLinearSpringDamper(const xml::XmlElement& e) { NotYet(diags(), e); }
void UrdfReader::ReadBallConstraint(const xml::XmlElement& e) { NotYet(diags(), e); }
void UrdfReader::ReadDistanceConstraint(const xml::XmlElement& e) { NotYet(diags(), e); }
void UrdfReader::ReadTendonConstraint(const xml::XmlElement& e) { NotYet(diags(), e); }

}  // namespace mdlc::frontend::urdf
