// sdf_joints.cc - the SDFormat writer's joints: type, pose, axes with
// dynamics and limits, the actuator SDFormat makes for a joint with its
// drake: parameters, <drake:mimic>, and planar joints as <drake:joint>
// (sdf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <variant>

#include "backend/writers/sdf_writer_detail.h"

namespace mdlc::writers::sdf {

// why a joint's default positions are not written (-Wlossy)
constexpr std::string_view kNoInitialPositions =
    "mdlc's SDFormat reader takes no initial positions";

void SdfWriter::WriteJoint(JointId id, ScopeId scope) {
  const PlantJoint& j = plant_.joint(id);
  const Loc loc = JointLoc(id);
  const std::string name = joint_names_[id.index()];
  if (IsFloating(j)) {
    if (!IsFreeRoot(j)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("floating joint '{}' has a parent other than the world or "
                                "frames apart from its links' frames, which SDFormat cannot "
                                "hold; link '{}' is written free",
                                j.name, link_names_[j.child.index()]));
    } else if (!j.unnamed || j.type == ir::JointType::RpyFloating) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("{} joint '{}' is written as a free link: SDFormat names no "
                                "floating joint{}",
                                ir::JointTypeName(j.type), j.name,
                                j.type == ir::JointType::RpyFloating
                                    ? ", and its coordinates become a quaternion's"
                                    : ""));
    }
    return;
  }
  if (j.type == ir::JointType::Planar) {
    WritePlanar(id, scope);
    return;
  }
  std::string_view type;
  switch (j.type) {
    case ir::JointType::Weld: type = "fixed"; break;
    case ir::JointType::Revolute: type = "revolute"; break;
    case ir::JointType::Prismatic: type = "prismatic"; break;
    case ir::JointType::Ball: type = "ball"; break;
    case ir::JointType::Universal: type = "universal"; break;
    case ir::JointType::Screw: type = "screw"; break;
    default:
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("{} joint '{}' has no SDFormat form; it is written as a "
                                "fixed joint",
                                ir::JointTypeName(j.type), j.name));
      type = "fixed";
  }
  out_.Open("joint").Attr("name", name).Attr("type", type);
  Value("parent", LinkRef(scope, j.parent));
  Value("child", LinkRef(scope, j.child));
  Pose(j.X_CM);
  if (type == "screw") {
    if (j.screw_thread_pitch == 0) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("screw joint '{}' has pitch 0, which SDFormat 1.9's "
                                "<thread_pitch> cannot hold; 1 m per revolution is written",
                                j.name));
    } else {
      // SDFormat 1.9: radians per meter, of the opposite handedness
      Value("thread_pitch", -2 * std::numbers::pi / j.screw_thread_pitch);
    }
  }
  if (type == "revolute" || type == "prismatic" || type == "screw") {
    Axis("axis", id, j, j.axis, 0);
  } else if (type == "universal") {
    // Drake's universal joint turns about F's x, then M's y
    Axis("axis", id, j, Eigen::Vector3d::UnitX(), 0);
    Axis("axis2", id, j, Eigen::Vector3d::UnitY(), 1);
  } else if (type == "ball") {
    if (j.damping[0] != 0 || !AllEqual(j.damping)) {
      if (!AllEqual(j.damping)) DampingLoss(j, loc);
      out_.Open("axis");
      out_.Open("dynamics");
      Value("damping", j.damping[0]);
      out_.Close();
      out_.Close();
    }
  }
  if (type != "fixed") {
    MultiDofLimits(j, loc);
    ActuatorParameters(id);
    MimicElements(id);
  }
  out_.Close();
  ReportUnwrittenDefaultPositions(j, loc, kNoInitialPositions);
}

void SdfWriter::DampingLoss(const PlantJoint& j, Loc loc) {
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("joint '{}' has a different damping per coordinate; SDFormat "
                            "holds one, so the first ({}) is written",
                            j.name, j.damping[0]));
}

