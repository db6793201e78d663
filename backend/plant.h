// plant.h - the instantiated multibody plant: plain data, no behaviour.
//
// A Plant is what BuildPlant (build_plant.h) makes of a resolved ir::Module.
// It owns copies of everything it needs (names included), so it outlives the
// Module it was built from. Tables keep the IR's indices: plant body i is IR
// body i, plant joint j is IR joint j, and so on; `BodyId`, `JointId` and
// `ModelId` therefore index both. Body 0 is the world body; model instance 0
// is WorldModelInstance and 1 is DefaultModelInstance.
//
// Conventions (Drake's): X_AB is the pose of frame B in frame A. A joint
// connects frame F, fixed on its parent body P (X_PF), with frame M, fixed on
// its child body C (X_CM); its motion is X_FM(q) (kinematics.h). Mass
// properties are about the body's center of mass and expressed in the body
// frame. Generalized positions q and velocities v are laid out joint by joint
// in `joint_order` (tree order: by tree level, and in IR order within a level).
//
// Adding a plant entity kind or a field (after the IR's, ir/entities.h):
//   here (or scene_graph.h)     the struct
//   build_plant.cc (or build_scene_graph.cc)   IR -> plant
//   plant_json.cc, plant_json.md   plant-json and its contract (mdlc-plant/1)
//   tools/python/py_model.{h,cc}   the Python model
//   tools/mdlc/view.cc          only what the viewer draws
//   entity_index.cc             what the writers look up by body or joint
// Driven from one place (plant_json.md still names a new key):
//   a constraint's field        its VisitFields (below): plant-json and Python
//   a force element's field     the IR's struct (ir/entities.h): the plant's
//                               copy, plant-json and Python
//   a shape field, a role       ir/shape_parameters.h, ir::kGeometryRoleNames
// Then add it to tests/models/every_entity/, which test_every_entity.py
// compares across `--emit=ir`, plant-json and Python.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "backend/model_instance_names.h"
#include "ir/entities.h"
#include "ir/ids.h"
#include "ir/transform.h"

