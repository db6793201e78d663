// build_plant.cc - module -> plant: copy, check, normalize, order.
#include "backend/build_plant.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "backend/inertia_scaled_gains.h"
#include "backend/ref_check.h"
#include "backend/topology.h"
#include "ir/count_text.h"
#include "ir/overloaded.h"

namespace mdlc::backend {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Builds the plant entity by entity. `ok_` turns false on the first error
/// but the builder keeps going, so one run reports every problem it can.
class PlantBuilder {
 public:
  PlantBuilder(const ir::Module& module, DiagnosticEngine& diags)
      : m_(module), diags_(diags) {}

  std::optional<Plant> Build() {
    if (m_.bodies.empty()) {
      diags_.Report(DiagKind::VerifierFailure, {}, "internal: the module has no world body");
      return std::nullopt;
    }
    for (const ir::ModelInstance& model : m_.models) {
      plant_.model_instances.Add(std::string(m_.Text(model.local_name)), model.parent);
    }
    if (m_.gravity) plant_.gravity = *m_.gravity;
    if (m_.time_step) plant_.time_step = *m_.time_step;
    // one plant entity per IR entity: sized once, not regrown (and moved)
    // as a scene of many models fills them
    plant_.bodies.reserve(m_.bodies.size());
    plant_.frames.reserve(m_.frames.size());
    plant_.joints.reserve(m_.joints.size());
    AddBodies();
    for (const ir::Frame& frame : m_.frames) AddFrame(frame);
    for (const ir::Joint& joint : m_.joints) AddJoint(joint);
    // the tree needs valid body ids only, so its problems are reported too
    if (refs_ok_ && !AssignTreeOrder(m_, plant_, diags_)) Fail();
    for (const ir::Actuator& actuator : m_.actuators) AddActuator(actuator);
    for (const ir::Constraint& constraint : m_.constraints) AddConstraint(constraint);
    for (const ir::ForceElement& element : m_.force_elements) AddForceElement(element);
    if (!ok_) return std::nullopt;
    // MJCF gains from the mass matrix at qpos0 (BEYOND-007, BEYOND-008)
    if (!ApplyInertiaScaledGains(m_, plant_, diags_)) return std::nullopt;
    return std::move(plant_);
  }

 private:
  void Fail() { ok_ = false; }

  std::string Scoped(ModelId model, Symbol name) const {
    return model.index() < m_.models.size() ? m_.ScopedName(model, name)
                                            : std::string(m_.Text(name));
  }

  template <typename IdT>
  IdT Resolve(const ir::Ref<IdT>& ref, size_t size, std::string_view what, Loc loc) {
    if (!CheckRef(m_, ref, size, what, loc, diags_)) {
      Fail();
      refs_ok_ = false;
    }
    return ref.id;
  }
  BodyId ResolveBody(const ir::Ref<BodyId>& ref, Loc loc) {
    return Resolve(ref, m_.bodies.size(), "body", loc);
  }
  JointId ResolveJoint(const ir::Ref<JointId>& ref, Loc loc) {
    return Resolve(ref, m_.joints.size(), "joint", loc);
  }
  void CheckEntityModel(ModelId model, Loc loc) {
    if (!CheckModel(m_, model, loc, diags_)) Fail();
  }

  void AddBodies() {
    for (size_t b = 0; b < m_.bodies.size(); ++b) {
      const ir::Body& src = m_.bodies[b];
      if (src.is_world != (b == 0)) {
        diags_.Report(DiagKind::VerifierFailure, src.loc,
                      fmt::format("internal: body '{}' {} the world body but is body {}",
                                  m_.Text(src.name), src.is_world ? "is" : "is not", b));
        Fail();
        refs_ok_ = false;
      }
      CheckEntityModel(src.model, src.loc);
      PlantBody& body = plant_.bodies.emplace_back();
      body.name = m_.Text(src.name);
      body.model = src.model;
      body.is_world = src.is_world;
      body.surface_velocity_axis = src.surface_velocity_axis;
      body.deformable = src.deformable;
      body.unnamed = src.unnamed;
      if (src.inertial) SetMassProperties(*src.inertial, body);
    }
  }

  static void SetMassProperties(const ir::Inertial& in, PlantBody& body) {
    Eigen::Matrix3d I_I;
    I_I << in.ixx, in.ixy, in.ixz,
           in.ixy, in.iyy, in.iyz,
           in.ixz, in.iyz, in.izz;
    const Eigen::Matrix3d& R_BI = in.X_BI.R;
    body.mass = in.mass;
    body.p_BoBcm_B = in.X_BI.p;
    body.I_BBcm_B = R_BI * I_I * R_BI.transpose();
  }