void SdfWriter::Axis(std::string_view tag, JointId id, const PlantJoint& j,
                     const Eigen::Vector3d& xyz, int k) {
  const Loc loc = JointLoc(id);
  out_.Open(tag);
  Value("xyz", xyz);
  const double damping = j.damping.empty() ? 0 : j.damping[0];
  if (k == 0 && !AllEqual(j.damping)) DampingLoss(j, loc);
  const backend::JointSpring* spring = nullptr;
  for (uint32_t i : springs_by_joint_[id.index()]) {
    spring = &std::get<backend::JointSpring>(plant_.force_elements[i]);
  }
  if (damping != 0 || spring) {
    out_.Open("dynamics");
    Value("damping", damping);
    if (spring && k == 0) {
      Value("spring_reference", spring->nominal);
      Value("spring_stiffness", spring->stiffness);
    }
    out_.Close();
  }
  if (j.nv == 1) SingleDofLimit(id, j, loc);
  out_.Close();
}

/// The effort SDFormat writes: an actuated joint's is its actuator's
/// limit; a joint without an actuator needs 0 (else SDFormat makes one).
double SdfWriter::EffortOf(JointId id, const PlantJoint& j, Loc loc) {
  const double joint_effort = j.effort.empty() ? kInf : j.effort[0];
  const backend::PlantActuator* actuator = nullptr;
  if (const auto actuators = actuators_by_joint_[id.index()]; !actuators.empty()) {
    actuator = &plant_.actuators[actuators.front()];
  }
  if (!actuator) {
    if (joint_effort != 0) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has no actuator; SDFormat makes one for every "
                                "joint whose effort limit is not 0, so its effort limit ({}) "
                                "is written as 0",
                                j.name, joint_effort));
    }
    return 0;
  }
  if (actuator->effort_limit != joint_effort && joint_effort != kInf) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has effort limit {} and its actuator '{}' {}; "
                              "SDFormat holds one, so the actuator's is written",
                              j.name, joint_effort, actuator->name, actuator->effort_limit));
  }
  return actuator->effort_limit;
}

void SdfWriter::SingleDofLimit(JointId id, const PlantJoint& j, Loc loc) {
  ReportAsymmetricLimits(j, loc, "SDFormat");
  if (j.type == ir::JointType::Screw && (j.lower[0] != -kInf || j.upper[0] != kInf)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the position limits of screw joint '{}' are not written "
                              "(Drake reads none for a screw joint)",
                              j.name));
  }
  const double effort = EffortOf(id, j, loc);
  out_.Open("limit");
  if (j.type != ir::JointType::Screw) {
    // an absent side is unbounded to mdlc (libsdformat says +-1e16)
    if (j.lower[0] != -kInf) Value("lower", j.lower[0]);
    if (j.upper[0] != kInf) Value("upper", j.upper[0]);
  }
  // negative effort and velocity mean "unbounded" (SDF-013)
  Value("effort", effort == kInf ? -1.0 : effort);
  Value("velocity", j.velocity_upper[0] == kInf ? -1.0 : j.velocity_upper[0]);
  if (j.acceleration_upper[0] != kInf) Value("drake:acceleration", j.acceleration_upper[0]);
  out_.Close();
}

/// Limits of joints with more than one coordinate: SDFormat's are per
/// single-dof axis, and Drake reads none for ball and universal joints.
void SdfWriter::MultiDofLimits(const PlantJoint& j, Loc loc) {
  if (j.nv <= 1) return;
  for (int k = 0; k < j.nv; ++k) {
    if (j.lower[k] != -kInf || j.upper[k] != kInf || j.velocity_upper[k] != kInf ||
        j.velocity_lower[k] != -kInf || j.effort[k] != kInf ||
        j.acceleration_upper[k] != kInf || j.acceleration_lower[k] != -kInf) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the limits of {} joint '{}' are not written (Drake reads "
                                "SDFormat limits for single-dof joints only)",
                                ir::JointTypeName(j.type), j.name));
      return;
    }
  }
}

