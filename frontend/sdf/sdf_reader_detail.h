// sdf_reader_detail.h - state shared by the pieces of the SDFormat frontend.
//
// The frontend is split by element group, one file each:
//   sdf_reader.cc         <sdf>, <world>, <model>: scopes, names, dispatch
//   sdf_include.cc        <include>: SDFormat and URDF files, merge-include
//   sdf_values.cc         element-text values (numbers, vectors, booleans, poses)
//   sdf_link.cc           <link>, <inertial>, <frame>
//   sdf_joint.cc          <joint>: types, axes, limits, dynamics, actuators
//   sdf_geometry.cc       <visual>, <collision>, shapes, materials, sensors
//   sdf_drake_elements.cc drake: elements of a model (dispatch: filter groups,
//                         bushings and constraints are read by the reader
//                         shared with URDF, drake_elements.h) and of a joint
//                         (mimic, actuator parameters)
//   sdf_drake_joint.cc    <drake:joint>: planar and curvilinear joints
//   sdf_deformable.cc     <drake:deformable_properties> of a link
// Poses and attachments are recorded in Module::frame_graph, unevaluated;
// the resolve-frames pass evaluates them. Other references stay names until
// resolve-names.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "frontend/frontend.h"
#include "ir/assets/package_map.h"
#include "frontend/xml/attribute_reader.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::frontend::sdf {

/// A file being read, and the chain of files that included it (SDF-033).
struct SdfFile {
  const xml::XmlDocument* doc = nullptr;
  std::string path;
  std::string dir;  // relative URIs resolve against it
  std::string canonical;  // absolute, for include-cycle checks
  const SdfFile* included_from = nullptr;
  Loc include_loc;        // the <uri> that included it
  /// SDFormat version as written on <sdf version>: major*100 + minor (1.9 -> 109).
  int version = 109;
};

/// The model scope being read: where its entities go and how names are looked up.
/// What an <axis> says besides its direction (sdf_joint.cc).
struct JointAxisValues;

struct ModelScope {
  FrameScopeId scope;
  ModelId model;
  const SdfFile* file = nullptr;
  bool is_static = false;
  /// The name "__model__" means in this scope (a merged model's own frame node name).
  Symbol model_frame_name;
  /// How deep `model` is nested: 0 for the world, 1 for a top-level model
  /// (a merged model shares its parent's).
  uint64_t depth = 0;
};

class SdfReader {
 public:
  SdfReader(FrontendContext& ctx) : ctx_(ctx), attrs_(ctx.diags) {}

  /// Reads the top-level file: a model file adds its model, a world file
  /// every model of the world. Returns the first instance added.
  std::optional<ModelId> ReadRootFile(FileId file);

  // --- sdf_values.cc: element-text values (all report at the element) ---
  /// Text of the child `name` (trimmed); nullopt when absent (error if required).
  std::optional<std::string> ChildText(const xml::XmlElement& parent, std::string_view name,
                                       xml::Need need = xml::Need::Optional);
  std::optional<double> TextDouble(const xml::XmlElement& e,
                                   xml::Finite finite = xml::Finite::Required);
  /// TextDouble's slow path, for text that is not one number: its leading
  /// number with a warning, or an error and nullopt when it has none.
  std::optional<double> LeadingNumber(const xml::XmlElement& e, std::string_view text);
  std::optional<double> ChildDouble(const xml::XmlElement& parent, std::string_view name,
                                    xml::Need need = xml::Need::Optional,
                                    xml::Finite finite = xml::Finite::Required);
  /// Exactly `count` numbers in the element's text.
  std::optional<std::vector<double>> TextDoubles(const xml::XmlElement& e, size_t count,
                                                 xml::Finite finite = xml::Finite::Required);
  std::optional<Eigen::Vector3d> TextVector3(const xml::XmlElement& e);
  std::optional<Eigen::Vector3d> ChildVector3(const xml::XmlElement& parent, std::string_view name,
                                              xml::Need need = xml::Need::Optional);
  /// SDFormat booleans: true/false/1/0.
  std::optional<bool> TextBool(const xml::XmlElement& e);
  std::optional<bool> ChildBool(const xml::XmlElement& parent, std::string_view name);
  /// <pose relative_to rotation_format degrees>: X_RF (SDF-003). Identity
  /// when `pose` is null. Reports bad values and returns identity for them.
  Transform ReadPoseValue(const xml::XmlElement& pose);
  /// relative_to of `pose` (empty NameRef when absent or `pose` is null).
  ir::NameRef RelativeTo(const xml::XmlElement& pose);

