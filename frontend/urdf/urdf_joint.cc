// urdf_joint.cc - <joint>, <frame> and <transmission> (URDF-010..024, URDF-041).
#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "frontend/urdf/urdf_reader_detail.h"

namespace mdlc::frontend::urdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Drake's planar joint moves in the x-y plane of its frame: rotate the frame
// so that its z axis is the URDF axis.
Eigen::Matrix3d FrameWithZAlong(const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
}
}  // namespace

void UrdfReader::ReadJoint(const xml::XmlElement& e) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto type = attrs_.String(e, "type", xml::Need::Required);
  attrs_.WarnUnknownAttributes(e, {"name", "type", "drake_ignore"});
  auto parent = e.Child("parent");
  auto child = e.Child("child");
  if (!parent) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   "<joint> is missing its <parent> element");
  }
  if (!child) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(), "<joint> is missing its <child> element");
  }
  auto parent_link = parent ? attrs_.String(parent, "link", xml::Need::Required) : std::nullopt;
  auto child_link = child ? attrs_.String(child, "link", xml::Need::Required) : std::nullopt;
  if (!name || !type || !parent_link || !child_link) return;

  ir::Joint joint;
  joint.name = module().Intern(*name);
  joint.model = model_;
  joint.loc = e.GetLoc();
  CheckUniqueName(joint_names_, joint.name, joint.loc, "joint");
  joint.parent = {module().Intern(*parent_link), parent.Attribute("link").loc, {}};
  joint.child = {module().Intern(*child_link), child.Attribute("link").loc, {}};
  joint.X_PF = ReadOrigin(e);

  const Loc type_loc = e.Attribute("type").loc;
  bool continuous = false;
  if (*type == "revolute") {
    joint.type = ir::JointType::Revolute;
  } else if (*type == "continuous") {
    joint.type = ir::JointType::Revolute;
    continuous = true;
  } else if (*type == "prismatic") {
    joint.type = ir::JointType::Prismatic;
  } else if (*type == "fixed") {
    joint.type = ir::JointType::Weld;
  } else if (*type == "floating") {
    // Drake makes no joint: the child stays a free body (URDF-012)
    diags().Report(DiagKind::FloatingJoint, type_loc,
                   fmt::format("joint '{}' of type 'floating' creates no joint: link '{}' becomes "
                               "a free body",
                               *name, *child_link));
    return;
  } else if (*type == "planar") {
    joint.type = ir::JointType::Planar;
  } else {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("joint '{}' has unrecognized type '{}'; expected revolute, "
                               "continuous, prismatic, fixed, floating or planar",
                               *name, *type));
    return;
  }

  // the axis, in the joint frame (URDF-011)
  const bool has_axis = joint.type == ir::JointType::Revolute ||
                        joint.type == ir::JointType::Prismatic ||
                        joint.type == ir::JointType::Planar;
  if (auto axis = e.Child("axis"); axis && has_axis) {
    if (auto xyz = attrs_.Vector3(axis, "xyz", xml::Need::Required)) {
      if (xyz->norm() < 1e-12) {
        diags().Report(DiagKind::ZeroAxis, axis.Attribute("xyz").loc,
                       fmt::format("joint '{}': axis is zero; it must have a direction", *name));
        return;
      }
      joint.axis = xyz->normalized();
    }
  }
  if (joint.type == ir::JointType::Planar) {
    joint.X_PF.R = joint.X_PF.R * FrameWithZAlong(joint.axis);
    joint.X_CM.R = FrameWithZAlong(joint.axis);
    joint.axis = Eigen::Vector3d::UnitZ();
  }

  const int nv = ir::JointVelocityCount(joint.type);
  joint.limits.lower.assign(nv, -kInf);
  joint.limits.upper.assign(nv, kInf);
  joint.limits.velocity_lower.assign(nv, -kInf);
  joint.limits.velocity_upper.assign(nv, kInf);
  joint.limits.acceleration_lower.assign(nv, -kInf);
  joint.limits.acceleration_upper.assign(nv, kInf);
  joint.limits.effort.assign(nv, kInf);
  joint.damping.assign(nv, 0.0);

  for (auto c = e.FirstChild(); c; c = c.NextSibling()) {
    std::string_view tag = c.Name();
    if (tag == "origin" || tag == "parent" || tag == "child" || tag == "axis") {
      continue;
    } else if (tag == "limit") {
      if (nv == 1) ReadLimits(c, joint, continuous);
    } else if (tag == "dynamics") {
      attrs_.WarnUnknownAttributes(c, {"damping", "friction", "coulomb_window", "spring_reference",
                                       "spring_stiffness"});
      if (joint.type == ir::JointType::Planar) {
        if (auto d = c.Attribute("damping"); d.present()) {
          auto values = attrs_.Doubles(c, "damping", 3);
          if (values) joint.damping = *values;
        }
      } else if (nv == 1) {
        if (auto d = attrs_.Double(c, "damping")) {
          if (*d < 0) {
            diags().Report(DiagKind::BadValue, c.Attribute("damping").loc,
                           fmt::format("joint '{}': damping must not be negative", *name));
          } else {
            joint.damping[0] = *d;
          }
        }
      }
      if (auto f = attrs_.Double(c, "friction"); f && *f != 0) {
        diags().Report(DiagKind::UnsupportedAttribute, c.Attribute("friction").loc,
                       "joint friction is currently unsupported and will be ignored");
      }
      if (auto w = c.Attribute("coulomb_window"); w.present()) {
        diags().Report(DiagKind::UnsupportedAttribute, w.loc,
                       "attribute 'coulomb_window' is currently unsupported and will be ignored");
      }
    } else if (tag == "mimic") {
      ReadMimic(c, joint);
    } else if (tag == "calibration" || tag == "safety_controller") {
      diags().Report(DiagKind::UnsupportedElement, c.GetLoc(),
                     fmt::format("tag '{}' found as a child of 'joint' is currently unsupported "
                                 "and will be ignored",
                                 tag));
    } else {
      diags().Report(DiagKind::UnknownElement, c.GetLoc(),
                     fmt::format("unknown element <{}> in <joint> is ignored", tag));
    }
  }
  joint_ids_[joint.name.value] = module().Add(std::move(joint));
}

