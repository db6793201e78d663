// sdf_geometry.cc - <visual>, <collision>, shapes, materials and sensors of
// a link (SDF-040, SDF-041, SDF-043, SDF-044, EXT-020..035).
//
// A visual becomes a geometry with the illustration and perception roles, a
// collision one with the proximity role; names are unique per link and kind,
// as libsdformat requires. Poses are not evaluated here: each geometry and
// camera gets an anchor node in the frame graph (after it is added to the
// module), and the resolve-frames pass writes Geometry::X_BG and
// Camera::X_BC. A plane's half space takes the rotation from +z to the
// plane's normal, folded into its anchor as Drake folds it into X_LC.
//
// <drake:visual> (EXT-032) is a <visual> whose every element carries the
// drake: prefix; it is read by the same code with the prefix stripped
// (Spelling), except the drake-only role elements, which keep their names.
//
// Missing SDFormat elements take libsdformat's defaults (it adds every
// required element it does not find), as Drake sees them.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "frontend/drake_proximity.h"
#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::sdf {
namespace {

constexpr std::string_view kDrakePrefix = "drake:";
constexpr std::string_view kProximityTag = "drake:proximity_properties";
constexpr std::string_view kIllustrationTag = "drake:illustration_properties";
constexpr std::string_view kPerceptionTag = "drake:perception_properties";
constexpr std::string_view kAcceptingTag = "drake:accepting_renderer";
constexpr std::string_view kDiffuseMapTag = "drake:diffuse_map";

// geometry_names_ keeps one name space per (link, kind): the kind is mixed
// into the key's scope
enum NameKind : uint32_t { kCollisionNames = 0, kVisualNames = 1, kSensorNames = 2 };

/// How the SDFormat elements of a visual are spelled: plain, or with the
/// drake: prefix inside a <drake:visual> (EXT-032).
struct Spelling {
  bool drake = false;
  std::string operator()(std::string_view sdf_name) const {
    return drake ? fmt::format("{}{}", kDrakePrefix, sdf_name) : std::string(sdf_name);
  }
  /// The SDFormat name of an element spelled this way.
  std::string_view Local(std::string_view tag) const {
    return drake && tag.starts_with(kDrakePrefix) ? tag.substr(kDrakePrefix.size()) : tag;
  }
};

bool Contains(std::initializer_list<std::string_view> list, std::string_view s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

/// CheckChildren for the elements a <drake:visual> may spell with the
/// prefix: `known` and `unsupported` hold SDFormat names (and drake-only
/// names, matched as written). Plain spelling is exactly CheckChildren.
void CheckVisualChildren(SdfReader& r, const xml::XmlElement& e, const Spelling& sp,
                         std::initializer_list<std::string_view> known,
                         std::initializer_list<std::string_view> unsupported = {}) {
  if (!sp.drake) {
    r.CheckChildren(e, known, unsupported);
    return;
  }
  // every child is drake:-prefixed here (checked up front); the messages are
  // CheckChildren's
  for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
    const std::string_view tag = child.Name();
    if (Contains(known, tag) || Contains(known, sp.Local(tag))) continue;
    if (Contains(unsupported, sp.Local(tag))) {
      r.diags().Report(DiagKind::UnsupportedElement, child.GetLoc(),
                       fmt::format("element <{}> in <{}> is not supported and is ignored",
                                   tag, e.Name()));
    } else {
      r.diags().Report(DiagKind::UnknownElement, child.GetLoc(),
                       fmt::format("unsupported element <{}> in <{}> is ignored", tag, e.Name()));
    }
  }
}

/// EXT-032: every element under a <drake:visual> must be drake:-prefixed,
/// down to the role elements (whose contents Drake reads as they are).
/// Walks the elements in document order in a loop, not by recursion: they
/// may nest as deep as a document may (its `depth` limit), past what the
/// stack holds of recursive calls.
bool CheckDrakeNamespaced(SdfReader& r, const xml::XmlElement& visual) {
  bool ok = true;
  xml::XmlElement e = visual.FirstChild();
  while (e) {
    const std::string_view tag = e.Name();
    bool descend = false;
    if (!tag.starts_with(kDrakePrefix)) {
      r.diags().Report(DiagKind::UnknownSdfElement, e.GetLoc(),
                       fmt::format("<{}> in <{}>: all tags under a drake-namespaced tag must "
                                   "likewise be drake-namespaced",
                                   tag, e.Parent().Name()));
      ok = false;
    } else {
      descend = tag != kIllustrationTag && tag != kPerceptionTag;
    }
    if (descend && e.FirstChild()) {
      e = e.FirstChild();
      continue;
    }
    // the next element: a sibling, or the sibling of the nearest ancestor
    // below the visual that has one
    while (!e.NextSibling()) {
      e = e.Parent();
      if (e.raw() == visual.raw()) return ok;
    }
    e = e.NextSibling();
  }
  return ok;
}

/// The first child of `e`'s parent with `e`'s name, when that is not `e`.
xml::XmlElement EarlierNamesake(const xml::XmlElement& e) {
  xml::XmlElement first = e.Parent().Child(e.Name());
  return first.raw() == e.raw() ? xml::XmlElement() : first;
}

ir::Property* FindProperty(ir::Geometry& g, std::string_view key) {
  auto it = std::find_if(g.properties.begin(), g.properties.end(),
                         [&](const ir::Property& p) { return p.key == key; });
  return it == g.properties.end() ? nullptr : &*it;
}

// --- shapes (SDF-040, EXT-034, EXT-035) ---

/// The number in `parent`'s child `name`, or `fallback` when there is none
/// (libsdformat's default); nullopt after reporting a bad value.
std::optional<double> SizeOr(SdfReader& r, const xml::XmlElement& parent, const std::string& name,
                             std::optional<double> fallback, bool zero_allowed = false) {
  xml::XmlElement child = parent.Child(name);
  if (!child) {
    if (!fallback) {
      r.diags().Report(DiagKind::MissingElement, parent.GetLoc(),
                       fmt::format("<{}> is missing required element <{}>", parent.Name(), name));
    }
    return fallback;
  }
  auto v = r.TextDouble(child);
  if (!v) return std::nullopt;
  if (zero_allowed ? !(*v >= 0) : !(*v > 0)) {
    r.diags().Report(DiagKind::BadValue, child.GetLoc(),
                     fmt::format("<{}> of <{}> must be {}, got {}", name, parent.Name(),
                                 zero_allowed ? "non-negative" : "positive", *v));
    return std::nullopt;
  }
  return v;
}

/// Three positive numbers in `parent`'s child `name`, or `fallback`.
std::optional<Eigen::Vector3d> Sizes3Or(SdfReader& r, const xml::XmlElement& parent,
                                        const std::string& name, const Eigen::Vector3d& fallback) {
  xml::XmlElement child = parent.Child(name);
  if (!child) return fallback;
  auto v = r.TextVector3(child);
  if (!v) return std::nullopt;
  if (!(v->minCoeff() > 0)) {
    r.diags().Report(DiagKind::BadValue, child.GetLoc(),
                     fmt::format("<{}> of <{}> must hold positive numbers, got '{}'", name,
                                 parent.Name(), xml::Trim(child.Text())));
    return std::nullopt;
  }
  return v;
}

/// Drake's HalfSpace::MakePose(normal, 0): the rotation taking +z to the
/// normal, with x and y built from the normal's smallest component.
Transform HalfSpacePose(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d u = normal.cwiseAbs();
  int min_axis = 0;
  u.minCoeff(&min_axis);
  Eigen::Vector3d perp = Eigen::Vector3d::Zero();
  perp(min_axis) = 1;
  const Eigen::Vector3d z = normal.normalized();
  const Eigen::Vector3d x = z.cross(perp).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Transform X;
  X.R.col(0) = x;
  X.R.col(1) = y;
  X.R.col(2) = z;
  return X;
}

struct ShapeResult {
  ir::Shape shape;
  Transform X_GC;  // the shape's canonical frame C in the geometry frame G
};

std::optional<ShapeResult> ReadShape(SdfReader& r, const xml::XmlElement& geometry,
                                     const Spelling& sp) {
  CheckVisualChildren(r, geometry, sp,
                      {"empty", "box", "capsule", "cylinder", "ellipsoid", "heightmap", "image",
                       "mesh", "plane", "polyline", "sphere", "cone", "drake:capsule",
                       "drake:ellipsoid"});
  // cone is SDFormat 1.11's; like heightmap, image and polyline Drake has no such shape
  static constexpr std::array<std::string_view, 14> kShapes = {
      "box",   "capsule",  "cylinder", "ellipsoid", "heightmap",     "image",          "mesh",
      "plane", "polyline", "sphere",   "empty",     "drake:capsule", "drake:ellipsoid", "cone"};
  xml::XmlElement e;
  for (auto c = geometry.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view kind = sp.Local(c.Name());
    if (std::find(kShapes.begin(), kShapes.end(), kind) == kShapes.end() || kind == "empty") {
      continue;
    }
    if (!e) {
      e = c;
    } else if (kind == "polyline" && sp.Local(e.Name()) == "polyline") {
      // SDFormat allows several polylines in one geometry (one unsupported shape)
    } else {
      r.diags()
          .Report(DiagKind::BadGeometry, c.GetLoc(),
                  fmt::format("<{}> must hold exactly one shape, but also holds <{}>",
                              geometry.Name(), c.Name()))
          .Note(e.GetLoc(), fmt::format("the first shape is <{}>", e.Name()));
    }
  }
  // <empty/>, or nothing at all: no geometry, silently (SDF-040)
  if (!e) return std::nullopt;
  const std::string_view kind = sp.Local(e.Name());
  ShapeResult result;
  if (kind == "box") {
    CheckVisualChildren(r, e, sp, {"size"});
    auto size = Sizes3Or(r, e, sp("size"), Eigen::Vector3d::Ones());
    if (!size) return std::nullopt;
    result.shape = ir::Box{*size};
  } else if (kind == "sphere") {
    CheckVisualChildren(r, e, sp, {"radius"});
    auto radius = SizeOr(r, e, sp("radius"), 1.0, /*zero_allowed=*/true);
    if (!radius) return std::nullopt;
    result.shape = ir::Sphere{*radius};
  } else if (kind == "cylinder" || kind == "capsule" || kind == "drake:capsule") {
    CheckVisualChildren(r, e, sp, {"radius", "length"});
    // drake:capsule's children have no defaults (Drake requires them)
    const bool custom = kind == "drake:capsule";
    const std::optional<double> default_radius =
        custom ? std::nullopt : std::optional<double>(kind == "capsule" ? 0.5 : 1.0);
    const std::optional<double> default_length =
        custom ? std::nullopt : std::optional<double>(1.0);
    auto radius = SizeOr(r, e, sp("radius"), default_radius);
    auto length = SizeOr(r, e, sp("length"), default_length);
    if (!radius || !length) return std::nullopt;
    if (kind == "cylinder") {
      result.shape = ir::Cylinder{*radius, *length};
    } else {
      result.shape = ir::Capsule{*radius, *length};
    }
  } else if (kind == "ellipsoid") {
    CheckVisualChildren(r, e, sp, {"radii"});
    auto radii = Sizes3Or(r, e, sp("radii"), Eigen::Vector3d::Ones());
    if (!radii) return std::nullopt;
    result.shape = ir::Ellipsoid{(*radii)[0], (*radii)[1], (*radii)[2]};
  } else if (kind == "drake:ellipsoid") {
    CheckVisualChildren(r, e, sp, {"a", "b", "c"});
    auto a = SizeOr(r, e, sp("a"), std::nullopt);
    auto b = SizeOr(r, e, sp("b"), std::nullopt);
    auto c = SizeOr(r, e, sp("c"), std::nullopt);
    if (!a || !b || !c) return std::nullopt;
    result.shape = ir::Ellipsoid{*a, *b, *c};
  } else if (kind == "plane") {
    // a half space whose +z is the normal; the size is ignored (Drake's
    // half spaces are unbounded) but must still be a valid size
    CheckVisualChildren(r, e, sp, {"normal", "size"});
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    if (xml::XmlElement n = e.Child(sp("normal"))) {
      auto v = r.TextVector3(n);
      if (!v) return std::nullopt;
      if (!(v->norm() >= 1e-10)) {
        r.diags().Report(DiagKind::BadValue, n.GetLoc(),
                         fmt::format("the plane normal must not be zero, got '{}'",
                                     xml::Trim(n.Text())));
        return std::nullopt;
      }
      normal = *v;
    }
    if (xml::XmlElement size = e.Child(sp("size"))) {
      auto v = r.TextDoubles(size, 2);
      if (!v) return std::nullopt;
      if ((*v)[0] < 0 || (*v)[1] < 0) {
        r.diags().Report(DiagKind::BadValue, size.GetLoc(),
                         fmt::format("<{}> of <{}> must not be negative, got '{}'", size.Name(),
                                     e.Name(), xml::Trim(size.Text())));
        return std::nullopt;
      }
    }
    result.shape = ir::HalfSpace{};
    result.X_GC = HalfSpacePose(normal);
  } else if (kind == "mesh") {
    CheckVisualChildren(r, e, sp, {"uri", "scale", "drake:declare_convex"},
                        {"submesh", "convex_decomposition", "optimization"});
    xml::XmlElement uri = e.Child(sp("uri"));
    const std::string written = uri ? uri.Text() : std::string();
    const std::string_view text = xml::Trim(written);
    if (!uri || text.empty()) {
      // libsdformat's default uri is "__default__", which Drake rejects
      r.diags().Report(DiagKind::MissingElement, uri ? uri.GetLoc() : e.GetLoc(),
                       fmt::format("<{}> is missing its required <{}>", e.Name(), sp("uri")));
      return std::nullopt;
    }
    ir::Mesh mesh;
    mesh.uri = std::string(text);
    mesh.uri_loc = uri.GetLoc();
    if (xml::XmlElement scale = e.Child(sp("scale"))) {
      auto v = r.TextVector3(scale);
      if (!v) return std::nullopt;
      mesh.scale = *v;
    }
    // EXT-034: declared convex, same uri and scale
    if (e.Child("drake:declare_convex")) mesh.convex = true;
    result.shape = std::move(mesh);
  } else {
    // heightmap, image, polyline, cone
    r.diags().Report(DiagKind::UnsupportedElement, e.GetLoc(),
                     fmt::format("element <{}> in <{}> is not supported and is ignored; the {} "
                                 "has no geometry",
                                 e.Name(), geometry.Name(), geometry.Parent().Name()));
    return std::nullopt;
  }
  // a <drake:declare_convex> elsewhere is an unknown child of its shape
  return result;
}

// --- visual materials and roles (SDF-041, EXT-030, EXT-031, EXT-033) ---

/// An SDFormat color: "r g b [a]", each in [0, 1]; alpha defaults to 1.
std::optional<Eigen::Vector4d> ReadColor(SdfReader& r, const xml::XmlElement& e) {
  const std::string text = e.Text();
  auto values = xml::ParseDoubleList(text);
  if (!values || (values->size() != 3 && values->size() != 4)) {
    r.diags().Report(DiagKind::BadValue, e.GetLoc(),
                     fmt::format("<{}> must hold a color 'r g b [a]', found '{}'", e.Name(),
                                 xml::Trim(text)));
    return std::nullopt;
  }
  for (double v : *values) {
    if (!(v >= 0 && v <= 1)) {
      r.diags().Report(DiagKind::BadValue, e.GetLoc(),
                       fmt::format("<{}> color values must be within [0, 1], got '{}'", e.Name(),
                                   xml::Trim(text)));
      return std::nullopt;
    }
  }
  const auto& v = *values;
  return Eigen::Vector4d(v[0], v[1], v[2], v.size() == 4 ? v[3] : 1.0);
}

/// <material>: diffuse becomes the geometry's color (drawn as phong/diffuse
/// by the backend); ambient, specular and emissive become phong properties,
/// and drake:diffuse_map the texture. Absent colors stay absent, so the
/// renderer's defaults apply (as in Drake).
void ReadMaterial(SdfReader& r, const xml::XmlElement& material, const Spelling& sp,
                  ir::Geometry& g) {
  // SDFormat's material rules, though Drake draws neither scripts nor
  // shaders. libsdformat rejects a <script> without a <uri> or a <name>, as
  // Gazebo-classic models write it (<script><name>Gazebo/Red</name></script>,
  // or the name as text); a script cannot affect the plant, so mdlc warns
  // and ignores it (a complete one is merely unsupported).
  xml::XmlElement script = material.Child("script");
  std::vector<std::string> script_lacks;
  for (std::string_view needed : {"uri", "name"}) {
    xml::XmlElement c = script ? script.Child(needed) : xml::XmlElement();
    if (script && (!c || xml::Trim(c.Text()).empty() || xml::Trim(c.Text()) == "__default__")) {
      script_lacks.push_back(fmt::format("<{}>", needed));
    }
  }
  if (script_lacks.empty()) {
    CheckVisualChildren(r, material, sp,
                        {"ambient", "diffuse", "specular", "emissive", kDiffuseMapTag},
                        {"script", "shader", "render_order", "lighting", "double_sided", "pbr"});
  } else {
    CheckVisualChildren(r, material, sp,
                        {"ambient", "diffuse", "specular", "emissive", kDiffuseMapTag, "script"},
                        {"shader", "render_order", "lighting", "double_sided", "pbr"});
    const xml::XmlElement owner = material.Parent();
    const xml::XmlAttribute owner_name = owner.Attribute("name");
    r.diags().Report(DiagKind::IncompleteMaterialScript, script.GetLoc(),
                     fmt::format("<script> in the material of {} '{}' has no {} (or {} empty), "
                                 "which libsdformat rejects; it is ignored, as a material "
                                 "script does not affect the plant",
                                 owner.Name(), owner_name.present() ? owner_name.value : "",
                                 fmt::join(script_lacks, " and "),
                                 script_lacks.size() > 1 ? "they are" : "it is"));
  }
  if (xml::XmlElement shader = material.Child("shader")) {
    auto type = shader.Attribute("type");
    if (type.present() && type.value.starts_with("normal_map") && !shader.Child("normal_map")) {
      r.diags().Report(DiagKind::MissingElement, shader.GetLoc(),
                       "a normal map shader type has been specified, but a <normal_map> has not");
    }
  }
  if (xml::XmlElement diffuse = material.Child(sp("diffuse"))) g.rgba = ReadColor(r, diffuse);
  for (std::string_view name : {"ambient", "specular", "emissive"}) {
    if (xml::XmlElement c = material.Child(sp(name))) {
      if (auto color = ReadColor(r, c)) {
        g.properties.push_back(
            {fmt::format("phong/{}", name), std::vector<double>(color->data(), color->data() + 4)});
      }
    }
  }
  if (xml::XmlElement map = material.Child(kDiffuseMapTag)) {
    const std::string written = map.Text();
    const std::string_view uri = xml::Trim(written);
    if (uri.empty()) {
      r.diags().Report(DiagKind::BadValue, map.GetLoc(),
                       fmt::format("<{}> is empty; it must name a texture file", kDiffuseMapTag));
    } else {
      g.properties.push_back({"phong/diffuse_map", std::string(uri)});
    }
  }
}

/// EXT-030: enabled="false" takes the role away; absent or true keeps it.
void ReadRoleElement(SdfReader& r, const xml::XmlElement& e, ir::Geometry& g) {
  if (auto first = EarlierNamesake(e)) {
    ReportRepeatedElement(r.diags(), e, first);
    return;
  }
  r.attrs_.WarnUnknownAttributes(e, {"enabled"});
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    r.diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                     fmt::format("unknown element <{}> in <{}> is ignored", c.Name(), e.Name()));
  }
  const uint8_t role = e.Name() == kIllustrationTag ? ir::kIllustrationRole : ir::kPerceptionRole;
  xml::XmlAttribute enabled = e.Attribute("enabled");
  if (!enabled.present()) return;
  const std::string_view value = xml::Trim(enabled.value);
  if (value == "true" || value == "1") {
    g.roles |= role;
  } else if (value == "false" || value == "0") {
    g.roles &= static_cast<uint8_t>(~role);
  } else {
    r.diags().Report(DiagKind::BadValue, enabled.loc,
                     fmt::format("invalid value '{}' for attribute 'enabled' of <{}>: expected "
                                 "'true' or 'false'",
                                 enabled.value, e.Name()));
  }
}

