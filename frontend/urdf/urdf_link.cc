// urdf_link.cc - <link>: bodies, inertials, visuals, collisions and shapes
// (URDF-002..004, URDF-031, URDF-032, URDF-040).
#include <fmt/format.h>

#include "frontend/original_names.h"
#include "frontend/unknown_element.h"
#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {

void UrdfReader::CheckUniqueName(absl::flat_hash_map<uint32_t, Loc>& seen, Symbol name, Loc loc,
                                 std::string_view kind) {
  auto [it, inserted] = seen.emplace(name.value, loc);
  if (!inserted) {
    diags()
        .Report(DiagKind::DuplicateName, loc,
                fmt::format("{} '{}' is already defined in this model", kind,
                            module().Text(name)))
        .Note(it->second, fmt::format("the first {} named '{}' is here", kind, module().Text(name)));
  }
}

void UrdfReader::ReadLink(const xml::XmlElement& e) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  if (auto type = e.Attribute("type"); type.present()) {
    diags().Report(DiagKind::UnsupportedAttribute, type.loc,
                   "attribute 'type' of <link> is not supported and is ignored");
  }
  attrs_.WarnUnknownAttributes(e, {"name", "type", "drake_ignore"});
  Symbol symbol = module().Intern(*name);
  CheckUniqueName(link_names_, symbol, e.GetLoc(), "link");

  BodyId body_id;
  if (*name == "world") {
    // the world link is the world body itself (URDF-003)
    body_id = ir::kWorldBody;
    if (auto inertial = e.Child("inertial")) {
      diags().Report(DiagKind::IgnoredInertial, inertial.GetLoc(),
                     "<inertial> on the link named 'world' is ignored: the world body has no "
                     "mass properties");
    }
  } else {
    ir::Body body;
    body.name = symbol;
    body.model = model_;
    body.loc = e.GetLoc();
    if (auto inertial = e.Child("inertial")) ReadInertial(inertial, body);
    body_id = module().Add(std::move(body));
    ReadOriginalName(e, body_id, ctx_);
  }

  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    std::string_view tag = child.Name();
    if (tag == "visual") {
      ReadGeometryElement(child, body_id, symbol, /*is_visual=*/true);
    } else if (tag == "collision") {
      ReadGeometryElement(child, body_id, symbol, /*is_visual=*/false);
    } else if (tag == "inertial") {
      // read above
    } else if (tag == "drake:surface_velocity_axis") {
      // EXT-060: the link's surface velocity axis, in the link frame; the
      // first such element counts
      if (auto first = e.Child(tag); first.raw() != child.raw()) {
        diags()
            .Report(DiagKind::UnsupportedElement, child.GetLoc(),
                    "<drake:surface_velocity_axis> is given more than once in <link>; only the "
                    "first one is used, this one is ignored")
            .Note(first.GetLoc(), "the first <drake:surface_velocity_axis> is here");
        continue;
      }
      if (body_id == ir::kWorldBody) {
        diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                       "<drake:surface_velocity_axis> on the 'world' link is ignored: only "
                       "<collision> and <visual> geometries can be given to the world link");
        continue;
      }
      attrs_.WarnUnknownAttributes(child, {"axis"});
      if (auto axis = attrs_.Vector3(child, "axis", xml::Need::Required)) {
        const double norm = axis->norm();
        if (!(norm > 0) || std::abs(1.0 - (*axis / norm).norm()) >= 1e-14) {
          diags().Report(DiagKind::BadValue, child.Attribute("axis").loc,
                         fmt::format("the 'axis' of <drake:surface_velocity_axis> must have a "
                                     "non-zero length, got '{}'",
                                     child.Attribute("axis").value));
        } else {
          module()[body_id].surface_velocity_axis = *axis / norm;
        }
      }
    } else if (tag == "self_collision_checking" || tag == "gazebo") {
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     fmt::format("element <{}> in <link> is not supported and is ignored",
                                 tag));
    } else {
      ReportUnknownElement(diags(), child, "link", {"inertial", "visual", "collision"});
    }
  }
}

void UrdfReader::ReadInertial(const xml::XmlElement& e, ir::Body& body) {
  ir::Inertial inertial;
  inertial.loc = e.GetLoc();
  inertial.X_BI = ReadOrigin(e);
  if (auto mass = e.Child("mass")) {
    if (auto v = attrs_.Double(mass, "value", xml::Need::Required)) inertial.mass = *v;
  }
  if (auto inertia = e.Child("inertia")) {
    double* fields[] = {&inertial.ixx, &inertial.iyy, &inertial.izz,
                        &inertial.ixy, &inertial.ixz, &inertial.iyz};
    const char* names[] = {"ixx", "iyy", "izz", "ixy", "ixz", "iyz"};
    for (int i = 0; i < 6; ++i) {
      if (auto v = attrs_.Double(inertia, names[i])) *fields[i] = *v;
    }
    attrs_.WarnUnknownAttributes(inertia, {"ixx", "iyy", "izz", "ixy", "ixz", "iyz"});
  }
  body.inertial = inertial;
}

