// urdf_reader_detail.h - state shared by the pieces of the URDF frontend.
//
// The URDF frontend is split by element group: urdf_reader.cc (the <robot>
// element, dispatch, materials), urdf_link.cc (links, inertials, visuals,
// collisions, shapes), urdf_joint.cc (joints, frames), urdf_joint_children.cc
// (a joint's <limit>, <dynamics> and <mimic>).
// Each piece lowers syntax into the Module and reports what it cannot read;
// references stay names until the resolve-names pass.
#pragma once

#include <string>

#include <absl/container/flat_hash_map.h>

#include "frontend/frontend.h"
#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::frontend::urdf {

/// A URDF joint type and the element that may declare it (urdf_joint.cc).
struct UrdfJointType;

struct UrdfMaterial {
  MaterialId id;
  Loc loc;
};

class UrdfReader {
 public:
  UrdfReader(FrontendContext& ctx, const xml::XmlDocument& doc)
      : ctx_(ctx), doc_(doc), attrs_(ctx.diags) {}

  std::optional<ModelId> Read();

 private:
  // urdf_reader.cc
  void ReadRobotMaterial(const xml::XmlElement& e);
  /// Reads <material> inside a visual; returns the color it gives, if any.
  std::optional<Eigen::Vector4d> ReadVisualMaterial(const xml::XmlElement& e, ir::Geometry& g);
  std::optional<Eigen::Vector4d> ReadColor(const xml::XmlElement& material);
  /// X_PC from an <origin xyz rpy> child (identity when absent).
  Transform ReadOrigin(const xml::XmlElement& parent);
  bool Ignored(const xml::XmlElement& e);

  // urdf_link.cc
  void ReadLink(const xml::XmlElement& e);
  void ReadInertial(const xml::XmlElement& e, ir::Body& body);
  void ReadGeometryElement(const xml::XmlElement& e, BodyId body, Symbol link_name,
                           bool is_visual);
  std::optional<ir::Shape> ReadShape(const xml::XmlElement& geometry);
  Symbol UniqueGeometryName(BodyId body, uint8_t role, std::string_view wanted, bool explicit_name,
                            Loc loc);

  // urdf_joint.cc
  void ReadJoint(const xml::XmlElement& e);
  void ReadFrame(const xml::XmlElement& e);
  // urdf_joint_children.cc
  void ReadLimits(const xml::XmlElement& e, ir::Joint& joint, bool continuous);
  void ReadDynamics(const xml::XmlElement& dynamics, ir::Joint& joint);
  void ReadMimic(const xml::XmlElement& e, const ir::Joint& joint);
  // urdf_transmission.cc
  void ReadTransmission(const xml::XmlElement& e);
  /// drake:rotor_inertia, drake:gear_ratio, drake:controller_gains under a
  /// transmission's <actuator> (EXT-012..014). Returns true when `child`
  /// was one of them (handled), false when it is something else.
  bool ReadActuatorExtension(const xml::XmlElement& child, ir::Actuator& actuator);