/// EXT-031: one renderer name per element, collected into a sorted set.
void ReadAcceptingRenderer(SdfReader& r, const xml::XmlElement& e, ir::Geometry& g) {
  r.attrs_.WarnUnknownAttributes(e, {});
  const std::string written = e.Text();
  const std::string_view name = xml::Trim(written);
  if (name.empty()) {
    r.diags().Report(DiagKind::BadValue, e.GetLoc(),
                     fmt::format("<{}> is empty; it must name a renderer", kAcceptingTag));
    return;
  }
  ir::Property* accepting = FindProperty(g, "renderer/accepting");
  if (!accepting) {
    g.properties.push_back({"renderer/accepting", std::vector<std::string>{}});
    accepting = &g.properties.back();
  }
  auto& names = std::get<std::vector<std::string>>(accepting->value);
  auto at = std::lower_bound(names.begin(), names.end(), name);
  if (at == names.end() || *at != name) names.insert(at, std::string(name));
}

// --- collision properties (EXT-020, EXT-021, SDF-041) ---
// The rules and messages of frontend/urdf/urdf_geometry_properties.cc, with
// the values read from element text instead of @value.

/// EXT-020: <drake:proximity_properties>, with the numbers in element text
/// (the rules are shared with the URDF frontend: frontend/drake_proximity.h).
void ReadProximityProperties(SdfReader& r, const xml::XmlElement& e, ir::Geometry& g) {
  ReadDrakeProximityProperties(e, g, r.attrs_, r.diags(),
                               [&](const xml::XmlElement& c) -> std::optional<Located> {
                                 r.attrs_.WarnUnknownAttributes(c, {});
                                 auto v = r.TextDouble(c);
                                 if (!v) return std::nullopt;
                                 return Located{*v, c.GetLoc()};
                               });
}

