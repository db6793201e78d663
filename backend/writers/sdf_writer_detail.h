// sdf_writer_detail.h - the SDFormat writer's class, shared by the files
// that write its parts (see sdf_writer.cc for the layout of what it writes):
//   sdf_writer.cc          models, their poses and frames, the <world>
//   sdf_links.cc           links: inertials, geometry, materials, cameras
//   sdf_joints.cc          joints: axes, limits, actuators, mimics, planar joints
//   sdf_drake_elements.cc  model-level drake: elements (constraints, bushings,
//                          spring-dampers, collision filter groups)
#pragma once

#include <fmt/format.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "backend/writers/writer.h"
#include "backend/writers/writer_base.h"
#include "backend/writers/xml_out.h"

namespace mdlc::writers::sdf {

using backend::PlantBody;
using backend::PlantJoint;
constexpr double kInf = std::numeric_limits<double>::infinity();

bool AllEqual(std::span<const double> values);
/// "a::b::c" -> {"a", "b", "c"}; "" -> {}.
std::vector<std::string> Split(const std::string& scoped);
std::string Join(const std::vector<std::string>& parts, size_t from = 0);
/// The innermost scope holding both: "a::b" and "a::c" -> "a"; "" is the world.
std::string CommonScope(const std::string& x, const std::string& y);
bool Within(const std::string& scope, const std::string& inner);

/// A model: its links, joints, frames, nested models and drake: elements.
struct ModelNode {
  std::string scoped;  // "outer::inner"
  std::string name;    // "inner"
  Loc loc;
  std::vector<BodyId> links;
  std::vector<JointId> joints;
  std::vector<size_t> frames;
  std::vector<std::string> children;  // scoped names of nested models
  std::vector<std::function<void()>> elements;  // drake: elements, written last
  std::set<std::string> names;        // the model's one namespace
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
  std::string InstanceOf(BodyId body) const;
  ModelNode& Scope(const std::string& scoped);
  void AddModel(const std::string& scoped, Loc loc);
  void InstanceScopes();
  std::string Claim(ModelNode& scope, const std::string& name, std::string_view kind, Loc loc,
                    bool named = true);
  void BuildModels();
  void LinkFrameRefs();
  void ModelPoses();
  Transform ParentModelPose(const std::string& scoped) const;
  std::string BodyScope(BodyId body) const;
  std::string LinkRef(const std::string& scope, BodyId body) const;
  static std::string Relative(const std::string& scope, const std::string& owner,
                              const std::string& name);
  void LinkPoses();
  static bool IsFreeRoot(const PlantJoint& j);
  void Pose(const Transform& X, std::string_view relative_to = {});
  void Value(std::string_view tag, double v);
  void Value(std::string_view tag, const Eigen::Vector3d& v);
  void Value(std::string_view tag, std::string_view text);
  void WriteModel(const ModelNode& node);
  void WriteFrame(size_t f, const std::string& scope);

  // sdf_links.cc
  void WriteLink(BodyId body);
  void WriteGeometries(BodyId body);
  static std::string Unique(std::set<std::string>& names, const std::string& name);
  void WriteGeometry(const backend::SceneGeometry& g, Loc loc, std::set<std::string>& visuals,
                     std::set<std::string>& collisions);
  void Shape(const backend::SceneGeometry& g, Loc loc, bool collision);
  void Material(const backend::SceneGeometry& g, Loc loc);
  void WriteCameras(BodyId body);

  // sdf_joints.cc
  void WriteJoint(JointId id, const std::string& scope);
  void DampingLoss(const PlantJoint& j, Loc loc);
  void Axis(std::string_view tag, JointId id, const PlantJoint& j, const Eigen::Vector3d& xyz,
            int k);
  double EffortOf(JointId id, const PlantJoint& j, Loc loc);
  void SingleDofLimit(JointId id, const PlantJoint& j, Loc loc);
  void MultiDofLimits(const PlantJoint& j, Loc loc);
  void ActuatorParameters(JointId id);
  void MimicElements(JointId id);
  void WritePlanar(JointId id, const std::string& scope);

  // sdf_drake_elements.cc
  void Place(const std::vector<std::string>& scopes, Loc loc, const std::string& what,
             std::function<void(const std::string&)> write);
  void BuildElements();
  void BuildFilterGroups();
  void WriteFilterGroup(const std::string& scope, const std::vector<BodyId>& members,
                        const std::string& name, const std::string& ignored);
  void BodiesAndPoints(const std::string& scope, const std::string& prefix, BodyId A, BodyId B,
                       const Eigen::Vector3d& p_AP, const Eigen::Vector3d& p_BQ);

  std::vector<Transform> X_WB_;  // link poses (see the top)
  std::map<std::string, ModelNode> models_;
  ModelNode world_;
  bool use_world_ = false;
  std::map<size_t, std::string> body_scope_;
  std::vector<std::string> instance_scope_;  // by model instance; see InstanceScopes
  std::vector<std::string> link_names_, joint_names_, frame_names_, joint_scope_;
  struct FrameRef {
    std::string scope, name;
  };
  std::map<std::string, FrameRef> frame_refs_;  // plant scoped frame name -> written
  std::set<size_t> mimic_written_;
};

}  // namespace mdlc::writers::sdf
