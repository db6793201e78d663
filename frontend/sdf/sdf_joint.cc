// sdf_joint.cc - <joint>: type, parent and child frames, axes, limits,
// dynamics, springs and the actuator SDFormat joints get by default
// (SDF-010..014, SDF-020, SDF-035). Where the joint frame is, and what the
// parent and child frames are attached to, the resolve-frames pass decides.
// ReadJoint is the outline; each step below reads one concern: the type, the
// two ends, the axes (with their limits and dynamics), the values the joint
// takes from them, then the joint frame, the default actuator and the spring.
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "frontend/sdf/sdf_reader_detail.h"
#include "frontend/xml/trim.h"

namespace mdlc::frontend::sdf {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

struct JointAxisValues {
  double lower = -kInf, upper = kInf;
  double velocity = kInf, effort = kInf, acceleration = kInf;
  double damping = 0;
  double spring_reference = 0, spring_stiffness = 0;
  bool has_limit = false;
};

void SdfReader::ReadJoint(const xml::XmlElement& e, ModelScope& s) {
  auto name = attrs_.String(e, "name", xml::Need::Required);
  auto type_text = attrs_.String(e, "type", xml::Need::Required);
  if (!name || !type_text) return;
  attrs_.WarnUnknownAttributes(e, {"name", "type"});
  if (!CheckDefinedName(*name, e.GetLoc(), "joint", s.file->version)) return;
  CheckChildren(e,
                {"parent", "child", "pose", "axis", "axis2", "physics", "sensor",
                 "screw_thread_pitch", "thread_pitch", "gearbox_ratio",
                 "gearbox_reference_body", "drake:rotor_inertia", "drake:gear_ratio",
                 "drake:controller_gains", "drake:mimic"},
                {});
  const Symbol joint_name = module().Intern(*name);

  ir::Joint joint;
  joint.name = joint_name;
  joint.model = s.model;
  joint.loc = e.GetLoc();
  int axes_needed = 1;
  if (!ReadJointType(e, *type_text, *name, joint.type, axes_needed)) return;
  ir::NameRef parent, child;
  if (!ReadJointEnds(e, *name, parent, child)) return;
  ir::JointFrameSpec spec;
  spec.parent = parent;
  JointAxisValues values[2];
  if (!ReadJointAxes(e, s, joint, *type_text, *name, axes_needed, spec, values)) return;
  SetJointValues(e, *type_text, *name, values, joint);

  const JointId joint_id = module().Add(std::move(joint));
  AddJointFrame(e, s, joint_id, child, spec);
  std::optional<ActuatorId> actuator =
      AddDefaultActuator(e, s, joint_id, *type_text, *name, values);
  AddJointSpring(e, s, joint_id, *name, values[0]);
  ReadJointDrakeChildren(e, s, joint_id, actuator);
}

bool SdfReader::ReadJointType(const xml::XmlElement& e, std::string_view text,
                              std::string_view name, ir::JointType& type, int& axes_needed) {
  const Loc type_loc = e.Attribute("type").loc;
  axes_needed = 1;
  if (text == "revolute" || text == "continuous") {
    type = ir::JointType::Revolute;
  } else if (text == "prismatic") {
    type = ir::JointType::Prismatic;
  } else if (text == "screw") {
    type = ir::JointType::Screw;
  } else if (text == "fixed") {
    type = ir::JointType::Weld;
    axes_needed = 0;
  } else if (text == "ball") {
    type = ir::JointType::Ball;
    axes_needed = 0;
  } else if (text == "universal") {
    type = ir::JointType::Universal;
    axes_needed = 2;
  } else if (text == "revolute2" || text == "gearbox") {
    diags().Report(DiagKind::NotImplemented, type_loc,
                   fmt::format("joint type ({}) not supported for joint '{}': Drake's plant has "
                               "no such joint",
                               text, name));
    return false;
  } else {
    diags().Report(DiagKind::BadValue, type_loc,
                   fmt::format("unknown joint type '{}' for joint '{}'", text, name));
    return false;
  }
  return true;
}

bool SdfReader::ReadJointEnds(const xml::XmlElement& e, std::string_view name,
                              ir::NameRef& parent, ir::NameRef& child) {
  auto frame_name = [&](std::string_view tag) -> ir::NameRef {
    xml::XmlElement el = e.Child(tag);
    if (!el) {
      diags().Report(DiagKind::MissingElement, e.GetLoc(),
                     fmt::format("joint '{}' is missing required element <{}>", name, tag));
      return {};
    }
    const std::string text = el.Text();
    const std::string_view trimmed = xml::Trim(text);
    if (trimmed.empty()) {
      diags().Report(DiagKind::BadValue, el.GetLoc(),
                     fmt::format("<{}> of joint '{}' must name a frame", tag, name));
      return {};
    }
    return {module().Intern(trimmed), el.GetLoc()};
  };
  parent = frame_name("parent");
  child = frame_name("child");
  if (parent.empty() || child.empty()) return false;
  if (parent.name == child.name) {
    diags().Report(DiagKind::SelfJoint, e.GetLoc(),
                   fmt::format("joint '{}' must name different frames for parent and child, "
                               "but names '{}' for both",
                               name, module().Text(parent.name)));
    return false;
  }
  if (module().Text(child.name) == "world") {
    diags().Report(DiagKind::BadValue, child.loc,
                   fmt::format("joint '{}' names the world as its child: the world can only "
                               "be a parent",
                               name));
    return false;
  }
  return true;
}

bool SdfReader::ReadJointAxes(const xml::XmlElement& e, const ModelScope& s,
                              const ir::Joint& joint, std::string_view type,
                              std::string_view name, int axes_needed, ir::JointFrameSpec& spec,
                              JointAxisValues (&values)[2]) {
  const char* axis_tags[2] = {"axis", "axis2"};
  for (int k = 0; k < 2; ++k) {
    xml::XmlElement axis = e.Child(axis_tags[k]);
    if (!axis) continue;
    if (k >= axes_needed) {
      if (joint.type == ir::JointType::Ball || (joint.type != ir::JointType::Weld && k == 1)) {
        diags().Report(DiagKind::JointWarning, axis.GetLoc(),
                       fmt::format("<{}> of {} joint '{}' is ignored{}", axis_tags[k], type,
                                   name,
                                   joint.type == ir::JointType::Ball && k == 0
                                       ? ": only its dynamics are used"
                                       : ""));
      }
      if (k == 0 && joint.type == ir::JointType::Ball) {
        if (xml::XmlElement dyn = axis.Child("dynamics")) {
          if (auto d = ChildDouble(dyn, "damping")) values[0].damping = *d;
        }
      }
      continue;
    }
    CheckChildren(axis, {"xyz", "dynamics", "limit", "initial_position",
                         "use_parent_model_frame", "mimic"});
    spec.axis_count = k + 1;
    if (xml::XmlElement xyz = axis.Child("xyz")) {
      if (auto v = TextVector3(xyz)) {
        if (v->norm() < 1e-12) {
          diags().Report(DiagKind::ZeroAxis, xyz.GetLoc(),
                         fmt::format("the norm of the <xyz> of joint '{}' must not be zero", name));
          return false;
        }
        spec.xyz[k] = v->normalized();
      }
      if (auto a = xyz.Attribute("expressed_in"); a.present() && !a.value.empty()) {
        spec.expressed_in[k] = {module().Intern(a.value), a.loc};
      }
    } else {
      spec.xyz[k] = k == 0 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    }
    // SDFormat 1.5/1.6 could express the axis in the model frame; 1.4 always
    // did (libsdformat's 1.4 to 1.5 conversion sets use_parent_model_frame)
    auto upm = ChildBool(axis, "use_parent_model_frame");
    if (upm.value_or(s.file->version < 105) && spec.expressed_in[k].empty()) {
      spec.expressed_in[k] = {s.model_frame_name, axis.GetLoc()};
    }
    if (xml::XmlElement limit = axis.Child("limit")) ReadAxisLimit(limit, type, name, values[k]);
    if (xml::XmlElement dyn = axis.Child("dynamics")) ReadAxisDynamics(dyn, name, values[k]);
  }
  if (spec.axis_count < axes_needed) {
    diags().Report(DiagKind::MissingElement, e.GetLoc(),
                   axes_needed == 2
                       ? fmt::format("both <axis> and <axis2> must be specified for {} joint '{}'",
                                     type, name)
                       : fmt::format("an <axis> must be specified for {} joint '{}'", type, name));
    return false;
  }
  return true;
}

void SdfReader::ReadAxisLimit(const xml::XmlElement& limit, std::string_view type,
                              std::string_view name, JointAxisValues& v) {
  v.has_limit = true;
  CheckChildren(limit, {"lower", "upper", "effort", "velocity", "stiffness", "dissipation",
                        "drake:acceleration"});
  if (auto x = ChildDouble(limit, "lower", xml::Need::Optional, xml::Finite::NotRequired)) {
    v.lower = *x;
  }
  if (auto x = ChildDouble(limit, "upper", xml::Need::Optional, xml::Finite::NotRequired)) {
    v.upper = *x;
  }
  // negative velocity and effort mean "unlimited" (SDF-013)
  if (auto x = ChildDouble(limit, "velocity", xml::Need::Optional, xml::Finite::NotRequired)) {
    v.velocity = *x < 0 ? kInf : *x;
  }
  if (auto x = ChildDouble(limit, "effort", xml::Need::Optional, xml::Finite::NotRequired)) {
    v.effort = *x < 0 ? kInf : *x;
  }
  if (xml::XmlElement acc = limit.Child("drake:acceleration")) {
    if (auto x = TextDouble(acc, xml::Finite::NotRequired)) {
      if (*x < 0) {
        diags().Report(DiagKind::BadLimits, acc.GetLoc(),
                       fmt::format("the acceleration limit of joint '{}' must not be negative",
                                   name));
      } else {
        v.acceleration = *x;
      }
    }
  }
  if (v.lower > v.upper && type != "continuous") {
    diags().Report(DiagKind::BadLimits, limit.GetLoc(),
                   fmt::format("the lower limit must be lower than or equal to the upper "
                               "limit for joint '{}'",
                               name));
  }
}

void SdfReader::ReadAxisDynamics(const xml::XmlElement& dyn, std::string_view name,
                                 JointAxisValues& v) {
  CheckChildren(dyn, {"damping", "friction", "spring_reference", "spring_stiffness"});
  if (auto x = ChildDouble(dyn, "damping")) {
    if (*x < 0) {
      diags().Report(DiagKind::BadValue, dyn.Child("damping").GetLoc(),
                     fmt::format("joint damping is negative for joint '{}': it must be a "
                                 "non-negative number",
                                 name));
    } else {
      v.damping = *x;
    }
  }
  if (auto x = ChildDouble(dyn, "friction"); x && *x != 0) {
    diags().Report(DiagKind::JointWarning, dyn.Child("friction").GetLoc(),
                   fmt::format("joint friction of joint '{}' is unsupported and will be ignored",
                               name));
  }
  if (auto x = ChildDouble(dyn, "spring_reference")) v.spring_reference = *x;
  if (auto x = ChildDouble(dyn, "spring_stiffness")) v.spring_stiffness = *x;
}

void SdfReader::SetJointValues(const xml::XmlElement& e, std::string_view type,
                               std::string_view name, const JointAxisValues (&values)[2],
                               ir::Joint& joint) {
  const int nv = ir::JointVelocityCount(joint.type);
  joint.limits = ir::JointLimits::Unbounded(nv);
  joint.damping.assign(nv, values[0].damping);
  if (joint.type == ir::JointType::Universal && values[1].damping != values[0].damping) {
    diags().Report(DiagKind::JointWarning, e.GetLoc(),
                   fmt::format("joint damping must be equal for both axes of joint '{}': the "
                               "damping of <axis> ({}) is used, that of <axis2> ({}) ignored",
                               name, values[0].damping, values[1].damping));
  }
  if (nv == 1 && joint.type != ir::JointType::Weld) {
    const JointAxisValues& v = values[0];
    if (type != "continuous" && joint.type != ir::JointType::Screw) {
      joint.limits.lower.set(0, v.lower);
      joint.limits.upper.set(0, v.upper);
    }
    joint.limits.velocity_lower.set(0, -v.velocity);
    joint.limits.velocity_upper.set(0, v.velocity);
    joint.limits.acceleration_lower.set(0, -v.acceleration);
    joint.limits.acceleration_upper.set(0, v.acceleration);
    joint.limits.effort.set(0, v.effort);
  }
  if (joint.type == ir::JointType::Screw) {
    // meters per revolution; SDFormat before 1.10 wrote radians per meter
    // with the opposite handedness (libsdformat's conversion)
    joint.screw_thread_pitch = 1.0;
    if (auto p = ChildDouble(e, "screw_thread_pitch")) {
      joint.screw_thread_pitch = *p;
    } else if (auto legacy = ChildDouble(e, "thread_pitch")) {
      if (*legacy == 0) {
        diags().Report(DiagKind::BadValue, e.Child("thread_pitch").GetLoc(),
                       "thread_pitch must not be zero");
      } else {
        joint.screw_thread_pitch = -2 * std::numbers::pi / *legacy;
      }
    }
  }
}

void SdfReader::AddJointFrame(const xml::XmlElement& e, ModelScope& s, JointId joint,
                              const ir::NameRef& child, ir::JointFrameSpec& spec) {
  ir::FrameNode node;
  node.kind = ir::FrameNodeKind::Joint;
  node.name = module()[joint].name;
  node.loc = e.GetLoc();
  xml::XmlElement pose = e.Child("pose");
  node.relative_to = RelativeTo(pose);
  if (node.relative_to.empty()) node.relative_to = child;
  node.X_RN = ReadPoseValue(pose);
  node.attached_to = child;
  node.target = ir::FrameTarget::Joint;
  node.target_index = joint.value;
  spec.node = AddNode(s, std::move(node));  // may rename the joint (before 1.7)
  spec.joint = joint;
  graph().joints.push_back(spec);
}

std::optional<ActuatorId> SdfReader::AddDefaultActuator(const xml::XmlElement& e,
                                                        const ModelScope& s, JointId joint,
                                                        std::string_view type,
                                                        std::string_view name,
                                                        const JointAxisValues (&values)[2]) {
  const ir::Joint& j = module()[joint];
  const bool one_dof = ir::JointVelocityCount(j.type) == 1 && j.type != ir::JointType::Weld;
  if (one_dof && values[0].effort != 0) {
    ir::Actuator a;
    a.name = j.name;
    a.unnamed = true;  // made by the compiler, named after its joint
    a.model = s.model;
    a.loc = e.GetLoc();
    a.joint = {j.name, e.GetLoc(), joint};
    a.effort_limit = values[0].effort;
    const ActuatorId actuator = module().Add(std::move(a));
    joint_actuators_.emplace(joint.value, actuator);
    return actuator;
  }
  if ((j.type == ir::JointType::Universal && (values[0].effort != 0 || values[1].effort != 0) &&
       (values[0].has_limit || values[1].has_limit)) ||
      (j.type == ir::JointType::Ball && e.Child("axis") && values[0].effort != 0 &&
       values[0].has_limit)) {
    diags().Report(DiagKind::ActuatorWarning, e.GetLoc(),
                   fmt::format("the effort limits of {} joint '{}' make no actuator: mdlc "
                               "actuates single-dof joints only",
                               type, name));
  }
  return std::nullopt;
}

void SdfReader::AddJointSpring(const xml::XmlElement& e, const ModelScope& s, JointId joint,
                               std::string_view name, const JointAxisValues& v) {
  const ir::Joint& j = module()[joint];
  if ((j.type != ir::JointType::Revolute && j.type != ir::JointType::Prismatic) ||
      v.spring_stiffness == 0) {
    return;
  }
  if (v.spring_stiffness < 0) {
    diags().Report(DiagKind::BadValue, e.GetLoc(),
                   fmt::format("the spring stiffness of joint '{}' must be non-negative", name));
    return;
  }
  ir::JointSpring spring;
  spring.joint = {j.name, e.GetLoc(), joint};
  spring.nominal = v.spring_reference;
  spring.stiffness = v.spring_stiffness;
  module().Add(ir::ForceElement{s.model, e.GetLoc(), spring});
}

}  // namespace mdlc::frontend::sdf