/// <surface>: SDF-041, EXT-021: <friction><ode><mu> gives both friction
/// coefficients unless <drake:proximity_properties> gives a friction (then
/// <mu>/<mu2> are reported as ignored); <mu2> is not used.
void ReadSurface(SdfReader& r, const xml::XmlElement& surface, const xml::XmlElement& proximity,
                 ir::Geometry& g) {
  r.CheckChildren(surface, {"bounce", "friction", "contact", "soft_contact"});
  xml::XmlElement friction = surface.Child("friction");
  if (!friction) return;
  r.CheckChildren(friction, {"torsional", "ode", "bullet"});
  xml::XmlElement ode = friction.Child("ode");
  if (!ode) return;
  r.CheckChildren(ode, {"mu", "mu2", "fdir1", "slip1", "slip2"});
  xml::XmlElement mu = ode.Child("mu");
  const bool drake_friction =
      proximity && (proximity.Child("drake:mu_dynamic") || proximity.Child("drake:mu_static"));
  if (drake_friction) {
    xml::XmlElement given = mu ? mu : ode.Child("mu2");
    if (given) {
      r.diags()
          .Report(DiagKind::UnsupportedElement, given.GetLoc(),
                  "<mu> and <mu2> in <surface><friction><ode> are ignored: the friction comes "
                  "from <drake:proximity_properties>")
          .Note(proximity.GetLoc(), "<drake:proximity_properties> is here");
    }
    return;
  }
  if (!mu) return;
  auto value = r.TextDouble(mu);
  if (!value) return;
  const Located located{*value, mu.GetLoc()};
  if (auto coefficients = CoulombFriction(r.diags(), located, located)) {
    g.properties.push_back({"material/coulomb_friction", std::move(*coefficients)});
  }
}

