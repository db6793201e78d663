// urdf_joints.cc - the URDF writer's joints: <joint> with its limits,
// dynamics and <mimic>, the joint types only Drake's URDF holds as
// <drake:joint>, and actuators as <transmission> (urdf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "backend/writers/drake_out.h"
#include "backend/writers/urdf_writer_detail.h"

namespace mdlc::writers::urdf {

void UrdfWriter::WriteJoint(JointId id) {
  const PlantJoint& j = plant_.joint(id);
  const Loc loc = JointLoc(id);
  if (IsFloating(j)) {
    // plain URDF is one tree for urdfdom: the free link hangs from its
    // parent by a floating joint, which Drake and mdlc read as no joint
    // (URDF-012), so the link is free as before. The joint's name is not a
    // body's, where Drake's reader names the free body's own joint.
    if (plain_ && (!IsFreeRoot(j) || floats_free_roots_)) {
      out_.Open("joint")
          .Attr("name", BodyName(j.child) + "_floating")
          .Attr("type", "floating");
      Origin(InLink(j.parent, j.X_PF));
      out_.Open("parent").Attr("link", BodyName(j.parent)).Close();
      out_.Open("child").Attr("link", BodyName(j.child)).Close();
      out_.Close();
    }
    if (!IsFreeRoot(j)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("floating joint '{}' has a parent other than the world, "
                                "which URDF cannot hold; link '{}' is written free",
                                j.name, BodyName(j.child)));
    } else if (!j.unnamed || j.type == ir::JointType::RpyFloating) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("{} joint '{}' is written as a free root link: URDF names "
                                "no floating joint{}",
                                ir::JointTypeName(j.type), j.name,
                                j.type == ir::JointType::RpyFloating
                                    ? ", and its coordinates become a quaternion's"
                                    : ""));
    }
    if (!j.default_positions.empty() && !IsIdentityPose(j)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the default pose of free link '{}' is not written (URDF "
                                "has no initial positions)",
                                BodyName(j.child)));
    }
    return;
  }
  struct Spelling {
    std::string_view element, type;
  };
  Spelling s;
  switch (j.type) {
    case ir::JointType::Weld: s = {"joint", "fixed"}; break;
    case ir::JointType::Revolute:
      s = {"joint", j.lower[0] == -kInf && j.upper[0] == kInf ? "continuous" : "revolute"};
      break;
    case ir::JointType::Prismatic: s = {"joint", "prismatic"}; break;
    case ir::JointType::Planar: s = {"joint", "planar"}; break;
    case ir::JointType::Ball:
    case ir::JointType::Universal:
    case ir::JointType::Screw:
      if (!plain_) {
        s = {"drake:joint", ir::JointTypeName(j.type)};
        break;
      }
      // urdfdom passes over <drake:joint>, which would leave its child a
      // second root
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("{} joint '{}' has no plain URDF type; it is written as a "
                                "fixed joint at its zero position",
                                ir::JointTypeName(j.type), j.name));
      s = {"joint", "fixed"};
      break;
    default:
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("{} joint '{}' has no URDF form; it is written as a fixed "
                                "joint",
                                ir::JointTypeName(j.type), j.name));
      s = {"joint", "fixed"};
  }
  out_.Open(s.element).Attr("name", JointName(id)).Attr("type", s.type);
  OriginalName(j.model, j.name, JointName(id));
  Origin(InLink(j.parent, j.X_PF));
  out_.Open("parent").Attr("link", BodyName(j.parent)).Close();
  out_.Open("child").Attr("link", BodyName(j.child)).Close();
  if (j.type == ir::JointType::Revolute || j.type == ir::JointType::Prismatic ||
      j.type == ir::JointType::Screw || j.type == ir::JointType::Planar) {
    out_.Open("axis").Attr("xyz", j.axis).Close();
  }
  if (j.type == ir::JointType::Screw) {
    out_.Open("drake:screw_thread_pitch").Attr("value", j.screw_thread_pitch).Close();
  }
  if (s.type != "fixed") {
    Dynamics(j, loc);
    Limits(id, j, loc);
  }
  Mimic(id);
  out_.Close();
  ReportUnwrittenDefaultPositions(j, loc, "URDF has no initial positions");
}

bool UrdfWriter::IsIdentityPose(const PlantJoint& j) {
  const auto& q = j.default_positions;
  if (j.type == ir::JointType::QuaternionFloating) {
    return q.size() == 7 && q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0 && q[4] == 0 &&
           q[5] == 0 && q[6] == 0;
  }
  return std::all_of(q.begin(), q.end(), [](double v) { return v == 0; });
}

void UrdfWriter::Dynamics(const PlantJoint& j, Loc loc) {
  if (j.damping.empty() ||
      std::all_of(j.damping.begin(), j.damping.end(), [](double d) { return d == 0; })) {
    return;
  }
  if (j.type == ir::JointType::Planar && plain_) {
    // urdfdom reads one damping value, Drake three for a planar joint
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the damping of planar joint '{}' is not written: plain URDF's "
                              "readers take one value, Drake's three",
                              j.name));
    return;
  }
  if (j.type == ir::JointType::Planar) {
    out_.Open("dynamics").Attr("damping", VectorText(Eigen::Map<const Eigen::VectorXd>(
                                               j.damping.data(), 3)));
    out_.Close();
    return;
  }
  if (!AllEqual(j.damping)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has a different damping per coordinate; URDF "
                              "holds one, so the first ({}) is written",
                              j.name, j.damping[0]));
  }
  out_.Open("dynamics").Attr("damping", j.damping[0]).Close();
}

