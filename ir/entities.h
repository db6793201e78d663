// entities.h - the typed IR: plain structs, one per entity kind.
//
// Entities refer to each other by typed ids (ids.h), never by pointer, so a
// Module can be copied, printed and compared. A reference that a frontend
// reads from the file starts as a name (`Ref::name`, with its location) and a
// pass (resolve-names) fills in `Ref::id`. Every entity carries the location
// of the element that declared it.
//
// Units are SI and angles radians everywhere: frontends normalise on the way in.
//
// Adding an entity kind or a field: the places that decide something.
//   here                      the struct (a payload kind: its variant and type enum)
//   ir/module.h, ir/ids.h     a new kind's table and id
//   frontend/                 each reader that fills it (urdf/, sdf/, mjcf/,
//                             directives/, drake_elements.cc for drake: tags)
//   passes/resolve_names.cc   its references (Ref<>, FrameRef)
//   ir/verifier.cc            what a well-formed one is
//   ir/printer.cc             `--emit=ir` (and the golden files, tests/golden);
//                             a force element's fields print from its VisitFields
//   backend/plant.h           the plant's copy: see the checklist there
//   backend/writers/          each format that can write it
// Driven from one place, nothing else to change:
//   a geometry role           kGeometryRoleNames: the role names of every output
//   a shape or shape field    ir/shape_parameters.h: plant-json, `mdlc view`, Python
//   a format's names          ir/format.h
//   a force element field     its struct and ForEachField here: `--emit=ir`,
//                             the plant's copy, plant-json and Python
// tests/models/every_entity/ holds one of every kind the plant holds: add the
// new kind or field there, and tests/python/test_every_entity.py fails until
// `--emit=ir`, plant-json and the Python model all show it.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "ir/curvilinear_path.h"
#include "ir/dof_values.h"
#include "ir/ids.h"
#include "ir/location.h"
#include "ir/optional_box.h"
#include "ir/symbol.h"
#include "ir/transform.h"

