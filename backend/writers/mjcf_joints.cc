// mjcf_joints.cc - the MJCF writer's joints: <joint> with its range,
// damping, armature and spring; actuators as <motor>, <position> or
// <velocity>; and the force elements MJCF cannot hold (mjcf_writer_detail.h).
#include <fmt/format.h>

#include <algorithm>
#include <variant>

#include "backend/writers/mjcf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::mjcf {

void MjcfWriter::WriteJoint(JointId id, Kind kind, const Eigen::VectorXd& q0, BodyId body,
                            const Transform& X_BM) {
  const PlantJoint& j = plant_.joint(id);
  const Loc loc = JointLoc(id);
  if (kind == Kind::None) return;
  const Transform X_LM = X_BL_[body.index()].inverse() * X_BM;
  if (kind == Kind::Free) {
    if (!j.X_PF.IsIdentity()) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("floating joint '{}' has a frame F other than the world "
                                "frame; MJCF's free joint moves the body in the world frame, "
                                "so its coordinates differ",
                                j.name));
    }
    out_.Open("freejoint");
    if (!j.unnamed) {
      out_.Attr("name", JointName(id));
      // the reader names a free joint after its body
      OriginalName(j.model, j.name, BodyName(j.child));
    }
    out_.Close();
    return;
  }
  out_.Open("joint").Attr("name", JointName(id));
  out_.Attr("type", kind == Kind::Hinge ? "hinge" : kind == Kind::Slide ? "slide" : "ball");
  if (!X_LM.p.isZero(0)) out_.Attr("pos", X_LM.p);
  if (kind != Kind::Ball) {
    out_.Attr("axis", Eigen::Vector3d(X_LM.R * j.axis));
    if (q0[0] != 0) out_.Attr("ref", q0[0]);
    Range(j, loc);
  } else if (std::any_of(j.lower.begin(), j.lower.end(), [](double v) { return v != -kInf; }) ||
             std::any_of(j.upper.begin(), j.upper.end(), [](double v) { return v != kInf; })) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the limits of ball joint '{}' are dropped: mdlc reads no "
                              "MJCF ball joint range",
                              j.name));
  }
  if (!j.damping.empty() && j.damping[0] != 0) out_.Attr("damping", j.damping[0]);
  if (!std::all_of(j.damping.begin(), j.damping.end(),
                   [&](double d) { return d == j.damping[0]; })) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has a different damping per coordinate; MJCF "
                              "holds one, so the first is written",
                              j.name));
  }
  Armature(id, loc);
  Spring(id);
  OriginalName(j.model, j.name, JointName(id));
  out_.Close();
  DropUnwritableLimits(id, loc);
}

void MjcfWriter::Range(const PlantJoint& j, Loc loc) {
  constexpr double kFar = 1e10;
  const bool low = j.lower[0] > -kFar, high = j.upper[0] < kFar;
  if (!low && !high) {
    if (j.lower[0] != -kInf || j.upper[0] != kInf) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has limits [{}, {}], beyond what MuJoCo computes "
                                "with; it is written unbounded",
                                j.name, j.lower[0], j.upper[0]));
    }
    return;
  }
  if (low && high && j.lower[0] >= j.upper[0]) {
    // MJCF reads range="0 0" as no range, and rejects an empty one
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' has limits [{}, {}]; MJCF's range must be a "
                              "non-empty interval, so it is written unbounded",
                              j.name, j.lower[0], j.upper[0]));
    return;
  }
  if (!low || !high) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("joint '{}' is bounded on one side only ([{}, {}]); MJCF's "
                              "range has two finite bounds, so the other one is written as "
                              "{}",
                              j.name, j.lower[0], j.upper[0], low ? kFar : -kFar));
  }
  out_.Attr("range", VectorText(Eigen::Vector2d(low ? j.lower[0] : -kFar,
                                                high ? j.upper[0] : kFar)));
}

void MjcfWriter::DropUnwritableLimits(JointId id, Loc loc) {
  const PlantJoint& j = plant_.joint(id);
  auto bounded = [](const ir::DofValues& lo, const ir::DofValues& hi) {
    for (size_t k = 0; k < lo.size() && k < hi.size(); ++k) {
      if (lo[k] != -kInf || hi[k] != kInf) return true;
    }
    return false;
  };
  if (bounded(j.velocity_lower, j.velocity_upper)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the velocity limits of joint '{}' are dropped: MJCF has none",
                              j.name));
  }
  if (bounded(j.acceleration_lower, j.acceleration_upper)) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the acceleration limits of joint '{}' are dropped: MJCF has "
                              "none",
                              j.name));
  }
  const bool actuated = !actuators_by_joint_[id.index()].empty();
  const bool effort =
      std::any_of(j.effort.begin(), j.effort.end(), [](double e) { return e != kInf; });
  if (effort && !actuated) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("the effort limit of joint '{}' is dropped: it has no "
                              "actuator to hold it as a forcerange",
                              j.name));
  }
}

