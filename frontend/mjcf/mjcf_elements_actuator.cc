// mjcf_elements_actuator.cc - <actuator> (MJCF-060, MJCF-024, BEYOND-008).
//
// Each actuator on a `joint` becomes a joint actuator:
//   - order and names as Drake's parser: per <actuator> section, every
//     <motor>, then every <position>, then (mdlc) <velocity> and <general> in
//     document order; an unnamed one is "motor<N>", N the actuators so far;
//   - gear: the first value (1 or 6 values expected, else W);
//   - effort limit (MJCF-060): a motor's is max(|ctrlrange|) when
//     ctrl-limited (Drake's rule), then the min with max(|forcerange|) when
//     force-limited; asymmetric ranges W (the larger bound is used), lower >
//     upper W (ignored). Position, velocity and PD-like general actuators
//     take forcerange only: their ctrlrange is a range of positions or
//     velocities, not of forces (Drake's parser reads a position's ctrlrange
//     as forces; mdlc differs, README); motor-like general ones scale
//     ctrlrange by their gain;
//   - rotor inertia = joint armature / gear^2 (MJCF-024; every kind here);
//   - PD gains: position kp (default 1) and kv -> kp, kd (BEYOND-008; Drake's
//     parser reads "kd", which MuJoCo does not know: read, with a W);
//     velocity kv -> kd; general with fixed gain and affine bias -> kp, kd
//     where they have the position or velocity shape. Zero gains: none.
//     A position's `dampratio`, and a position-shaped general actuator's
//     positive biasprm[2] (MuJoCo reads it as a damping ratio), set kd from
//     the joint-space inertia at qpos0: recorded as a request
//     (ir::InertiaScaledGains) that the backend computes (BEYOND-008).
// Other transmissions (tendon, site, body, ...) and the other kinds
// (intvelocity, damper, cylinder, muscle, adhesion, plugin) W once each,
// and are skipped.
// Each element reads its own kind's default class (as Drake's parser does).
#include <fmt/format.h>

#include <array>
#include <cmath>

#include "frontend/mjcf/mjcf_elements.h"
#include "frontend/original_names.h"

namespace mdlc::frontend::mjcf {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// MuJoCo 3.3's attributes common to the joint-transmission kinds
#define MDLC_MJCF_ACTUATOR_COMMON                                                           \
  "name", "class", "group", "ctrllimited", "forcelimited", "ctrlrange", "forcerange",       \
      "lengthrange", "gear", "cranklength", "user", "joint", "jointinparent", "tendon",     \
      "slidersite", "cranksite", "site", "refsite"

struct Gains {
  double kp = 0, kd = 0;
  /// > 0: kd = 2 dampratio sqrt(kp m) once the inertia m at qpos0 is known
  double dampratio = 0;
  Loc dampratio_loc;
};

class ActuatorLowering {
 public:
  ActuatorLowering(ElementsLowering& L, const Element& e) : L_(L), e_(e), x_(e.xml()) {}

  void Lower() {
    const std::string_view kind = x_.Name();
    if (kind == "motor") {
      L_.r.attrs.WarnUnknownAttributes(x_, {MDLC_MJCF_ACTUATOR_COMMON});
    } else if (kind == "position") {
      L_.r.attrs.WarnUnknownAttributes(
          x_, {MDLC_MJCF_ACTUATOR_COMMON, "inheritrange", "kp", "kv", "dampratio", "timeconst",
               "kd"});
    } else if (kind == "velocity") {
      L_.r.attrs.WarnUnknownAttributes(x_, {MDLC_MJCF_ACTUATOR_COMMON, "kv"});
    } else {
      L_.r.attrs.WarnUnknownAttributes(
          x_, {MDLC_MJCF_ACTUATOR_COMMON, "body", "actlimited", "actrange", "actdim", "dyntype",
               "gaintype", "biastype", "dynprm", "gainprm", "biasprm", "actearly"});
    }
    name_ = e_.HasOwn("name") ? std::string(x_.Attribute("name").value)
                              : fmt::format("motor{}", L_.module().actuators.size());
    std::optional<JointId> joint = Joint();
    if (!joint) return;
    for (const char* attr : {"group", "lengthrange", "cranklength", "user", "refsite"}) {
      L_.WarnAttribute(e_, kind, attr);
    }

    ir::Actuator a;
    a.name = L_.module().Intern(name_);
    a.unnamed = !e_.HasOwn("name");
    a.model = L_.r.model;
    a.loc = e_.loc();
    a.joint = L_.JointRef(*joint, e_.Get("joint").loc);
    a.gear_ratio = Gear();

    std::optional<Gains> gains;
    bool ctrl_is_force = true;  // a motor's ctrlrange is a range of forces
    double ctrl_scale = 1;
    if (kind == "position") {
      gains = Position(*joint);
      ctrl_is_force = false;  // a range of positions (Drake reads it as forces)
    } else if (kind == "velocity") {
      gains = Velocity();
      ctrl_is_force = false;
    } else if (kind == "general") {
      if (!General(gains, ctrl_is_force, ctrl_scale)) return;
    }
    if (!ok_) return;
    a.effort_limit = EffortLimit(ctrl_is_force, ctrl_scale);
    if (gains && (gains->kp != 0 || gains->kd != 0)) {
      a.kp = gains->kp;
      a.kd = gains->kd;
    }
    // BEYOND-008: a damping ratio needs kp > 0 to give a gain (MuJoCo: 2
    // dampratio sqrt(kp m) is 0 otherwise)
    const bool scaled = gains && gains->dampratio > 0 && gains->kp > 0;
    // MJCF-024: the joint's armature, reflected through the gear
    if (auto it = L_.r.joint_armature.find(joint->value); it != L_.r.joint_armature.end()) {
      it->second.reflected = true;
      if (a.gear_ratio != 0) {
        a.rotor_inertia = it->second.value / (a.gear_ratio * a.gear_ratio);
      } else if (it->second.value != 0) {
        L_.WarnValueOnce("actuator/gear0", e_.Get("gear").loc,
                         "a gear of 0 cannot reflect the joint's armature; rotor inertia 0");
      }
    }
    const ActuatorId id = L_.module().Add(std::move(a));
    ReadOriginalName(x_, id, L_.r.ctx);
    if (scaled) {
      L_.r.scaled_gains.damp_ratios.push_back({id, gains->dampratio_loc, gains->dampratio});
    }
  }

