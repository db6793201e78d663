// mjcf_elements.cc - phase 3b of the MJCF reader: the model elements that
// refer to the kinematic tree (<equality>, <tendon>, <actuator>, <contact>,
// <keyframe>), and the value, lookup and warning helpers they share.
//
// Kinds are lowered in this order, each kind over every section of the
// merged document in document order: equality, tendon, actuator, contact,
// then keyframes last, because a keyframe changes the joints' default
// positions and the constraints above are set up at MuJoCo's qpos0.
#include <fmt/format.h>

#include <cmath>

#include "frontend/mjcf/mjcf_elements.h"
#include "frontend/xml/attribute_reader.h"

namespace mdlc::frontend::mjcf {

namespace {

void WarnUnreflectedArmature(MjcfReader& r) {
  // MJCF-024: the plant holds armature only as an actuator's rotor inertia,
  // as Drake's does; a joint no actuator drives (a finger moved through a
  // tendon) has it only where mdlc computes gains from MuJoCo's inertia at
  // qpos0 (BEYOND-007, BEYOND-008), not in the mass matrix, whose diagonal
  // MuJoCo adds it to
  for (const JointId id : r.joint_order) {
    const auto it = r.joint_armature.find(id.value);
    if (it == r.joint_armature.end() || it->second.reflected || it->second.value == 0) continue;
    r.diags().Report(
        DiagKind::UnsupportedAttribute, it->second.loc,
        fmt::format("armature {} of joint '{}' is left out of the mass matrix: the plant holds "
                    "armature only as the rotor inertia of an actuator on the joint, as Drake's "
                    "does, and no actuator drives it (MuJoCo adds it to the mass matrix)",
                    it->second.value, r.module().Text(r.module()[id].name)));
  }
}

}  // namespace

void LowerModelElements(MjcfReader& reader, const std::vector<xml::XmlElement>& top_level) {
  ElementsLowering L(reader);
  std::vector<xml::XmlElement> keyframes;
  for (const char* kind : {"equality", "tendon", "actuator", "contact"}) {
    for (const xml::XmlElement& e : top_level) {
      if (e.Name() != kind) continue;
      if (e.Name() == "equality") LowerEquality(L, e);
      if (e.Name() == "tendon") LowerTendons(L, e);
      if (e.Name() == "actuator") LowerActuators(L, e);
      if (e.Name() == "contact") LowerContact(L, e);
    }
  }
  for (const xml::XmlElement& e : top_level) {
    if (e.Name() == "keyframe") keyframes.push_back(e);
  }
  if (!keyframes.empty() || !reader.attached_keys.empty()) LowerKeyframes(L, keyframes);
  WarnUnreflectedArmature(reader);
}


// --- values ------------------------------------------------------------------

std::optional<double> ElementsLowering::Double(const Attribute& a) {
  if (!a.present()) return std::nullopt;
  std::optional<double> v = xml::ParseDouble(a.value);
  if (!v || !std::isfinite(*v)) {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("attribute '{}' must be a finite number, not '{}'", a.name,
                               a.value));
    return std::nullopt;
  }
  return v;
}

std::optional<std::vector<double>> ElementsLowering::Doubles(const Attribute& a, size_t n,
                                                             bool at_most) {
  std::optional<std::vector<double>> v = AnyDoubles(a);
  if (!v) return std::nullopt;
  const bool count_ok = at_most ? (!v->empty() && v->size() <= n) : v->size() == n;
  if (!count_ok) {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("attribute '{}' needs {}{} number{}, got {}", a.name,
                               at_most ? "1 to " : "", n, n == 1 ? "" : "s", v->size()));
    return std::nullopt;
  }
  return v;
}

std::optional<std::vector<double>> ElementsLowering::AnyDoubles(const Attribute& a) {
  if (!a.present()) return std::nullopt;
  std::optional<std::vector<double>> v = xml::ParseDoubleList(a.value);
  bool finite = v.has_value();
  if (v) {
    for (double x : *v) finite = finite && std::isfinite(x);
  }
  if (!finite) {
    diags().Report(DiagKind::BadValue, a.loc,
                   fmt::format("attribute '{}' must be a list of finite numbers, not '{}'",
                               a.name, a.value));
    return std::nullopt;
  }
  return v;
}

std::optional<bool> ElementsLowering::Bool(const Attribute& a) {
  if (!a.present()) return std::nullopt;
  if (a.value == "true") return true;
  if (a.value == "false") return false;
  diags().Report(DiagKind::BadValue, a.loc,
                 fmt::format("attribute '{}' must be 'true' or 'false', not '{}'", a.name,
                             a.value));
  return std::nullopt;
}

