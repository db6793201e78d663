// urdf_geometry_properties.cc - drake: children of <collision> and <visual>
// (EXT-020, EXT-021, EXT-030, EXT-031, EXT-033, URDF-033).
//
// Collision: <drake:proximity_properties> becomes `material/...` and
// `hydroelastic/...` properties; the legacy <drake_compliance> gives the
// friction when <drake:proximity_properties> does not. Visual:
// <drake:illustration_properties enabled> / <drake:perception_properties
// enabled> choose the roles, <drake:accepting_renderer name> lists renderers
// for the perception role, and a material's texture becomes
// `phong/diffuse_map`. As in Drake, only the first element of each name
// counts; later ones are reported and ignored.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {

constexpr std::string_view kProximityTag = "drake:proximity_properties";
constexpr std::string_view kAcceptingTag = "drake:accepting_renderer";

/// The first child of `e`'s parent with `e`'s name, when that is not `e`.
xml::XmlElement EarlierNamesake(const xml::XmlElement& e) {
  xml::XmlElement first = e.Parent().Child(e.Name());
  return first.raw() == e.raw() ? xml::XmlElement() : first;
}

/// Reports `e` as a repeat of `first` that is ignored.
void ReportRepeated(DiagnosticEngine& diags, const xml::XmlElement& e,
                    const xml::XmlElement& first) {
  diags
      .Report(DiagKind::UnsupportedElement, e.GetLoc(),
              fmt::format("<{}> is given more than once in <{}>; only the first one is used, "
                          "this one is ignored",
                          e.Name(), e.Parent().Name()))
      .Note(first.GetLoc(), fmt::format("the first <{}> is here", e.Name()));
}

bool IsBlank(std::string_view s) {
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; });
}

ir::Property* FindProperty(ir::Geometry& g, std::string_view key) {
  auto it = std::find_if(g.properties.begin(), g.properties.end(),
                         [&](const ir::Property& p) { return p.key == key; });
  return it == g.properties.end() ? nullptr : &*it;
}

/// A value read from a file: the number and where it was written.
struct Located {
  double value = 0;
  Loc loc;
};

/// Drake's CoulombFriction rules: both coefficients non-negative, dynamic
/// at most static. Returns [static, dynamic], or nullopt after reporting.
std::optional<std::vector<double>> Friction(DiagnosticEngine& diags, const Located& mu_static,
                                            const Located& mu_dynamic) {
  bool ok = true;
  auto non_negative = [&](const Located& mu, std::string_view name) {
    if (mu.value >= 0) return;
    diags.Report(DiagKind::BadValue, mu.loc,
                 fmt::format("the {} friction coefficient must not be negative, got {}", name,
                             mu.value));
    ok = false;
  };
  non_negative(mu_static, "static");
  if (mu_dynamic.loc != mu_static.loc) non_negative(mu_dynamic, "dynamic");
  if (ok && mu_dynamic.value > mu_static.value) {
    diags
        .Report(DiagKind::BadValue, mu_dynamic.loc,
                fmt::format("the dynamic friction coefficient ({}) is greater than the static "
                            "one ({}); dynamic friction must be less than or equal to static "
                            "friction",
                            mu_dynamic.value, mu_static.value))
        .Note(mu_static.loc, "the static friction coefficient is given here");
    ok = false;
  }
  if (!ok) return std::nullopt;
  return std::vector<double>{mu_static.value, mu_dynamic.value};
}

// <drake:proximity_properties> children that carry a number in @value, with
// the range each must be in and the property it becomes, in Drake's order
// of properties.
enum ValueTag {
  kResolutionHint,
  kModulus,
  kDissipation,
  kStiffness,
  kMuDynamic,
  kMuStatic,
  kRelaxationTime,
  kMargin,
  kValueTagCount
};
struct ValueTagInfo {
  std::string_view tag;
  bool zero_allowed;      // else the value must be positive; never negative
  std::string_view what;  // for messages
  std::string_view key;   // the property; empty for friction (two tags, one key)
};
constexpr std::array<ValueTagInfo, kValueTagCount> kValueTags = {{
    {"drake:mesh_resolution_hint", false, "mesh resolution hint", "hydroelastic/resolution_hint"},
    {"drake:hydroelastic_modulus", false, "hydroelastic modulus",
     "hydroelastic/hydroelastic_modulus"},
    {"drake:hunt_crossley_dissipation", true, "Hunt-Crossley dissipation",
     "material/hunt_crossley_dissipation"},
    {"drake:point_contact_stiffness", false, "point contact stiffness",
     "material/point_contact_stiffness"},
    {"drake:mu_dynamic", true, "dynamic friction coefficient", ""},
    {"drake:mu_static", true, "static friction coefficient", ""},
    {"drake:relaxation_time", true, "relaxation time", "material/relaxation_time"},
    {"drake:hydroelastic_margin", true, "hydroelastic margin", "hydroelastic/margin"},
}};