  // --- sdf_reader.cc: names and the frame graph ---
  /// Room in the IR's tables and in the frame graph's name index for what
  /// `doc` adds, before it is read: a world of 100,000 models otherwise
  /// rehashed its names seventeen times as they came.
  void ReserveRoomFor(const xml::XmlDocument& doc);
  /// Checks a name defined in a scope (SDF-034, COMMON-031): not empty, no
  /// "::", not reserved (world, __model__, __anything__). False after an error.
  bool CheckDefinedName(std::string_view name, Loc loc, std::string_view kind,
                        int version = 109);
  /// Adds a named frame node to scope `s`, reporting a sibling of the same
  /// name (SDF names of links, joints, frames and models share one namespace).
  /// As libsdformat does, a name shared across kinds in a model older than
  /// SDFormat 1.7, or in a world, is a warning: the kind loaded earlier
  /// (links and models, then joints, then frames) keeps it, and the other
  /// is renamed NAME_joint or NAME_frame, wherever each stands in the file.
  FrameNodeId AddNode(const ModelScope& s, ir::FrameNode node);
  /// Renames a joint AddNode renamed, and the actuator made for it.
  void RenameJoint(JointId joint, Symbol name);
  /// Whether a joint of `model` is named `name` (a <drake:joint> shares the
  /// joint namespace of its model, COMMON-023). Counts names as joints come,
  /// so N such joints cost N lookups, not N^2 comparisons.
  bool JointNameTaken(ModelId model, Symbol name);
  /// Adds an unnamed anchor node: the pose of `pose_element` relative to its
  /// relative_to, defaulting to `link_name` (visuals, collisions, sensors).
  /// It is attached to its link's node, `link_node`, with no name lookup.
  FrameNodeId AddAnchor(const ModelScope& s, const xml::XmlElement& pose_element,
                        Symbol link_name, FrameNodeId link_node, Loc loc,
                        ir::FrameTarget target, uint32_t index);
  /// Reports unknown children of an SDF element (SDF-001): drake: ones warn,
  /// other namespaced ones are skipped silently, plain ones are errors.
  void CheckChildren(const xml::XmlElement& e, std::initializer_list<std::string_view> known,
                     std::initializer_list<std::string_view> unsupported = {});
  /// One walk over `e`'s children for a reader that wants a few of them:
  /// `first[k]` is set to the first child named `names[k]` (left null when
  /// there is none), and every child of another name is checked against
  /// `also_known` as CheckChildren does. Defined here, so each caller's
  /// names are constants the comparisons unfold on (every link's
  /// <inertial> and <inertia> come here; out of line, the 1,000-model
  /// world compiled 3% slower).
  void FirstChildrenNamed(const xml::XmlElement& e, std::span<const std::string_view> names,
                          std::span<xml::XmlElement> first,
                          std::span<const std::string_view> also_known) {
    for (auto child = e.FirstChild(); child; child = child.NextSibling()) {
      const std::string_view tag = child.Name();
      size_t k = 0;
      while (k < names.size() && !xml::SameName(tag, names[k])) ++k;
      if (k == names.size()) {
        CheckChild(e, child, also_known, {});
      } else if (!first[k]) {
        first[k] = child;
      }
    }
  }
  /// CheckChildren for one child, for a reader that walks the children
  /// anyway: a model's or world's may be many thousand, and one walk over
  /// them is much cheaper than two once they no longer fit in the cache.
  /// Inline, as it runs for every child of most elements: only a child that
  /// is not `known` leaves it.
  void CheckChild(const xml::XmlElement& e, const xml::XmlElement& child,
                  std::span<const std::string_view> known,
                  std::span<const std::string_view> unsupported) {
    if (!Listed(known, child.Name())) ReportUnknownChild(e, child, known, unsupported);
  }
  static bool Listed(std::span<const std::string_view> names, std::string_view tag) {
    for (std::string_view name : names) {
      if (xml::SameName(name, tag)) return true;
    }
    return false;
  }
  /// `known` and `unsupported` are what `e` may have: a child that is
  /// neither gets the closest of them as a suggestion.
  void ReportUnknownChild(const xml::XmlElement& e, const xml::XmlElement& child,
                          std::span<const std::string_view> known,
                          std::span<const std::string_view> unsupported);