 private:
  // the driven joint; other transmissions W (once each) and skip the actuator
  std::optional<JointId> Joint() {
    const Attribute joint = e_.Get("joint");
    if (joint.present()) return L_.FindJoint(joint, x_.Name());
    for (const char* other :
         {"jointinparent", "tendon", "site", "body", "cranksite", "slidersite"}) {
      const Attribute a = e_.Get(other);
      if (!a.present()) continue;
      L_.WarnOnce(fmt::format("actuator/transmission/{}", other), DiagKind::UnsupportedAttribute,
                  a.loc,
                  fmt::format("{} '{}' acts through '{}', which mdlc does not support (only "
                              "'joint'); the actuator is ignored",
                              x_.Name(), name_, other));
      return std::nullopt;
    }
    L_.diags().Report(DiagKind::UnsupportedElement, e_.loc(),
                      fmt::format("{} '{}' names no joint to act on (mdlc supports only "
                                  "'joint'); the {} is ignored",
                                  x_.Name(), name_, x_.Name()));
    return std::nullopt;
  }

  double Gear() {
    const Attribute gear = e_.Get("gear");
    if (!gear.present()) return 1;
    std::optional<std::vector<double>> v = L_.AnyDoubles(gear);
    if (!v || v->empty()) {
      ok_ = false;
      return 1;
    }
    if (v->size() != 1 && v->size() != 6) {
      L_.diags().Report(DiagKind::ActuatorWarning, gear.loc,
                        fmt::format("attribute 'gear' has 1 or 6 values, not '{}'; its first "
                                    "is used",
                                    gear.value));
    }
    return (*v)[0];
  }

  std::optional<double> Param(const char* attr) {
    const Attribute a = e_.Get(attr);
    std::optional<double> v = L_.Double(a);
    if (a.present() && !v) ok_ = false;
    return v;
  }

  Gains Position(JointId joint) {
    Gains g;
    g.kp = Param("kp").value_or(1);
    std::optional<double> kv = Param("kv");
    const std::optional<double> kd = Param("kd");
    const std::optional<double> dampratio = Param("dampratio");
    if (kd) {
      L_.WarnOnce("position/kd", DiagKind::UnsupportedAttribute, e_.Get("kd").loc,
                  "'kd' is not a MuJoCo attribute (MuJoCo rejects it); it is read as the "
                  "derivative gain, as Drake's parser does. MuJoCo's name is 'kv'");
      if (!kv) kv = kd;
    }
    if (kv && dampratio) {
      L_.diags().Report(DiagKind::BadValue, e_.Get("dampratio").loc,
                        "kv and dampratio cannot both be defined");
      ok_ = false;
    }
    if ((kv && *kv < 0) || (dampratio && *dampratio < 0) || g.kp < 0) {
      L_.diags().Report(DiagKind::BadValue, e_.loc(),
                        "kp, kv and dampratio cannot be negative");
      ok_ = false;
    }
    g.kd = kv.value_or(0);
    if (dampratio && !kv) {
      g.dampratio = *dampratio;
      g.dampratio_loc = e_.Get("dampratio").loc;
    }
    if (auto tc = Param("timeconst"); tc && *tc != 0) {
      L_.WarnAttribute(e_, "position", "timeconst", "activation dynamics");
    }
    InheritRange(joint);
    return g;
  }