/// Claims `name` among the link's names of `kind`; reports a duplicate.
bool ClaimName(SdfReader& r, BodyId body, NameKind kind, Symbol name, Loc loc,
               std::string_view what, Symbol link_name) {
  const SdfReader::ScopedKey key{body.value * 4 + kind, name.value};
  auto [it, inserted] = r.geometry_names_.emplace(key, loc);
  if (inserted) return true;
  r.diags()
      .Report(DiagKind::DuplicateName, loc,
              fmt::format("{} name '{}' is already used by another {} of link '{}'", what,
                          r.module().Text(name), what, r.module().Text(link_name)))
      .Note(it->second, "first defined here");
  return false;
}

bool IsCameraType(std::string_view type) {
  return type == "camera" || type == "rgbd_camera" || type == "rgbd" ||
         type == "depth_camera" || type == "depth";
}

/// A positive whole number in `parent`'s child `name`, or `fallback`.
std::optional<int> PixelsOr(SdfReader& r, const xml::XmlElement& parent, std::string_view name,
                            int fallback) {
  xml::XmlElement child = parent.Child(name);
  if (!child) return fallback;
  auto v = r.TextDouble(child);
  if (!v) return std::nullopt;
  if (!(*v >= 1 && *v <= 1e6 && *v == std::floor(*v))) {
    r.diags().Report(DiagKind::BadValue, child.GetLoc(),
                     fmt::format("<{}> must be a positive whole number of pixels, got '{}'",
                                 name, xml::Trim(child.Text())));
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

}  // namespace

void SdfReader::ReadVisual(const xml::XmlElement& e, ModelScope& s, BodyId body,
                           Symbol link_name, FrameNodeId link_node) {
  const Spelling sp{e.Name() == "drake:visual"};
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  attrs_.WarnUnknownAttributes(e, {"name"});
  if (!CheckDefinedName(*name, e.GetLoc(), "visual", s.file->version)) return;
  // EXT-032: Drake drops a <drake:visual> with a non-prefixed element
  if (sp.drake && !CheckDrakeNamespaced(*this, e)) return;
  const Symbol symbol = module().Intern(*name);
  if (!ClaimName(*this, body, kVisualNames, symbol, e.GetLoc(), "visual", link_name)) return;
  CheckVisualChildren(*this, e, sp,
                      {"pose", "material", "geometry", "transparency", "plugin",
                       kIllustrationTag, kPerceptionTag, kAcceptingTag},
                      {"cast_shadows", "laser_retro", "visibility_flags", "meta"});

  xml::XmlElement geometry = e.Child(sp("geometry"));
  if (!geometry) {
    // libsdformat fills in an empty geometry, which Drake skips; the material
    // is still checked
    diags().Report(DiagKind::EmptyGeometry, e.GetLoc(),
                   fmt::format("<{}> has no <{}>: nothing is registered for it", e.Name(),
                               sp("geometry")));
    if (xml::XmlElement material = e.Child(sp("material"))) {
      ir::Geometry unused;
      ReadMaterial(*this, material, sp, unused);
    }
    return;
  }
  auto shape = ReadShape(*this, geometry, sp);

  ir::Geometry g;
  g.name = symbol;
  g.model = s.model;
  g.loc = e.GetLoc();
  g.body = {link_name, e.GetLoc(), body};
  g.roles = ir::kIllustrationRole | ir::kPerceptionRole;
  // SDF-041: color and texture
  if (xml::XmlElement material = e.Child(sp("material"))) ReadMaterial(*this, material, sp, g);
  if (xml::XmlElement transparency = e.Child(sp("transparency"))) {
    if (auto t = TextDouble(transparency)) {
      if (!(*t >= 0 && *t <= 1)) {
        diags().Report(DiagKind::BadValue, transparency.GetLoc(),
                       fmt::format("<{}> must be within [0, 1], got {}", transparency.Name(), *t));
      } else if (g.rgba) {
        (*g.rgba)[3] = 1 - *t;
      }
    }
  }
  // EXT-030, EXT-031: the roles and the renderers of the perception role
  xml::XmlElement accepting;
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view tag = c.Name();
    if (tag == kIllustrationTag || tag == kPerceptionTag) {
      ReadRoleElement(*this, c, g);
    } else if (tag == kAcceptingTag) {
      if (!accepting) accepting = c;
      ReadAcceptingRenderer(*this, c, g);
    }
  }
  if (!shape) return;  // empty or unreadable geometry: nothing to add

  const bool illustration = g.roles & ir::kIllustrationRole;
  const bool perception = g.roles & ir::kPerceptionRole;
  if (!illustration && !perception) {
    // EXT-030: a visual with no role is dropped; a <drake:visual> is
    // allowed to do that quietly (EXT-032)
    if (!sp.drake) {
      diags().Report(DiagKind::UnsupportedValue, e.GetLoc(),
                     fmt::format("visual geometry '{}' in link '{}' has both its illustration "
                                 "and perception properties disabled; the geometry is ignored",
                                 *name, module().Text(link_name)));
    }
    return;
  }
  if (!perception) {
    auto it = std::find_if(g.properties.begin(), g.properties.end(),
                           [](const ir::Property& p) { return p.key == "renderer/accepting"; });
    if (it != g.properties.end()) {
      diags().Report(DiagKind::UnsupportedElement, accepting.GetLoc(),
                     fmt::format("<{}> is ignored: the perception role of this visual is "
                                 "disabled",
                                 kAcceptingTag));
      g.properties.erase(it);
    }
  }
  g.shape = std::move(shape->shape);
  const GeometryId id = module().Add(std::move(g));
  const FrameNodeId node = AddAnchor(s, e.Child(sp("pose")), link_name, link_node, e.GetLoc(),
                                     ir::FrameTarget::Geometry, id.value);
  if (!shape->X_GC.IsIdentity()) graph()[node].X_RN = graph()[node].X_RN * shape->X_GC;
}

