// mjcf_geom.cc - geoms, sites and cameras (MJCF-040..043, MJCF-090,
// BEYOND-002, BEYOND-004).
//
// As Drake's parser does, a geom is registered up to twice under one name:
// a visual registration (illustration + perception) unless group > 2, and
// a collision registration (proximity, with its friction) unless contype
// and conaffinity are both 0. When the body's mass comes from its geoms,
// the geom's share (MassContribution) rides on exactly one registration:
// the collision one when there is one. A geom that registers nothing but
// still has mass in MuJoCo keeps a registration with no roles, so the mass
// pass sees it.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <span>

#include "frontend/mjcf/mjcf_lowering.h"
#include "frontend/mjcf/mjcf_orientation.h"

namespace mdlc::frontend::mjcf {
namespace {

ir::Ref<BodyId> RefTo(const ir::Module& m, BodyId id) { return {m[id].name, m[id].loc, id}; }

/// fromto (capsule, cylinder, box, ellipsoid): MuJoCo centres the geom at the
/// midpoint with +z along from - to, and sets the half length (MJCF-041).
/// Returns the pose and updates `size`; nullopt after an error.
std::optional<Transform> FromTo(MjcfReader& r, const Element& g, std::string_view type,
                                std::span<double, 3> size) {
  auto v = r.Numbers(g, "fromto", 6);
  if (!v) return std::nullopt;
  const Attribute at = g.Get("fromto");
  if (type != "capsule" && type != "cylinder" && type != "box" && type != "ellipsoid") {
    r.diags().Report(DiagKind::BadValue, at.loc,
                     fmt::format("fromto requires a capsule, cylinder, box or ellipsoid, not a {}",
                                 type));
    return std::nullopt;
  }
  if (auto pos = r.Numbers(g, "pos", 3); pos && ((*pos)[0] || (*pos)[1] || (*pos)[2])) {
    r.diags().Report(DiagKind::BadValue, at.loc, "both pos and fromto are given");
    return std::nullopt;
  }
  const Eigen::Vector3d from((*v)[0], (*v)[1], (*v)[2]), to((*v)[3], (*v)[4], (*v)[5]);
  const Eigen::Vector3d vec = from - to;
  const double half = vec.norm() / 2;
  if (half < 1e-14) {
    r.diags().Report(DiagKind::BadValue, at.loc, "fromto points are too close");
    return std::nullopt;
  }
  size[1] = half;
  if (type == "box" || type == "ellipsoid") {
    size[2] = half;
    size[1] = size[0];
  }
  Transform X;
  X.p = (from + to) / 2;
  X.R = std::get<Eigen::Matrix3d>(RotationFromZAxis(vec));
  return X;
}

/// The primitive's shape from MuJoCo's size (MJCF-040), zero-sized when
/// the size comes from a mesh (BEYOND-002).
std::optional<ir::Shape> Primitive(std::string_view type, std::span<const double, 3> s) {
  if (type == "sphere") return ir::Sphere{s[0]};
  if (type == "capsule") return ir::Capsule{s[0], 2 * s[1]};
  if (type == "cylinder") return ir::Cylinder{s[0], 2 * s[1]};
  if (type == "ellipsoid") return ir::Ellipsoid{s[0], s[1], s[2]};
  if (type == "box") return ir::Box{Eigen::Vector3d(2 * s[0], 2 * s[1], 2 * s[2])};
  return std::nullopt;
}

/// MuJoCo rejects a primitive whose size it needs is zero, negative or not
/// a number ("size N must be positive in geom"): a missing value counts as
/// zero, so too few values are caught here too (MJCF-040, COMMON-007).
bool CheckPrimitiveSize(MjcfReader& r, const Element& g, std::string_view type,
                        std::string_view name, std::span<const double, 3> size) {
  const size_t needed = type == "sphere" ? 1 : (type == "capsule" || type == "cylinder") ? 2 : 3;
  for (size_t k = 0; k < needed; ++k) {
    if (std::isfinite(size[k]) && size[k] > 0) continue;
    const Attribute at = g.Get("size");
    r.diags().Report(DiagKind::BadValue, at.present() ? at.loc : g.loc(),
                     fmt::format("geom '{}': a {} needs {} positive, finite size value{}; "
                                 "size[{}] is {}",
                                 name, type, needed, needed > 1 ? "s" : "", k,
                                 k < size.size() && std::isnan(size[k]) ? "not a number"
                                 : at.present()                         ? fmt::format("{}", size[k])
                                                                        : "missing"));
    return false;
  }
  return true;
}

int Int(MjcfReader& r, const Element& e, std::string_view name, int fallback) {
  return r.Integer(e, name, fallback).value_or(fallback);  // a bad value is reported
}

}  // namespace

bool LowerGeom(MjcfReader& r, const BodyItem& item, BodyId body, bool is_world,
               bool mass_from_geometry, int index) {
  ir::Module& m = r.module();
  r.CheckAttributes(item.e, "geom");
  const Element g = r.Resolve(item.e, "geom", item.childclass);
  const xml::XmlAttribute name_attr = item.e.Attribute("name");  // never from a default
  const std::string name =
      name_attr.present() ? std::string(name_attr.value) : fmt::format("geom{}", index);
  const Attribute type_attr = g.Get("type");
  const std::string_view type = type_attr.present() ? type_attr.value : "sphere";

  if (type == "sdf") {
    r.LeaveOut(type_attr.loc, "<geom type=\"sdf\">",
               "the plant holds no signed-distance-field shapes (MuJoCo takes them from a "
               "plugin)");
    return false;
  }
  if (type == "hfield") {
    r.WarnOnce(type_attr.loc, DiagKind::UnsupportedValue, "geom", fmt::format("type={}", type),
               "is not supported; the geom is ignored");
    return false;
  }
  std::array<double, 3> size{0, 0, 0};
  if (!r.LayeredNumbers(g, "size", size)) return false;

  std::optional<Transform> X_FG;
  if (g.Get("fromto").present()) {
    X_FG = FromTo(r, g, type, size);
  } else {
    X_FG = r.ReadPose(g);
  }
  if (!X_FG) return false;

  ir::Geometry geom;
  geom.name = m.Intern(name);
  geom.unnamed = !name_attr.present();
  geom.model = r.model;
  geom.loc = item.e.GetLoc();
  geom.body = RefTo(m, body);
  geom.X_BG = item.X_BF * *X_FG;

  const Attribute mesh_attr = g.Get("mesh");
  const MeshAsset* asset = nullptr;
  if (mesh_attr.present()) {
    auto it = r.meshes.find(std::string(mesh_attr.value));
    if (it == r.meshes.end()) {
      // Drake warns and skips the geom (MJCF-042); MuJoCo rejects the file
      r.diags().Report(DiagKind::UnknownAsset, mesh_attr.loc,
                       fmt::format("geom '{}' names unknown mesh '{}'; the geom is ignored", name,
                                   mesh_attr.value));
      return false;
    }
    if (!it->second.left_out.empty()) {
      // said once per mesh: MuJoCo would build the geom, the plant cannot
      MeshAsset& left = it->second;
      if (!left.left_out_said) {
        left.left_out_said = true;
        r.diags()
            .Report(DiagKind::UnsupportedElement, mesh_attr.loc,
                    fmt::format("geom '{}' uses mesh '{}', which is left out: {}; the geom is left "
                                "out too, as is every geom using that mesh",
                                name, mesh_attr.value, left.left_out))
            .Note(left.loc, "the mesh is defined here");
      }
      return false;
    }
    it->second.used = true;
    asset = &it->second;
  }
  if (type == "plane") {
    geom.shape = ir::HalfSpace{};
  } else if (type == "mesh") {
    if (!asset) {
      r.diags().Report(DiagKind::MissingAttribute, item.e.GetLoc(),
                       fmt::format("geom '{}' has type 'mesh' but no 'mesh' attribute", name));
      return false;
    }
    geom.shape = asset->mesh;
  } else if (auto shape = Primitive(type, size)) {
    if (asset) {
      // BEYOND-002: the fit-to-mesh pass sizes and places the primitive
      geom.shape = *Primitive(type, std::array<double, 3>{0, 0, 0});
      ir::MeshFit fit;
      fit.mesh = asset->mesh;
      fit.aabb = r.compiler.fitaabb;
      fit.fitscale = r.Number(g, "fitscale", 1).value_or(1);
      fit.mesh_inertia = asset->inertia;
      geom.fit_to_mesh = std::move(fit);
    } else {
      if (!CheckPrimitiveSize(r, g, type, name, size)) return false;
      geom.shape = *shape;
    }
  } else {
    r.diags().Report(DiagKind::BadValue, type_attr.loc,
                     fmt::format("unknown geom type '{}'", type));
    return false;
  }

  // roles (MJCF-043)
  const int contype = Int(r, g, "contype", 1), conaffinity = Int(r, g, "conaffinity", 1);
  const int condim = Int(r, g, "condim", 3), group = Int(r, g, "group", 0);
  bool collision = !(contype == 0 && conaffinity == 0);
  bool visual = group <= 2;
  if (!collision && r.compiler.discard_visual) visual = false;  // BEYOND-006: MuJoCo drops it
  if (collision && (contype != 1 || conaffinity != 1)) {
    r.WarnOnce(g.Get(contype != 1 ? "contype" : "conaffinity").loc, DiagKind::UnsupportedValue,
               "geom", "contype/conaffinity",
               "other than (1, 1) or (0, 0) are not supported: collision filtering by bits is "
               "not modelled");
  }
  if (condim != 3) {
    r.WarnOnce(g.Get("condim").loc, DiagKind::UnsupportedValue, "geom", "condim",
               "other than 3 is not supported; condim=3 is used");
  }
  std::array<double, 3> friction{1, 0.005, 0.0001};
  if (!r.LayeredNumbers(g, "friction", friction)) return false;
  if (const Attribute f = g.Get("friction"); f.present()) {
    auto written = xml::ParseDoubleList(f.value);
    if (written && ((written->size() > 1 && (*written)[1] != 0) ||
                    (written->size() > 2 && (*written)[2] != 0))) {
      r.WarnOnce(f.loc, DiagKind::UnsupportedValue, "geom", "friction",
                 "torsional and rolling coefficients are not supported and are ignored");
    }
  }
  for (std::string_view a : {"fluidshape", "fluidcoef", "user"}) {
    if (g.Get(a).present()) r.WarnOnce(g.Get(a).loc, DiagKind::UnsupportedAttribute, "geom", a);
  }
  if (!asset && g.Get("fitscale").present()) {
    r.WarnOnce(g.Get("fitscale").loc, DiagKind::UnsupportedAttribute, "geom", "fitscale",
               "has no effect without a mesh and is ignored");
  }
  // S: priority, solmix, solref, solimp, margin, gap (solver parameters)

  // MJCF-031: this geom's share of the body's mass
  std::optional<ir::MassContribution> mass;
  const bool in_group = group >= r.compiler.inertia_group_min && group <= r.compiler.inertia_group_max;
  if (mass_from_geometry && !is_world && in_group && type != "plane") {
    ir::MassContribution c;
    if (g.Get("mass").present()) c.mass = r.Number(g, "mass", 0);
    c.density = r.Number(g, "density", 1000).value_or(1000);
    if (const Attribute shell = g.Get("shellinertia"); shell.present()) {
      c.shell = shell.value == "true";
      if (c.shell && type == "mesh") {
        r.diags().Report(DiagKind::BadValue, shell.loc,
                         "for mesh geoms, shell inertia is set on the mesh asset "
                         "(mesh inertia=\"shell\")");
      }
    }
    c.mesh_inertia = asset ? asset->inertia : ir::MeshInertia::Legacy;
    mass = c;
  }

  // appearance: the material's color unless the geom gives rgba (Drake's rule)
  if (const Attribute mat = g.Get("material"); mat.present()) {
    auto it = r.materials.find(std::string(mat.value));
    if (it != r.materials.end()) {
      geom.material = {m[it->second].name, mat.loc, it->second};
    } else {
      r.diags().Report(DiagKind::UnknownAsset, mat.loc,
                       fmt::format("geom '{}' names unknown material '{}', which is ignored", name,
                                   mat.value));
    }
  }
  if (g.Get("rgba").present()) {
    if (Eigen::Vector4d c; r.FixedNumbers(g, "rgba", c.data(), 4)) geom.rgba = c;
  } else if (!geom.material.id.valid() || !m[geom.material.id].rgba) {
    geom.rgba = Eigen::Vector4d(0.5, 0.5, 0.5, 1);  // MuJoCo's default geom color
  }

  // registered as illustration, proximity or both: the last registration
  // takes `geom` itself, and only a geom registered twice is copied
  std::optional<GeometryId> visual_id, collision_id;
  if (visual) {
    ir::Geometry v = collision ? ir::Geometry(geom) : std::move(geom);
    v.roles = ir::kIllustrationRole | ir::kPerceptionRole;
    visual_id = m.Add(std::move(v));
    ReadOriginalName(item.e, *visual_id, r.ctx);
  }
  if (collision) {
    ir::Geometry c = std::move(geom);
    c.roles = ir::kProximityRole;
    c.material = {};
    c.rgba.reset();
    c.properties.push_back({"material/coulomb_friction", std::vector<double>{friction[0], friction[0]}});
    collision_id = m.Add(std::move(c));
    ReadOriginalName(item.e, *collision_id, r.ctx);
  }
  if (mass) {
    if (collision_id) {
      m[*collision_id].mass_contribution = mass;
    } else if (visual_id) {
      m[*visual_id].mass_contribution = mass;
    } else {
      ir::Geometry carrier = std::move(geom);  // neither branch above took it
      carrier.roles = 0;  // registered nowhere; carries MuJoCo's mass only
      carrier.mass_contribution = mass;
      collision_id = m.Add(std::move(carrier));
    }
  }
  if (name_attr.present()) {
    const auto id = collision_id ? collision_id : visual_id;
    if (id) {
      auto [first, inserted] = r.geoms.Insert(m[*id].name, *id);
      if (!inserted) {
        r.diags()
            .Report(DiagKind::DuplicateName, name_attr.loc, fmt::format("repeated geom name '{}'", name))
            .Note(m[first].loc, "the first geom of that name is here");
      }
    }
  }
  return true;
}

void LowerSite(MjcfReader& r, const BodyItem& item, BodyId body) {
  ir::Module& m = r.module();
  r.CheckAttributes(item.e, "site");
  const Element s = r.Resolve(item.e, "site", item.childclass);
  std::optional<Transform> X;
  if (s.Get("fromto").present()) {
    const Attribute type = s.Get("type");
    std::array<double, 3> size{0.005, 0.005, 0.005};
    X = FromTo(r, s, type.present() ? type.value : "sphere", size);
  } else {
    X = r.ReadPose(s);
  }
  if (!X) return;
  const xml::XmlAttribute name = item.e.Attribute("name");
  if (!name.present()) return;  // nothing can refer to an unnamed site
  ir::Frame f;
  f.name = m.Intern(name.value);
  f.model = r.model;
  f.loc = item.e.GetLoc();
  f.body = RefTo(m, body);
  f.X_BF = item.X_BF * *X;
  const FrameId id = m.Add(std::move(f));
  ReadOriginalName(item.e, id, r.ctx);
  auto [first, inserted] = r.sites.Insert(m.frames[id.index()].name, id);
  if (!inserted) {
    r.diags()
        .Report(DiagKind::DuplicateName, name.loc, fmt::format("repeated site name '{}'", name.value))
        .Note(m.frames[first.index()].loc, "the first site of that name is here");
  }
}

void LowerCamera(MjcfReader& r, const BodyItem& item, BodyId body) {
  ir::Module& m = r.module();
  r.CheckAttributes(item.e, "camera");
  const Element c = r.Resolve(item.e, "camera", item.childclass);
  const xml::XmlAttribute name_attr = item.e.Attribute("name");
  const std::string local = name_attr.present() ? std::string(name_attr.value)
                                                : fmt::format("camera{}", r.num_cameras);
  ++r.num_cameras;
  auto X = r.ReadPose(c);
  if (!X) return;
  ir::Camera cam;
  cam.name = m.Intern(fmt::format("{}/{}", r.model_name, local));
  cam.unnamed = !name_attr.present();
  cam.model = r.model;
  cam.loc = item.e.GetLoc();
  cam.body = RefTo(m, body);
  // MuJoCo's camera looks along -z with +y up; Drake's along +z with +y
  // down: a half turn about x between the two
  const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, -1).asDiagonal();
  cam.X_BC = item.X_BF * *X * Transform::FromRotation(flip);
  // fovy is in degrees whatever compiler@angle says (MJCF-002)
  cam.fov_y = r.Number(c, "fovy", 45).value_or(45) * M_PI / 180.0;
  if (c.Get("resolution").present()) {
    if (auto res = r.Integers(c, "resolution", 2)) {
      cam.width = (*res)[0];
      cam.height = (*res)[1];
    }
  }
  if (const Attribute mode = c.Get("mode"); mode.present() && mode.value != "fixed") {
    r.WarnOnce(mode.loc, DiagKind::UnsupportedValue, "camera", "mode",
               "other than 'fixed' is not supported; a fixed camera is used");
  }
  if (const Attribute o = c.Get("orthographic"); o.present() && o.value == "true") {
    r.WarnOnce(o.loc, DiagKind::UnsupportedValue, "camera", "orthographic",
               "projection is not supported; a perspective projection is used");
  }
  for (std::string_view a : {"target", "focal", "focalpixel", "principal", "principalpixel",
                             "sensorsize", "ipd", "user"}) {
    if (c.Get(a).present()) r.WarnOnce(c.Get(a).loc, DiagKind::UnsupportedAttribute, "camera", a);
  }
  const CameraId id = m.Add(std::move(cam));
  ReadOriginalName(item.e, id, r.ctx);
}

}  // namespace mdlc::frontend::mjcf
