// frame_graph.h - SDFormat's frame semantics, as the file states them.
//
// SDFormat places every frame-like element (model, link, joint, frame, and
// the visuals, collisions and sensors of a link) by a pose relative to a named
// frame, and attaches frames to links through `attached_to`, joint children
// and canonical links (SDF-003..005, SDF-011, SDF-012, SDF-042). A frontend
// cannot evaluate these: names may point forward, into nested models, or form
// cycles. It records them here, unevaluated, and the resolve-frames pass
// turns them into the body-fixed poses of the entities (Frame::X_BF,
// Joint::X_PF/X_CM/axis, Geometry::X_BG, Camera::X_BC, Body::default_pose).
//
// Every reference is a name as written (possibly scoped, `a::b::c`), looked
// up in the scope of the node that wrote it. Defaults are spelled as names
// too (a link's pose is relative to "__model__", a joint's to its child), so
// the pass has a single lookup rule.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "ir/ids.h"
#include "ir/location.h"
#include "ir/scoped_symbol_map.h"
#include "ir/symbol.h"
#include "ir/transform.h"

namespace mdlc {
struct FrameScopeTag;
struct FrameNodeTag;
using FrameScopeId = Id<FrameScopeTag>;
using FrameNodeId = Id<FrameNodeTag>;
}  // namespace mdlc

namespace mdlc::ir {

enum class FrameNodeKind : uint8_t {
  World,   // the world frame: the root of the world scope
  Model,   // a model's own frame (`__model__`); in its parent scope it is named after the model
  Link,    // a link's frame (the body frame)
  Joint,   // a joint frame J, attached to the joint's child
  Frame,   // an explicit <frame>
  Anchor,  // an unnamed pose: a visual, collision or sensor; never referenced
};

/// A name written in the file, with where it was written.
struct NameRef {
  Symbol name;
  Loc loc;
  bool empty() const { return name.empty(); }
};

/// The IR entity a node's resolved pose is written to.
enum class FrameTarget : uint8_t { None, Body, Frame, Joint, Geometry, Camera };

struct FrameNode {
  FrameNodeKind kind = FrameNodeKind::Frame;
  Symbol name;          // local name (empty for anchors)
  FrameScopeId scope;   // the scope whose names it is looked up in
  Loc loc;
  /// <pose relative_to=R>X_RN</pose>; R is never empty (defaults are filled in).
  NameRef relative_to;
  Transform X_RN;
  /// What fixes the node to a body: a frame's attached_to, a joint's child,
  /// an anchor's link, a model's canonical link (empty: the scope's default).
  NameRef attached_to;
  /// The node attached_to names, when the frontend knows it as it writes the
  /// node (an anchor's own link): resolve-frames then looks no name up, which
  /// in a scene of many models is a cache miss per visual and collision.
  FrameNodeId attached_node;
  FrameTarget target = FrameTarget::None;
  uint32_t target_index = UINT32_MAX;
  FrameScopeId nested;  // kind Model: the scope this node is the frame of
};

/// One model's name scope. A merge-included model keeps its own scope (its
/// `__model__` is the `_merged__NAME__model__` frame) but publishes its names
/// into the scope it merges into (SDF-032).
struct FrameScope {
  Symbol name;
  Loc loc;
  FrameScopeId parent;        // invalid for the world scope
  FrameScopeId merged_into;   // valid for merge-included models
  ModelId model;              // instance owning the scope's entities
  FrameNodeId frame;          // the node of kind Model (or World) standing for __model__
  NameRef canonical_link;     // empty: the first link, else the first nested model's
  NameRef placement_frame;    // empty: the model frame itself
  bool is_world = false;
  bool is_static = false;
  std::vector<FrameNodeId> links;   // in document order, for the canonical link default
  std::vector<FrameScopeId> children;
};

/// The parts of an SDFormat joint that need the frame graph (SDF-011, SDF-012).
struct JointFrameSpec {
  JointId joint;
  FrameNodeId node;        // the joint frame J
  NameRef parent;          // the parent frame's name ("world" allowed)
  int axis_count = 0;      // 0, 1 or 2 (universal)
  Eigen::Vector3d xyz[2] = {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY()};
  NameRef expressed_in[2]; // empty: the joint frame
  /// drake:joint (EXT-001): F is the parent frame itself and M the child
  /// frame itself (node J stands for the child frame), not one frame J.
  bool frames_given = false;
};

/// A link of a static model is welded to the world where it stands (SDF-006);
/// an included URDF's bodies are placed by its own kinematics.
struct FrameGraph {
  std::vector<FrameScope> scopes;
  std::vector<FrameNode> nodes;
  std::vector<JointFrameSpec> joints;

  bool empty() const { return scopes.empty(); }
  FrameScope& operator[](FrameScopeId id) { return scopes[id.index()]; }
  FrameNode& operator[](FrameNodeId id) { return nodes[id.index()]; }
  const FrameScope& operator[](FrameScopeId id) const { return scopes[id.index()]; }
  const FrameNode& operator[](FrameNodeId id) const { return nodes[id.index()]; }
  FrameScopeId Add(FrameScope s) { scopes.push_back(std::move(s)); return FrameScopeId(scopes.size() - 1); }
  FrameNodeId Add(FrameNode n) { nodes.push_back(std::move(n)); return FrameNodeId(nodes.size() - 1); }

  /// The scope whose names `scope`'s nodes share: itself, or the scope it
  /// is merged into (SDF-032).
  FrameScopeId Namespace(FrameScopeId scope) const {
    while (scopes[scope.index()].merged_into.valid()) scope = scopes[scope.index()].merged_into;
    return scope;
  }
  /// Every named node (all but anchors and the world's) by its namespace
  /// and local name; the first node of a name keeps it. The SDFormat reader
  /// fills it as it adds nodes, finding repeated names in it, and
  /// resolve-frames looks references up in it: one table, built once, where
  /// each kept its own (in a world of 100,000 models, the tables outgrow
  /// the cache and every insert misses). The world scope (scope 0), whose
  /// names are its models', is indexed by symbol, and each other scope's
  /// first name by the scope, so a world's names are kept in order
  /// (scoped_symbol_map.h).
  /// `names_complete` says it holds every node; a graph built any other way
  /// leaves it false, and resolve-frames calls IndexNames.
  ScopedSymbolMap<FrameNodeId> names{0};
  bool names_complete = false;
  /// The node named `name` in the namespace of `scope`, if any.
  std::optional<FrameNodeId> FindName(FrameScopeId scope, Symbol name) const {
    if (name.empty()) return std::nullopt;
    const FrameNodeId* found = names.Find(Namespace(scope).value, name);
    if (!found) return std::nullopt;
    return *found;
  }
  /// Builds `names` from the nodes, in order, and marks it complete.
  void IndexNames();
};

}  // namespace mdlc::ir