/// EXT-020: the children of one <drake:proximity_properties>. Each problem
/// is reported in document order; the properties are added in Drake's order.
void ReadProximityProperties(const xml::XmlElement& e, ir::Geometry& g,
                             xml::AttributeReader& attrs, DiagnosticEngine& diags) {
  attrs.WarnUnknownAttributes(e, {});
  // Drake reads the first of each, wherever it is
  const xml::XmlElement rigid = e.Child("drake:rigid_hydroelastic");
  const xml::XmlElement compliant = e.Child("drake:compliant_hydroelastic");
  std::array<xml::XmlElement, kValueTagCount> elements;
  std::array<std::optional<Located>, kValueTagCount> values;  // each one in range
  bool friction_ok = true;
  bool marker_seen = false;  // a first rigid or compliant marker
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view tag = c.Name();
    if (tag == "drake:soft_hydroelastic") {
      diags.Report(DiagKind::BadValue, c.GetLoc(),
                   "<drake:soft_hydroelastic> is no longer supported; use "
                   "<drake:compliant_hydroelastic>");
      continue;
    }
    if (tag == "drake:rigid_hydroelastic" || tag == "drake:compliant_hydroelastic") {
      const xml::XmlElement& first = tag == "drake:rigid_hydroelastic" ? rigid : compliant;
      if (first.raw() != c.raw()) {
        ReportRepeated(diags, c, first);
        continue;
      }
      attrs.WarnUnknownAttributes(c, {});
      if (marker_seen) {
        // the other one came first
        const xml::XmlElement& other = tag == "drake:rigid_hydroelastic" ? compliant : rigid;
        diags
            .Report(DiagKind::BadValue, c.GetLoc(),
                    "<drake:rigid_hydroelastic> and <drake:compliant_hydroelastic> are mutually "
                    "exclusive; only one can be given")
            .Note(other.GetLoc(), fmt::format("<{}> is given here", other.Name()));
      }
      marker_seen = true;
      continue;
    }
    const auto* info = std::find_if(kValueTags.begin(), kValueTags.end(),
                                    [&](const ValueTagInfo& t) { return t.tag == tag; });
    if (info == kValueTags.end()) {
      diags.Report(DiagKind::UnknownElement, c.GetLoc(),
                   fmt::format("unknown element <{}> in <{}> is ignored", tag, kProximityTag));
      continue;
    }
    const auto i = static_cast<size_t>(info - kValueTags.begin());
    if (elements[i]) {
      ReportRepeated(diags, c, elements[i]);
      continue;
    }
    elements[i] = c;
    attrs.WarnUnknownAttributes(c, {"value"});
    auto v = attrs.Double(c, "value", xml::Need::Required);
    if (!v) {
      if (i == kMuDynamic || i == kMuStatic) friction_ok = false;
      continue;
    }
    const Loc loc = c.Attribute("value").loc;
    if (i == kModulus && rigid && !compliant) {
      // Drake warns and drops it, whatever the value
      diags
          .Report(DiagKind::UnsupportedElement, c.GetLoc(),
                  fmt::format("<drake:hydroelastic_modulus> is ignored on a rigid hydroelastic "
                              "geometry (<drake:rigid_hydroelastic>); the value {} is not used",
                              *v))
          .Note(rigid.GetLoc(), "the geometry is declared rigid here");
      continue;
    }
    if (info->zero_allowed ? !(*v >= 0) : !(*v > 0)) {
      diags.Report(DiagKind::BadValue, loc,
                   info->key.empty()
                       ? fmt::format("the {} must not be negative, got {}", info->what, *v)
                       : fmt::format("the {} given by <{}> must be {}, got {}", info->what, tag,
                                     info->zero_allowed ? "non-negative" : "positive", *v));
      if (i == kMuDynamic || i == kMuStatic) friction_ok = false;
      continue;
    }
    values[i] = Located{*v, loc};
  }

  if (rigid && !compliant) {
    g.properties.push_back({"hydroelastic/compliance_type", std::string("rigid")});
  } else if (compliant && !rigid) {
    g.properties.push_back({"hydroelastic/compliance_type", std::string("compliant")});
  }
  for (size_t i = 0; i < kValueTagCount; ++i) {
    if (i == kMuDynamic) {
      // EXT-021: one coefficient alone gives both; dynamic may not exceed static
      const auto& mu_static = values[kMuStatic];
      const auto& mu_dynamic = values[kMuDynamic];
      if (!friction_ok || !(mu_static || mu_dynamic)) continue;
      if (auto friction = Friction(diags, mu_static ? *mu_static : *mu_dynamic,
                                   mu_dynamic ? *mu_dynamic : *mu_static)) {
        g.properties.push_back({"material/coulomb_friction", std::move(*friction)});
      }
    } else if (values[i] && !kValueTags[i].key.empty()) {
      g.properties.push_back({std::string(kValueTags[i].key), values[i]->value});
    }
  }
}

