// drake_out.cc - see drake_out.h.
#include "backend/writers/drake_out.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <variant>
#include <vector>

#include "ir/proximity_keys.h"

namespace mdlc::writers {

void DrakeValue(XmlOut& out, syntax::ValueSpelling spelling, std::string_view tag, double v) {
  if (spelling == syntax::ValueSpelling::Attribute) {
    out.Open(tag).Attr("value", v).Close();
  } else {
    out.Open(tag).Text(NumberText(v)).Close();
  }
}

void DrakeValue(XmlOut& out, syntax::ValueSpelling spelling, std::string_view tag,
                const Eigen::Vector3d& v) {
  if (spelling == syntax::ValueSpelling::Attribute) {
    out.Open(tag).Attr("value", v).Close();
  } else {
    out.Open(tag).Text(VectorText(v)).Close();
  }
}

void WriteProximityProperties(XmlOut& out, syntax::ValueSpelling spelling, std::string_view format,
                              const backend::SceneGeometry& g, Loc loc, DiagnosticEngine& diags) {
  bool open = false;
  auto open_once = [&] {
    if (!open) out.Open(syntax::kProximityPropertiesTag);
    open = true;
  };
  for (const ir::Property& p : g.properties) {
    if (p.key.starts_with("phong/") || p.key.starts_with("renderer/") ||
        p.key.starts_with("label/")) {
      continue;  // appearance: the visual's
    }
    const double* number = std::get_if<double>(&p.value);
    const auto* vector = std::get_if<std::vector<double>>(&p.value);
    const auto* text = std::get_if<std::string>(&p.value);
    const auto child = std::find_if(
        syntax::kProximityValueTags.begin(), syntax::kProximityValueTags.end(),
        [&](const syntax::ProximityValueTag& t) { return !t.key.empty() && t.key == p.key; });
    if (child != syntax::kProximityValueTags.end() && number) {
      open_once();
      DrakeValue(out, spelling, child->tag, *number);
    } else if (p.key == ir::kCoulombFrictionKey && vector && vector->size() == 2) {
      open_once();
      DrakeValue(out, spelling, syntax::kProximityValueTags[syntax::kMuStatic].tag, (*vector)[0]);
      DrakeValue(out, spelling, syntax::kProximityValueTags[syntax::kMuDynamic].tag, (*vector)[1]);
    } else if (p.key == ir::kComplianceTypeKey && text &&
               (*text == "rigid" || *text == "compliant")) {
      open_once();
      out.Open(*text == "rigid" ? syntax::kRigidHydroelasticTag : syntax::kCompliantHydroelasticTag)
          .Close();
    } else {
      diags.Report(DiagKind::Lossy, loc,
                   fmt::format("proximity property '{}' of geometry '{}' has no {} spelling; it "
                               "is dropped",
                               p.key, g.name, format));
    }
  }
  if (open) out.Close();
}

}  // namespace mdlc::writers