void SdfReader::ReadCollision(const xml::XmlElement& e, ModelScope& s, BodyId body,
                              Symbol link_name, FrameNodeId link_node) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  if (!name) return;
  attrs_.WarnUnknownAttributes(e, {"name"});
  if (!CheckDefinedName(*name, e.GetLoc(), "collision", s.file->version)) return;
  const Symbol symbol = module().Intern(*name);
  if (!ClaimName(*this, body, kCollisionNames, symbol, e.GetLoc(), "collision", link_name)) {
    return;
  }
  CheckChildren(e,
                {"pose", "geometry", "surface", "laser_retro", "density", "auto_inertia_params",
                 kProximityTag},
                {"max_contacts"});
  if (xml::XmlElement retro = e.Child("laser_retro")) {
    if (auto v = TextDouble(retro); v && *v != 0) {
      diags().Report(DiagKind::UnsupportedValue, retro.GetLoc(),
                     fmt::format("<laser_retro> of <collision> is not supported; the value "
                                 "{} is ignored",
                                 *v));
    }
  }
  xml::XmlElement geometry = e.Child("geometry");
  if (!geometry) {
    // libsdformat fills in an empty geometry, which Drake skips
    diags().Report(DiagKind::EmptyGeometry, e.GetLoc(),
                   "<collision> has no <geometry>: nothing is registered for it");
    return;
  }
  auto shape = ReadShape(*this, geometry, Spelling{});

  ir::Geometry g;
  g.name = symbol;
  g.model = s.model;
  g.loc = e.GetLoc();
  g.body = {link_name, e.GetLoc(), body};
  g.roles = ir::kProximityRole;
  // EXT-020, EXT-021: drake: properties first, then the SDFormat friction
  xml::XmlElement proximity;
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    if (c.Name() != kProximityTag) continue;
    if (!proximity) {
      proximity = c;
      ReadProximityProperties(*this, c, g);
    } else {
      ReportRepeatedElement(diags(), c, proximity);
    }
  }
  if (xml::XmlElement surface = e.Child("surface")) ReadSurface(*this, surface, proximity, g);
  if (!shape) return;

  g.shape = std::move(shape->shape);
  // SDFormat 1.11: the collision's own density, for <inertial auto="true">
  if (auto density = ChildDouble(e, "density")) {
    if (*density > 0) {
      g.density = *density;
    } else {
      diags().Report(DiagKind::BadValue, e.Child("density").GetLoc(),
                     fmt::format("<density> must be positive, got {}", *density));
    }
  }
  const GeometryId id = module().Add(std::move(g));
  const FrameNodeId node = AddAnchor(s, e.Child("pose"), link_name, link_node, e.GetLoc(),
                                     ir::FrameTarget::Geometry, id.value);
  if (!shape->X_GC.IsIdentity()) graph()[node].X_RN = graph()[node].X_RN * shape->X_GC;
}

