// sdf_deformable.cc - <drake:deformable_properties> of an SDFormat link
// (EXT-070): the FEM parameters, wall boundary conditions, and what a
// deformable link may hold and be attached to.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::sdf {
namespace {
bool EndsWithVtk(std::string_view uri) {
  if (uri.size() < 4) return false;
  std::string ext(uri.substr(uri.size() - 4));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".vtk";
}
}  // namespace

// --- drake:deformable_properties (EXT-070) ---

void SdfReader::ReadDeformableProperties(const xml::XmlElement& link, ModelScope&, BodyId body) {
  const xml::XmlElement props = link.Child("drake:deformable_properties");
  const std::string link_name(link.Attribute("name").value);
  ir::DeformableProperties d;
  d.loc = props.GetLoc();
  bool ok = true;
  auto fail = [&](DiagKind kind, Loc loc, std::string message) {
    diags().Report(kind, loc, std::move(message));
    ok = false;
  };

  // the FEM parameters (Drake's LoadDeformableConfig), each optional
  CheckChildren(props, {"drake:youngs_modulus", "drake:poissons_ratio", "drake:mass_damping",
                        "drake:stiffness_damping", "drake:mass_density",
                        "drake:material_model"});
  struct Param {
    const char* tag;
    double* out;
    bool (*valid)(double);
    const char* rule;
  };
  const Param params[] = {
      {"drake:youngs_modulus", &d.youngs_modulus, [](double v) { return v > 0; },
       "<drake:youngs_modulus> must be positive"},
      {"drake:poissons_ratio", &d.poissons_ratio, [](double v) { return v > -1 && v < 0.5; },
       "<drake:poissons_ratio> must lie in (-1, 0.5)"},
      {"drake:mass_damping", &d.mass_damping, [](double v) { return v >= 0; },
       "<drake:mass_damping> must be non-negative"},
      {"drake:stiffness_damping", &d.stiffness_damping, [](double v) { return v >= 0; },
       "<drake:stiffness_damping> must be non-negative"},
      {"drake:mass_density", &d.mass_density, [](double v) { return v > 0; },
       "<drake:mass_density> must be positive"},
  };
  for (const Param& p : params) {
    xml::XmlElement c = props.Child(p.tag);
    if (!c) continue;
    auto v = TextDouble(c);
    if (!v) {
      ok = false;
      continue;
    }
    if (!p.valid(*v)) {
      fail(DiagKind::BadValue, c.GetLoc(), fmt::format("{}, got {}", p.rule, *v));
      continue;
    }
    *p.out = *v;
  }
  if (xml::XmlElement c = props.Child("drake:material_model")) {
    const std::string mm(xml::Trim(c.Text()));
    if (mm == "linear_corotated" || mm == "corotated" || mm == "neohookean" || mm == "linear") {
      d.material_model = mm;
    } else {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("<drake:material_model> '{}' is none of 'linear', 'linear_corotated', "
                       "'neohookean' and 'corotated'",
                       mm));
    }
  }

  // wall boundary conditions: children of the link, in world coordinates
  for (auto c = link.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() != "drake:wall_boundary_condition") continue;
    CheckChildren(c, {"drake:point_on_plane", "drake:outward_normal"});
    auto point = ChildVector3(c, "drake:point_on_plane");
    auto normal = ChildVector3(c, "drake:outward_normal");
    for (const char* t : {"drake:point_on_plane", "drake:outward_normal"}) {
      if (!c.Child(t)) {
        fail(DiagKind::MissingElement, c.GetLoc(),
             fmt::format("<drake:wall_boundary_condition> needs a <{}>", t));
      }
    }
    if (!point || !normal) {
      ok = false;
      continue;
    }
    if (!(normal->norm() > 1e-10)) {
      fail(DiagKind::ZeroAxis, c.Child("drake:outward_normal").GetLoc(),
           "<drake:outward_normal> must not be zero");
      continue;
    }
    d.wall_boundary_conditions.push_back({*point, normal->normalized()});
  }

  // what a deformable link may hold: one collision, at most one visual, and
  // no mass properties or frames of its own (Drake: AddDeformableLinkFromSpecification)
  std::vector<xml::XmlElement> collisions, visuals;
  for (auto c = link.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view t = c.Name();
    if (t == "collision") {
      collisions.push_back(c);
    } else if (t == "visual") {
      visuals.push_back(c);
    } else if (t == "inertial") {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("deformable link '{}' must not have an <inertial>: its mass comes from "
                       "drake:mass_density and its mesh",
                       link_name));
    } else if (t == "frame") {
      fail(DiagKind::BadValue, c.GetLoc(),
           fmt::format("deformable link '{}' must not have frames attached to it", link_name));
    } else if (t != "pose" && t != "drake:deformable_properties" &&
               t != "drake:wall_boundary_condition") {
      diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                     fmt::format("element <{}> of deformable link '{}' is not supported and "
                                 "is ignored",
                                 t, link_name));
    }
  }
  if (collisions.size() != 1) {
    fail(DiagKind::BadValue, link.GetLoc(),
         fmt::format("deformable link '{}' has {} <collision> elements; a deformable link "
                     "has exactly one",
                     link_name, collisions.size()));
  } else {
    const xml::XmlElement collision = collisions.front();
    const xml::XmlElement geometry = collision.Child("geometry");
    const xml::XmlElement sphere = geometry ? geometry.Child("sphere") : xml::XmlElement();
    const xml::XmlElement mesh = geometry ? geometry.Child("mesh") : xml::XmlElement();
    std::optional<double> hint;
    if (auto proximity = collision.Child("drake:proximity_properties")) {
      if (auto h = proximity.Child("drake:mesh_resolution_hint")) hint = TextDouble(h);
    }
    if (sphere) {
      if (!hint) {
        fail(DiagKind::MissingElement, geometry.GetLoc(),
             "a deformable link's <sphere> needs a <drake:mesh_resolution_hint> in its "
             "<drake:proximity_properties>: the hint sets the size of the tetrahedra it is "
             "meshed into");
      } else if (!(*hint > 0)) {
        fail(DiagKind::BadValue, geometry.GetLoc(),
             "<drake:mesh_resolution_hint> must be positive");
      } else {
        d.resolution_hint = *hint;
      }
    } else if (mesh) {
      const std::string uri(
          xml::Trim(mesh.Child("uri") ? mesh.Child("uri").Text() : std::string()));
      if (!EndsWithVtk(uri)) {
        fail(DiagKind::BadValue, mesh.GetLoc(),
             fmt::format("a deformable link's <mesh> names '{}'; it must name a .vtk file "
                         "holding a tetrahedral mesh",
                         uri));
      }
      if (hint) {
        diags().Report(DiagKind::UnsupportedElement, geometry.GetLoc(),
                       "<drake:mesh_resolution_hint> of a deformable link's <mesh> is ignored: "
                       "the mesh is used as given");
      }
    } else {
      std::string found;
      if (geometry) {
        for (auto g = geometry.FirstChild(); g; g = g.NextSibling()) {
          found += fmt::format("{}<{}>", found.empty() ? "" : ", ", g.Name());
        }
      }
      fail(DiagKind::BadGeometry, geometry ? geometry.GetLoc() : collision.GetLoc(),
           fmt::format("a deformable link's <geometry> holds {}; it must be a <sphere> or a "
                       "<mesh> naming a .vtk tetrahedral mesh",
                       found.empty() ? "nothing" : found));
    }
  }
  if (visuals.size() > 1) {
    fail(DiagKind::BadValue, visuals[1].GetLoc(),
         fmt::format("A deformable <link> may have at most one <visual> element; link '{}' has "
                     "{}",
                     link_name, visuals.size()));
  }

  // nothing may be jointed or attached to it: it is not a rigid body
  const xml::XmlElement model = link.Parent();
  for (auto c = model.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view t = c.Name();
    if (t == "joint" || t == "drake:joint") {
      const bool drake_joint = t == "drake:joint";
      for (const char* end : {"parent", "child"}) {
        const xml::XmlElement ref = c.Child(drake_joint ? fmt::format("drake:{}", end) : end);
        if (ref && xml::Trim(ref.Text()) == link_name) {
          fail(DiagKind::BadValue, ref.GetLoc(),
               fmt::format("deformable link '{}' cannot be the {} of joint '{}': a deformable "
                           "body has no joints",
                           link_name, end, c.Attribute("name").value));
        }
      }
    } else if (t == "frame") {
      if (auto a = c.Attribute("attached_to"); a.present() && xml::Trim(a.value) == link_name) {
        fail(DiagKind::BadValue, a.loc,
             fmt::format("frame '{}' cannot be attached to deformable link '{}'",
                         c.Attribute("name").value, link_name));
      }
    }
  }

  if (!ok) return;
  ir::Body& b = module()[body];
  // no mass in the rigid plant: the FEM model has it (mass_density)
  b.inertial.reset();
  b.deformable = std::move(d);
}

}  // namespace mdlc::frontend::sdf
