// shape_parameters.h - a geometry shape's parameters by name, written once.
//
// plant-json (backend/plant_json.cc), `mdlc view`'s model JSON
// (tools/mdlc/view.cc) and the Python module's Geometry.shape_parameters
// (tools/python/py_model.cc) all list a shape through VisitShapeParameters,
// so a new shape or a new shape field is added here and reaches all three.
// The IR printer (`--emit=ir`) keeps its own terser spelling ("abc=[a b c]")
// that the golden files hold.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <variant>

#include "ir/entities.h"
#include "ir/overloaded.h"

namespace mdlc::ir {

/// Calls visit(name, value) for each parameter of `shape`, in the order the
/// outputs write them. A value is a `double`, an `Eigen::Vector3d` or, for a
/// mesh's uri (as written) only, a `std::string`. The type name
/// (ShapeTypeName) is not a parameter, and a half space has none. An output's
/// extras (the viewer's mesh index, Python's resolved mesh path) come after
/// these, written by that output.
template <typename Visit>
void VisitShapeParameters(const Shape& shape, Visit&& visit) {
  std::visit(Overloaded{
                 [&](const Box& s) { visit(std::string_view("size"), s.size); },
                 [&](const Sphere& s) { visit(std::string_view("radius"), s.radius); },
                 [&](const Cylinder& s) {
                   visit(std::string_view("radius"), s.radius);
                   visit(std::string_view("length"), s.length);
                 },
                 [&](const Capsule& s) {
                   visit(std::string_view("radius"), s.radius);
                   visit(std::string_view("length"), s.length);
                 },
                 [&](const Ellipsoid& s) {
                   visit(std::string_view("a"), s.a);
                   visit(std::string_view("b"), s.b);
                   visit(std::string_view("c"), s.c);
                 },
                 [](const HalfSpace&) {},
                 [&](const Mesh& s) {
                   visit(std::string_view("uri"), s.uri);
                   visit(std::string_view("scale"), s.scale);
                 },
             },
             shape);
}

}  // namespace mdlc::ir
