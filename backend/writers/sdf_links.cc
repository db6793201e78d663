// sdf_links.cc - the SDFormat writer's links: <inertial>, <visual> and
// <collision> with their shapes, materials and proximity properties, and
// cameras as <sensor type="camera"> (sdf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <variant>

#include "backend/writers/drake_out.h"
#include "backend/writers/sdf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::sdf {

void SdfWriter::WriteLink(BodyId body) {
  const PlantBody& b = plant_.body(body);
  out_.Open("link").Attr("name", link_names_[body.index()]);
  Pose(models_[BodyScope(body)].X_WM.inverse() * X_WB_[body.index()]);
  if (b.deformable) {
    diags_.Report(DiagKind::Lossy, BodyLoc(body),
                  fmt::format("link '{}' is deformable; its deformable properties are not "
                              "written, so it is a massless rigid link",
                              b.name));
  }
  // always an <inertial>: without one SDFormat gives a link 1 kg
  out_.Open("inertial");
  Pose(Transform::FromTranslation(b.p_BoBcm_B));
  Value("mass", b.mass);
  const Eigen::Matrix3d& I = b.I_BBcm_B;
  out_.Open("inertia");
  Value("ixx", I(0, 0));
  Value("ixy", I(0, 1));
  Value("ixz", I(0, 2));
  Value("iyy", I(1, 1));
  Value("iyz", I(1, 2));
  Value("izz", I(2, 2));
  out_.Close();
  out_.Close();
  if (b.surface_velocity_axis) Value("drake:surface_velocity_axis", *b.surface_velocity_axis);
  WriteGeometries(body);
  WriteCameras(body);
  out_.Close();
}

void SdfWriter::WriteGeometries(BodyId body) {
  UniqueNames visual_names, collision_names;
  for (uint32_t i : geometries_by_body_[body.index()]) {
    WriteGeometry(scene_.geometries[i], GeometryLoc(i), visual_names, collision_names);
  }
}

std::string SdfWriter::Unique(UniqueNames& names, const std::string& name) {
  const std::string first = name.empty() ? "geometry" : name;
  return names.Take(first) ? first : names.TakeSuffixed(name);
}

void SdfWriter::WriteGeometry(const backend::SceneGeometry& g, Loc loc, UniqueNames& visuals,
                              UniqueNames& collisions) {
  if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape); mesh && mesh->inline_data) {
    std::string why;
    if (!assets_.NameInlineMesh(*mesh, loc, &why)) {
      assets_.ReportInlineMeshLeftOut(g.name, *mesh, "SDFormat", why, loc);
      return;
    }
  }
  const bool illustration = g.roles & ir::kIllustrationRole;
  const bool perception = g.roles & ir::kPerceptionRole;
  if (illustration || perception) {
    out_.Open("visual").Attr("name", Unique(visuals, g.name));
    Pose(g.X_BG);
    Shape(g, loc, /*collision=*/false);
    Material(g, loc);
    if (!illustration) {
      out_.Open("drake:illustration_properties").Attr("enabled", "false").Close();
    }
    if (!perception) {
      out_.Open("drake:perception_properties").Attr("enabled", "false").Close();
    }
    if (const ir::Property* accepting = FindProperty(g, "renderer/accepting")) {
      if (const auto* names = std::get_if<std::vector<std::string>>(&accepting->value)) {
        for (const std::string& n : *names) Value("drake:accepting_renderer", n);
      }
    }
    out_.Close();
  }
  if (g.roles & ir::kProximityRole) {
    out_.Open("collision").Attr("name", Unique(collisions, g.name));
    Pose(g.X_BG);
    Shape(g, loc, /*collision=*/true);
    WriteProximityProperties(out_, syntax::ValueSpelling::Text, "SDFormat", g, loc, diags_);
    out_.Close();
  }
}