/// URDF-033: the legacy <drake_compliance>: friction from <static_friction>
/// and <dynamic_friction> (text), both required, unless
/// <drake:proximity_properties> gives a friction (EXT-021).
void ReadDrakeCompliance(const xml::XmlElement& e, ir::Geometry& g, xml::AttributeReader& attrs,
                         DiagnosticEngine& diags) {
  attrs.WarnUnknownAttributes(e, {});
  if (auto proximity = e.Parent().Child(kProximityTag);
      proximity && (proximity.Child("drake:mu_dynamic") || proximity.Child("drake:mu_static"))) {
    diags
        .Report(DiagKind::UnsupportedElement, e.GetLoc(),
                "<drake_compliance> is ignored: the friction comes from "
                "<drake:proximity_properties>; consider removing <drake_compliance>")
        .Note(proximity.GetLoc(), "<drake:proximity_properties> is here");
    return;
  }
  xml::XmlElement static_element, dynamic_element;
  std::optional<Located> mu_static, mu_dynamic;
  bool bad = false;
  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    const std::string_view tag = c.Name();
    if (tag == "youngs_modulus" || tag == "dissipation") {
      diags.Report(DiagKind::UnsupportedElement, c.GetLoc(),
                   fmt::format("tag '{}' found as a child of 'drake_compliance' is currently "
                               "unsupported and will be ignored",
                               tag));
      continue;
    }
    if (tag != "static_friction" && tag != "dynamic_friction") {
      diags.Report(DiagKind::UnknownElement, c.GetLoc(),
                   fmt::format("unknown element <{}> in <drake_compliance> is ignored", tag));
      continue;
    }
    const bool is_static = tag == "static_friction";
    xml::XmlElement& slot = is_static ? static_element : dynamic_element;
    if (slot) {
      ReportRepeated(diags, c, slot);
      continue;
    }
    slot = c;
    attrs.WarnUnknownAttributes(c, {});
    const std::string text = c.Text();
    auto value = xml::ParseDouble(text);
    if (!value) {
      diags.Report(DiagKind::BadValue, c.GetLoc(),
                   fmt::format("<{}> must hold a number, got '{}'", tag, text));
      bad = true;
    } else if (!std::isfinite(*value)) {
      diags.Report(DiagKind::NonFinite, c.GetLoc(),
                   fmt::format("<{}> must be finite, got '{}'", tag, text));
      bad = true;
    } else {
      (is_static ? mu_static : mu_dynamic) = Located{*value, c.GetLoc()};
    }
  }
  if (!static_element && !dynamic_element) return;
  if (!static_element || !dynamic_element) {
    diags.Report(DiagKind::MissingElement, e.GetLoc(),
                 fmt::format("<drake_compliance> gives <{}> without <{}>: when specifying the "
                             "coefficient of friction, both static and dynamic coefficients "
                             "must be defined",
                             static_element ? "static_friction" : "dynamic_friction",
                             static_element ? "dynamic_friction" : "static_friction"));
    return;
  }
  if (bad || !mu_static || !mu_dynamic) return;
  if (auto friction = Friction(diags, *mu_static, *mu_dynamic)) {
    g.properties.push_back({"material/coulomb_friction", std::move(*friction)});
  }
}

}  // namespace

bool UrdfReader::ReadCollisionExtension(const xml::XmlElement& child, ir::Geometry& geometry) {
  const std::string_view tag = child.Name();
  if (tag != kProximityTag && tag != "drake_compliance") return false;
  if (auto first = EarlierNamesake(child)) {
    ReportRepeated(diags(), child, first);
  } else if (tag == kProximityTag) {
    ReadProximityProperties(child, geometry, attrs_, diags());
  } else {
    ReadDrakeCompliance(child, geometry, attrs_, diags());
  }
  return true;
}