// drake:rotor_inertia, drake:gear_ratio, drake:controller_gains (SDF-021)
void SdfWriter::ActuatorParameters(JointId id) {
  const PlantJoint& j = plant_.joint(id);
  int count = 0;
  for (uint32_t i : actuators_by_joint_[id.index()]) {
    const backend::PlantActuator& a = plant_.actuators[i];
    const Loc loc = ActuatorLoc(i);
    if (j.nv != 1 || j.type == ir::JointType::Planar) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("actuator '{}' of {} joint '{}' is dropped: SDFormat makes "
                                "actuators for single-dof joints only",
                                a.name, ir::JointTypeName(j.type), j.name));
      continue;
    }
    if (++count > 1) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("actuator '{}' is dropped: SDFormat makes one actuator per "
                                "joint, and joint '{}' has another",
                                a.name, j.name));
      continue;
    }
    if (!a.unnamed && a.name != j.name) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("actuator '{}' takes the name of its joint '{}': SDFormat "
                                "names a joint's actuator after it",
                                a.name, joint_names_[id.index()]));
    }
    if (a.rotor_inertia != 0) Value("drake:rotor_inertia", a.rotor_inertia);
    if (a.gear_ratio != 1) Value("drake:gear_ratio", a.gear_ratio);
    if (a.kp && a.kd) {
      out_.Open("drake:controller_gains").Attr("p", *a.kp).Attr("d", *a.kd).Close();
    } else if (a.kp || a.kd) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("actuator '{}' has only a {} gain; "
                                "<drake:controller_gains> needs both, so none is written",
                                a.name, a.kp ? "proportional" : "derivative"));
    }
  }
}

// a coupler whose follower is this joint becomes its <drake:mimic> (EXT-010)
void SdfWriter::MimicElements(JointId id) {
  for (uint32_t i : couplers_by_follower_[id.index()]) {
    const auto* coupler = std::get_if<backend::CouplerConstraint>(&plant_.constraints[i].payload);
    const Loc loc = ConstraintLoc(i);
    if (mimic_written_.count(id.index())) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' follows more than one joint; <drake:mimic> holds "
                                "one, so this coupler is dropped",
                                plant_.joint(coupler->joint0).name));
      continue;
    }
    if (joint_scope_[coupler->joint1.index()] != joint_scope_[id.index()]) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the coupler of joint '{}' is dropped: <drake:mimic> names a "
                                "joint of the same model, and joint '{}' is in another",
                                plant_.joint(id).name, plant_.joint(coupler->joint1).name));
      continue;
    }
    mimic_written_.insert(id.index());
    out_.Open("drake:mimic")
        .Attr("joint", joint_names_[coupler->joint1.index()])
        .Attr("multiplier", coupler->gear_ratio)
        .Attr("offset", coupler->offset)
        .Close();
  }
}

// <drake:joint type="planar">: F and M are named frames (EXT-001)
void SdfWriter::WritePlanar(JointId id, ScopeId scope) {
  const PlantJoint& j = plant_.joint(id);
  const Loc loc = JointLoc(id);
  ModelNode& node = models_[scope];
  auto frame_for = [&](BodyId body, const Transform& X, std::string_view suffix) {
    if (X.IsIdentity()) return LinkRef(scope, body);
    const std::string fname =
        Claim(node, fmt::format("{}_{}", joint_names_[id.index()], suffix), "frame", loc);
    out_.Open("frame").Attr("name", fname).Attr("attached_to", LinkRef(scope, body));
    Pose(X, LinkRef(scope, body));
    out_.Close();
    return fname;
  };
  const std::string parent = frame_for(j.parent, j.X_PF, "F");
  const std::string child = frame_for(j.child, j.X_CM, "M");
  out_.Open("drake:joint").Attr("name", joint_names_[id.index()]).Attr("type", "planar");
  Value("drake:parent", parent);
  Value("drake:child", child);
  Value("drake:damping", VectorText(Eigen::Map<const Eigen::VectorXd>(j.damping.data(), 3)));
  out_.Close();
  MultiDofLimits(j, loc);
  for (uint32_t i : actuators_by_joint_[id.index()]) {
    diags_.Report(DiagKind::Lossy, ActuatorLoc(i),
                  fmt::format("actuator '{}' of planar joint '{}' is dropped: SDFormat makes "
                              "actuators for single-dof joints only",
                              plant_.actuators[i].name, j.name));
  }
  ReportUnwrittenDefaultPositions(j, loc, kNoInitialPositions);
}

}  // namespace mdlc::writers::sdf
