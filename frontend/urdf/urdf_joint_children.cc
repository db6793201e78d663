// urdf_joint_children.cc - the <limit>, <dynamics> and <mimic> children of
// a <joint> or <drake:joint> (URDF-013, URDF-014, URDF-018); urdf_joint.cc
// decides which joints read them.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

void UrdfReader::ReadLimits(const xml::XmlElement& e, ir::Joint& joint, bool continuous) {
  // a misspelled bound (uper=) leaves that side unbounded: the note says so
  static constexpr std::string_view kUnbounded[] = {"the lower limit is -inf: unbounded",
                                                    "the upper limit is +inf: unbounded"};
  attrs_.WarnUnknownAttributes(
      e, {"lower", "upper", "velocity", "effort", "drake:acceleration"},
      continuous ? std::initializer_list<xml::AttributeReader::WhenAbsent>{}
                 : std::initializer_list<xml::AttributeReader::WhenAbsent>{
                       {"lower", kUnbounded[0]}, {"upper", kUnbounded[1]}});
  // joint limits may be infinite: that means "unbounded"
  auto lower = attrs_.Double(e, "lower", xml::Need::Optional, xml::Finite::NotRequired);
  auto upper = attrs_.Double(e, "upper", xml::Need::Optional, xml::Finite::NotRequired);
  auto velocity = attrs_.Double(e, "velocity", xml::Need::Optional, xml::Finite::NotRequired);
  auto effort = attrs_.Double(e, "effort", xml::Need::Optional, xml::Finite::NotRequired);
  auto accel =
      attrs_.Double(e, "drake:acceleration", xml::Need::Optional, xml::Finite::NotRequired);
  for (auto [value, attr] : {std::pair{&lower, "lower"}, {&upper, "upper"},
                             {&velocity, "velocity"}, {&effort, "effort"},
                             {&accel, "drake:acceleration"}}) {
    if (*value && std::isnan(**value)) {
      diags().Report(DiagKind::NonFinite, e.Attribute(attr).loc,
                     fmt::format("attribute '{}' of <limit> is NaN", attr));
      value->reset();
    }
  }
  if (!continuous) {
    // an absent bound leaves that side unbounded, as in Drake
    const double lo = lower.value_or(-kInf), hi = upper.value_or(kInf);
    if (lo > hi) {
      diags().Report(DiagKind::BadLimits, e.GetLoc(),
                     fmt::format("joint '{}': lower limit {} is greater than upper limit {}",
                                 module().Text(joint.name), lo, hi));
      return;
    }
    joint.limits.lower.set(0, lo);
    joint.limits.upper.set(0, hi);
  }
  for (auto [value, what] : {std::pair{&velocity, "velocity"}, {&effort, "effort"},
                             {&accel, "drake:acceleration"}}) {
    if (*value && **value < 0) {
      diags().Report(DiagKind::BadLimits, e.Attribute(what).loc,
                     fmt::format("joint '{}': {} limit must not be negative",
                                 module().Text(joint.name), what));
      value->reset();
    }
  }
  if (velocity) {
    joint.limits.velocity_lower.set(0, -*velocity);
    joint.limits.velocity_upper.set(0, *velocity);
  }
  if (effort) joint.limits.effort.set(0, *effort);
  if (accel) {
    joint.limits.acceleration_lower.set(0, -*accel);
    joint.limits.acceleration_upper.set(0, *accel);
  }
}

void UrdfReader::ReadMimic(const xml::XmlElement& e, const ir::Joint& joint) {
  // q_joint = multiplier * q_other + offset, as a coupler constraint (URDF-018).
  // Drake's convention: joint0 is the joint that follows (the one holding
  // <mimic>), joint1 the joint it follows.
  auto other = attrs_.String(e, "joint", xml::Need::Required);
  if (!other) return;
  attrs_.WarnUnknownAttributes(e, {"joint", "multiplier", "offset"});
  if (module().Intern(*other) == joint.name) {
    diags().Report(DiagKind::BadValue, e.Attribute("joint").loc,
                   fmt::format("joint '{}' cannot mimic itself", module().Text(joint.name)));
    return;
  }
  ir::CouplerConstraint c;
  c.joint0 = {joint.name, joint.loc, {}};
  c.joint1 = {module().Intern(*other), e.Attribute("joint").loc, {}};
  c.gear_ratio = attrs_.Double(e, "multiplier").value_or(1.0);
  c.offset = attrs_.Double(e, "offset").value_or(0.0);
  module().Add(ir::Constraint{model_, e.GetLoc(), std::move(c)});
}

void UrdfReader::ReadDynamics(const xml::XmlElement& dynamics, ir::Joint& joint) {
  const std::string_view name = module().Text(joint.name);
  const int nv = ir::JointVelocityCount(joint.type);
  attrs_.WarnUnknownAttributes(dynamics, {"damping", "friction", "coulomb_window",
                                          "spring_reference", "spring_stiffness"});
  if (joint.type == ir::JointType::Planar) {
    // three values: x, y and the rotation about z (URDF-014)
    if (auto d = dynamics.Attribute("damping"); d.present()) {
      if (auto values = attrs_.Doubles(dynamics, "damping", 3)) {
        if (std::any_of(values->begin(), values->end(), [](double v) { return v < 0; })) {
          diags().Report(DiagKind::BadValue, d.loc,
                         fmt::format("joint '{}': damping must not be negative", name));
        } else {
          joint.damping = *values;
        }
      }
    }
  } else if (nv > 0) {
    // one value; ball and universal joints apply it to every dof, as
    // Drake's BallRpyJoint and UniversalJoint do
    if (auto d = attrs_.Double(dynamics, "damping")) {
      if (*d < 0) {
        diags().Report(DiagKind::BadValue, dynamics.Attribute("damping").loc,
                       fmt::format("joint '{}': damping must not be negative", name));
      } else {
        joint.damping.assign(nv, *d);
      }
    }
  }
  if (auto f = attrs_.Double(dynamics, "friction"); f && *f != 0 && !said_friction_) {
    said_friction_ = true;
    diags().Report(DiagKind::UnsupportedAttribute, dynamics.Attribute("friction").loc,
                   "joint friction is ignored: the plant holds no Coulomb friction in joints, "
                   "only <dynamics damping> (said once per file)");
  }
  if (auto w = dynamics.Attribute("coulomb_window"); w.present()) {
    diags().Report(DiagKind::UnsupportedAttribute, w.loc,
                   "attribute 'coulomb_window' is not supported and is ignored");
  }
}

}  // namespace mdlc::frontend::urdf