Symbol UrdfReader::UniqueGeometryName(BodyId body, uint8_t role, std::string_view wanted,
                                      bool explicit_name, Loc loc) {
  const Symbol symbol = module().Intern(wanted);
  auto [it, inserted] = geometry_names_.try_emplace({body.value, symbol.value, role}, 0);
  if (inserted) return symbol;
  // a duplicate within this link and role: NAME_1, NAME_2, ... (URDF-040)
  Symbol renamed;
  int counter = it->second;
  do {
    renamed = module().Intern(fmt::format("{}_{}", wanted, ++counter));
  } while (geometry_names_.count({body.value, renamed.value, role}));
  geometry_names_[{body.value, symbol.value, role}] = counter;
  geometry_names_.try_emplace({body.value, renamed.value, role}, 0);
  if (explicit_name) {
    diags().Report(DiagKind::RenamedDuplicate, loc,
                   fmt::format("geometry name '{}' is already used in this link; renamed to '{}'",
                               wanted, module().Text(renamed)));
  }
  return renamed;
}

void UrdfReader::ReadGeometryElement(const xml::XmlElement& e, BodyId body, Symbol link_name,
                                     bool is_visual) {
  const std::string_view tag = is_visual ? "visual" : "collision";
  attrs_.WarnUnknownAttributes(e, {"name", "group"});
  if (auto group = e.Attribute("group"); group.present()) {
    diags().Report(DiagKind::UnsupportedAttribute, group.loc,
                   fmt::format("attribute 'group' of <{}> is not supported and is ignored",
                               tag));
  }
  auto geometry = e.Child("geometry");
  if (!geometry) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   fmt::format("<{}> has no <geometry> element", tag));
    return;
  }
  auto shape = ReadShape(geometry);
  if (!shape) return;

  ir::Geometry g;
  g.model = model_;
  g.loc = e.GetLoc();
  g.body = {link_name, e.GetLoc(), body};
  g.X_BG = ReadOrigin(e);
  g.shape = std::move(*shape);
  g.roles = is_visual ? (ir::kIllustrationRole | ir::kPerceptionRole) : ir::kProximityRole;

  auto name_attr = e.Attribute("name");
  std::string default_name(ir::ShapeTypeName(g.shape));
  default_name[0] = static_cast<char>(std::toupper(default_name[0]));
  if (default_name == "Half_space") default_name = "HalfSpace";
  g.unnamed = !name_attr.present() || name_attr.value.empty();
  g.name = UniqueGeometryName(body, g.roles,
                              name_attr.present() && !name_attr.value.empty() ? name_attr.value
                                                                              : default_name,
                              name_attr.present(), e.GetLoc());

  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    std::string_view ctag = child.Name();
    if (ctag == "origin" || ctag == "geometry") continue;
    if (is_visual && ctag == "material") {
      g.rgba = ReadVisualMaterial(child, g);
    } else if (!is_visual && ctag == "verbose") {
      diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                     "element <verbose> in <collision> is not supported and is ignored");
    } else if (is_visual ? ReadVisualExtension(child, g) : ReadCollisionExtension(child, g)) {
      // a drake: extension, read
    } else if (is_visual) {
      ReportUnknownElement(diags(), child, tag, {"origin", "geometry", "material"});
    } else {
      ReportUnknownElement(diags(), child, tag, {"origin", "geometry"});
    }
  }
  if (is_visual && !FinishVisual(e, g)) return;
  module().Add(std::move(g));
}

namespace {

bool IsShapeTag(std::string_view tag) {
  return tag == "box" || tag == "sphere" || tag == "cylinder" || tag == "capsule" ||
         tag == "drake:capsule" || tag == "ellipsoid" || tag == "drake:ellipsoid" || tag == "mesh";
}

}  // namespace