void SdfReader::ReadSensor(const xml::XmlElement& e, ModelScope& s, BodyId body,
                           Symbol link_name, FrameNodeId link_node) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto type = attrs_.String(e, "type", xml::Need::Required);
  if (!name || !type) return;
  attrs_.WarnUnknownAttributes(e, {"name", "type"});
  if (!CheckDefinedName(*name, e.GetLoc(), "sensor", s.file->version)) return;
  const Symbol symbol = module().Intern(*name);
  if (!ClaimName(*this, body, kSensorNames, symbol, e.GetLoc(), "sensor", link_name)) return;
  // one rule for every sensor, modelled or not: an element SDFormat does not
  // define in <sensor> is an error (SDF-001), as libsdformat reports it under
  // Drake's policy (a Gazebo <gz_frame_id> in an imu as in a camera)
  // (SDFormat 1.12's elements of <sensor>: air_speed since 1.10, frame_id 1.12)
  CheckChildren(e, {"always_on", "update_rate", "visualize", "topic", "enable_metrics",
                    "frame_id", "pose", "plugin", "camera", "air_pressure", "air_speed",
                    "altimeter", "contact", "force_torque", "gps", "imu", "lidar",
                    "logical_camera", "magnetometer", "navsat", "ray", "rfid", "rfidtag", "sonar",
                    "transceiver"});
  if (!IsCameraType(*type)) {
    // SDF-043: only cameras are modelled
    diags().Report(DiagKind::UnsupportedElement, e.GetLoc(),
                   fmt::format("sensor '{}' of type '{}' is not supported and is ignored",
                               *name, *type));
    return;
  }

  // SDF-044: libsdformat's defaults where the file says nothing
  ir::Camera camera;
  camera.name = module().Intern(fmt::format("{}/{}", module().ModelName(s.model), *name));
  camera.model = s.model;
  camera.loc = e.GetLoc();
  camera.body = {link_name, e.GetLoc(), body};
  double hfov = 1.047;
  int width = 320, height = 240;
  Transform X_SC;  // the camera's own pose, in the sensor frame
  if (xml::XmlElement c = e.Child("camera")) {
    attrs_.WarnUnknownAttributes(c, {"name"});
    CheckChildren(c, {"horizontal_fov", "image", "clip", "save", "depth_camera",
                      "segmentation_type", "box_type", "noise", "distortion", "lens",
                      "visibility_mask", "pose", "camera_info_topic", "triggered",
                      "trigger_topic", "optical_frame_id"});
    if (xml::XmlElement fov = c.Child("horizontal_fov")) {
      auto v = TextDouble(fov);
      if (!v) return;
      if (!(*v > 0 && *v < std::numbers::pi)) {
        diags().Report(DiagKind::BadValue, fov.GetLoc(),
                       fmt::format("<horizontal_fov> must be within (0, pi) radians, got {}", *v));
        return;
      }
      hfov = *v;
    }
    if (xml::XmlElement image = c.Child("image")) {
      CheckChildren(image, {"width", "height", "format", "anti_aliasing"});
      auto w = PixelsOr(*this, image, "width", width);
      auto h = PixelsOr(*this, image, "height", height);
      if (!w || !h) return;
      width = *w;
      height = *h;
    }
    if (xml::XmlElement pose = c.Child("pose")) {
      if (ir::NameRef ref = RelativeTo(pose); !ref.empty()) {
        diags().Report(DiagKind::UnsupportedAttribute, ref.loc,
                       "relative_to on a <camera> pose is not supported: the pose is relative to "
                       "the sensor");
      }
      X_SC = ReadPoseValue(pose);
    }
  }
  camera.width = width;
  camera.height = height;
  camera.fov_y = 2 * std::atan(std::tan(hfov / 2) * height / width);
  const CameraId id = module().Add(std::move(camera));
  const FrameNodeId node = AddAnchor(s, e.Child("pose"), link_name, link_node, e.GetLoc(),
                                     ir::FrameTarget::Camera, id.value);
  if (!X_SC.IsIdentity()) graph()[node].X_RN = graph()[node].X_RN * X_SC;
}

}  // namespace mdlc::frontend::sdf
