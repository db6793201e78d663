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

#include "frontend/drake_proximity.h"
#include "frontend/urdf/urdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::urdf {
namespace {

constexpr std::string_view kProximityTag = "drake:proximity_properties";
constexpr std::string_view kAcceptingTag = "drake:accepting_renderer";

/// The first child of `e`'s parent with `e`'s name, when that is not `e`.
xml::XmlElement EarlierNamesake(const xml::XmlElement& e) {
  xml::XmlElement first = e.Parent().Child(e.Name());
  return first.raw() == e.raw() ? xml::XmlElement() : first;
}

bool IsBlank(std::string_view s) { return std::all_of(s.begin(), s.end(), xml::IsXmlSpace); }

ir::Property* FindProperty(ir::Geometry& g, std::string_view key) {
  auto it = std::find_if(g.properties.begin(), g.properties.end(),
                         [&](const ir::Property& p) { return p.key == key; });
  return it == g.properties.end() ? nullptr : &*it;
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
                   fmt::format("element <{}> in <drake_compliance> is not supported and is "
                               "ignored",
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
      ReportRepeatedElement(diags, c, slot);
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
  if (auto friction = CoulombFriction(diags, *mu_static, *mu_dynamic)) {
    g.properties.push_back({"material/coulomb_friction", std::move(*friction)});
  }
}

}  // namespace

bool UrdfReader::ReadCollisionExtension(const xml::XmlElement& child, ir::Geometry& geometry) {
  const std::string_view tag = child.Name();
  if (tag != kProximityTag && tag != "drake_compliance") return false;
  if (auto first = EarlierNamesake(child)) {
    ReportRepeatedElement(diags(), child, first);
  } else if (tag == kProximityTag) {
    ReadDrakeProximityProperties(child, geometry, attrs_, diags(),
                                 [&](const xml::XmlElement& c) -> std::optional<Located> {
                                   attrs_.WarnUnknownAttributes(c, {"value"});
                                   auto v = attrs_.Double(c, "value", xml::Need::Required);
                                   if (!v) return std::nullopt;
                                   return Located{*v, c.Attribute("value").loc};
                                 });
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
      ReportRepeatedElement(diags(), child, first);
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
