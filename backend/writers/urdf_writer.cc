// urdf_writer.cc - the compiled model as URDF, with Drake's extensions for
// what plain URDF cannot hold.
//
// URDF puts a link's frame where its inbound joint's child frame M is (a
// joint's origin is the pose of its frame F in the parent link, and the child
// link's frame is F at q = 0). A plant body B whose joint has X_CM != I is
// therefore written as a link whose frame is M: everything on B (inertia,
// geometry, frames, the F frames of outbound joints) is re-expressed in M by
// X_MB = X_CM^-1, exactly; the link's pose in the world is X_WB * X_BM. The
// kinematics and the mass matrix at every q are unchanged.
//
// Mapping (what cannot be written is a -Wlossy warning at its source):
//   weld -> fixed; revolute -> revolute (bounded) or continuous;
//   prismatic -> prismatic; planar -> planar; ball, universal, screw ->
//   <drake:joint>; a floating joint on a root link -> nothing (URDF's root
//   links are free; the default pose is not kept); coupler -> <mimic>;
//   actuators -> <transmission>; ball and distance constraints, tendons,
//   bushings and spring-dampers -> their drake: elements; collision filters
//   -> one <drake:collision_filter_group> per filtered body pair.
// Plain URDF (--plain, for urdfdom and ROS): one root link, so free bodies
// beside the world or beside each other hang from a "world" link by
// <joint type="floating">, as does a floating joint whose parent is not the
// world; capsules and ellipsoids become the cylinder and sphere that bound
// them, and ball, universal and screw joints fixed joints (-Wlossy). Drake's
// other elements stay: urdfdom passes over elements it does not know.
// Several model instances become one robot whose names carry their
// instance ("arm/link1"; a nested instance "arm::hand" gives "arm/hand/link1").
// A link, joint, frame or actuator whose written name does not give back its
// scoped name holds a comment naming its instance and name, which mdlc's
// reader restores (ir/syntax/original_name_comment.h).
//
// This file writes the document, links and geometry; urdf_writer_detail.h
// lists the files that write the rest.
#include <fmt/format.h>

#include <variant>

#include "backend/writers/drake_out.h"
#include "backend/writers/urdf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::urdf {

double FiniteLimit(double value) {
  if (value == kInf) return std::numeric_limits<double>::max();
  if (value == -kInf) return -std::numeric_limits<double>::max();
  return value;
}

std::string UrdfWriter::Write() {
  names_.ReportFlattening(m_, "URDF robot", diags_);
  out_.Open("robot").Attr("name", names_.model_name());
  out_.Attr("xmlns:drake", "http://drake.mit.edu");
  floats_free_roots_ = FloatsFreeRoots();
  if (NeedsWorldLink() || floats_free_roots_) WriteLink(ir::kWorldBody);
  for (size_t b = 1; b < plant_.bodies.size(); ++b) WriteLink(BodyId(b));
  for (size_t j = 0; j < plant_.joints.size(); ++j) WriteJoint(JointId(j));
  WriteFrames();
  WriteTransmissions();
  WriteConstraints();
  WriteForceElements();
  WriteCollisionFilters();
  WriteCameras();
  out_.Close();
  return out_.Finish();
}

bool UrdfWriter::NeedsWorldLink() const {
  if (plant_.bodies.size() <= 1) return true;  // a robot has at least one link
  for (const PlantJoint& j : plant_.joints) {
    if (j.parent.index() == 0 && !IsFreeRoot(j)) return true;
  }
  for (const auto& g : scene_.geometries) {
    if (g.body.index() == 0) return true;
  }
  for (const auto& f : plant_.frames) {
    if (f.body.index() == 0 && !f.unnamed) return true;
  }
  return false;
}

bool UrdfWriter::FloatsFreeRoots() const {
  if (!plain_) return false;
  size_t free_roots = 0;
  for (const PlantJoint& j : plant_.joints) free_roots += IsFreeRoot(j) ? 1 : 0;
  return free_roots > 1 || (free_roots == 1 && NeedsWorldLink());
}

void UrdfWriter::WriteLink(BodyId body) {
  const PlantBody& b = plant_.body(body);
  frame_names_.Take(BodyName(body));
  out_.Open("link").Attr("name", BodyName(body));
  if (body.index() != 0) OriginalName(b.model, b.name, BodyName(body));
  if (b.deformable) {
    diags_.Report(DiagKind::Lossy, BodyLoc(body),
                  fmt::format("link '{}' is deformable; URDF has no deformable bodies, so "
                              "it is written as a massless rigid link",
                              b.name));
  }
  const bool has_mass_properties =
      b.mass != 0 || !b.p_BoBcm_B.isZero(0) || !b.I_BBcm_B.isZero(0);
  if (body.index() != 0 && has_mass_properties) {
    const Transform X_LB = LinkInBody(body).inverse();
    const Eigen::Vector3d p_LBcm = X_LB * b.p_BoBcm_B;
    const Eigen::Matrix3d I = X_LB.R * b.I_BBcm_B * X_LB.R.transpose();
    out_.Open("inertial");
    Origin(Transform::FromTranslation(p_LBcm));
    out_.Open("mass").Attr("value", b.mass).Close();
    out_.Open("inertia")
        .Attr("ixx", I(0, 0))
        .Attr("ixy", I(0, 1))
        .Attr("ixz", I(0, 2))
        .Attr("iyy", I(1, 1))
        .Attr("iyz", I(1, 2))
        .Attr("izz", I(2, 2))
        .Close();
    out_.Close();
  }
  if (b.surface_velocity_axis) {  // EXT-060, in the link frame
    const Eigen::Vector3d axis = LinkInBody(body).R.transpose() * *b.surface_velocity_axis;
    out_.Open("drake:surface_velocity_axis").Attr("axis", axis).Close();
  }
  for (uint32_t i : geometries_by_body_[body.index()]) {
    WriteGeometry(scene_.geometries[i], GeometryLoc(i));
  }
  out_.Close();
}