namespace mdlc::ir {

/// A reference to another entity: the (possibly scoped) name the source
/// wrote, and the id a pass resolved it to.
template <typename IdT>
struct Ref {
  Symbol name;
  Loc loc;
  IdT id;
  bool resolved() const { return id.valid(); }
};

enum class SourceFormat { Urdf, Sdf, Mjcf, Directives, Internal };

/// Whole-model corrections of mass properties that MuJoCo's compiler applies
/// after every body's mass properties are known (MJCF compiler attributes,
/// BEYOND-006), in this order: boundmass/boundinertia, balanceinertia,
/// settotalmass. Bodies other than the world body only.
struct MassAdjustments {
  double bound_mass = 0;      // compiler@boundmass: mass at least this
  double bound_inertia = 0;   // compiler@boundinertia: principal moments at least this
  bool balance_inertia = false;  // compiler@balanceinertia: fix triangle-inequality violations
  std::optional<double> total_mass;  // compiler@settotalmass (> 0): scale all masses and inertias
};

/// A model instance's name is stored as its parent's plus its own local
/// part, never spelled out in full, so that N nested instances cost O(N)
/// memory (issue 16); Module::ModelName builds the full "a::b::c" on demand.
struct ModelInstance {
  /// The name below `parent` ("c" of "a::b::c"); a top-level instance's whole
  /// name, which may itself hold "::" (a Model Directives namespace)
  Symbol local_name;
  Loc loc;
  SourceFormat format = SourceFormat::Internal;
  std::optional<MassAdjustments> mass_adjustments;  // MJCF only
  /// The instance this one is nested in (SDFormat nested models); invalid at top level
  ModelId parent;
};

/// Mass properties exactly as the file gave them: mass, the pose of the
/// inertia frame I in the body frame B, and the moments and products of
/// inertia about the center of mass expressed in I. The check-inertia pass
/// validates them; the backend re-expresses them in B.
struct Inertial {
  Loc loc;
  double mass = 0;
  Transform X_BI;
  double ixx = 0, iyy = 0, izz = 0, ixy = 0, ixz = 0, iyz = 0;
};

/// A deformable body's FEM parameters (Drake's DeformableBodyConfig, with its
/// defaults) and wall boundary conditions (EXT-070).
struct DeformableProperties {
  Loc loc;  // the drake:deformable_properties element
  double youngs_modulus = 1e8;   // Pa, > 0
  double poissons_ratio = 0.49;  // in (-1, 0.5)
  double mass_damping = 0;       // 1/s, >= 0
  double stiffness_damping = 0;  // s, >= 0
  double mass_density = 1.5e3;   // kg/m^3, > 0
  /// linear_corotated, corotated, neohookean or linear
  std::string material_model = "linear_corotated";
  /// drake:mesh_resolution_hint of a sphere collision (tetrahedralization); absent for meshes
  std::optional<double> resolution_hint;
  /// drake:wall_boundary_condition: nodes in the half space behind the plane
  /// through point_on_plane, with unit outward_normal (both in world) are fixed
  struct WallBoundaryCondition {
    Eigen::Vector3d point_on_plane = Eigen::Vector3d::Zero();
    Eigen::Vector3d outward_normal = Eigen::Vector3d::UnitZ();
    template <typename Visit> void VisitFields(Visit&& visit) const {
      visit("point_on_plane", point_on_plane);
      visit("outward_normal", outward_normal);
    }
  };
  std::vector<WallBoundaryCondition> wall_boundary_conditions;
  /// Each field once, in plant-json's order (`bodies[].deformable`), which
  /// Python's Body.deformable follows too.
  template <typename Visit> void VisitFields(Visit&& visit) const {
    visit("youngs_modulus", youngs_modulus);
    visit("poissons_ratio", poissons_ratio);
    visit("mass_damping", mass_damping);
    visit("stiffness_damping", stiffness_damping);
    visit("mass_density", mass_density);
    visit("material_model", material_model);
    visit("resolution_hint", resolution_hint);
    visit("wall_boundary_conditions", wall_boundary_conditions);
  }
};

struct Body {
  Symbol name;
  ModelId model;
  Loc loc;
  std::optional<Inertial> inertial;  // absent: massless body
  bool is_world = false;             // the one world body (body 0)
  /// drake:surface_velocity_axis (EXT-060): a unit axis in the body frame
  std::optional<Eigen::Vector3d> surface_velocity_axis;
  /// X_WB where the file places the body (SDFormat links); a free body's
  /// floating joint starts there (SDF-008)
  std::optional<Transform> default_pose;
  /// drake:deformable_properties (EXT-070): the link is a deformable body,
  /// simulated by FEM outside the rigid plant. It has no mass and no joint
  /// in the rigid plant; its one collision (and optional visual) geometry
  /// stays registered on it.
  OptionalBox<DeformableProperties> deformable;  // boxed: rare, and 136 bytes
  /// SDFormat <inertial auto="true"> (SDF-007): the mass properties are
  /// computed from the body's collision geometry at this density (kg/m^3)
  std::optional<double> inertia_from_collisions;
  /// ... and scaled to this total mass, when the <inertial> gives one
  std::optional<double> inertia_from_collisions_mass;
  /// MJCF inertiafromgeom (MJCF-005, MJCF-031): the mass properties are the
  /// sum of the geometries' MassContribution on this body (none: massless);
  /// `inertial` is ignored and overwritten by the mass-properties pass.
  bool mass_from_geometry = false;
  /// MJCF free-joint alignment (<freejoint align>, compiler@alignfree): once
  /// the mass properties are known, the mass-from-geometry pass moves the
  /// body frame to the body's principal inertial frame and re-expresses its
  /// geometries, frames, cameras, inertia and free joint, so that world
  /// poses are unchanged. `aligned_default_pose`: default_pose and the free
  /// joint's default positions already place the aligned frame (a
  /// keyframe's qpos), so the pass keeps them.
  bool align_free = false;
  bool aligned_default_pose = false;
  bool unnamed = false;  // named by the compiler (MJCF-020, MJCF-023)
};

/// A frame fixed to a body: X_BF.
struct Frame {
  Symbol name;
  ModelId model;
  Loc loc;
  Ref<BodyId> body;
  Transform X_BF;
  bool unnamed = false;  // named by the compiler
};

enum class JointType {
  Revolute,
  Prismatic,
  Ball,
  Universal,
  Planar,
  Screw,
  Curvilinear,
  Weld,
  QuaternionFloating,
  RpyFloating,
};
/// Drake's name for the type ("revolute", "quaternion_floating", ...).
std::string_view JointTypeName(JointType type);
/// Number of position coordinates (quaternion floating: 7) and of velocities.
int JointPositionCount(JointType type);
int JointVelocityCount(JointType type);

/// Limits per velocity coordinate; +-infinity when unbounded.
struct JointLimits {
  /// Unbounded limits for `nv` velocity coordinates.
  static JointLimits Unbounded(int nv);

