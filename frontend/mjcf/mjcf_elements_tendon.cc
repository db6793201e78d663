// mjcf_elements_tendon.cc - <tendon> (BEYOND-005, MJCF-008).
//
// A fixed tendon's length is L(q) = sum coef_i q_i over its joints. Drake's
// tendon constraint keeps l(q) = a.q + offset within [lower, upper], rigidly
// (stiffness infinite) or through a spring-damper that acts outside the
// bounds. A MuJoCo fixed tendon lowers to up to two such constraints:
//   - range (when limited, MJCF-004 rules): lower/upper, rigid; MuJoCo's
//     soft-limit settings (solreflimit, solimplimit, margin) are ignored;
//   - stiffness > 0: MuJoCo's tendon spring, force -k (L - L0) - b dL/dt,
//     which is a constraint with lower = upper = L0 and that stiffness and
//     damping; MuJoCo 3's dead-band springlength "lo hi" is lower = lo,
//     upper = hi. When springlength is not given, L0 is the length at
//     MuJoCo's qpos_spring (each joint's springref, which the frontend keeps
//     in joint springs; 0 otherwise).
// Damping without stiffness (a pure damper) has no plant equivalent: W.
// Spatial tendons route through sites and geoms and the plant has nothing
// for them: W once. Visual attributes (width, material, rgba) are ignored
// silently, like solver settings.
#include <fmt/format.h>

#include "frontend/mjcf/mjcf_elements.h"

namespace mdlc::frontend::mjcf {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// the joint's spring reference (qpos_spring), where a joint spring keeps it
double SpringReference(const ir::Module& m, JointId joint) {
  for (const ir::ForceElement& f : m.force_elements) {
    const auto* spring = std::get_if<ir::JointSpring>(&f.payload);
    if (!spring) continue;
    if (spring->joint.resolved() ? spring->joint.id == joint
                                 : spring->joint.name == m[joint].name) {
      return spring->nominal;
    }
  }
  return 0;
}

void LowerFixed(ElementsLowering& L, const Element& e) {
  const xml::XmlElement& x = e.xml();
  L.r.attrs.WarnUnknownAttributes(
      x, {"name", "class", "group", "limited", "actuatorfrclimited", "range", "actuatorfrcrange",
          "solreflimit", "solimplimit", "solreffriction", "solimpfriction", "frictionloss",
          "springlength", "margin", "stiffness", "damping", "armature", "user", "width",
          "material", "rgba"});
  for (const char* attr : {"group", "actuatorfrclimited", "actuatorfrcrange", "user"}) {
    L.WarnAttribute(e, "tendon", attr);
  }
  for (const char* attr : {"frictionloss", "armature"}) {
    if (auto v = L.Double(e.Get(attr)); v && *v != 0) L.WarnAttribute(e, "tendon", attr);
  }

  // the path: <joint joint coef>
  std::vector<ir::Ref<JointId>> joints;
  std::vector<double> coefs;
  bool ok = true;
  for (const xml::XmlElement& j : L.r.Children(x)) {
    if (j.Name() != "joint") {
      L.diags().Report(DiagKind::BadValue, j.GetLoc(),
                       fmt::format("a fixed tendon's path holds <joint> elements only, not <{}>",
                                   j.Name()));
      ok = false;
      continue;
    }
    L.r.attrs.WarnUnknownAttributes(j, {"joint", "coef"});
    const Attribute name = j.Attribute("joint"), coef = j.Attribute("coef");
    if (!name.present() || !coef.present()) {
      L.diags().Report(DiagKind::MissingAttribute, j.GetLoc(),
                       "a fixed tendon's <joint> needs the attributes 'joint' and 'coef'");
      ok = false;
      continue;
    }
    std::optional<JointId> id = L.FindJoint(name, "joint");
    std::optional<double> c = L.Double(coef);
    if (!id || !c) {
      ok = false;
      continue;
    }
    joints.push_back(L.JointRef(*id, name.loc));
    coefs.push_back(*c);
  }
  if (ok && joints.empty()) {
    L.diags().Report(DiagKind::MissingElement, e.loc(),
                     "tendon path cannot be empty: a fixed tendon needs at least one <joint>");
    return;
  }

  const Attribute range_attr = e.Get("range");
  const bool limited = L.IsLimited(e.Get("limited"), range_attr);
  std::optional<std::vector<double>> range = L.Doubles(range_attr, 2);
  std::optional<double> stiffness = L.Double(e.Get("stiffness"));
  std::optional<double> damping = L.Double(e.Get("damping"));
  std::optional<std::vector<double>> springlength =
      L.Doubles(e.Get("springlength"), 2, /*at_most=*/true);
  if (!ok) return;

  auto add = [&](double lower, double upper, double k, double b) {
    ir::TendonConstraint tendon;
    tendon.joints = joints;
    tendon.a = coefs;
    tendon.offset = 0;
    tendon.lower = lower;
    tendon.upper = upper;
    tendon.stiffness = k;
    tendon.damping = b;
    L.module().Add(ir::Constraint{L.r.model, e.loc(), std::move(tendon)});
  };

  if (limited && range) {
    if ((*range)[0] >= (*range)[1]) {
      L.diags().Report(DiagKind::BadValue, range_attr.loc,
                       fmt::format("invalid limits in tendon: range {} {} is empty",
                                   (*range)[0], (*range)[1]));
    } else {
      add((*range)[0], (*range)[1], kInf, 0);
    }
  }

  const double k = stiffness.value_or(0), b = damping.value_or(0);
  if (k < 0 || b < 0) {
    L.diags().Report(DiagKind::BadValue, e.loc(),
                     "tendon stiffness and damping must not be negative");
    return;
  }
  if (k > 0) {
    double lo = 0, hi = 0;
    if (springlength && !((*springlength)[0] == -1 &&
                          (springlength->size() == 1 || (*springlength)[1] == -1))) {
      lo = (*springlength)[0];
      hi = springlength->size() == 2 ? (*springlength)[1] : lo;
    } else {
      for (size_t i = 0; i < joints.size(); ++i) {
        lo += coefs[i] * SpringReference(L.module(), joints[i].id);
      }
      hi = lo;
    }
    if (lo > hi) {
      L.diags().Report(DiagKind::BadValue, e.Get("springlength").loc,
                       "invalid springlength in tendon: the first value exceeds the second");
      return;
    }
    add(lo, hi, k, b);
  } else if (b > 0) {
    L.WarnOnce("tendon/damper", DiagKind::UnsupportedAttribute, e.Get("damping").loc,
               "tendon damping without stiffness (a pure damper) has no plant equivalent and "
               "is ignored");
  }
}

}  // namespace

void LowerTendons(ElementsLowering& L, const xml::XmlElement& section) {
  for (const xml::XmlElement& child : L.r.Children(section)) {
    const std::string_view tag = child.Name();
    if (tag == "fixed") {
      LowerFixed(L, L.r.Resolve(child, "tendon", ""));
    } else if (tag == "spatial") {
      L.r.LeaveOut(child.GetLoc(), "spatial tendon <spatial>",
                   "the plant holds fixed tendons only, and a spatial tendon's length follows "
                   "a path through sites and wrapping geoms");
    } else {
      L.WarnOnce(fmt::format("tendon-unknown/{}", tag), DiagKind::UnknownElement,
                 child.GetLoc(), fmt::format("unknown element <{}> in <tendon> is ignored", tag));
    }
  }
}

}  // namespace mdlc::frontend::mjcf