  // --- sdf_link.cc ---
  void ReadLink(const xml::XmlElement& e, ModelScope& s);
  void ReadInertial(const xml::XmlElement& e, ir::Body& body);
  /// The six moments of <inertia>, each the first element of its name.
  void ReadMoments(const xml::XmlElement& inertia, ir::Inertial& inertial);
  void ReadFrame(const xml::XmlElement& e, ModelScope& s);

  // --- sdf_joint.cc: <joint>, one step per concern ---
  void ReadJoint(const xml::XmlElement& e, ModelScope& s);
  /// The joint's type and how many <axis> elements it needs; false (after an
  /// error) for a type the plant has no joint for.
  bool ReadJointType(const xml::XmlElement& e, std::string_view type_text,
                     std::string_view name, ir::JointType& type, int& axes_needed);
  /// <parent> and <child> (SDF-011); false after an error.
  bool ReadJointEnds(const xml::XmlElement& e, std::string_view name, ir::NameRef& parent,
                     ir::NameRef& child);
  /// <axis> and <axis2> (SDF-012..014) into `spec` and `values`; false after
  /// an error that leaves the joint without an axis it needs.
  bool ReadJointAxes(const xml::XmlElement& e, const ModelScope& s, const ir::Joint& joint,
                     std::string_view type, std::string_view name, int axes_needed,
                     ir::JointFrameSpec& spec, JointAxisValues (&values)[2]);
  void ReadAxisLimit(const xml::XmlElement& limit, std::string_view type, std::string_view name,
                     JointAxisValues& v);
  void ReadAxisDynamics(const xml::XmlElement& dyn, std::string_view name, JointAxisValues& v);
  /// The limits, damping and screw pitch the axes' values give `joint`.
  void SetJointValues(const xml::XmlElement& e, std::string_view type, std::string_view name,
                      const JointAxisValues (&values)[2], ir::Joint& joint);
  /// The joint frame J: attached to the child, posed relative to it by default.
  void AddJointFrame(const xml::XmlElement& e, ModelScope& s, JointId joint,
                     const ir::NameRef& child, ir::JointFrameSpec& spec);
  /// The actuator every actuable SDFormat joint gets unless its effort is 0
  /// (SDF-020).
  std::optional<ActuatorId> AddDefaultActuator(const xml::XmlElement& e, const ModelScope& s,
                                               JointId joint, std::string_view type,
                                               std::string_view name,
                                               const JointAxisValues (&values)[2]);
  /// A spring on a revolute or prismatic joint with a stiffness (SDF-013).
  void AddJointSpring(const xml::XmlElement& e, const ModelScope& s, JointId joint,
                      std::string_view name, const JointAxisValues& v);

  // --- sdf_geometry.cc: children of a link ---
  void ReadVisual(const xml::XmlElement& e, ModelScope& s, BodyId body, Symbol link_name,
                  FrameNodeId link_node);
  void ReadCollision(const xml::XmlElement& e, ModelScope& s, BodyId body, Symbol link_name,
                     FrameNodeId link_node);
  void ReadSensor(const xml::XmlElement& e, ModelScope& s, BodyId body, Symbol link_name,
                  FrameNodeId link_node);

  // --- sdf_drake_elements.cc: model-level drake: elements, read after every
  // link, joint and nested model of the model (EXT-001, EXT-040, EXT-050..054)
  void ReadDrakeModelElement(const xml::XmlElement& e, ModelScope& s);
  // --- sdf_drake_joint.cc: <drake:joint> (EXT-001, EXT-003, EXT-004)
  void ReadDrakeJoint(const xml::XmlElement& e, ModelScope& s);
  void AddDrakeJointFrames(JointId joint, const ModelScope& s, const ir::Ref<BodyId>& parent,
                           const ir::Ref<BodyId>& child);
  /// drake: children of a <joint> (drake:mimic, drake:rotor_inertia,
  /// drake:gear_ratio, drake:controller_gains; SDF-021, EXT-010, EXT-012..014).
  /// Called after the joint and its actuator (if any) exist.
  /// SDFormat 1.11's <axis><mimic>: a coupler, as <drake:mimic> makes.
  void ReadAxisMimic(const xml::XmlElement& joint_element, ModelScope& s, JointId joint);
  void ReadJointDrakeChildren(const xml::XmlElement& joint_element, ModelScope& s, JointId joint,
                              std::optional<ActuatorId> actuator);
  // --- sdf_deformable.cc
  /// drake:deformable_properties on a link (EXT-070); `body` is the link's body.
  void ReadDeformableProperties(const xml::XmlElement& link, ModelScope& s, BodyId body);