  DofValues lower, upper;  // position
  DofValues velocity_lower, velocity_upper;
  DofValues acceleration_lower, acceleration_upper;
  DofValues effort;  // symmetric, per dof
};

/// A joint connects frame F, fixed on the parent body (X_PF), with frame M,
/// fixed on the child body (X_CM); the joint's motion is X_FM(q).
struct Joint {
  Symbol name;
  ModelId model;
  Loc loc;
  JointType type = JointType::Weld;
  Ref<BodyId> parent;
  Ref<BodyId> child;
  Transform X_PF;
  Transform X_CM;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();  // unit, in F (== in M)
  JointLimits limits;
  DofValues damping;            // per velocity coordinate
  DofValues default_positions;  // per position coordinate; empty = zero/identity
  double screw_thread_pitch = 0;          // screw joints: meters per revolution
  CurvilinearPath curvilinear_path;       // curvilinear joints: the path M follows in F
  bool unnamed = false;                   // synthesized by the compiler
};

struct Box { Eigen::Vector3d size = Eigen::Vector3d::Zero(); };
struct Sphere { double radius = 0; };
struct Cylinder { double radius = 0, length = 0; };
struct Capsule { double radius = 0, length = 0; };
struct Ellipsoid { double a = 0, b = 0, c = 0; };
struct HalfSpace {};
/// A mesh the model file holds itself (MJCF <mesh vertex="..." face="...">),
/// in the mesh frame (MuJoCo's refpos/refquat applied), unscaled. No faces:
/// a point cloud, whose convex hull is the mesh (as MuJoCo takes it).
struct InlineMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> faces;
};
struct Mesh {
  std::string uri;       // as written
  Loc uri_loc;           // where it is written
  std::string resolved;  // filesystem path once resolved (inline meshes: their key, no file)
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  bool convex = false;   // drake:declare_convex / convex hull requested
  std::shared_ptr<const InlineMesh> inline_data;  // set: no file, the mesh is this
};
using Shape = std::variant<Box, Sphere, Cylinder, Capsule, Ellipsoid, HalfSpace, Mesh>;

/// How a mesh's mass properties are computed (MuJoCo's mesh@inertia):
/// the solid convex hull, the exact solid (closed mesh, divergence theorem),
/// MuJoCo's legacy volume rule, or a thin shell on the surface.
enum class MeshInertia { Convex, Exact, Legacy, Shell };

/// A geometry's share of its body's mass when the body's mass properties come
/// from geometry (Body::mass_from_geometry; MJCF-031).
struct MassContribution {
  std::optional<double> mass;  // geom@mass: total mass of this geometry, wins over density
  double density = 1000;       // kg/m^3 (kg/m^2 when shell)
  bool shell = false;          // geom@shellinertia: mass spread over the surface
  MeshInertia mesh_inertia = MeshInertia::Legacy;  // mesh shapes: mesh@inertia (MuJoCo 3.3 default: legacy)
};

/// A primitive geometry (box, sphere, capsule, cylinder, ellipsoid) whose
/// size and pose come from a mesh, as MuJoCo fits them (BEYOND-002). The
/// geometry's shape holds the primitive's type with zero size and X_BG the
/// geom frame until the fit-to-mesh step sets the size and composes the
/// mesh's principal frame onto X_BG.
struct MeshFit {
  Mesh mesh;           // the mesh asset: uri, resolved path, scale
  bool aabb = false;   // compiler@fitaabb: fit the bounding box, not the equivalent inertia box
  double fitscale = 1; // geom@fitscale: scales the fitted size
  MeshInertia mesh_inertia = MeshInertia::Legacy;
};
/// Drake's shape type name ("box", ..., "mesh" or "convex" for meshes).
std::string_view ShapeTypeName(const Shape& shape);

enum GeometryRole : uint8_t {
  kProximityRole = 1,
  kIllustrationRole = 2,
  kPerceptionRole = 4,
};