  // the scoped name plant-json uses for a frame: an explicit frame's, or the body's
  std::string FrameName(const ir::FrameRef& ref, Loc loc) {
    if (ref.frame.valid() && ref.frame.index() < m_.frames.size()) {
      const ir::Frame& f = m_[ref.frame];
      return Scoped(f.model, f.name);
    }
    if (ref.body.valid() && ref.body.index() < m_.bodies.size()) return m_.ScopedName(ref.body);
    diags_.Report(DiagKind::VerifierFailure, ref.loc.valid() ? ref.loc : loc,
                  fmt::format("internal: unresolved frame reference '{}'", m_.Text(ref.name)));
    Fail();
    return {};
  }

  // The plant's force element is the IR's with its references resolved:
  // the two are one template (ir/entities.h), copied field by field in step.
  void AddForceElement(const ir::ForceElement& src) {
    CheckEntityModel(src.model, src.loc);
    std::visit(
        [&](const auto& from) {
          using Kind = std::decay_t<decltype(from)>;
          typename Kind::template Rebind<PlantReferences> to;
          Kind::ForEachField(
              [&](std::string_view, const auto& in, auto& out) { out = Resolved(in, src.loc); },
              from, to);
          plant_.force_elements.emplace_back(std::move(to));
        },
        src.payload);
  }
  BodyId Resolved(const ir::Ref<BodyId>& ref, Loc loc) { return ResolveBody(ref, loc); }
  JointId Resolved(const ir::Ref<JointId>& ref, Loc loc) { return ResolveJoint(ref, loc); }
  std::string Resolved(const ir::FrameRef& ref, Loc loc) { return FrameName(ref, loc); }
  template <typename Value>
  const Value& Resolved(const Value& value, Loc) { return value; }  // numbers, vectors

  void AddFrame(const ir::Frame& src) {
    CheckEntityModel(src.model, src.loc);
    plant_.frames.push_back(
        {std::string(m_.Text(src.name)), src.model, ResolveBody(src.body, src.loc), src.X_BF,
         src.unnamed});
  }

  void AddJoint(const ir::Joint& src) {
    CheckEntityModel(src.model, src.loc);
    PlantJoint& joint = plant_.joints.emplace_back();
    joint.name = m_.Text(src.name);
    joint.model = src.model;
    joint.type = src.type;
    joint.parent = ResolveBody(src.parent, src.loc);
    joint.child = ResolveBody(src.child, src.loc);
    joint.X_PF = src.X_PF;
    joint.X_CM = src.X_CM;
    joint.screw_thread_pitch = src.screw_thread_pitch;
    joint.curvilinear_path = src.curvilinear_path;
    joint.unnamed = src.unnamed;
    joint.nq = ir::JointPositionCount(src.type);
    joint.nv = ir::JointVelocityCount(src.type);

    // the axis matters for revolute, prismatic and screw joints only
    const bool uses_axis = src.type == ir::JointType::Revolute ||
                           src.type == ir::JointType::Prismatic ||
                           src.type == ir::JointType::Screw;
    const double norm = src.axis.norm();
    if (uses_axis && !(norm > 0 && std::isfinite(norm))) {
      diags_.Report(DiagKind::ZeroAxis, src.loc,
                    fmt::format("joint '{}' has a zero or non-finite axis",
                                plant_.ScopedName(joint)));
      Fail();
    } else if (uses_axis) {
      joint.axis = src.axis / norm;
    } else {
      joint.axis = src.axis;
    }

    const ir::JointLimits& lim = src.limits;
    const Loc loc = src.loc;
    joint.lower = PerDof(lim.lower, joint, -kInf, "lower limits", loc);
    joint.upper = PerDof(lim.upper, joint, kInf, "upper limits", loc);
    joint.velocity_lower = PerDof(lim.velocity_lower, joint, -kInf, "velocity lower limits", loc);
    joint.velocity_upper = PerDof(lim.velocity_upper, joint, kInf, "velocity upper limits", loc);
    joint.acceleration_lower =
        PerDof(lim.acceleration_lower, joint, -kInf, "acceleration lower limits", loc);
    joint.acceleration_upper =
        PerDof(lim.acceleration_upper, joint, kInf, "acceleration upper limits", loc);
    joint.effort = PerDof(lim.effort, joint, kInf, "effort limits", loc);
    joint.damping = PerDof(src.damping, joint, 0.0, "damping coefficients", loc);
    joint.default_positions = DefaultPositions(src, joint);
  }

