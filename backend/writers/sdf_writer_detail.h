// sdf_writer_detail.h - the SDFormat writer's class, shared by the files
// that write its parts (see sdf_writer.cc for the layout of what it writes):
//   sdf_writer.cc          models, their poses and frames, the <world>
//   sdf_links.cc           links: inertials, geometry, materials, cameras
//   sdf_joints.cc          joints: axes, limits, actuators, mimics, planar joints
//   sdf_drake_elements.cc  model-level drake: elements (constraints, bushings,
//                          spring-dampers, collision filter groups)
#pragma once

#include <fmt/format.h>

#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "backend/writers/unique_names.h"
#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"

namespace mdlc::writers::sdf {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// "a::b::c" -> {"a", "b", "c"}; "" -> {}.
std::vector<std::string> Split(const std::string& scoped);

/// A model the writer writes, by its index in SdfWriter::models_. Scopes
/// are held as a parent and a local name, as the plant holds its model
/// instances: spelling each scope out in full costs the square of the
/// nesting depth in time and memory.
using ScopeId = size_t;
constexpr ScopeId kWorldScope = 0;

/// A model: its links, joints, frames, nested models and drake: elements.
struct ModelNode {
  std::string name;  // "inner" in "outer::inner"; empty for the world
  ScopeId parent = kWorldScope;
  size_t depth = 0;  // 0 the world, 1 a top-level model
  Loc loc;
  std::vector<BodyId> links;
  std::vector<JointId> joints;
  std::vector<size_t> frames;
  std::vector<ScopeId> children;              // nested models, as made
  std::map<std::string, ScopeId> child_named;  // the same, by name
  std::vector<std::function<void()>> elements;  // drake: elements, written last
  UniqueNames names;                            // the model's one namespace
  /// The plant's frame for this model's `__model__`, when it is on one of
  /// the model's links: the model is posed there (X_WM, at q = 0) and its
  /// canonical link is that link, so the frame is SDFormat's own.
  std::optional<size_t> model_frame;
  Transform X_WM;
};

class SdfWriter : WriterBase {
 public:
  SdfWriter(const backend::CompiledModel& model, const ir::Module& module,
            const WriteOptions& options, DiagnosticEngine& diags)
      : WriterBase(model, module, options, diags) {}
  std::string Write();

 private:
  // sdf_writer.cc
  ScopeId ChildScope(ScopeId parent, const std::string& name, Loc loc);
  ScopeId InstanceScope(size_t m);
  std::string ScopedName(ScopeId scope) const;
  ScopeId CommonScope(ScopeId a, ScopeId b) const;
  bool Within(ScopeId scope, ScopeId inner) const;
  ScopeId TopLevelModel(ScopeId scope) const;
  std::string Claim(ModelNode& scope, const std::string& name, std::string_view kind, Loc loc,
                    bool named = true);
  void BuildModels();
  void LinkFrameRefs();
  void ModelPoses();
  Transform ParentModelPose(ScopeId scope) const;
  ScopeId BodyScope(BodyId body) const;
  std::string LinkRef(ScopeId scope, BodyId body) const;
  std::string Relative(ScopeId scope, ScopeId owner, const std::string& name) const;
  void LinkPoses();
  static bool IsFreeRoot(const PlantJoint& j);
  void Pose(const Transform& X, std::string_view relative_to = {});
  void Value(std::string_view tag, double v);
  void Value(std::string_view tag, const Eigen::Vector3d& v);
  void Value(std::string_view tag, std::string_view text);
  void WriteModel(ScopeId scope);
  void WriteFrame(size_t f, ScopeId scope);

  // sdf_links.cc
  void WriteLink(BodyId body);
  void WriteGeometries(BodyId body);
  static std::string Unique(UniqueNames& names, const std::string& name);
  void WriteGeometry(const backend::SceneGeometry& g, Loc loc, UniqueNames& visuals,
                     UniqueNames& collisions);
  void Shape(const backend::SceneGeometry& g, Loc loc, bool collision);
  void Material(const backend::SceneGeometry& g, Loc loc);
  void WriteCameras(BodyId body);

  // sdf_joints.cc
  void WriteJoint(JointId id, ScopeId scope);
  void DampingLoss(const PlantJoint& j, Loc loc);
  void Axis(std::string_view tag, JointId id, const PlantJoint& j, const Eigen::Vector3d& xyz,
            int k);
  double EffortOf(JointId id, const PlantJoint& j, Loc loc);
  void SingleDofLimit(JointId id, const PlantJoint& j, Loc loc);
  void MultiDofLimits(const PlantJoint& j, Loc loc);
  void ActuatorParameters(JointId id);
  void MimicElements(JointId id);
  void WritePlanar(JointId id, ScopeId scope);

  // sdf_drake_elements.cc
  void Place(const std::vector<ScopeId>& scopes, Loc loc, const std::string& what,
             std::function<void(ScopeId)> write);
  void BuildElements();
  void BuildFilterGroups();
  void WriteFilterGroup(ScopeId scope, const std::vector<BodyId>& members,
                        const std::string& name, const std::string& ignored);
  void BodiesAndPoints(ScopeId scope, const std::string& prefix, BodyId A, BodyId B,
                       const Eigen::Vector3d& p_AP, const Eigen::Vector3d& p_BQ);

  std::vector<Transform> X_WB_;  // link poses (see the top)
  std::deque<ModelNode> models_{1};  // by ScopeId; [0] is the world
  bool use_world_ = false;
  std::vector<ScopeId> body_scope_, joint_scope_;
  std::vector<std::optional<ScopeId>> instance_scope_;  // by model instance, once made
  std::vector<std::string> link_names_, joint_names_, frame_names_;
  struct FrameRef {
    ScopeId scope;
    std::string name;
  };
  bool bushings_ = false;                        // whether frame_refs_ is needed
  std::map<std::string, FrameRef> frame_refs_;  // plant scoped frame name -> written
  std::set<size_t> mimic_written_;
};

}  // namespace mdlc::writers::sdf
