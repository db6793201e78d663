// urdf_writer.cc - the compiled model as URDF, with Drake's extensions for
// what plain URDF cannot hold.
//
// URDF puts a link's frame where its inbound joint's child frame M is (a
// joint's origin is the pose of its frame F in the parent link, and the child
// link's frame is F at q = 0). A plant body B whose joint has X_CM != I is
// therefore written as a link whose frame is M: everything on B (inertia,
// geometry, frames, the F frames of outbound joints) is re-expressed in M by
// X_MB = X_CM^-1, exactly; the link's pose in the world is X_WB * X_BM. The
// kinematics and the mass matrix at every q are unchanged.
//
// Mapping (what cannot be written is a -Wlossy warning at its source):
//   weld -> fixed; revolute -> revolute (bounded) or continuous;
//   prismatic -> prismatic; planar -> planar; ball, universal, screw ->
//   <drake:joint>; a floating joint on a root link -> nothing (URDF's root
//   links are free; the default pose is not kept); coupler -> <mimic>;
//   actuators -> <transmission>; ball and distance constraints, tendons,
//   bushings and spring-dampers -> their drake: elements; collision filters
//   -> one <drake:collision_filter_group> per filtered body pair.
// Several model instances become one robot whose names carry their
// instance ("arm/link1"; a nested instance "arm::hand" gives "arm/hand/link1").
// A link, joint, frame or actuator whose written name does not give back its
// scoped name holds a comment naming its instance and name, which mdlc's
// reader restores (ir/original_names.h).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <variant>

#include "backend/writers/drake_out.h"
#include "backend/writers/filter_declarations.h"
#include "backend/writers/names.h"
#include "backend/writers/unique_names.h"
#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"
#include "ir/overloaded.h"

namespace mdlc::writers {
namespace {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// URDF readers other than Drake's (urdfdom) need finite numbers in a
/// <limit>: an unbounded side is written as the largest double.
double FiniteLimit(double value) {
  if (value == kInf) return std::numeric_limits<double>::max();
  if (value == -kInf) return -std::numeric_limits<double>::max();
  return value;
}

bool AllEqual(std::span<const double> values) {
  return std::adjacent_find(values.begin(), values.end(), std::not_equal_to<>()) ==
         values.end();
}

class UrdfWriter : FlatWriterBase {
 public:
  UrdfWriter(const backend::CompiledModel& model, const ir::Module& module,
             const WriteOptions& options, DiagnosticEngine& diags)
      : FlatWriterBase(model, module, options, diags) {}

  std::string Write() {
    names_.ReportFlattening(m_, "URDF robot", diags_);
    out_.Open("robot").Attr("name", names_.model_name());
    out_.Attr("xmlns:drake", "http://drake.mit.edu");
    if (NeedsWorldLink()) WriteLink(ir::kWorldBody);
    for (size_t b = 1; b < plant_.bodies.size(); ++b) WriteLink(BodyId(b));
    for (size_t j = 0; j < plant_.joints.size(); ++j) WriteJoint(JointId(j));
    WriteFrames();
    WriteTransmissions();
    WriteConstraints();
    WriteForceElements();
    WriteCollisionFilters();
    WriteCameras();
    out_.Close();
    return out_.Finish();
  }

 private:
  // -- frames: X_BL, the pose of body B's link frame L in B

  Transform LinkInBody(BodyId body) const {
    const PlantBody& b = plant_.body(body);
    if (!b.inbound_joint.valid()) return {};
    return plant_.joint(b.inbound_joint).X_CM;
  }
  /// X_LA for a pose X_BA given in body B.
  Transform InLink(BodyId body, const Transform& X_BA) const {
    return LinkInBody(body).inverse() * X_BA;
  }

  void Origin(const Transform& X) {
    if (X.IsIdentity()) return;
    out_.Open("origin").Attr("xyz", X.p).Attr("rpy", RpyFromRotation(X.R)).Close();
  }

  // -- links

  bool NeedsWorldLink() const {
    if (plant_.bodies.size() <= 1) return true;  // a robot has at least one link
    for (const PlantJoint& j : plant_.joints) {
      if (j.parent.index() == 0 && !IsFreeRoot(j)) return true;
    }
    for (const auto& g : scene_.geometries) {
      if (g.body.index() == 0) return true;
    }
    for (const auto& f : plant_.frames) {
      if (f.body.index() == 0 && !f.unnamed) return true;
    }
    return false;
  }
  static bool IsFreeRoot(const PlantJoint& j) { return IsFloating(j) && j.parent.index() == 0; }