  FrontendContext& ctx_;
  xml::AttributeReader attrs_;
  ir::Module& module() { return ctx_.module; }
  ir::FrameGraph& graph() { return ctx_.module.frame_graph; }
  DiagnosticEngine& diags() { return ctx_.diags; }
  /// "__model__", every model's own frame (COMMON-024): interned once, not
  /// looked up again for each model
  Symbol ModelFrameName() {
    if (model_frame_name_.empty()) model_frame_name_ = module().Intern("__model__");
    return model_frame_name_;
  }
  Symbol model_frame_name_;

  // implementation details of sdf_reader.cc / sdf_include.cc
  std::optional<ModelId> ReadWorld(const xml::XmlElement& e, const SdfFile& file);
  struct ModelOverrides {
    std::optional<std::string> name;
    std::optional<bool> is_static;
    xml::XmlElement pose;             // the include's <pose>, if any
    ir::NameRef placement_frame;
    Loc loc;                          // the <include>
  };
  /// Reads a <model> and every model nested in it (SDF-030). Nested models
  /// wait on a work list instead of recursing, so depth costs no stack.
  std::optional<ModelId> ReadModelTree(const xml::XmlElement& e, const SdfFile& file,
                                       ModelScope parent, const ModelOverrides* overrides);
  std::optional<ModelId> ReadModel(const xml::XmlElement& e, const SdfFile& file,
                                   ModelScope parent, const ModelOverrides* overrides);
  /// Creates a model's scope, its frame node in `parent` and its IR frame
  /// (`__model__`, or `_merged__NAME__model__` when merged into `parent`).
  FrameScopeId OpenScope(const xml::XmlElement& e, const ModelScope& parent,
                         const ModelOverrides* overrides, const std::string& local_name,
                         ModelId model, bool merged);
  void ReadModelBody(const xml::XmlElement& e, ModelScope& s);
  void DrainPendingModels(size_t down_to);
  void ReadInclude(const xml::XmlElement& e, const SdfFile& file, ModelScope parent);
  void MergeModel(const xml::XmlElement& model, const SdfFile& file, ModelScope parent,
                  const ModelOverrides& overrides);
  void IncludeUrdf(FileId file, ModelScope parent, const ModelOverrides& overrides, bool merge);
  static int ParseVersionNumber(std::string_view text);

  struct PendingModel {
    xml::XmlElement element;
    const SdfFile* file;
    ModelScope parent;
  };
  std::vector<PendingModel> pending_models_;

  // (owner, name) keys of per-owner name tables
  struct ScopedKey {
    uint32_t scope, name;
    friend bool operator==(const ScopedKey&, const ScopedKey&) = default;
    template <typename H>
    friend H AbslHashValue(H h, const ScopedKey& k) {
      return H::combine(std::move(h), k.scope, k.name);
    }
  };
  // the link being read's geometry names per role, for uniqueness checks in
  // sdf_geometry.cc (cleared for each link: sdf_link.cc)
  absl::flat_hash_map<ScopedKey, Loc> geometry_names_;
  // how many joints of a model hold a name: filled by JointNameTaken up to
  // the joints it has seen, kept by RenameJoint
  absl::flat_hash_map<ScopedKey, uint32_t> joint_name_counts_;
  size_t joint_names_counted_ = 0;
  // the actuator made for a joint and named after it (sdf_joint.cc), which a
  // rename of the joint takes along
  absl::flat_hash_map<uint32_t, ActuatorId> joint_actuators_;
  std::vector<std::shared_ptr<const xml::XmlDocument>> documents_;
  std::vector<std::unique_ptr<SdfFile>> files_;
  std::optional<ModelId> first_model_;
};

}  // namespace mdlc::frontend::sdf
