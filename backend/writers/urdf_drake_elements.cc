// urdf_drake_elements.cc - the URDF writer's <frame>s and what only Drake's
// URDF holds: constraints, bushings and spring-dampers, and collision filter
// groups; cameras are reported dropped (urdf_writer_detail.h).
#include <fmt/format.h>

#include <variant>

#include "backend/writers/drake_out.h"
#include "backend/writers/filter_declarations.h"
#include "backend/writers/urdf_writer_detail.h"
#include "ir/overloaded.h"

namespace mdlc::writers::urdf {

void UrdfWriter::WriteFrames() {
  for (size_t f = 0; f < plant_.frames.size(); ++f) {
    const backend::PlantFrame& frame = plant_.frames[f];
    if (frame.unnamed) continue;
    const Transform X_LF = InLink(frame.body, frame.X_BF);
    const Loc loc = FrameLoc(f);
    const std::string name = FrameName(frame, loc);
    out_.Open("frame")
        .Attr("name", name)
        .Attr("link", BodyName(frame.body))
        .Attr("xyz", X_LF.p)
        .Attr("rpy", RpyFromRotation(X_LF.R));
    OriginalName(frame.model, frame.name, name);
    out_.Close();
  }
}

void UrdfWriter::BodiesAndPoints(std::string_view prefix, BodyId A, BodyId B,
                                 const Eigen::Vector3d& p_AP, const Eigen::Vector3d& p_BQ) {
  out_.Open(fmt::format("{}_body_A", prefix)).Attr("name", BodyName(A)).Close();
  out_.Open(fmt::format("{}_p_AP", prefix)).Attr("value", PointInLink(A, p_AP)).Close();
  out_.Open(fmt::format("{}_body_B", prefix)).Attr("name", BodyName(B)).Close();
  out_.Open(fmt::format("{}_p_BQ", prefix)).Attr("value", PointInLink(B, p_BQ)).Close();
}

void UrdfWriter::WriteConstraints() {
  for (size_t i = 0; i < plant_.constraints.size(); ++i) {
    const backend::PlantConstraint& c = plant_.constraints[i];
    const Loc loc = ConstraintLoc(i);
    std::visit(
        ir::Overloaded{
            [&](const backend::CouplerConstraint& k) {
              // written as the follower's <mimic>; URDF holds one per joint
              if (mimic_written_.insert(k.joint0.index()).second) return;
              diags_.Report(DiagKind::Lossy, loc,
                            fmt::format("joint '{}' follows more than one joint; URDF's "
                                        "<mimic> holds one, so this coupler is dropped",
                                        plant_.joint(k.joint0).name));
            },
            [&](const backend::BallConstraint& k) {
              out_.Open("drake:ball_constraint");
              BodiesAndPoints("drake:ball_constraint", k.body_A, k.body_B, k.p_AP, k.p_BQ);
              out_.Close();
            },
            [&](const backend::DistanceConstraint& k) {
              out_.Open("drake:distance_constraint");
              BodiesAndPoints("drake:distance_constraint", k.body_A, k.body_B, k.p_AP,
                              k.p_BQ);
              out_.Open("drake:distance_constraint_distance").Attr("value", k.distance).Close();
              out_.Open("drake:distance_constraint_stiffness").Attr("value", k.stiffness);
              out_.Close();
              out_.Open("drake:distance_constraint_damping").Attr("value", k.damping).Close();
              out_.Close();
            },
            [&](const backend::WeldConstraint&) {
              diags_.Report(DiagKind::Lossy, loc,
                            "URDF has no weld constraint (Drake reads none); this one is "
                            "dropped");
            },
            [&](const backend::TendonConstraint& k) {
              out_.Open("drake:tendon_constraint");
              for (size_t n = 0; n < k.joints.size(); ++n) {
                out_.Open("drake:tendon_constraint_joint")
                    .Attr("name", JointName(k.joints[n]))
                    .Attr("a", k.a[n])
                    .Close();
              }
              auto value = [&](std::string_view tag, double v) {
                out_.Open(tag).Attr("value", v).Close();
              };
              value("drake:tendon_constraint_offset", k.offset);
              if (k.lower != -kInf) value("drake:tendon_constraint_lower_limit", k.lower);
              if (k.upper != kInf) value("drake:tendon_constraint_upper_limit", k.upper);
              value("drake:tendon_constraint_stiffness", k.stiffness);
              value("drake:tendon_constraint_damping", k.damping);
              out_.Close();
            },
        },
        c.payload);
  }
}

std::string UrdfWriter::FrameOrLink(const std::string& scoped) const {
  // the plant names a bushing's frames by scoped name ("instance::frame")
  return names_.NamedScoped(scoped);
}

std::string UrdfWriter::FrameName(const backend::PlantFrame& frame, Loc loc) {
  std::string name = Named(frame.model, frame.name);
  if (frame_names_.Take(name)) return name;
  std::string unique = frame.model.index() < plant_.model_instances.size()
                           ? Prefixed(plant_.model_instances[frame.model.index()], frame.name)
                           : name;
  if (!frame_names_.Take(unique)) unique = frame_names_.TakeSuffixed(name);
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("frame '{}' is written as '{}': URDF frames share one namespace "
                            "with the robot's links and other frames",
                            frame.name, unique));
  return unique;
}