void UrdfReader::ReadLimits(const xml::XmlElement& e, ir::Joint& joint, bool continuous) {
  attrs_.WarnUnknownAttributes(e, {"lower", "upper", "velocity", "effort", "drake:acceleration"});
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
    joint.limits.lower[0] = lo;
    joint.limits.upper[0] = hi;
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
    joint.limits.velocity_lower[0] = -*velocity;
    joint.limits.velocity_upper[0] = *velocity;
  }
  if (effort) joint.limits.effort[0] = *effort;
  if (accel) {
    joint.limits.acceleration_lower[0] = -*accel;
    joint.limits.acceleration_upper[0] = *accel;
  }
}

void UrdfReader::ReadMimic(const xml::XmlElement& e, const ir::Joint& joint) {
  // q_joint = multiplier * q_other + offset, as a coupler constraint (URDF-018)
  auto other = attrs_.String(e, "joint", xml::Need::Required);
  if (!other) return;
  attrs_.WarnUnknownAttributes(e, {"joint", "multiplier", "offset"});
  if (module().Intern(*other) == joint.name) {
    diags().Report(DiagKind::BadValue, e.Attribute("joint").loc,
                   fmt::format("joint '{}' cannot mimic itself", module().Text(joint.name)));
    return;
  }
  ir::Constraint c;
  c.type = ir::ConstraintType::Coupler;
  c.model = model_;
  c.loc = e.GetLoc();
  c.joint0 = {module().Intern(*other), e.Attribute("joint").loc, {}};
  c.joint1 = {joint.name, joint.loc, {}};
  c.gear_ratio = attrs_.Double(e, "multiplier").value_or(1.0);
  c.offset = attrs_.Double(e, "offset").value_or(0.0);
  module().Add(std::move(c));
}

void UrdfReader::ReadFrame(const xml::XmlElement& e) {
  // Drake's <frame name link xyz rpy> extension (URDF-041)
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto link = attrs_.String(e, "link", xml::Need::Required);
  attrs_.WarnUnknownAttributes(e, {"name", "link", "xyz", "rpy"});
  if (!name || !link) return;
  ir::Frame frame;
  frame.name = module().Intern(*name);
  frame.model = model_;
  frame.loc = e.GetLoc();
  CheckUniqueName(frame_names_, frame.name, frame.loc, "frame");
  frame.body = {module().Intern(*link), e.Attribute("link").loc, {}};
  if (auto xyz = attrs_.Vector3(e, "xyz")) frame.X_BF.p = *xyz;
  if (auto rpy = attrs_.Vector3(e, "rpy")) frame.X_BF.R = RotationFromRpy(*rpy);
  module().Add(std::move(frame));
}

}  // namespace mdlc::frontend::urdf
