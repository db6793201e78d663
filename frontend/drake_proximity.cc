// drake_proximity.cc - see drake_proximity.h.
#include "frontend/drake_proximity.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string_view>

#include "ir/proximity_keys.h"
#include "ir/syntax/drake_proximity_tags.h"

namespace mdlc::frontend {

/// Reports `e` as a repeat of `first` that is ignored.
void ReportRepeatedElement(DiagnosticEngine& diags, const xml::XmlElement& e,
                    const xml::XmlElement& first) {
  diags
      .Report(DiagKind::UnsupportedElement, e.GetLoc(),
              fmt::format("<{}> is given more than once in <{}>; only the first one is used, "
                          "this one is ignored",
                          e.Name(), e.Parent().Name()))
      .Note(first.GetLoc(), fmt::format("the first <{}> is here", e.Name()));
}

namespace {
constexpr std::string_view kProximityTag = syntax::kProximityPropertiesTag;
}  // namespace


/// Drake's CoulombFriction rules: both coefficients non-negative, dynamic
/// at most static. Returns [static, dynamic], or nullopt after reporting.
std::optional<std::vector<double>> CoulombFriction(DiagnosticEngine& diags, const Located& mu_static,
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

// <drake:proximity_properties> children that carry a number, with the range
// each must be in and the property it becomes, in Drake's order of
// properties: ir/syntax/drake_proximity_tags.h, which the writers share.
using syntax::kProximityValueTags;
using syntax::ProximityValueTag;
constexpr size_t kValueTagCount = syntax::kProximityValueTagCount;
using syntax::kMuDynamic;
using syntax::kMuStatic;
using syntax::kModulus;

/// EXT-020: the children of one <drake:proximity_properties>. Each problem
/// is reported in document order; the properties are added in Drake's order.
void ReadDrakeProximityProperties(const xml::XmlElement& e, ir::Geometry& g,
                                  xml::AttributeReader& attrs, DiagnosticEngine& diags,
                                  const ProximityValueReader& read_value) {
  attrs.WarnUnknownAttributes(e, {});
  // Drake reads the first of each, wherever it is
  const xml::XmlElement rigid = e.Child(syntax::kRigidHydroelasticTag);
  const xml::XmlElement compliant = e.Child(syntax::kCompliantHydroelasticTag);
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
    if (tag == syntax::kRigidHydroelasticTag || tag == syntax::kCompliantHydroelasticTag) {
      const xml::XmlElement& first = tag == syntax::kRigidHydroelasticTag ? rigid : compliant;
      if (first.raw() != c.raw()) {
        ReportRepeatedElement(diags, c, first);
        continue;
      }
      attrs.WarnUnknownAttributes(c, {});
      if (marker_seen) {
        // the other one came first
        const xml::XmlElement& other = tag == syntax::kRigidHydroelasticTag ? compliant : rigid;
        diags
            .Report(DiagKind::BadValue, c.GetLoc(),
                    "<drake:rigid_hydroelastic> and <drake:compliant_hydroelastic> are mutually "
                    "exclusive; only one can be given")
            .Note(other.GetLoc(), fmt::format("<{}> is given here", other.Name()));
      }
      marker_seen = true;
      continue;
    }
    const auto* info = std::find_if(kProximityValueTags.begin(), kProximityValueTags.end(),
                                    [&](const ProximityValueTag& t) { return t.tag == tag; });
    if (info == kProximityValueTags.end()) {
      diags.Report(DiagKind::UnknownElement, c.GetLoc(),
                   fmt::format("unknown element <{}> in <{}> is ignored", tag, kProximityTag));
      continue;
    }
    const auto i = static_cast<size_t>(info - kProximityValueTags.begin());
    if (elements[i]) {
      ReportRepeatedElement(diags, c, elements[i]);
      continue;
    }
    elements[i] = c;
    const std::optional<Located> read = read_value(c);
    if (!read) {
      if (i == kMuDynamic || i == kMuStatic) friction_ok = false;
      continue;
    }
    const std::optional<double> v = read->value;
    const Loc loc = read->loc;
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
    g.properties.push_back({std::string(ir::kComplianceTypeKey), std::string("rigid")});
  } else if (compliant && !rigid) {
    g.properties.push_back({std::string(ir::kComplianceTypeKey), std::string("compliant")});
  }
  for (size_t i = 0; i < kValueTagCount; ++i) {
    if (i == kMuDynamic) {
      // EXT-021: one coefficient alone gives both; dynamic may not exceed static
      const auto& mu_static = values[kMuStatic];
      const auto& mu_dynamic = values[kMuDynamic];
      if (!friction_ok || !(mu_static || mu_dynamic)) continue;
      if (auto friction = CoulombFriction(diags, mu_static ? *mu_static : *mu_dynamic,
                                   mu_dynamic ? *mu_dynamic : *mu_static)) {
        g.properties.push_back({std::string(ir::kCoulombFrictionKey), std::move(*friction)});
      }
    } else if (values[i] && !kProximityValueTags[i].key.empty()) {
      g.properties.push_back({std::string(kProximityValueTags[i].key), values[i]->value});
    }
  }
}

}  // namespace mdlc::frontend