void UrdfWriter::WriteGeometry(const backend::SceneGeometry& g, Loc loc) {
  if (std::holds_alternative<ir::HalfSpace>(g.shape)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("geometry '{}' is a half space, which URDF cannot hold; it is "
                              "dropped",
                              g.name));
    return;
  }
  if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape); mesh && mesh->inline_data) {
    std::string why;
    if (!assets_.NameInlineMesh(*mesh, loc, &why)) {
      assets_.ReportInlineMeshLeftOut(g.name, *mesh, "URDF", why, loc);
      return;
    }
  }
  const Transform X_LG = InLink(g.body, g.X_BG);
  if (g.roles & (ir::kIllustrationRole | ir::kPerceptionRole)) {
    if (!(g.roles & ir::kPerceptionRole) || !(g.roles & ir::kIllustrationRole)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("geometry '{}' has only the {} role; a URDF visual has both "
                                "illustration and perception",
                                g.name,
                                (g.roles & ir::kIllustrationRole) ? "illustration"
                                                                  : "perception"));
    }
    out_.Open("visual").Attr("name", g.name);
    Origin(X_LG);
    Shape(g, loc, /*collision=*/false);
    Material(g, loc);
    out_.Close();
  }
  if (g.roles & ir::kProximityRole) {
    out_.Open("collision").Attr("name", g.name);
    Origin(X_LG);
    Shape(g, loc, /*collision=*/true);
    WriteProximityProperties(out_, syntax::ValueSpelling::Attribute, "URDF", g, loc, diags_);
    out_.Close();
  }
}

void UrdfWriter::Shape(const backend::SceneGeometry& g, Loc loc, bool collision) {
  out_.Open("geometry");
  if (plain_ && (std::holds_alternative<ir::Capsule>(g.shape) ||
                 std::holds_alternative<ir::Ellipsoid>(g.shape))) {
    PlainShape(g, loc);
    out_.Close();
    return;
  }
  std::visit(ir::Overloaded{
                 [&](const ir::Box& s) { out_.Open("box").Attr("size", s.size).Close(); },
                 [&](const ir::Sphere& s) {
                   out_.Open("sphere").Attr("radius", s.radius).Close();
                 },
                 [&](const ir::Cylinder& s) {
                   out_.Open("cylinder").Attr("radius", s.radius).Attr("length", s.length);
                   out_.Close();
                 },
                 [&](const ir::Capsule& s) {
                   out_.Open("drake:capsule").Attr("radius", s.radius);
                   out_.Attr("length", s.length).Close();
                 },
                 [&](const ir::Ellipsoid& s) {
                   out_.Open("drake:ellipsoid").Attr("a", s.a).Attr("b", s.b);
                   out_.Attr("c", s.c).Close();
                 },
                 [&](const ir::HalfSpace&) {},
                 [&](const ir::Mesh& s) {
                   out_.Open("mesh");
                   const Loc at = s.uri_loc.valid() ? s.uri_loc : loc;
                   std::string why;  // an inline mesh without an OBJ is left out above
                   if (auto name = s.inline_data ? assets_.NameInlineMesh(s, at, &why)
                                                 : assets_.Name(s.uri, s.resolved, at)) {
                     out_.Attr("filename", *name);
                   }
                   if (s.scale != Eigen::Vector3d::Ones()) out_.Attr("scale", s.scale);
                   if (s.convex && collision) out_.Open("drake:declare_convex").Close();
                   out_.Close();
                 },
             },
             g.shape);
  out_.Close();
}

void UrdfWriter::PlainShape(const backend::SceneGeometry& g, Loc loc) {
  if (const auto* c = std::get_if<ir::Capsule>(&g.shape)) {
    const double length = c->length + 2 * c->radius;
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("capsule '{}' is written as the cylinder that bounds it (radius "
                              "{}, length {}): plain URDF has no capsule",
                              g.name, c->radius, length));
    out_.Open("cylinder").Attr("radius", c->radius).Attr("length", length).Close();
    return;
  }
  const auto& e = std::get<ir::Ellipsoid>(g.shape);
  const double radius = std::max({e.a, e.b, e.c});
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("ellipsoid '{}' is written as the sphere that bounds it (radius "
                            "{}): plain URDF has no ellipsoid",
                            g.name, radius));
  out_.Open("sphere").Attr("radius", radius).Close();
}

void UrdfWriter::Material(const backend::SceneGeometry& g, Loc loc) {
  const ir::Property* diffuse = FindProperty(g, "phong/diffuse");
  const ir::Property* texture = FindProperty(g, "phong/diffuse_map");
  if (!diffuse && !texture) return;
  // a material needs a name (urdfdom); each visual has its own
  out_.Open("material").Attr("name", fmt::format("{}:{}", BodyName(g.body), g.name));
  if (diffuse) {
    if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
        rgba && rgba->size() == 4) {
      out_.Open("color").Attr("rgba", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
      out_.Close();
    }
  }
  if (texture) {
    if (const auto* path = std::get_if<std::string>(&texture->value)) {
      if (auto name = assets_.Name(*path, *path, loc)) {
        out_.Open("texture").Attr("filename", *name).Close();
      }
    }
  }
  out_.Close();
}

}  // namespace mdlc::writers::urdf

namespace mdlc::writers {

std::optional<std::string> WriteUrdf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags) {
  return urdf::UrdfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