  void WriteLink(BodyId body) {
    const PlantBody& b = plant_.body(body);
    frame_names_.Take(BodyName(body));
    out_.Open("link").Attr("name", BodyName(body));
    if (body.index() != 0) OriginalName(b.model, b.name, BodyName(body));
    if (b.deformable) {
      diags_.Report(DiagKind::Lossy, BodyLoc(body),
                    fmt::format("link '{}' is deformable; URDF has no deformable bodies, so "
                                "it is written as a massless rigid link",
                                b.name));
    }
    const bool has_mass_properties =
        b.mass != 0 || !b.p_BoBcm_B.isZero(0) || !b.I_BBcm_B.isZero(0);
    if (body.index() != 0 && has_mass_properties) {
      const Transform X_LB = LinkInBody(body).inverse();
      const Eigen::Vector3d p_LBcm = X_LB * b.p_BoBcm_B;
      const Eigen::Matrix3d I = X_LB.R * b.I_BBcm_B * X_LB.R.transpose();
      out_.Open("inertial");
      Origin(Transform::FromTranslation(p_LBcm));
      out_.Open("mass").Attr("value", b.mass).Close();
      out_.Open("inertia")
          .Attr("ixx", I(0, 0))
          .Attr("ixy", I(0, 1))
          .Attr("ixz", I(0, 2))
          .Attr("iyy", I(1, 1))
          .Attr("iyz", I(1, 2))
          .Attr("izz", I(2, 2))
          .Close();
      out_.Close();
    }
    if (b.surface_velocity_axis) {  // EXT-060, in the link frame
      const Eigen::Vector3d axis = LinkInBody(body).R.transpose() * *b.surface_velocity_axis;
      out_.Open("drake:surface_velocity_axis").Attr("axis", axis).Close();
    }
    for (uint32_t i : geometries_by_body_[body.index()]) {
      WriteGeometry(scene_.geometries[i], GeometryLoc(i));
    }
    out_.Close();
  }

  // -- geometry

  void WriteGeometry(const backend::SceneGeometry& g, Loc loc) {
    if (std::holds_alternative<ir::HalfSpace>(g.shape)) {
      diags_.Report(DiagKind::Lossy, loc,
                    fmt::format("geometry '{}' is a half space, which URDF cannot hold; it is "
                                "dropped",
                                g.name));
      return;
    }
    const Transform X_LG = InLink(g.body, g.X_BG);
    if (g.roles & (ir::kIllustrationRole | ir::kPerceptionRole)) {
      if (!(g.roles & ir::kPerceptionRole) || !(g.roles & ir::kIllustrationRole)) {
        diags_.Report(DiagKind::Lossy, loc,
                      fmt::format("geometry '{}' has only the {} role; a URDF visual has both "
                                  "illustration and perception",
                                  g.name,
                                  (g.roles & ir::kIllustrationRole) ? "illustration"
                                                                    : "perception"));
      }
      out_.Open("visual").Attr("name", g.name);
      Origin(X_LG);
      Shape(g, loc, /*collision=*/false);
      Material(g, loc);
      out_.Close();
    }
    if (g.roles & ir::kProximityRole) {
      out_.Open("collision").Attr("name", g.name);
      Origin(X_LG);
      Shape(g, loc, /*collision=*/true);
      WriteProximityProperties(out_, ir::ValueSpelling::Attribute, "URDF", g, loc, diags_);
      out_.Close();
    }
  }

  void Shape(const backend::SceneGeometry& g, Loc loc, bool collision) {
    out_.Open("geometry");
    std::visit(ir::Overloaded{
                   [&](const ir::Box& s) { out_.Open("box").Attr("size", s.size).Close(); },
                   [&](const ir::Sphere& s) {
                     out_.Open("sphere").Attr("radius", s.radius).Close();
                   },
                   [&](const ir::Cylinder& s) {
                     out_.Open("cylinder").Attr("radius", s.radius).Attr("length", s.length);
                     out_.Close();
                   },
                   [&](const ir::Capsule& s) {
                     out_.Open("drake:capsule").Attr("radius", s.radius);
                     out_.Attr("length", s.length).Close();
                   },
                   [&](const ir::Ellipsoid& s) {
                     out_.Open("drake:ellipsoid").Attr("a", s.a).Attr("b", s.b);
                     out_.Attr("c", s.c).Close();
                   },
                   [&](const ir::HalfSpace&) {},
                   [&](const ir::Mesh& s) {
                     out_.Open("mesh");
                     if (auto name = assets_.Name(s.uri, s.resolved, s.uri_loc.valid() ? s.uri_loc : loc)) {
                       out_.Attr("filename", *name);
                     }
                     if (s.scale != Eigen::Vector3d::Ones()) out_.Attr("scale", s.scale);
                     if (s.convex && collision) out_.Open("drake:declare_convex").Close();
                     out_.Close();
                   },
               },
               g.shape);
    out_.Close();
  }