  Gains Velocity() {
    Gains g;
    g.kd = Param("kv").value_or(1);
    if (g.kd < 0) {
      L_.diags().Report(DiagKind::BadValue, e_.Get("kv").loc, "kv cannot be negative");
      ok_ = false;
    }
    return g;
  }

  // position inheritrange: ctrlrange from the joint's range, scaled about its middle
  void InheritRange(JointId joint) {
    const Attribute ir_attr = e_.Get("inheritrange");
    std::optional<double> inherit = L_.Double(ir_attr);
    if (!inherit || *inherit <= 0) return;
    if (auto cr = L_.Doubles(e_.Get("ctrlrange"), 2); cr && ((*cr)[0] != 0 || (*cr)[1] != 0)) {
      L_.diags().Report(DiagKind::BadValue, ir_attr.loc,
                        "ctrlrange and inheritrange cannot both be defined");
      ok_ = false;
      return;
    }
    const ir::JointLimits& limits = L_.module()[joint].limits;
    if (limits.lower.size() != 1 || !std::isfinite(limits.lower[0]) ||
        !std::isfinite(limits.upper[0]) || limits.lower[0] == limits.upper[0]) {
      L_.diags().Report(DiagKind::BadValue, ir_attr.loc,
                        fmt::format("inheritrange used but joint '{}' has no range defined",
                                    e_.Get("joint").value));
      ok_ = false;
      return;
    }
    const double mean = 0.5 * (limits.upper[0] + limits.lower[0]);
    const double radius = 0.5 * (limits.upper[0] - limits.lower[0]) * *inherit;
    inherited_ctrl_ = std::array<double, 2>{mean - radius, mean + radius};
  }

  // general: PD gains where gain and bias have the position or velocity shape;
  // false when the actuator is left out
  bool General(std::optional<Gains>& gains, bool& ctrl_is_force, double& ctrl_scale) {
    const Attribute dyntype = e_.Get("dyntype"), gaintype = e_.Get("gaintype"),
                    biastype = e_.Get("biastype");
    const std::string_view dyn = dyntype.present() ? dyntype.value : "none";
    const std::string_view gain = gaintype.present() ? gaintype.value : "fixed";
    const std::string_view bias = biastype.present() ? biastype.value : "none";
    if (dyn != "none") {
      L_.WarnOnce("general/dyntype", DiagKind::UnsupportedValue, dyntype.loc,
                  fmt::format("general actuator dyntype=\"{}\": activation dynamics are not "
                              "supported by the plant and are ignored",
                              dyn));
    }
    std::vector<double> gainprm(10, 0.0), biasprm(10, 0.0);
    gainprm[0] = 1;
    for (auto [attr, prm] : {std::pair{"gainprm", &gainprm}, std::pair{"biasprm", &biasprm}}) {
      const Attribute a = e_.Get(attr);
      if (!a.present()) continue;
      auto v = L_.Doubles(a, 10, /*at_most=*/true);
      if (!v) return false;
      std::copy(v->begin(), v->end(), prm->begin());
    }
    if (gain != "fixed" && gain != "affine") {
      return Unrepresentable(gaintype, fmt::format("gaintype=\"{}\"", gain));
    }
    if (bias != "none" && bias != "affine") {
      return Unrepresentable(biastype, fmt::format("biastype=\"{}\"", bias));
    }
    // an affine gain that depends on length or velocity scales the control by the state
    if (gain == "affine" && (gainprm[1] != 0 || gainprm[2] != 0)) {
      return Unrepresentable(gaintype, "a gain that depends on the joint's state");
    }
    const double g = gainprm[0];
    if (bias == "none" || (biasprm[0] == 0 && biasprm[1] == 0 && biasprm[2] == 0)) {
      // force = g * ctrl: the actuation is the force
      ctrl_scale = std::abs(g);
      if (g != 1) {
        L_.WarnValueOnce("general/gain", e_.Get("gainprm").loc,
                         "a general actuator's control gain other than 1 is not kept: the "
                         "plant's actuation input is the force itself");
      }
      return true;
    }
    ctrl_is_force = false;
    if (biasprm[0] == 0 && g == -biasprm[1] && g > 0) {
      // position servo: force = kp (ctrl - q) + biasprm[2] qdot; MuJoCo
      // reads a positive biasprm[2] as a damping ratio (BEYOND-008)
      gains.emplace();
      gains->kp = g;
      gains->kd = std::max(0.0, -biasprm[2]);
      if (biasprm[2] > 0) {
        gains->dampratio = biasprm[2];
        gains->dampratio_loc = e_.Get("biasprm").loc;
      }
      return true;
    }
    if (biasprm[0] == 0 && biasprm[1] == 0 && g == -biasprm[2] && g > 0) {
      gains.emplace();  // velocity servo: force = kv (ctrl - qdot)
      gains->kd = g;
      return true;
    }
    L_.WarnValueOnce("general/affine", e_.Get("biasprm").loc,
                     "this general actuator's gain and bias do not have the shape of a "
                     "position or velocity servo; it is added without PD gains");
    return true;
  }