/// Every role bit with the name every output gives it (`--emit=ir`,
/// plant-json, `mdlc view`, Python), in the order they list a geometry's
/// roles. A new role is added here and nowhere else.
struct GeometryRoleName {
  GeometryRole role;
  std::string_view name;
};
inline constexpr std::array<GeometryRoleName, 3> kGeometryRoleNames = {{
    {kProximityRole, "proximity"},
    {kIllustrationRole, "illustration"},
    {kPerceptionRole, "perception"},
}};

/// Calls fn(name) for each role set in `roles` (GeometryRole bits), in
/// kGeometryRoleNames order.
template <typename Fn>
void ForEachRoleName(uint8_t roles, Fn&& fn) {
  for (const GeometryRoleName& r : kGeometryRoleNames) {
    if (roles & r.role) fn(r.name);
  }
}

/// A value in a geometry's property map.
using PropertyValue = std::variant<bool, double, std::string, std::vector<double>,
                                   std::vector<std::string>>;
struct Property {
  std::string key;  // "group/name"
  PropertyValue value;
};

struct Material {
  Symbol name;
  ModelId model;
  Loc loc;
  std::optional<Eigen::Vector4d> rgba;
  std::string texture;
};

struct Geometry {
  Symbol name;
  ModelId model;
  Loc loc;
  Ref<BodyId> body;
  Transform X_BG;
  Shape shape;
  uint8_t roles = 0;  // GeometryRole bits
  Ref<MaterialId> material;  // optional; empty name when none
  std::optional<Eigen::Vector4d> rgba;  // inline color, wins over material
  std::vector<Property> properties;
  /// kg/m^3, for mass properties computed from collisions (SDFormat <density>)
  std::optional<double> density;
  /// MJCF: this geometry's share of its body's mass (Body::mass_from_geometry).
  /// A geom registered twice (illustration and proximity) carries it once.
  std::optional<MassContribution> mass_contribution;
  /// MJCF: a primitive sized from a mesh (BEYOND-002).
  OptionalBox<MeshFit> fit_to_mesh;  // boxed: rare, and 144 bytes
  bool unnamed = false;  // named by the compiler
};

/// Name scopes, at most one per role: a list that never allocates (the
/// unique-names pass asks for every entity's, twice).
struct NameScopeList {
  std::array<uint64_t, 3> items{};
  size_t count = 0;
  const uint64_t* begin() const { return items.data(); }
  const uint64_t* end() const { return items.data() + count; }
};

/// The scopes a geometry's name must be unique in, as Drake's scene graph
/// requires: its body, once per role it has (body and role in one key).
NameScopeList NameScopes(const Geometry& geometry);

struct Actuator {
  Symbol name;
  ModelId model;
  Loc loc;
  Ref<JointId> joint;
  double effort_limit = std::numeric_limits<double>::infinity();
  double gear_ratio = 1;
  double rotor_inertia = 0;
  std::optional<double> kp, kd;
  bool unnamed = false;  // named by the compiler
};

/// Drake's AddCouplerConstraint: q0 = gear_ratio * q1 + offset, joint0 being
/// the joint that follows (the mimicking joint) and joint1 the joint it follows.
struct CouplerConstraint {
  Ref<JointId> joint0, joint1;
  double gear_ratio = 1, offset = 0;
};
/// Drake's AddBallConstraint: point P of body A coincides with point Q of B.
struct BallConstraint {
  Ref<BodyId> body_A, body_B;
  Eigen::Vector3d p_AP = Eigen::Vector3d::Zero(), p_BQ = Eigen::Vector3d::Zero();
};
/// Drake's AddDistanceConstraint: |p_PQ| = distance, rigid when stiffness is
/// infinite.
struct DistanceConstraint {
  Ref<BodyId> body_A, body_B;
  Eigen::Vector3d p_AP = Eigen::Vector3d::Zero(), p_BQ = Eigen::Vector3d::Zero();
  double distance = 0, stiffness = 0, damping = 0;
};
/// Drake's AddWeldConstraint: frame P (on A) coincides with frame Q (on B).
struct WeldConstraint {
  Ref<BodyId> body_A, body_B;
  Transform X_AP, X_BQ;
};
/// Drake's AddTendonConstraint: lower <= sum a_i q_i + offset <= upper.
struct TendonConstraint {
  std::vector<Ref<JointId>> joints;
  std::vector<double> a;
  double offset = 0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double stiffness = std::numeric_limits<double>::infinity(), damping = 0;
};