  /// `values` padded to the joint's nv with `fill` when empty; an error when
  /// it has some other size.
  ir::DofValues PerDof(const ir::DofValues& values, const PlantJoint& joint, double fill,
                       std::string_view what, Loc loc) {
    if (values.empty()) return ir::DofValues(static_cast<size_t>(joint.nv), fill);
    if (values.size() != static_cast<size_t>(joint.nv)) {
      diags_.Report(DiagKind::BadLimits, loc,
                    fmt::format("joint '{}' has {} {} but {}", plant_.ScopedName(joint),
                                values.size(), what,
                                ir::CountOf(joint.nv, "degree of freedom", "degrees of freedom")));
      Fail();
    }
    return values;
  }

  ir::DofValues DefaultPositions(const ir::Joint& src, const PlantJoint& joint) {
    if (src.default_positions.size() == static_cast<size_t>(joint.nq)) {
      return src.default_positions;
    }
    if (!src.default_positions.empty()) {
      diags_.Report(DiagKind::BadValue, src.loc,
                    fmt::format("joint '{}' has {} but {}", plant_.ScopedName(joint),
                                ir::CountOf(src.default_positions.size(), "default position"),
                                ir::CountOf(joint.nq, "position")));
      Fail();
    }
    // zero, or the identity quaternion [w x y z] first; built whole, so the
    // list is recognized as a shared constant rather than copied and edited
    double q[ir::DofValues::kCapacity] = {};
    if (src.type == ir::JointType::QuaternionFloating) q[0] = 1;
    ir::DofValues positions;
    positions.assign(q, q + joint.nq);
    return positions;
  }

  void AddActuator(const ir::Actuator& src) {
    CheckEntityModel(src.model, src.loc);
    plant_.actuators.push_back({std::string(m_.Text(src.name)), src.model,
                                ResolveJoint(src.joint, src.loc), src.effort_limit,
                                src.gear_ratio, src.rotor_inertia, src.kp, src.kd,
                                src.unnamed});
  }

  void AddConstraint(const ir::Constraint& src) {
    CheckEntityModel(src.model, src.loc);
    auto body = [&](const ir::Ref<BodyId>& ref) { return ResolveBody(ref, src.loc); };
    auto joint = [&](const ir::Ref<JointId>& ref) { return ResolveJoint(ref, src.loc); };
    ConstraintPayload payload = std::visit(
        ir::Overloaded{
            [&](const ir::CouplerConstraint& k) -> ConstraintPayload {
              return CouplerConstraint{joint(k.joint0), joint(k.joint1), k.gear_ratio, k.offset};
            },
            [&](const ir::BallConstraint& k) -> ConstraintPayload {
              return BallConstraint{body(k.body_A), body(k.body_B), k.p_AP, k.p_BQ};
            },
            [&](const ir::DistanceConstraint& k) -> ConstraintPayload {
              return DistanceConstraint{body(k.body_A), body(k.body_B), k.p_AP,     k.p_BQ,
                                        k.distance,     k.stiffness,    k.damping};
            },
            [&](const ir::WeldConstraint& k) -> ConstraintPayload {
              return WeldConstraint{body(k.body_A), body(k.body_B), k.X_AP, k.X_BQ};
            },
            [&](const ir::TendonConstraint& k) -> ConstraintPayload {
              TendonConstraint out;
              for (const ir::Ref<JointId>& ref : k.joints) out.joints.push_back(joint(ref));
              if (k.a.size() != k.joints.size()) {
                diags_.Report(DiagKind::BadValue, src.loc,
                              fmt::format("tendon constraint has {} joints but {} coefficients",
                                          k.joints.size(), k.a.size()));
                Fail();
              }
              out.a = k.a;
              out.offset = k.offset;
              out.lower = k.lower;
              out.upper = k.upper;
              out.stiffness = k.stiffness;
              out.damping = k.damping;
              return out;
            },
        },
        src.payload);
    plant_.constraints.push_back({src.model, std::move(payload)});
  }

  const ir::Module& m_;
  DiagnosticEngine& diags_;
  Plant plant_;
  bool ok_ = true;
  bool refs_ok_ = true;  // every id in range (body 0 is the world)
};

}  // namespace

std::optional<Plant> BuildPlant(const ir::Module& module, DiagnosticEngine& diags) {
  return PlantBuilder(module, diags).Build();
}

}  // namespace mdlc::backend