std::optional<Limited> ElementsLowering::LimitedValue(const Attribute& a) {
  if (!a.present() || a.value == "auto") return Limited::Auto;
  if (a.value == "true") return Limited::True;
  if (a.value == "false") return Limited::False;
  diags().Report(DiagKind::BadValue, a.loc,
                 fmt::format("attribute '{}' must be 'true', 'false' or 'auto', not '{}'",
                             a.name, a.value));
  return std::nullopt;
}

bool ElementsLowering::IsLimited(const Attribute& limited, const Attribute& range) {
  std::optional<Limited> l = LimitedValue(limited);
  if (!l) return false;
  if (*l != Limited::Auto) return *l == Limited::True;
  // auto: MuJoCo limits iff a range is written (and is not "0 0", its unset value)
  auto values = xml::ParseDoubleList(range.value);
  const bool has_range = range.present() && values && values->size() == 2 &&
                         ((*values)[0] != 0 || (*values)[1] != 0);
  if (!has_range) return false;
  if (!r.compiler.autolimits) {
    // ctrlrange -> ctrllimited, range -> limited
    const std::string limited_name =
        std::string(range.name.substr(0, range.name.size() - 5)) + "limited";
    diags().Report(DiagKind::BadValue, range.loc,
                   fmt::format("attribute '{}' sets no limit while <compiler autolimits> is "
                               "false; give '{}' as well",
                               range.name, limited_name));
    return false;
  }
  return true;
}

// --- lookups -----------------------------------------------------------------

namespace {

template <typename Id>
std::optional<Id> Find(ElementsLowering& L, const MjcfReader::ByName<Id>& table,
                       const Attribute& a, std::string_view element, std::string_view what) {
  if (auto id = table.Find(L.module().symbols, a.value)) return id;
  L.diags().Report(DiagKind::UnknownReference, a.loc,
                   fmt::format("<{}> {}=\"{}\" names no {} of that name", element, a.name,
                               a.value, what));
  return std::nullopt;
}

}  // namespace

std::optional<BodyId> ElementsLowering::FindBody(const Attribute& a, std::string_view element) {
  if (a.value == "world") return ir::kWorldBody;
  return Find(*this, r.bodies, a, element, "body");
}

std::optional<JointId> ElementsLowering::FindJoint(const Attribute& a, std::string_view element) {
  return Find(*this, r.joints, a, element, "joint");
}

std::optional<FrameId> ElementsLowering::FindSite(const Attribute& a, std::string_view element) {
  return Find(*this, r.sites, a, element, "site");
}

std::optional<GeometryId> ElementsLowering::FindGeom(const Attribute& a,
                                                     std::string_view element) {
  return Find(*this, r.geoms, a, element, "geom");
}

std::optional<BodyId> ElementsLowering::BodyOf(const ir::Ref<BodyId>& ref) const {
  if (ref.resolved()) return ref.id;
  const std::string_view name = r.ctx.module.Text(ref.name);
  if (name == "world") return ir::kWorldBody;
  if (auto id = r.bodies.Find(r.ctx.module.symbols, name)) return id;
  // a body the frontend created itself (a stacked-joint body) by its IR name
  for (size_t i = 0; i < r.ctx.module.bodies.size(); ++i) {
    const ir::Body& b = r.ctx.module.bodies[i];
    if (b.model == r.model && b.name == ref.name) return BodyId(i);
  }
  return std::nullopt;
}

ir::Ref<BodyId> ElementsLowering::BodyRef(BodyId id, Loc loc) {
  const Symbol name = id == ir::kWorldBody ? module().Intern("world") : module()[id].name;
  return {name, loc, id};
}

ir::Ref<JointId> ElementsLowering::JointRef(JointId id, Loc loc) {
  return {module()[id].name, loc, id};
}

// --- warnings ----------------------------------------------------------------

void ElementsLowering::WarnOnce(std::string_view key, DiagKind kind, Loc loc,
                                std::string message) {
  if (!warned_.emplace(key).second) return;
  diags().Report(kind, loc, std::move(message));
}

void ElementsLowering::WarnAttribute(const Element& e, std::string_view kind,
                                     std::string_view attr, std::string_view why) {
  const Attribute a = e.Get(attr);
  if (!a.present()) return;
  WarnOnce(fmt::format("attr:{}/{}", kind, attr), DiagKind::UnsupportedAttribute, a.loc,
           fmt::format("attribute '{}' of <{}> is not supported and is ignored{}{}",
                       attr, e.xml().Name(), why.empty() ? "" : ": ", why));
}

}  // namespace mdlc::frontend::mjcf