/// The kinds of constraint, in the order of ConstraintPayload's alternatives.
enum class ConstraintType { Coupler, Ball, Distance, Weld, Tendon };
std::string_view ConstraintTypeName(ConstraintType type);
using ConstraintPayload = std::variant<CouplerConstraint, BallConstraint, DistanceConstraint,
                                       WeldConstraint, TendonConstraint>;

struct Constraint {
  ModelId model;
  Loc loc;
  ConstraintPayload payload;
  ConstraintType type() const { return static_cast<ConstraintType>(payload.index()); }
  /// The payload of kind T (the caller knows the kind).
  template <typename T> T& As() { return std::get<T>(payload); }
  template <typename T> const T& As() const { return std::get<T>(payload); }
};

struct CollisionFilterGroup {
  Symbol name;
  ModelId model;
  Loc loc;
  std::vector<Ref<BodyId>> members;
  std::vector<Ref<FilterGroupId>> member_groups;
  std::vector<Ref<FilterGroupId>> ignored_groups;
};

/// A reference to a frame that may be a body's own frame (a link name) or an
/// explicit Frame; resolve-names fills exactly one of `frame` and `body`.
struct FrameRef {
  Symbol name;
  Loc loc;
  FrameId frame;
  BodyId body;
  bool resolved() const { return frame.valid() || body.valid(); }
};

// Force elements are written once, here, for the IR and the plant both: each
// is a template over how it refers to other entities. The IR instantiates it
// with references as read (IrReferences: a name and location that
// resolve-names fills in), the plant (backend/plant.h) with resolved ones
// (PlantReferences: ids, scoped frame names). Each lists its fields once, in
// ForEachField: visit(name, field...) per field, in the order every output
// writes them, over one element or several of the same kind in step (the
// backend copies the IR's into the plant's that way). So a field added here,
// with its line in ForEachField, reaches `--emit=ir`, the plant, plant-json
// and Python; only its reader sets it and its consumer uses it. The names are
// plant-json's (mdlc-plant/1).

/// How the IR's force elements refer to bodies, joints and frames.
struct IrReferences {
  using Body = Ref<BodyId>;
  using Joint = Ref<JointId>;
  using Frame = FrameRef;
};

/// Drake's LinearBushingRollPitchYaw between frames A and C, gains per axis.
template <typename References>
struct LinearBushingRpyOf {
  static constexpr std::string_view kKind = "linear_bushing_rpy";
  template <typename Other> using Rebind = LinearBushingRpyOf<Other>;
  typename References::Frame frame_A, frame_C;
  Eigen::Vector3d torque_stiffness = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque_damping = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_stiffness = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_damping = Eigen::Vector3d::Zero();
  template <typename Visit, typename... Self>
  static void ForEachField(Visit&& visit, Self&... self) {
    visit("frameA", self.frame_A...);
    visit("frameC", self.frame_C...);
    visit("torque_stiffness", self.torque_stiffness...);
    visit("torque_damping", self.torque_damping...);
    visit("force_stiffness", self.force_stiffness...);
    visit("force_damping", self.force_damping...);
  }
  template <typename Visit> void VisitFields(Visit&& visit) const { ForEachField(visit, *this); }
};
/// Drake's LinearSpringDamper between point P of body A and point Q of body B.
template <typename References>
struct LinearSpringDamperOf {
  static constexpr std::string_view kKind = "linear_spring_damper";
  template <typename Other> using Rebind = LinearSpringDamperOf<Other>;
  typename References::Body body_A, body_B;
  Eigen::Vector3d p_AP = Eigen::Vector3d::Zero(), p_BQ = Eigen::Vector3d::Zero();
  double free_length = 0, stiffness = 0, damping = 0;
  template <typename Visit, typename... Self>
  static void ForEachField(Visit&& visit, Self&... self) {
    visit("body_A", self.body_A...);
    visit("p_AP", self.p_AP...);
    visit("body_B", self.body_B...);
    visit("p_BQ", self.p_BQ...);
    visit("free_length", self.free_length...);
    visit("stiffness", self.stiffness...);
    visit("damping", self.damping...);
  }
  template <typename Visit> void VisitFields(Visit&& visit) const { ForEachField(visit, *this); }
};
/// Drake's RevoluteSpring or PrismaticSpring, by the joint's type.
template <typename References>
struct JointSpringOf {
  static constexpr std::string_view kKind = "joint_spring";
  template <typename Other> using Rebind = JointSpringOf<Other>;
  typename References::Joint joint;
  double nominal = 0, stiffness = 0;
  template <typename Visit, typename... Self>
  static void ForEachField(Visit&& visit, Self&... self) {
    visit("joint", self.joint...);
    visit("nominal", self.nominal...);
    visit("stiffness", self.stiffness...);
  }
  template <typename Visit> void VisitFields(Visit&& visit) const { ForEachField(visit, *this); }
};