  // urdf_drake_joint.cc: <drake:joint> (EXT-001..003)
  void ReadDrakeJoint(const xml::XmlElement& e);
  // --- begin: <joint> / <drake:joint> helpers (urdf_joint.cc, urdf_drake_joint.cc) ---
  /// Reads one <joint> (drake_element = false) or <drake:joint> (true): the
  /// children both share (parent, child, origin, axis, limit, dynamics,
  /// mimic) and the drake: children of custom types; registers the joint in
  /// joint_ids_ / joint_names_ (URDF-010..014, URDF-042, EXT-001..003).
  void ReadAnyJoint(const xml::XmlElement& e, bool drake_element);
  // ReadAnyJoint's steps, in order:
  /// name, type, <parent>, <child> and <origin>; the type's text, or nullopt
  /// when the joint cannot be made.
  std::optional<std::string_view> ReadJointEnds(const xml::XmlElement& e, ir::Joint& joint);
  /// Sets joint.type; nullptr for an unknown type and for floating (no joint).
  const UrdfJointType* ReadJointType(const xml::XmlElement& e, std::string_view type,
                                     bool drake_element, ir::Joint& joint);
  /// <axis> (URDF-011) and the planar frame; false for a zero axis (no joint).
  bool ReadJointAxis(const xml::XmlElement& e, const UrdfJointType& kind, ir::Joint& joint);
  /// The drake: parameters of screw and curvilinear joints (EXT-002, EXT-003).
  void ReadCustomTypeParameters(const xml::XmlElement& e, ir::Joint& joint);
  /// Every child but the ends, origin and axis, read above.
  void ReadJointChildren(const xml::XmlElement& e, const UrdfJointType& kind, ir::Joint& joint);
  /// <limit>: read for revolute and prismatic joints (ReadLimits).
  void ReadJointLimit(const xml::XmlElement& limit, const UrdfJointType& kind, ir::Joint& joint);
  /// <calibration> or <safety_controller>: ignored, said once per file.
  void ReportRosJointSetting(const xml::XmlElement& c, std::string_view element);
  /// True when `c` is a drake: child of one custom type (warned about on
  /// joints of other types), false when it is none.
  bool CheckTypeSpecificChild(const xml::XmlElement& c, const UrdfJointType& kind,
                              const ir::Joint& joint);
  /// drake:screw_thread_pitch of a screw joint (EXT-002).
  void ReadScrewThreadPitch(const xml::XmlElement& e, ir::Joint& joint);
  /// drake:plane_normal, drake:initial_tangent, drake:is_periodic and
  /// drake:curves of a curvilinear joint (EXT-003); false after an error.
  bool ReadCurvilinearPath(const xml::XmlElement& e, ir::Joint& joint);
  // --- end: <joint> / <drake:joint> helpers ---

  // urdf_geometry_properties.cc: drake: children of <collision> and <visual>
  // (EXT-020, EXT-021, EXT-030, EXT-031, URDF-033). Each returns true when
  // `child` was one of its elements (handled).
  bool ReadCollisionExtension(const xml::XmlElement& child, ir::Geometry& geometry);
  bool ReadVisualExtension(const xml::XmlElement& child, ir::Geometry& geometry);
  /// After all of a visual's children were read: settle its roles (EXT-030)
  /// and role-dependent properties (EXT-031). Returns false when the visual
  /// ends with no role and must be dropped.
  bool FinishVisual(const xml::XmlElement& visual, ir::Geometry& geometry);

  void CheckUniqueName(absl::flat_hash_map<uint32_t, Loc>& seen, Symbol name, Loc loc,
                       std::string_view kind);

  FrontendContext& ctx_;
  const xml::XmlDocument& doc_;
  xml::AttributeReader attrs_;
  ModelId model_;
  absl::flat_hash_map<uint32_t, UrdfMaterial> materials_;  // by Symbol value
  absl::flat_hash_map<uint32_t, Loc> link_names_, joint_names_, frame_names_;
  absl::flat_hash_map<uint32_t, JointId> joint_ids_;  // by Symbol value
  std::vector<xml::XmlElement> transmissions_;  // read after every joint
  std::vector<xml::XmlElement> late_elements_;  // drake: model-level elements, read last
  // ROS's standard settings the plant does not hold (<calibration>,
  // <safety_controller>, <dynamics friction>, a transmission's name): said
  // once per file, at the first, not on every joint of a 40-joint robot
  bool said_calibration_ = false, said_safety_controller_ = false, said_friction_ = false,
       said_transmission_name_ = false;
  // geometry names already used, keyed by (body, role, name); the value is
  // the last suffix tried for that name
  struct GeometryNameKey {
    uint32_t body, name;
    uint8_t role;
    friend bool operator==(const GeometryNameKey&, const GeometryNameKey&) = default;
    template <typename H>
    friend H AbslHashValue(H h, const GeometryNameKey& k) {
      return H::combine(std::move(h), k.body, k.name, k.role);
    }
  };
  absl::flat_hash_map<GeometryNameKey, int> geometry_names_;
  ir::Module& module() { return ctx_.module; }
  DiagnosticEngine& diags() { return ctx_.diags; }
};

}  // namespace mdlc::frontend::urdf