  bool Unrepresentable(const Attribute& at, std::string what) {
    L_.WarnOnce(fmt::format("general/{}", what), DiagKind::UnsupportedValue, at.loc,
                fmt::format("general actuator with {} is not supported by the plant and is "
                            "ignored",
                            what));
    return false;
  }

  // one range's contribution (Drake's messages); nullopt when not limited
  std::optional<double> RangeLimit(const char* range_attr, const char* limited_attr,
                                   std::optional<std::array<double, 2>> inherited = {}) {
    const Attribute range = e_.Get(range_attr);
    std::array<double, 2> values;
    if (inherited) {
      values = *inherited;  // inheritrange: ctrlrange is set, so auto-limited
      if (auto l = L_.LimitedValue(e_.Get(limited_attr)); l && *l == Limited::False) {
        return std::nullopt;
      }
    } else {
      if (!L_.IsLimited(e_.Get(limited_attr), range)) return std::nullopt;
      auto v = L_.Doubles(range, 2);
      if (!v) {
        if (!range.present()) values = {0, 0};  // limited="true" with no range: MuJoCo's 0 0
        else return std::nullopt;
      } else {
        values = {(*v)[0], (*v)[1]};
      }
    }
    const Loc loc = range.present() ? range.loc : e_.loc();
    if (values[0] > values[1]) {
      L_.diags().Report(DiagKind::ActuatorWarning, loc,
                        fmt::format("{} '{}' has a '{}' whose lower limit is above its upper "
                                    "limit; the limits are ignored",
                                    x_.Name(), name_, range_attr));
      return std::nullopt;
    }
    const double limit = std::max(values[1], -values[0]);
    if (-values[0] != values[1]) {
      L_.diags().Report(DiagKind::ActuatorWarning, loc,
                        fmt::format("{} '{}' has an asymmetric '{}', which a plant's effort "
                                    "limit cannot hold; the larger magnitude, {}, is used",
                                    x_.Name(), name_, range_attr, limit));
    }
    return limit;
  }

  double EffortLimit(bool ctrl_is_force, double ctrl_scale) {
    double effort = kInf;
    if (ctrl_is_force) {
      if (auto c = RangeLimit("ctrlrange", "ctrllimited", inherited_ctrl_)) {
        effort = *c * ctrl_scale;
      }
    }
    if (auto f = RangeLimit("forcerange", "forcelimited")) effort = std::min(effort, *f);
    return effort;
  }

  ElementsLowering& L_;
  const Element& e_;
  xml::XmlElement x_;
  std::string name_;
  bool ok_ = true;
  std::optional<std::array<double, 2>> inherited_ctrl_;
};

}  // namespace

void LowerActuators(ElementsLowering& L, const xml::XmlElement& section) {
  // Drake's order: motors, then positions; then the kinds mdlc adds
  std::vector<xml::XmlElement> motors, positions, others;
  for (const xml::XmlElement& child : L.r.Children(section)) {
    ++L.actuator_elements;
    const std::string_view kind = child.Name();
    if (kind == "motor") {
      motors.push_back(child);
    } else if (kind == "position") {
      positions.push_back(child);
    } else if (kind == "velocity" || kind == "general") {
      others.push_back(child);
    } else if (kind == "intvelocity" || kind == "damper" || kind == "cylinder" ||
               kind == "muscle" || kind == "adhesion") {
      L.WarnOnce(fmt::format("actuator/{}", kind), DiagKind::UnsupportedElement,
                 child.GetLoc(),
                 fmt::format("<{}> actuators are not supported by the plant and are ignored",
                             kind));
    } else if (kind == "plugin") {
      L.r.LeaveOut(child.GetLoc(), "<plugin> actuator", kPluginLeftOut);
    } else {
      L.WarnOnce(fmt::format("actuator-unknown/{}", kind), DiagKind::UnknownElement,
                 child.GetLoc(), fmt::format("unknown element <{}> in <actuator> is ignored",
                                             kind));
    }
  }
  for (const auto* list : {&motors, &positions, &others}) {
    for (const xml::XmlElement& x : *list) {
      const Element e = L.r.Resolve(x, x.Name(), "");
      ActuatorLowering(L, e).Lower();
    }
  }
}

}  // namespace mdlc::frontend::mjcf