bool UrdfReader::ReadVisualExtension(const xml::XmlElement& child, ir::Geometry& geometry) {
  const std::string_view tag = child.Name();
  if (tag == "drake:illustration_properties" || tag == "drake:perception_properties") {
    // EXT-030: enabled="false" takes the role away; absent or "true" keeps it
    if (auto first = EarlierNamesake(child)) {
      ReportRepeated(diags(), child, first);
      return true;
    }
    attrs_.WarnUnknownAttributes(child, {"enabled"});
    for (auto c = child.FirstChild(); c; c = c.NextSibling()) {
      diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                     fmt::format("unknown element <{}> in <{}> is ignored", c.Name(), tag));
    }
    const uint8_t role =
        tag == "drake:illustration_properties" ? ir::kIllustrationRole : ir::kPerceptionRole;
    if (auto enabled = child.Attribute("enabled"); enabled.present()) {
      if (enabled.value == "true") {
        geometry.roles |= role;
      } else if (enabled.value == "false") {
        geometry.roles &= static_cast<uint8_t>(~role);
      } else {
        diags().Report(DiagKind::BadValue, enabled.loc,
                       fmt::format("invalid value '{}' for attribute 'enabled' of <{}>: expected "
                                   "'true' or 'false'",
                                   enabled.value, tag));
      }
    }
    return true;
  }
  if (tag == kAcceptingTag) {
    // EXT-031: one renderer name per element, collected into a sorted set
    attrs_.WarnUnknownAttributes(child, {"name"});
    auto name = attrs_.String(child, "name", xml::Need::Required);
    if (!name) return true;
    if (IsBlank(*name)) {
      diags().Report(DiagKind::BadValue, child.Attribute("name").loc,
                     fmt::format("<{}> has an empty 'name'; it must name a renderer",
                                 kAcceptingTag));
      return true;
    }
    ir::Property* accepting = FindProperty(geometry, "renderer/accepting");
    if (!accepting) {
      geometry.properties.push_back({"renderer/accepting", std::vector<std::string>{}});
      accepting = &geometry.properties.back();
    }
    auto& names = std::get<std::vector<std::string>>(accepting->value);
    auto at = std::lower_bound(names.begin(), names.end(), *name);
    if (at == names.end() || *at != *name) names.insert(at, std::string(*name));
    return true;
  }
  return false;
}

bool UrdfReader::FinishVisual(const xml::XmlElement& visual, ir::Geometry& geometry) {
  const bool illustration = geometry.roles & ir::kIllustrationRole;
  const bool perception = geometry.roles & ir::kPerceptionRole;
  if (!illustration && !perception) {
    // EXT-030: a visual with no role is dropped, and its name is free again
    diags().Report(DiagKind::UnsupportedValue, visual.GetLoc(),
                   fmt::format("visual geometry '{}' in link '{}' has both its illustration and "
                               "perception properties disabled; the geometry is ignored",
                               module().Text(geometry.name), module().Text(geometry.body.name)));
    const uint8_t visual_roles = ir::kIllustrationRole | ir::kPerceptionRole;
    auto it = geometry_names_.find({geometry.body.id.value, geometry.name.value, visual_roles});
    if (it != geometry_names_.end() && it->second == 0) geometry_names_.erase(it);
    return false;
  }
  // EXT-031: renderer names belong to the perception role
  if (!perception) {
    auto it = std::find_if(geometry.properties.begin(), geometry.properties.end(),
                           [](const ir::Property& p) { return p.key == "renderer/accepting"; });
    if (it != geometry.properties.end()) {
      xml::XmlElement accepting = visual.Child(kAcceptingTag);
      diags().Report(DiagKind::UnsupportedElement, accepting ? accepting.GetLoc() : visual.GetLoc(),
                     fmt::format("<{}> is ignored: the perception role of this visual is "
                                 "disabled",
                                 kAcceptingTag));
      geometry.properties.erase(it);
    }
  }
  // EXT-033: the material's texture, written inline or on the named material
  std::string texture;
  if (auto material = visual.Child("material")) {
    if (auto t = material.Child("texture")) {
      if (auto file = t.Attribute("filename"); file.present()) texture = std::string(file.value);
    }
  }
  if (texture.empty() && geometry.material.id.valid()) {
    texture = module()[geometry.material.id].texture;
  }
  if (!texture.empty() && !FindProperty(geometry, "phong/diffuse_map")) {
    geometry.properties.push_back({"phong/diffuse_map", std::move(texture)});
  }
  return true;
}

}  // namespace mdlc::frontend::urdf