  void Material(const backend::SceneGeometry& g, Loc loc) {
    const ir::Property* diffuse = FindProperty(g, "phong/diffuse");
    const ir::Property* texture = FindProperty(g, "phong/diffuse_map");
    if (!diffuse && !texture) return;
    // a material needs a name (urdfdom); each visual has its own
    out_.Open("material").Attr("name", fmt::format("{}:{}", BodyName(g.body), g.name));
    if (diffuse) {
      if (const auto* rgba = std::get_if<std::vector<double>>(&diffuse->value);
          rgba && rgba->size() == 4) {
        out_.Open("color").Attr("rgba", VectorText(Eigen::Map<const Eigen::Vector4d>(rgba->data())));
        out_.Close();
      }
    }
    if (texture) {
      if (const auto* path = std::get_if<std::string>(&texture->value)) {
        if (auto name = assets_.Name(*path, *path, loc)) {
          out_.Open("texture").Attr("filename", *name).Close();
        }
      }
    }
    out_.Close();
  }

  // -- joints

  void WriteJoint(JointId id) {
    const PlantJoint& j = plant_.joint(id);
    const Loc loc = JointLoc(id);
    if (IsFloating(j)) {
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
      case ir::JointType::Ball: s = {"drake:joint", "ball"}; break;
      case ir::JointType::Universal: s = {"drake:joint", "universal"}; break;
      case ir::JointType::Screw: s = {"drake:joint", "screw"}; break;
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

  static bool IsIdentityPose(const PlantJoint& j) {
    const auto& q = j.default_positions;
    if (j.type == ir::JointType::QuaternionFloating) {
      return q.size() == 7 && q[0] == 1 && q[1] == 0 && q[2] == 0 && q[3] == 0 && q[4] == 0 &&
             q[5] == 0 && q[6] == 0;
    }
    return std::all_of(q.begin(), q.end(), [](double v) { return v == 0; });
  }

  void Dynamics(const PlantJoint& j, Loc loc) {
    if (j.damping.empty() ||
        std::all_of(j.damping.begin(), j.damping.end(), [](double d) { return d == 0; })) {
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

  /// The effort limit URDF writes: an actuated joint's limit is its
  /// actuator's (Drake reads an actuator's effort from its joint's <limit>).
  double EffortOf(JointId id, const PlantJoint& j, Loc loc) {
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

  void Limits(JointId id, const PlantJoint& j, Loc loc) {
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

  // a coupler whose follower is this joint becomes its <mimic> (EXT-010)
  void Mimic(JointId id) {
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

  // -- frames, actuators, constraints, force elements, filters, cameras

  void WriteFrames() {
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

  void WriteTransmissions() {
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

  /// p_LP for a point given in body B.
  Eigen::Vector3d PointInLink(BodyId body, const Eigen::Vector3d& p_BP) const {
    return InLink(body, Transform::FromTranslation(p_BP)).p;
  }

  void BodiesAndPoints(std::string_view prefix, BodyId A, BodyId B, const Eigen::Vector3d& p_AP,
                       const Eigen::Vector3d& p_BQ) {
    out_.Open(fmt::format("{}_body_A", prefix)).Attr("name", BodyName(A)).Close();
    out_.Open(fmt::format("{}_p_AP", prefix)).Attr("value", PointInLink(A, p_AP)).Close();
    out_.Open(fmt::format("{}_body_B", prefix)).Attr("name", BodyName(B)).Close();
    out_.Open(fmt::format("{}_p_BQ", prefix)).Attr("value", PointInLink(B, p_BQ)).Close();
  }

  void WriteConstraints() {
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

  std::string FrameOrLink(const std::string& scoped) const {
    // the plant names a bushing's frames by scoped name ("instance::frame")
    return names_.NamedScoped(scoped);
  }
  /// A frame's name, unique among the robot's links and frames: a frame of
  /// another instance (or of the world) that repeats a name takes its
  /// instance's prefix, then a number (reported).
  std::string FrameName(const backend::PlantFrame& frame, Loc loc) {
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

  void WriteForceElements() {
    for (const backend::ForceElement& f : plant_.force_elements) {
      std::visit(
          ir::Overloaded{
              [&](const backend::LinearBushingRpy& k) {
                out_.Open("drake:linear_bushing_rpy");
                out_.Open("drake:bushing_frameA").Attr("name", FrameOrLink(k.frameA)).Close();
                out_.Open("drake:bushing_frameC").Attr("name", FrameOrLink(k.frameC)).Close();
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

  // one group per declaration (two for a group that ignores another):
  // exactly the plant's filters, in proportion to the declarations
  void WriteCollisionFilters() {
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

  void WriteCameras() {
    for (size_t i = 0; i < scene_.cameras.size(); ++i) {
      diags_.Report(DiagKind::Lossy, CameraLoc(i),
                    fmt::format("camera '{}' is dropped: Drake's URDF has no cameras",
                                scene_.cameras[i].name));
    }
  }

  std::set<size_t> mimicked_, mimic_written_;
  UniqueNames frame_names_;  // links' and frames' names
};

}  // namespace

std::optional<std::string> WriteUrdf(const backend::CompiledModel& model,
                                     const ir::Module& module, const WriteOptions& options,
                                     DiagnosticEngine& diags) {
  return UrdfWriter(model, module, options, diags).Write();
}

}  // namespace mdlc::writers
