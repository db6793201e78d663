// drake_proximity.h - <drake:proximity_properties> (EXT-020, EXT-021), and
// Drake's friction rules, shared by the URDF and SDFormat frontends. The two
// formats differ only in where a number is written (URDF: @value; SDFormat:
// the element's text), which the caller's reader supplies.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"
#include "ir/entities.h"

namespace mdlc::frontend {

/// A value read from a file: the number and where it was written.
struct Located {
  double value = 0;
  Loc loc;
};

/// Reads the number one child carries, reporting its own problems (nullopt then).
using ProximityValueReader = std::function<std::optional<Located>(const xml::XmlElement&)>;

/// EXT-020: the children of one <drake:proximity_properties> become
/// `material/...` and `hydroelastic/...` properties of `g`. Each problem is
/// reported in document order; the properties are added in Drake's order.
void ReadDrakeProximityProperties(const xml::XmlElement& e, ir::Geometry& g,
                                  xml::AttributeReader& attrs, DiagnosticEngine& diags,
                                  const ProximityValueReader& read_value);

/// Drake's CoulombFriction rules: both coefficients non-negative, dynamic at
/// most static. Returns [static, dynamic], or nullopt after reporting.
std::optional<std::vector<double>> CoulombFriction(DiagnosticEngine& diags,
                                                   const Located& mu_static,
                                                   const Located& mu_dynamic);

/// Reports `e` as a repeat of `first` that is ignored (Drake reads the first).
void ReportRepeatedElement(DiagnosticEngine& diags, const xml::XmlElement& e,
                           const xml::XmlElement& first);

}  // namespace mdlc::frontend
