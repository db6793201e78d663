// drake_out.h - Drake's XML extensions as the URDF and SDFormat writers
// write them. The two formats differ only in where a value goes (URDF: an
// attribute; SDFormat: the element's text, syntax::ValueSpelling), so each
// element is written once here, as frontend/drake_proximity.cc reads it.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "backend/scene_graph.h"
#include "backend/writers/xml_out.h"
#include "ir/diagnostics.h"
#include "ir/syntax/drake_proximity_tags.h"

namespace mdlc::writers {

/// <tag value="v"/> (Attribute) or <tag>v</tag> (Text).
void DrakeValue(XmlOut& out, syntax::ValueSpelling spelling, std::string_view tag, double v);
void DrakeValue(XmlOut& out, syntax::ValueSpelling spelling, std::string_view tag,
                const Eigen::Vector3d& v);

/// The proximity properties of `g` as <drake:proximity_properties> children
/// (EXT-020; nothing when it has none); a property with no such child is a
/// -Wlossy warning at `loc` naming `format` ("URDF", "SDFormat").
void WriteProximityProperties(XmlOut& out, syntax::ValueSpelling spelling, std::string_view format,
                              const backend::SceneGeometry& g, Loc loc, DiagnosticEngine& diags);

}  // namespace mdlc::writers