/// Every kind of force element, for the references `R`: the one list of kinds.
template <typename R>
using ForceElementVariant =
    std::variant<LinearBushingRpyOf<R>, LinearSpringDamperOf<R>, JointSpringOf<R>>;

using LinearBushingRpy = LinearBushingRpyOf<IrReferences>;
using LinearSpringDamper = LinearSpringDamperOf<IrReferences>;
using JointSpring = JointSpringOf<IrReferences>;

/// The kinds of force element, in the order of ForceElementVariant's alternatives.
enum class ForceElementType { LinearBushingRpy, LinearSpringDamper, JointSpring };
using ForceElementPayload = ForceElementVariant<IrReferences>;

/// Force elements of the plant (Drake's ForceElement subclasses).
struct ForceElement {
  ModelId model;
  Loc loc;
  ForceElementPayload payload;
  ForceElementType type() const { return static_cast<ForceElementType>(payload.index()); }
  template <typename T> T& As() { return std::get<T>(payload); }
  template <typename T> const T& As() const { return std::get<T>(payload); }
};

/// Gains that MuJoCo's compiler derives from an MJCF model's joint-space
/// inertia M at its reference configuration qpos0 (BEYOND-007, BEYOND-008).
/// The frontend records what the file asks for, with what the plant does not
/// keep (each joint's qpos0 and armature); the backend computes the gains
/// once the plant, and so M(qpos0), exists. M holds the model's joints only
/// (other models' joints stay locked at their default positions) and the
/// armature on its diagonal, as MuJoCo's does.
///   springdamper = timeconst dampratio (both > 0): the joint's damping
///       2 I / timeconst on every dof and, for hinges and slides, a joint
///       spring of stiffness I / (timeconst dampratio)^2 about springref,
///       where I = n / sum of (M^-1)_kk over the joint's n dofs, except a
///       slide on a MuJoCo "simple" body, where (M^-1)_kk is 1 / the body's
///       mass (MuJoCo's dof_invweight0);
///   dampratio (position actuators, general ones' biasprm[2] > 0): the
///       actuator's kd = 2 dampratio sqrt(kp m), m = M_kk / gear^2 of its
///       joint's dof (MuJoCo's dof_M0, through the transmission).
struct InertiaScaledGains {
  ModelId model;
  Loc loc;  // the model's root element
  /// Every joint of the model in document order (MuJoCo's dof order).
  struct JointState {
    JointId joint;
    double qpos0 = 0;    // hinge, slide: `ref`; ball joints are at identity, free ones anywhere
    double armature = 0;  // on each of the joint's dofs
  };
  std::vector<JointState> joints;
  struct SpringDamper {
    JointId joint;
    Loc loc;  // the springdamper attribute
    double timeconst = 0, dampratio = 0;
    double springref = 0;  // hinge, slide: the spring's nominal position
    /// A slide-only MuJoCo "simple" body by its structure (a leaf whose
    /// parent is the world or a joint-less child of it, moved only by
    /// slides at its origin along its own axes): MuJoCo's dof_invweight0 is
    /// 1 / its mass when, moreover, its inertia frame is the body frame.
    BodyId simple_body;
  };
  std::vector<SpringDamper> spring_dampers;
  struct DampRatio {
    ActuatorId actuator;
    Loc loc;  // dampratio, or the general actuator's biasprm
    double dampratio = 0;
  };
  std::vector<DampRatio> damp_ratios;
  bool empty() const { return spring_dampers.empty() && damp_ratios.empty(); }
};

struct Camera {
  Symbol name;
  ModelId model;
  Loc loc;
  Ref<BodyId> body;
  Transform X_BC;  // Drake camera frame: +z forward, +x right, +y down
  int width = 640, height = 480;
  double fov_y = 0.785398163397448;
  bool unnamed = false;  // named by the compiler (`camera<i>`)
};

}  // namespace mdlc::ir