namespace mdlc::backend {

struct PlantBody {
  std::string name;  // local name; Plant::ScopedName gives "instance::name"
  ModelId model;
  double mass = 0;
  Eigen::Vector3d p_BoBcm_B = Eigen::Vector3d::Zero();  // center of mass in B
  Eigen::Matrix3d I_BBcm_B = Eigen::Matrix3d::Zero();   // inertia about Bcm, in B
  bool is_world = false;
  std::optional<Eigen::Vector3d> surface_velocity_axis;  // unit, in B (EXT-060)
  /// A deformable link (EXT-070): outside the rigid plant's dynamics; it is
  /// kept as a massless body so its geometry and properties stay reachable.
  OptionalBox<ir::DeformableProperties> deformable;
  bool unnamed = false;  // named by the compiler
  // topology: the joint whose child this body is, its parent body and its
  // depth in the tree (world: invalid ids, level 0)
  JointId inbound_joint;
  BodyId parent;
  int level = 0;
};

struct PlantFrame {
  std::string name;
  ModelId model;
  BodyId body;
  Transform X_BF;
  bool unnamed = false;  // named by the compiler
};

/// A joint, with every per-coordinate vector normalized to its full length:
/// limits, effort and damping have `nv` entries (+-infinity / 0 when the IR
/// gave none) and `default_positions` has `nq` (zero, or the identity
/// quaternion [1, 0, 0, 0] for quaternion_floating, where the IR gave none).
struct PlantJoint {
  std::string name;  // local name; Plant::ScopedName gives "instance::name"
  ModelId model;
  ir::JointType type = ir::JointType::Weld;
  BodyId parent, child;
  Transform X_PF, X_CM;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit, in F
  ir::DofValues lower, upper;
  ir::DofValues velocity_lower, velocity_upper;
  ir::DofValues acceleration_lower, acceleration_upper;
  ir::DofValues effort;
  ir::DofValues damping;
  ir::DofValues default_positions;
  double screw_thread_pitch = 0;  // meters per revolution
  ir::CurvilinearPath curvilinear_path;  // curvilinear joints: X_FM(q) = path pose at s = q
  bool unnamed = false;           // synthesized by the compiler
  int q_start = 0, nq = 0;        // this joint's slice of q
  int v_start = 0, nv = 0;        // this joint's slice of v
};

struct PlantActuator {
  std::string name;
  ModelId model;
  JointId joint;
  double effort_limit = 0;  // +infinity when unbounded
  double gear_ratio = 1;
  double rotor_inertia = 0;
  std::optional<double> kp, kd;
  bool unnamed = false;  // named by the compiler
};

// Constraints: the IR's (ir::CouplerConstraint, ...) with references
// resolved to ids. Like the force elements below, each lists its fields once
// in VisitFields, for plant-json and Python's Constraint.parameters; a value
// may also be a Transform, a std::vector<double> or a std::vector<JointId>.
struct CouplerConstraint {  // q0 = gear_ratio * q1 + offset (joint0 follows)
  JointId joint0, joint1;
  double gear_ratio = 1, offset = 0;
  template <typename Visit>
  void VisitFields(Visit&& visit) const {
    visit("joint0", joint0);
    visit("joint1", joint1);
    visit("gear_ratio", gear_ratio);
    visit("offset", offset);
  }
};
struct BallConstraint {  // P (on A) and Q (on B) coincide
  BodyId body_A, body_B;
  Eigen::Vector3d p_AP = Eigen::Vector3d::Zero(), p_BQ = Eigen::Vector3d::Zero();
  template <typename Visit>
  void VisitFields(Visit&& visit) const {
    visit("body_A", body_A);
    visit("body_B", body_B);
    visit("p_AP", p_AP);
    visit("p_BQ", p_BQ);
  }
};
struct DistanceConstraint {  // |p_PQ| = distance
  BodyId body_A, body_B;
  Eigen::Vector3d p_AP = Eigen::Vector3d::Zero(), p_BQ = Eigen::Vector3d::Zero();
  double distance = 0, stiffness = 0, damping = 0;
  template <typename Visit>
  void VisitFields(Visit&& visit) const {
    visit("body_A", body_A);
    visit("body_B", body_B);
    visit("p_AP", p_AP);
    visit("p_BQ", p_BQ);
    visit("distance", distance);
    visit("stiffness", stiffness);
    visit("damping", damping);
  }
};
struct WeldConstraint {  // frames P (on A) and Q (on B) coincide
  BodyId body_A, body_B;
  Transform X_AP, X_BQ;
  template <typename Visit>
  void VisitFields(Visit&& visit) const {
    visit("body_A", body_A);
    visit("body_B", body_B);
    visit("X_AP", X_AP);
    visit("X_BQ", X_BQ);
  }
};
struct TendonConstraint {  // lower <= sum a_i q_i + offset <= upper
  std::vector<JointId> joints;
  std::vector<double> a;
  double offset = 0, lower = 0, upper = 0, stiffness = 0, damping = 0;
  template <typename Visit>
  void VisitFields(Visit&& visit) const {
    visit("joints", joints);
    visit("a", a);
    visit("offset", offset);
    visit("lower", lower);
    visit("upper", upper);
    visit("stiffness", stiffness);
    visit("damping", damping);
  }
};
/// Alternatives in the order of ir::ConstraintType.
using ConstraintPayload = std::variant<CouplerConstraint, BallConstraint, DistanceConstraint,
                                       WeldConstraint, TendonConstraint>;
struct PlantConstraint {
  ModelId model;
  ConstraintPayload payload;
  ir::ConstraintType type() const { return static_cast<ir::ConstraintType>(payload.index()); }
};

// Force elements, with references resolved: the IR's structs
// (ir/entities.h), instantiated with ids for bodies and joints and scoped
// names ("model::frame") for frames. Their fields, and the order plant-json
// and Python's Model.force_elements write them in, are the IR's
// ForEachField; ForceElementTypeName names the kind.
struct PlantReferences {
  using Body = BodyId;
  using Joint = JointId;
  using Frame = std::string;
};
using LinearBushingRpy = ir::LinearBushingRpyOf<PlantReferences>;
using LinearSpringDamper = ir::LinearSpringDamperOf<PlantReferences>;
using JointSpring = ir::JointSpringOf<PlantReferences>;
using ForceElement = ir::ForceElementVariant<PlantReferences>;

struct Plant {
  ModelInstanceNames model_instances;        // names, by ModelId
  std::vector<PlantBody> bodies;             // by BodyId; 0 is world
  std::vector<PlantFrame> frames;            // by FrameId
  std::vector<PlantJoint> joints;            // by JointId
  std::vector<PlantActuator> actuators;      // by ActuatorId
  std::vector<PlantConstraint> constraints;  // by ConstraintId
  std::vector<ForceElement> force_elements;

  /// Every body, parents before children; world first.
  std::vector<BodyId> body_order;
  /// Every joint in tree order (the inbound joints of body_order[1..]); this
  /// is the order of the joints' slices in q and v.
  std::vector<JointId> joint_order;
  int num_positions = 0;
  int num_velocities = 0;

  Eigen::Vector3d gravity{0, 0, -9.81};  // m/s^2, in world
  double time_step = 0;                  // s; 0 = continuous

  const PlantBody& body(BodyId id) const { return bodies[id.index()]; }
  const PlantJoint& joint(JointId id) const { return joints[id.index()]; }

  /// "instance::name" of a body ("world" for the world body) or a joint,
  /// built on each call (O(nesting depth)): names are stored unscoped.
  std::string ScopedName(const PlantBody& b) const {
    return b.is_world ? std::string("world") : model_instances.Scoped(b.model, b.name);
  }
  std::string ScopedName(const PlantJoint& j) const {
    return model_instances.Scoped(j.model, j.name);
  }
};

/// A force element's kind as plant-json and Python name it: a joint spring is
/// a prismatic_spring on a prismatic joint and a revolute_spring otherwise.
inline std::string_view ForceElementTypeName(const Plant& plant, const ForceElement& element) {
  if (std::holds_alternative<LinearBushingRpy>(element)) return "linear_bushing_rpy";
  if (std::holds_alternative<LinearSpringDamper>(element)) return "linear_spring_damper";
  const JointSpring& spring = std::get<JointSpring>(element);
  return plant.joint(spring.joint).type == ir::JointType::Prismatic ? "prismatic_spring"
                                                                     : "revolute_spring";
}

}  // namespace mdlc::backend