void MjcfWriter::Armature(JointId id, Loc loc) {
  std::optional<double> armature;
  for (uint32_t i : actuators_by_joint_[id.index()]) {
    const backend::PlantActuator& a = plant_.actuators[i];
    if (a.rotor_inertia == 0) continue;
    const double reflected = a.rotor_inertia * a.gear_ratio * a.gear_ratio;
    if (armature && *armature != reflected) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("joint '{}' has actuators of different reflected inertia; "
                                "MJCF's armature holds one, so the first is written",
                                plant_.joint(id).name));
      continue;
    }
    armature = reflected;
  }
  if (armature) out_.Attr("armature", *armature);
}

void MjcfWriter::Spring(JointId id) {
  for (uint32_t i : springs_by_joint_[id.index()]) {
    const auto& s = std::get<backend::JointSpring>(plant_.force_elements[i]);
    out_.Attr("stiffness", s.stiffness);
    if (s.nominal != 0) out_.Attr("springref", s.nominal);
    written_springs_.insert(id.index());
    return;
  }
}

void MjcfWriter::WriteActuators() {
  if (plant_.actuators.empty()) return;
  out_.Open("actuator");
  for (size_t i = 0; i < plant_.actuators.size(); ++i) {
    const backend::PlantActuator& a = plant_.actuators[i];
    const Loc loc = ActuatorLoc(i);
    const PlantJoint& j = plant_.joint(a.joint);
    const Kind kind = KindOf(j);
    if (kind != Kind::Hinge && kind != Kind::Slide) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("actuator '{}' is dropped: its {} joint '{}' is not written "
                                "as an MJCF hinge or slide",
                                a.name, ir::JointTypeName(j.type), j.name));
      continue;
    }
    const bool kp = a.kp && *a.kp != 0, kd = a.kd && *a.kd != 0;
    const char* tag = kp ? "position" : kd ? "velocity" : "motor";
    out_.Open(tag).Attr("name", Named(a.model, a.name)).Attr("joint", JointName(a.joint));
    if (a.gear_ratio != 1) out_.Attr("gear", a.gear_ratio);
    if (kp) out_.Attr("kp", *a.kp);
    if (kd) out_.Attr("kv", *a.kd);
    // the joint's effort limit is its actuator's (as the URDF writer does)
    double effort = a.effort_limit;
    if (effort == kInf && !j.effort.empty()) effort = j.effort[0];
    if (effort != kInf) out_.Attr("forcerange", VectorText(Eigen::Vector2d(-effort, effort)));
    OriginalName(a.model, a.name, Named(a.model, a.name));
    out_.Close();
  }
  out_.Close();
}

void MjcfWriter::WriteForceElements() {
  for (size_t i = 0; i < plant_.force_elements.size(); ++i) {
    const Loc loc = ForceElementLoc(i);
    std::visit(ir::Overloaded{
                   [&](const backend::LinearBushingRpy& k) {
                     diags_.Report(DiagKind::Lossy, loc,
                                   fmt::format("the bushing between frames '{}' and '{}' is "
                                               "dropped: MJCF has no bushings",
                                               k.frame_A, k.frame_C));
                   },
                   [&](const backend::LinearSpringDamper& k) {
                     diags_.Report(DiagKind::Lossy, loc,
                                   fmt::format("the spring-damper between bodies '{}' and "
                                               "'{}' is dropped: the MJCF writer writes no "
                                               "spatial tendons",
                                               BodyName(k.body_A), BodyName(k.body_B)));
                   },
                   [&](const backend::JointSpring& k) {
                     if (written_springs_.count(k.joint.index())) return;
                     diags_.Report(DiagKind::Lossy, JointLoc(k.joint),
                                   fmt::format("the spring of joint '{}' is dropped: the "
                                               "joint is not written as an MJCF hinge or "
                                               "slide, or has another spring",
                                               plant_.joint(k.joint).name));
                   },
               },
               plant_.force_elements[i]);
  }
}

}  // namespace mdlc::writers::mjcf
