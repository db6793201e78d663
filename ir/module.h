// module.h - the IR container: one table per entity kind, plus the symbols.
//
// Tables are in insertion order, which is document order, so everything that
// iterates a Module is deterministic. Entity 0 of `bodies` is the world body
// and models 0 and 1 are WorldModelInstance and DefaultModelInstance, as in
// Drake; a fresh Module already holds them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/entities.h"
#include "ir/frame_graph.h"
#include "ir/original_name.h"
#include "ir/scene_directives.h"
#include "ir/scoped_symbol_map.h"
#include "ir/symbol.h"

namespace mdlc::ir {

inline constexpr ModelId kWorldModel{uint32_t{0}};
inline constexpr ModelId kDefaultModel{uint32_t{1}};
inline constexpr BodyId kWorldBody{uint32_t{0}};

struct Module {
  Module();

  SymbolTable symbols;
  std::vector<ModelInstance> models;
  std::vector<Body> bodies;
  std::vector<Frame> frames;
  std::vector<Joint> joints;
  std::vector<Geometry> geometries;
  std::vector<Material> materials;
  std::vector<Actuator> actuators;
  std::vector<Constraint> constraints;
  std::vector<ForceElement> force_elements;
  std::vector<CollisionFilterGroup> filter_groups;
  std::vector<Camera> cameras;
  /// SDFormat poses and attachments awaiting the resolve-frames pass.
  FrameGraph frame_graph;
  /// Model Directives' frames, welds and default poses awaiting the
  /// apply-directives pass, in directive order.
  std::vector<SceneEdit> scene_edits;
  /// MJCF gains that need the plant's mass matrix at qpos0 (the backend
  /// computes them), one entry per model that asks for any.
  std::vector<InertiaScaledGains> inertia_scaled_gains;
  /// Names `mdlc convert` changed when it wrote the file (round-trip
  /// metadata), awaiting the restore-names pass.
  std::vector<OriginalName> original_names;

  /// Plant-wide settings a model may give (MJCF <option>); unset: Drake's defaults.
  std::optional<Eigen::Vector3d> gravity;  // m/s^2, in world
  std::optional<double> time_step;         // s; 0 = continuous

  // typed access
  ModelInstance& operator[](ModelId id) { return models[id.index()]; }
  Body& operator[](BodyId id) { return bodies[id.index()]; }
  Frame& operator[](FrameId id) { return frames[id.index()]; }
  Joint& operator[](JointId id) { return joints[id.index()]; }
  Geometry& operator[](GeometryId id) { return geometries[id.index()]; }
  Material& operator[](MaterialId id) { return materials[id.index()]; }
  Actuator& operator[](ActuatorId id) { return actuators[id.index()]; }
  const ModelInstance& operator[](ModelId id) const { return models[id.index()]; }
  const Body& operator[](BodyId id) const { return bodies[id.index()]; }
  const Frame& operator[](FrameId id) const { return frames[id.index()]; }
  const Joint& operator[](JointId id) const { return joints[id.index()]; }
  const Geometry& operator[](GeometryId id) const { return geometries[id.index()]; }
  const Material& operator[](MaterialId id) const { return materials[id.index()]; }
  const Actuator& operator[](ActuatorId id) const { return actuators[id.index()]; }

  // adding entities returns their id
  ModelId Add(ModelInstance m);
  BodyId Add(Body b) { bodies.push_back(std::move(b)); return BodyId(bodies.size() - 1); }
  FrameId Add(Frame f) { frames.push_back(std::move(f)); return FrameId(frames.size() - 1); }
  JointId Add(Joint j) { joints.push_back(std::move(j)); return JointId(joints.size() - 1); }
  GeometryId Add(Geometry g) { geometries.push_back(std::move(g)); return GeometryId(geometries.size() - 1); }
  MaterialId Add(Material m) { materials.push_back(std::move(m)); return MaterialId(materials.size() - 1); }
  ActuatorId Add(Actuator a) { actuators.push_back(std::move(a)); return ActuatorId(actuators.size() - 1); }
  ForceElementId Add(ForceElement f) { force_elements.push_back(std::move(f)); return ForceElementId(force_elements.size() - 1); }
  ConstraintId Add(Constraint c) { constraints.push_back(std::move(c)); return ConstraintId(constraints.size() - 1); }
  FilterGroupId Add(CollisionFilterGroup g) { filter_groups.push_back(std::move(g)); return FilterGroupId(filter_groups.size() - 1); }
  CameraId Add(Camera c) { cameras.push_back(std::move(c)); return CameraId(cameras.size() - 1); }

  std::string_view Text(Symbol s) const { return symbols.Text(s); }
  Symbol Intern(std::string_view s) { return symbols.Intern(s); }

  /// "model::local" for an entity of `model` (just "world" for the world body).
  std::string ScopedName(ModelId model, Symbol local) const;
  std::string ScopedName(BodyId body) const;
  std::string ScopedName(JointId joint) const;

  /// The full name of a model instance: its ancestors' local names and its
  /// own, joined by "::". Built on each call (O(depth)): for printing.
  std::string ModelName(ModelId model) const;
  /// The model instance whose full name is `scoped` ("a::b::c"); with
  /// `within`, the one named `scoped` relative to it ("<within>::a::b::c").
  /// Walks nested instances by local name, so its cost grows with the
  /// length of `scoped`, not with the depth of `within` or the module's size
  /// (unless a top-level name holds "::" and the walk fails: then the full
  /// name is looked up too).
  std::optional<ModelId> FindModel(std::string_view scoped, ModelId within = ModelId()) const;
  /// The instance nested directly in `parent` (invalid: the top level) as `local`.
  std::optional<ModelId> FindChildModel(ModelId parent, Symbol local) const;
  /// Renames model instance `model` to `local` below `parent` (invalid: top level).
  void RenameModel(ModelId model, ModelId parent, Symbol local);
  /// Removes the last model instance added (nothing may refer to it any more).
  void RemoveLastModel();
  /// Room for `more` model instances past the current ones in the table.
  /// The index by name needs none for a top-level instance or a parent's
  /// first child, which it keeps without hashing (scoped_symbol_map.h).
  void ReserveModels(size_t more);

 private:
  // (parent, local name) -> the first instance added so; kept by Add. The
  // top level (an invalid parent) is indexed by symbol: a world of many
  // models adds one top-level entry per model, in the order their names
  // were interned (scoped_symbol_map.h).
  ScopedSymbolMap<ModelId> model_by_parent_{ModelId().value};
  // the most "::" in a top-level instance's local name: FindModel tries that
  // many longer first components before walking down
  size_t max_top_level_separators_ = 0;
};

}  // namespace mdlc::ir