void UrdfWriter::WriteForceElements() {
  for (const backend::ForceElement& f : plant_.force_elements) {
    std::visit(
        ir::Overloaded{
            [&](const backend::LinearBushingRpy& k) {
              out_.Open("drake:linear_bushing_rpy");
              out_.Open("drake:bushing_frameA").Attr("name", FrameOrLink(k.frame_A)).Close();
              out_.Open("drake:bushing_frameC").Attr("name", FrameOrLink(k.frame_C)).Close();
              out_.Open("drake:bushing_torque_stiffness").Attr("value", k.torque_stiffness);
              out_.Close();
              out_.Open("drake:bushing_torque_damping").Attr("value", k.torque_damping).Close();
              out_.Open("drake:bushing_force_stiffness").Attr("value", k.force_stiffness);
              out_.Close();
              out_.Open("drake:bushing_force_damping").Attr("value", k.force_damping).Close();
              out_.Close();
            },
            [&](const backend::LinearSpringDamper& k) {
              const std::string p = "drake:linear_spring_damper";
              out_.Open(p);
              out_.Open(p + "_body_A").Attr("name", BodyName(k.body_A)).Close();
              out_.Open(p + "_p_AP").Attr("value", PointInLink(k.body_A, k.p_AP)).Close();
              out_.Open(p + "_body_B").Attr("name", BodyName(k.body_B)).Close();
              out_.Open(p + "_p_BQ").Attr("value", PointInLink(k.body_B, k.p_BQ)).Close();
              out_.Open(p + "_free_length").Attr("value", k.free_length).Close();
              out_.Open(p + "_stiffness").Attr("value", k.stiffness).Close();
              out_.Open(p + "_damping").Attr("value", k.damping).Close();
              out_.Close();
            },
            [&](const backend::JointSpring& k) {
              diags_.Report(DiagKind::Lossy, JointLoc(k.joint),
                            fmt::format("the spring of joint '{}' (stiffness {}) is dropped: "
                                        "URDF has no joint springs",
                                        plant_.joint(k.joint).name, k.stiffness));
            },
        },
        f);
  }
}

void UrdfWriter::WriteCollisionFilters() {
  const std::vector<FilterDeclaration> declarations = DeclarationsWithoutWorld(
      scene_.collision_filters, [&](BodyId body) {
        diags_.Report(DiagKind::Lossy, BodyLoc(body),
                      fmt::format("the collision filter between link '{}' and the world is "
                                  "dropped: a URDF collision filter group cannot name the world",
                                  BodyName(body)));
      });
  int n = 0;
  auto group = [&](const std::vector<BodyId>& members, const std::string& name,
                   const std::string& ignored) {
    out_.Open("drake:collision_filter_group").Attr("name", name);
    for (BodyId b : members) out_.Open("drake:member").Attr("link", BodyName(b)).Close();
    if (!ignored.empty()) {
      out_.Open("drake:ignored_collision_filter_group").Attr("name", ignored).Close();
    }
    out_.Close();
  };
  for (const FilterDeclaration& d : declarations) {
    const std::string name = fmt::format("filter{}", n++);
    if (d.ignores_itself()) {
      group(d.members, name, name);
      continue;
    }
    const std::string ignored = fmt::format("filter{}", n++);
    group(d.members, name, ignored);
    group(d.ignored, ignored, "");
  }
}

void UrdfWriter::WriteCameras() {
  for (size_t i = 0; i < scene_.cameras.size(); ++i) {
    diags_.Report(DiagKind::Lossy, CameraLoc(i),
                  fmt::format("camera '{}' is dropped: Drake's URDF has no cameras",
                              scene_.cameras[i].name));
  }
}

}  // namespace mdlc::writers::urdf