double UrdfWriter::EffortOf(JointId id, const PlantJoint& j, Loc loc) {
  double effort = j.effort.empty() ? kInf : j.effort[0];
  for (uint32_t i : actuators_by_joint_[id.index()]) {
    const backend::PlantActuator& a = plant_.actuators[i];
    if (a.effort_limit == effort) continue;
    if (effort != kInf) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has effort limit {} and its actuator '{}' {}; "
                                "URDF holds one, so the actuator's is written",
                                j.name, effort, a.name, a.effort_limit));
    }
    effort = a.effort_limit;
  }
  return effort;
}

void UrdfWriter::Limits(JointId id, const PlantJoint& j, Loc loc) {
  const bool single = j.nv == 1 && j.type != ir::JointType::Planar;
  const double effort = EffortOf(id, j, loc);
  if (!single) {
    const bool bounded = [&] {
      for (int k = 0; k < j.nv; ++k) {
        if (j.lower[k] != -kInf || j.upper[k] != kInf || j.velocity_upper[k] != kInf ||
            j.velocity_lower[k] != -kInf || j.effort[k] != kInf) {
          return true;
        }
      }
      return false;
    }();
    if (bounded) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("the limits of {} joint '{}' are not written (URDF reads "
                                "limits for single-dof joints only)",
                                ir::JointTypeName(j.type), j.name));
    }
    return;
  }
  ReportAsymmetricLimits(j, loc, "URDF");
  const bool revolute_continuous =
      j.type == ir::JointType::Revolute && j.lower[0] == -kInf && j.upper[0] == kInf;
  if (j.type == ir::JointType::Screw && (j.lower[0] != -kInf || j.upper[0] != kInf)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the position limits of screw joint '{}' are not written "
                              "(Drake reads none for a screw joint)",
                              j.name));
  }
  // revolute and prismatic joints always have a <limit> (urdfdom requires
  // one); with it go effort and velocity, which urdfdom requires too
  const bool has_position = (j.type == ir::JointType::Revolute && !revolute_continuous) ||
                            j.type == ir::JointType::Prismatic;
  if (!has_position && j.velocity_upper[0] == kInf && effort == kInf &&
      j.acceleration_upper[0] == kInf) {
    return;
  }
  out_.Open("limit");
  if (has_position) {
    out_.Attr("lower", FiniteLimit(j.lower[0])).Attr("upper", FiniteLimit(j.upper[0]));
  }
  out_.Attr("effort", FiniteLimit(effort));
  out_.Attr("velocity", FiniteLimit(j.velocity_upper[0]));
  if (j.acceleration_upper[0] != kInf) {
    out_.Attr("drake:acceleration", j.acceleration_upper[0]);
  }
  out_.Close();
}

void UrdfWriter::Mimic(JointId id) {
  for (uint32_t i : couplers_by_follower_[id.index()]) {
    const auto* coupler = std::get_if<backend::CouplerConstraint>(&plant_.constraints[i].payload);
    if (!mimicked_.insert(id.index()).second) continue;  // a second one: see WriteConstraints
    out_.Open("mimic")
        .Attr("joint", JointName(coupler->joint1))
        .Attr("multiplier", coupler->gear_ratio)
        .Attr("offset", coupler->offset)
        .Close();
  }
}

void UrdfWriter::WriteTransmissions() {
  for (size_t i = 0; i < plant_.actuators.size(); ++i) {
    const backend::PlantActuator& a = plant_.actuators[i];
    out_.Open("transmission");
    out_.Open("type").Text("transmission_interface/SimpleTransmission").Close();
    out_.Open("joint").Attr("name", JointName(a.joint));
    out_.Open("hardwareInterface").Text("hardware_interface/EffortJointInterface").Close();
    out_.Close();
    out_.Open("actuator").Attr("name", Named(a.model, a.name));
    OriginalName(a.model, a.name, Named(a.model, a.name));
    if (a.rotor_inertia != 0) {
      out_.Open("drake:rotor_inertia").Attr("value", a.rotor_inertia).Close();
    }
    if (a.gear_ratio != 1) out_.Open("drake:gear_ratio").Attr("value", a.gear_ratio).Close();
    if (a.kp && a.kd) {
      out_.Open("drake:controller_gains").Attr("p", *a.kp).Attr("d", *a.kd).Close();
    } else if (a.kp || a.kd) {
      diags_.Report(DiagKind::Lossy, ActuatorLoc(i),
                    fmt::format("actuator '{}' has only a {} gain; URDF's "
                                "<drake:controller_gains> needs both, so none is written",
                                a.name, a.kp ? "proportional" : "derivative"));
    }
    out_.Close();
    out_.Close();
  }
}

}  // namespace mdlc::writers::urdf