void SdfWriter::Shape(const backend::SceneGeometry& g, Loc loc, bool collision) {
  out_.Open("geometry");
  std::visit(ir::Overloaded{
                 [&](const ir::Box& s) {
                   out_.Open("box");
                   Value("size", s.size);
                   out_.Close();
                 },
                 [&](const ir::Sphere& s) {
                   out_.Open("sphere");
                   Value("radius", s.radius);
                   out_.Close();
                 },
                 [&](const ir::Cylinder& s) {
                   out_.Open("cylinder");
                   Value("radius", s.radius);
                   Value("length", s.length);
                   out_.Close();
                 },
                 [&](const ir::Capsule& s) {
                   out_.Open("capsule");
                   Value("radius", s.radius);
                   Value("length", s.length);
                   out_.Close();
                 },
                 [&](const ir::Ellipsoid& s) {
                   out_.Open("ellipsoid");
                   Value("radii", Eigen::Vector3d(s.a, s.b, s.c));
                   out_.Close();
                 },
                 [&](const ir::HalfSpace&) {
                   // a plane's +z normal is the half space's (X_BG holds it)
                   out_.Open("plane");
                   Value("normal", "0 0 1");
                   out_.Close();
                 },
                 [&](const ir::Mesh& s) {
                   out_.Open("mesh");
                   const Loc at = s.uri_loc.valid() ? s.uri_loc : loc;
                   std::string why;  // an inline mesh without an OBJ is left out above
                   if (auto name = s.inline_data ? assets_.NameInlineMesh(s, at, &why)
                                                 : assets_.Name(s.uri, s.resolved, at)) {
                     Value("uri", *name);
                   }
                   if (s.scale != Eigen::Vector3d::Ones()) Value("scale", s.scale);
                   if (s.convex && collision) out_.Open("drake:declare_convex").Close();
                   out_.Close();
                 },
             },
             g.shape);
  out_.Close();
}

void SdfWriter::Material(const backend::SceneGeometry& g, Loc loc) {
  const ir::Property* diffuse = FindProperty(g, "phong/diffuse");
  const ir::Property* texture = FindProperty(g, "phong/diffuse_map");
  // SDFormat's other material colors, as the reader takes them
  static constexpr std::string_view kColors[] = {"ambient", "specular", "emissive"};
  auto is_color = [&](std::string_view key) {
    return std::any_of(std::begin(kColors), std::end(kColors),
                       [&](std::string_view c) { return key == fmt::format("phong/{}", c); });
  };
  bool colors = false;
  for (const ir::Property& p : g.properties) {
    if (is_color(p.key)) {
      const auto* rgba = std::get_if<std::vector<double>>(&p.value);
      colors = colors || (rgba && rgba->size() == 4);
    }
  }
  for (const ir::Property& p : g.properties) {
    if (is_color(p.key)) {
      const auto* rgba = std::get_if<std::vector<double>>(&p.value);
      if (rgba && rgba->size() == 4) continue;
    }
    if ((p.key.starts_with("phong/") && p.key != "phong/diffuse" &&
         p.key != "phong/diffuse_map") ||
        (p.key.starts_with("renderer/") && p.key != "renderer/accepting") ||
        p.key.starts_with("label/")) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("property '{}' of geometry '{}' has no SDFormat spelling; it "
                                "is dropped",
                                p.key, g.name));
    }
  }
  if (!diffuse && !texture && !colors) return;
  out_.Open("material");
  for (std::string_view c : kColors) {
    const ir::Property* p = FindProperty(g, fmt::format("phong/{}", c));
    const auto* rgba = p ? std::get_if<std::vector<double>>(&p->value) : nullptr;
    if (rgba && rgba->size() == 4) {
      Value(c, VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
    }
  }
  if (diffuse) {
    if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
        rgba && rgba->size() == 4) {
      Value("diffuse", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
    }
  }
  if (texture) {
    if (const auto* path = std::get_if<std::string>(&texture->value)) {
      if (auto name = assets_.Name(*path, *path, loc)) Value("drake:diffuse_map", *name);
    }
  }
  out_.Close();
}

void SdfWriter::WriteCameras(BodyId body) {
  UniqueNames names;
  for (uint32_t i : cameras_by_body_[body.index()]) {
    const backend::SceneCamera& c = scene_.cameras[i];
    // the reader names a camera "model/sensor"
    std::string name = c.name;
    const std::string& inst = plant_.model_instances[c.model.index()];
    if (name.starts_with(inst + "/")) name = name.substr(inst.size() + 1);
    out_.Open("sensor").Attr("name", Unique(names, name)).Attr("type", "camera");
    Pose(c.X_BC);
    out_.Open("camera");
    const double hfov = 2 * std::atan(std::tan(c.fov_y / 2) * c.width / c.height);
    Value("horizontal_fov", hfov);
    out_.Open("image");
    Value("width", std::to_string(c.width));
    Value("height", std::to_string(c.height));
    out_.Close();
    out_.Close();
    out_.Close();
  }
}

}  // namespace mdlc::writers::sdf