std::optional<ir::Shape> UrdfReader::ReadShape(const xml::XmlElement& geometry) {
  // one shape, plus Drake's <drake:declare_convex/> marker beside a mesh.
  // Anything else (a <material> or <origin> written inside <geometry>) is
  // ignored with a warning, as Drake and urdfdom read the shape beside it;
  // without a shape, the first such element is taken for an unknown one.
  xml::XmlElement e, declare_convex, first_other;
  bool two_shapes = false;
  for (auto c = geometry.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() == "drake:declare_convex") {
      declare_convex = c;
    } else if (!IsShapeTag(c.Name())) {
      if (!first_other) first_other = c;
    } else if (!e) {
      e = c;
    } else {
      // Drake takes the first by its own order of shapes, urdfdom the first
      // written: the two would read different shapes
      diags().Report(DiagKind::BadGeometry, c.GetLoc(),
                     fmt::format("<geometry> must hold exactly one shape, but also holds <{}>",
                                 c.Name()));
      two_shapes = true;
    }
  }
  if (!e && first_other) {
    diags().Report(DiagKind::BadGeometry, first_other.GetLoc(),
                   fmt::format("unknown shape <{}> in <geometry>", first_other.Name()));
    return std::nullopt;
  }
  if (!e) {
    diags().Report(DiagKind::MissingElement, geometry.GetLoc(), "<geometry> has no shape element");
    return std::nullopt;
  }
  for (auto c = geometry.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() == "drake:declare_convex" || IsShapeTag(c.Name())) continue;
    const bool belongs_outside = c.Name() == "origin" || c.Name() == "material";
    diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                   fmt::format("element <{}> in <geometry> is ignored{}; the shape <{}> is read",
                               c.Name(),
                               belongs_outside ? fmt::format(" (it belongs in <{}>, beside "
                                                             "<geometry>)",
                                                             geometry.Parent().Name())
                                               : "",
                               e.Name()));
  }
  if (two_shapes) return std::nullopt;
  if (declare_convex && e.Name() != "mesh") {
    diags().Report(DiagKind::UnsupportedElement, declare_convex.GetLoc(),
                   "<drake:declare_convex> applies only to a <mesh> and is ignored here");
  }
  auto positive = [&](const char* attr, double v) {
    if (v >= 0) return true;
    diags().Report(DiagKind::BadValue, e.Attribute(attr).loc,
                   fmt::format("attribute '{}' of <{}> must not be negative, got {}", attr,
                               e.Name(), v));
    return false;
  };
  std::string_view tag = e.Name();
  if (tag == "box") {
    auto size = attrs_.Vector3(e, "size", xml::Need::Required);
    if (!size) return std::nullopt;
    if (size->minCoeff() < 0) {
      positive("size", size->minCoeff());
      return std::nullopt;
    }
    return ir::Box{*size};
  }
  if (tag == "sphere") {
    auto r = attrs_.Double(e, "radius", xml::Need::Required);
    if (!r || !positive("radius", *r)) return std::nullopt;
    return ir::Sphere{*r};
  }
  if (tag == "cylinder" || tag == "capsule" || tag == "drake:capsule") {
    auto r = attrs_.Double(e, "radius", xml::Need::Required);
    auto l = attrs_.Double(e, "length", xml::Need::Required);
    if (!r || !l || !positive("radius", *r) || !positive("length", *l)) return std::nullopt;
    if (tag == "cylinder") return ir::Cylinder{*r, *l};
    return ir::Capsule{*r, *l};
  }
  if (tag == "drake:ellipsoid" || tag == "ellipsoid") {
    auto a = attrs_.Double(e, "a", xml::Need::Required);
    auto b = attrs_.Double(e, "b", xml::Need::Required);
    auto c = attrs_.Double(e, "c", xml::Need::Required);
    if (!a || !b || !c) return std::nullopt;
    return ir::Ellipsoid{*a, *b, *c};
  }
  if (tag == "mesh") {
    auto filename = attrs_.String(e, "filename", xml::Need::Required);
    if (!filename) return std::nullopt;
    ir::Mesh mesh;
    mesh.uri = std::string(*filename);
    mesh.uri_loc = e.Attribute("filename").loc;
    if (auto scale = e.Attribute("scale"); scale.present()) {
      auto values = xml::ParseDoubleList(scale.value);
      if (values && values->size() == 1) {
        mesh.scale.setConstant((*values)[0]);
      } else if (values && values->size() == 3) {
        mesh.scale = Eigen::Vector3d((*values)[0], (*values)[1], (*values)[2]);
      } else {
        diags().Report(DiagKind::BadValue, scale.loc,
                       fmt::format("mesh scale must be one or three numbers, got '{}'",
                                   scale.value));
        return std::nullopt;
      }
      if (!mesh.scale.allFinite()) {
        diags().Report(DiagKind::NonFinite, scale.loc, "mesh scale must be finite");
        return std::nullopt;
      }
    }
    if (declare_convex || e.Child("drake:declare_convex")) mesh.convex = true;
    return mesh;
  }
  diags().Report(DiagKind::BadGeometry, e.GetLoc(),
                 fmt::format("unknown shape <{}> in <geometry>", tag));
  return std::nullopt;
}

}  // namespace mdlc::frontend::urdf
