// resolve_frames.cc - the resolve-frames pass: evaluates SDFormat's pose and
// attachment graphs (Module::frame_graph) into body-fixed poses.
//
// SDFormat defines two graphs over the named frames of each model scope
// (SDF-003..005, SDF-011, SDF-012, SDF-042):
//   pose-relative-to: every frame's pose is given relative to another frame;
//   attached-to:      every frame is fixed to a link (directly, through a
//                     joint's child, a frame's attached_to, or a model's
//                     canonical link).
// Both are evaluated by depth-first search with an explicit stack (no
// recursion per nesting level), memoised, so the cost is linear in the
// number of frames plus the length of the names written; a cycle is reported
// once, with a note per frame on it.
//
// Poses are first evaluated relative to the frame of the node's own scope
// (the model frame), because a model's placement_frame makes the model's pose
// depend on frames inside it; world poses follow top-down.
//
// Reads: Module::frame_graph. Writes: Frame::body/X_BF, Joint::parent/child/
// X_PF/X_CM/axis, Geometry::X_BG, Camera::X_BC, Body::default_pose, and the
// welds of static models' links (SDF-006).
#include <absl/container/inlined_vector.h>
#include <fmt/format.h>

#include <cmath>

#include "passes/name_index.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

// A node's dependencies: one or two for nearly every node (its attachment,
// its relative_to frame), so they are kept inline, not on the heap.
using FrameDeps = absl::InlinedVector<FrameNodeId, 4>;

using ir::FrameNode;
using ir::FrameNodeKind;
using ir::FrameScope;

class ResolveFramesPass : public Pass {
 public:
  std::string_view name() const override { return "resolve-frames"; }
  std::string_view description() const override {
    return "Evaluate SDFormat poses (relative_to) and attachments into body-fixed poses";
  }
  bool Run(PassContext& ctx) override;

 private:
  // --- names ---
  std::optional<FrameNodeId> Lookup(FrameScopeId scope, const ir::NameRef& ref,
                                    std::string_view what);
  // --- graph evaluation ---
  FrameDeps PoseDependencies(FrameNodeId n) const;
  void ChainTo(FrameNodeId x, FrameScopeId ancestor, FrameDeps& out) const;
  FrameScopeId CommonAncestor(FrameScopeId a, FrameScopeId b) const;
  /// Pose of node x in the frame of scope C (every dependency evaluated).
  Transform PoseInScope(FrameNodeId x, FrameScopeId c) const;
  void EvaluateLocalPose(FrameNodeId n);
  /// The frame a model with no canonical_link is attached to.
  std::optional<FrameNodeId> DefaultAttachment(const FrameScope& s) const;
  /// The node n is fixed to: none for links, the world and a model without a
  /// scope; else as looked up before the attachments are evaluated.
  std::optional<FrameNodeId> AttachmentOf(const FrameNode& node, FrameNodeId n) const {
    if (node.kind == FrameNodeKind::World || node.kind == FrameNodeKind::Link) return std::nullopt;
    if (node.kind == FrameNodeKind::Model && !node.nested.valid()) return std::nullopt;
    return attached_to_[n.index()];
  }
  template <typename Deps, typename Eval>
  bool Evaluate(std::string_view graph_name, Deps&& deps, Eval&& eval);
  void ReportCycle(std::string_view graph_name, const std::vector<FrameNodeId>& cycle);
  // --- results ---
  static bool HasResult(const FrameNode& node) {
    return node.target != ir::FrameTarget::None && node.target != ir::FrameTarget::Body;
  }
  void WriteResult(FrameNodeId n);
  void WriteJoint(const ir::JointFrameSpec& spec);
  void WeldStaticLinks();
  std::string NodeName(FrameNodeId n) const;

  ir::FrameGraph& g() const { return ctx_->module.frame_graph; }
  ir::Module& m() const { return ctx_->module; }

  PassContext* ctx_ = nullptr;
  std::vector<uint32_t> depth_;                      // per scope
  std::vector<std::optional<FrameNodeId>> relative_to_, attached_to_, placement_;
  std::vector<std::optional<FrameNodeId>> joint_parents_;  // per JointFrameSpec
  std::vector<Transform> local_;                     // pose in the node's scope frame
  std::vector<Transform> world_;                     // X_W of each node
  std::vector<BodyId> body_;                         // the body each node is fixed to
  std::vector<Transform> body_pose_;                 // X_WB per body
  bool failed_ = false;
};

std::string ResolveFramesPass::NodeName(FrameNodeId n) const {
  const FrameNode& node = g()[n];
  if (node.kind == FrameNodeKind::Anchor) return "(unnamed pose)";
  const FrameScope& s = g()[node.scope];
  std::string name(m().Text(node.name));
  if (s.is_world) return name;
  return m().ScopedName(s.model, node.name);
}

std::optional<FrameNodeId> ResolveFramesPass::Lookup(FrameScopeId scope, const ir::NameRef& ref,
                                                     std::string_view what) {
  std::string_view text = m().Text(ref.name);
  if (text == "world") return g().scopes[0].frame;
  if (text == "__model__") return g()[scope].frame;
  // SDFormat 1.7 names could hold "::" themselves (flattened models)
  if (auto found = g().FindName(scope, ref.name)) return found;
  auto split = SplitScopedName(text);
  if (!split) {
    ctx_->diags.Report(DiagKind::InvalidName, ref.loc,
                       fmt::format("'{}' is not a valid scoped name", text));
    return std::nullopt;
  }
  FrameScopeId s = scope;
  std::string_view rest = text;
  auto not_found = [&](std::string_view component, FrameScopeId where) {
    const FrameScope& sc = g()[where];
    ctx_->diags.Report(DiagKind::UnknownReference, ref.loc,
                       fmt::format("{} '{}' does not match a nested model, link, joint, or frame "
                                   "name in {} '{}'",
                                   what, component == text ? text : component,
                                   sc.is_world ? "world" : "model",
                                   sc.is_world ? std::string_view("world") : m().Text(sc.name)));
    return std::nullopt;
  };
  while (true) {
    size_t sep = rest.find("::");
    std::string_view component = rest.substr(0, sep);
    std::optional<FrameNodeId> found = g().FindName(s, m().symbols.Find(component));
    if (sep == std::string_view::npos) {
      if (!found) return not_found(text, s);
      return found;
    }
    if (!found || g()[*found].kind != FrameNodeKind::Model || !g()[*found].nested.valid()) {
      return not_found(component, s);
    }
    s = g()[*found].nested;
    rest = rest.substr(sep + 2);
  }
}

FrameScopeId ResolveFramesPass::CommonAncestor(FrameScopeId a, FrameScopeId b) const {
  while (depth_[a.index()] > depth_[b.index()]) a = g()[a].parent;
  while (depth_[b.index()] > depth_[a.index()]) b = g()[b].parent;
  while (a != b) {
    a = g()[a].parent;
    b = g()[b].parent;
  }
  return a;
}

// The nodes whose local poses compose the pose of x in the frame of `ancestor`.
void ResolveFramesPass::ChainTo(FrameNodeId x, FrameScopeId ancestor,
                                FrameDeps& out) const {
  out.push_back(x);
  for (FrameScopeId s = g()[x].scope; s != ancestor; s = g()[s].parent) out.push_back(g()[s].frame);
}

Transform ResolveFramesPass::PoseInScope(FrameNodeId x, FrameScopeId c) const {
  if (x == g()[c].frame) return Transform::Identity();
  const FrameScopeId a = CommonAncestor(g()[x].scope, c);
  Transform P1 = local_[x.index()];
  for (FrameScopeId s = g()[x].scope; s != a; s = g()[s].parent) {
    P1 = local_[g()[s].frame.index()] * P1;
  }
  Transform P2 = Transform::Identity();
  for (FrameScopeId s = c; s != a; s = g()[s].parent) P2 = local_[g()[s].frame.index()] * P2;
  return P2.inverse() * P1;
}

FrameDeps ResolveFramesPass::PoseDependencies(FrameNodeId n) const {
  FrameDeps deps;
  const FrameNode& node = g()[n];
  const auto& target = relative_to_[n.index()];
  if (target && *target != g()[node.scope].frame) {
    const FrameScopeId a = CommonAncestor(g()[*target].scope, node.scope);
    ChainTo(*target, a, deps);
    for (FrameScopeId s = node.scope; s != a; s = g()[s].parent) deps.push_back(g()[s].frame);
  }
  if (node.kind == FrameNodeKind::Model && node.nested.valid()) {
    if (const auto& p = placement_[node.nested.index()]; p && *p != n) {
      const FrameScopeId a = CommonAncestor(g()[*p].scope, node.nested);
      ChainTo(*p, a, deps);
      for (FrameScopeId s = node.nested; s != a; s = g()[s].parent) deps.push_back(g()[s].frame);
    }
  }
  return deps;
}

void ResolveFramesPass::EvaluateLocalPose(FrameNodeId n) {
  const FrameNode& node = g()[n];
  Transform X = node.X_RN;
  if (const auto& target = relative_to_[n.index()]) X = PoseInScope(*target, node.scope) * X;
  if (node.kind == FrameNodeKind::Model && node.nested.valid()) {
    // placement_frame: the pose places frame P, not the model frame (SDF-005)
    if (const auto& p = placement_[node.nested.index()]; p && *p != n) {
      X = X * PoseInScope(*p, node.nested).inverse();
    }
  }
  local_[n.index()] = X;
}

std::optional<FrameNodeId> ResolveFramesPass::DefaultAttachment(const FrameScope& s) const {
  if (!s.links.empty()) return s.links.front();
  for (FrameScopeId c : s.children) return g()[c].frame;
  // a static model may have no link at all: its frame is fixed in the world
  return g().scopes[0].frame;
}

void ResolveFramesPass::ReportCycle(std::string_view graph_name,
                                    const std::vector<FrameNodeId>& cycle) {
  std::string names;
  for (FrameNodeId n : cycle) names += NodeName(n) + " -> ";
  names += NodeName(cycle.front());
  const FrameNode& first = g()[cycle.front()];
  auto diag = ctx_->diags.Report(DiagKind::FrameCycle, first.loc,
                                 fmt::format("{} cycle: {}", graph_name, names));
  for (FrameNodeId n : cycle) {
    const FrameNode& node = g()[n];
    const ir::NameRef& ref = graph_name == "attached_to" ? node.attached_to : node.relative_to;
    diag.Note(ref.loc.valid() ? ref.loc : node.loc,
              fmt::format("'{}' is {} '{}'", NodeName(n),
                          graph_name == "attached_to" ? "attached to" : "posed relative to",
                          m().Text(ref.name)));
  }
  failed_ = true;
}

// Depth-first evaluation of every node after its dependencies, with an
// explicit stack that is exactly the current path (for cycle reports).
template <typename Deps, typename Eval>
bool ResolveFramesPass::Evaluate(std::string_view graph_name, Deps&& deps, Eval&& eval) {
  enum : uint8_t { kNew, kOnPath, kDone, kFailed };
  std::vector<uint8_t> state(g().nodes.size(), kNew);
  struct Entry {
    FrameNodeId node;
    FrameDeps deps;
    size_t next = 0;
    bool ok = true;
  };
  std::vector<Entry> stack;
  bool ok = true;
  for (size_t root = 0; root < g().nodes.size(); ++root) {
    if (state[root] != kNew) continue;
    stack.push_back({FrameNodeId(root), deps(FrameNodeId(root))});
    state[root] = kOnPath;
    while (!stack.empty()) {
      Entry& top = stack.back();
      if (top.next < top.deps.size()) {
        FrameNodeId d = top.deps[top.next++];
        if (state[d.index()] == kNew) {
          state[d.index()] = kOnPath;
          stack.push_back({d, deps(d)});
        } else if (state[d.index()] == kOnPath) {
          std::vector<FrameNodeId> cycle;
          size_t i = stack.size();
          while (i > 0 && stack[i - 1].node != d) --i;
          for (size_t k = i - 1; k < stack.size(); ++k) cycle.push_back(stack[k].node);
          ReportCycle(graph_name, cycle);
          for (size_t k = i - 1; k < stack.size(); ++k) stack[k].ok = false;
          ok = false;
        } else if (state[d.index()] == kFailed) {
          top.ok = false;
        }
        continue;
      }
      const FrameNodeId n = top.node;
      const bool node_ok = top.ok;
      stack.pop_back();
      if (node_ok) eval(n);
      state[n.index()] = node_ok ? kDone : kFailed;
      if (!node_ok && !stack.empty()) stack.back().ok = false;
    }
  }
  return ok;
}

// The pose of node n in its body's frame, written to the frame, geometry or
// camera the node stands for.
void ResolveFramesPass::WriteResult(FrameNodeId n) {
  const FrameNode& node = g()[n];
  const BodyId b = body_[n.index()];
  const Transform X_BN = body_pose_[b.index()].inverse() * world_[n.index()];
  const ir::Body& body = m()[b];
  switch (node.target) {
    case ir::FrameTarget::Frame: {
      ir::Frame& f = m().frames[node.target_index];
      f.body = {body.name, node.attached_to.loc.valid() ? node.attached_to.loc : node.loc, b};
      f.X_BF = X_BN;
      break;
    }
    case ir::FrameTarget::Geometry: {
      ir::Geometry& geom = m().geometries[node.target_index];
      geom.body = {body.name, node.loc, b};
      geom.X_BG = X_BN;
      break;
    }
    case ir::FrameTarget::Camera: {
      // SDFormat sensors look along +x with +z up; Drake's camera frame
      // looks along +z with +y down: C = (-Sy, -Sz, Sx)
      Eigen::Matrix3d R_SC;
      R_SC << 0, 0, 1, -1, 0, 0, 0, -1, 0;
      ir::Camera& cam = m().cameras[node.target_index];
      cam.body = {body.name, node.loc, b};
      cam.X_BC = X_BN * Transform::FromRotation(R_SC);
      break;
    }
    default:
      break;
  }
}

void ResolveFramesPass::WriteJoint(const ir::JointFrameSpec& spec) {
  ir::Joint& joint = m()[spec.joint];
  const FrameNode& jnode = g()[spec.node];
  auto parent = joint_parents_[&spec - g().joints.data()];
  auto child = attached_to_[spec.node.index()];
  if (!parent || !child) return;
  const BodyId P = body_[parent->index()];
  const BodyId C = body_[child->index()];
  if (!P.valid() || !C.valid()) return;
  if (P == C) {
    ctx_->diags.Report(DiagKind::SelfJoint, joint.loc,
                       fmt::format("joint '{}' connects '{}' to '{}', which are both fixed to "
                                   "link '{}'",
                                   m().Text(joint.name), m().Text(spec.parent.name),
                                   m().Text(jnode.attached_to.name), m().ScopedName(P)));
    return;
  }
  const Transform& X_WJ = world_[spec.node.index()];
  // drake:joint: F is the parent frame, M the child frame (node J is M)
  const Transform& X_WF = spec.frames_given ? world_[parent->index()] : X_WJ;
  Transform X_PJ = body_pose_[P.index()].inverse() * X_WF;
  Transform X_CJ = body_pose_[C.index()].inverse() * X_WJ;
  // axes in J (SDF-012)
  Eigen::Vector3d axis_J[2];
  for (int k = 0; k < spec.axis_count; ++k) {
    axis_J[k] = spec.xyz[k];
    if (!spec.expressed_in[k].empty()) {
      auto e = Lookup(jnode.scope, spec.expressed_in[k], "expressed_in frame");
      if (!e) return;
      axis_J[k] = X_WJ.R.transpose() * (world_[e->index()].R * spec.xyz[k]);
    }
  }
  if (joint.type == ir::JointType::Universal) {
    // Drake's universal joint turns about Fx, then My: build frame I whose x
    // and y are the two axes, and put F and M there
    const Eigen::Vector3d x = axis_J[0].normalized(), y = axis_J[1].normalized();
    if (std::abs(x.dot(y)) > 1e-10) {
      ctx_->diags.Report(DiagKind::BadValue, joint.loc,
                         fmt::format("axis and axis2 must be orthogonal for joint '{}'",
                                     m().Text(joint.name)));
      return;
    }
    Eigen::Matrix3d R_JI;
    R_JI.col(0) = x;
    R_JI.col(1) = y;
    R_JI.col(2) = x.cross(y);
    X_PJ = X_PJ * Transform::FromRotation(R_JI);
    X_CJ = X_CJ * Transform::FromRotation(R_JI);
  } else if (spec.axis_count >= 1) {
    joint.axis = axis_J[0].normalized();
  }
  joint.parent = {spec.parent.name, spec.parent.loc, P};
  joint.child = {jnode.attached_to.name, jnode.attached_to.loc, C};
  joint.X_PF = X_PJ;
  joint.X_CM = X_CJ;
}

void ResolveFramesPass::WeldStaticLinks() {
  std::vector<bool> has_parent(m().bodies.size(), false);
  for (const ir::Joint& j : m().joints) {
    if (j.child.resolved()) has_parent[j.child.id.index()] = true;
  }
  for (const ir::JointFrameSpec& spec : g().joints) {
    const FrameScope& s = g()[g()[spec.node].scope];
    const ir::Joint& j = m()[spec.joint];
    if (s.is_static && j.type != ir::JointType::Weld) {
      ctx_->diags.Report(DiagKind::StaticModelJoint, j.loc,
                         fmt::format("joint '{}' is not fixed: only fixed joints are permitted "
                                     "in static models",
                                     m().Text(j.name)));
      failed_ = true;
    }
  }
  for (const FrameScope& s : g().scopes) {
    if (!s.is_static) continue;
    for (FrameNodeId link : s.links) {
      const BodyId b(g()[link].target_index);
      if (has_parent[b.index()]) continue;
      ir::Joint weld;
      weld.name = m().Intern(fmt::format("sdformat_model_static_world_welds_to_{}",
                                         m().Text(m()[b].name)));
      weld.model = m()[b].model;
      weld.loc = m()[b].loc;
      weld.type = ir::JointType::Weld;
      weld.parent = {m().bodies[0].name, {}, ir::kWorldBody};
      weld.child = {m()[b].name, m()[b].loc, b};
      weld.X_PF = body_pose_[b.index()];
      weld.limits = ir::JointLimits::Unbounded(0);
      weld.unnamed = true;
      m().Add(std::move(weld));
      has_parent[b.index()] = true;
    }
  }
}

bool ResolveFramesPass::Run(PassContext& ctx) {
  ctx_ = &ctx;
  if (g().empty()) return true;
  const size_t n_nodes = g().nodes.size();
  const size_t n_scopes = g().scopes.size();

  // scope depths (parents are created before their children)
  depth_.assign(n_scopes, 0);
  for (size_t i = 0; i < n_scopes; ++i) {
    const FrameScope& s = g().scopes[i];
    depth_[i] = s.parent.valid() ? depth_[s.parent.index()] + 1 : 0;
  }
  // names: first definition wins (duplicates were reported by the
  // frontend, which indexes the names as it adds the nodes)
  if (!g().names_complete) g().IndexNames();

  // every reference, looked up once
  relative_to_.assign(n_nodes, std::nullopt);
  attached_to_.assign(n_nodes, std::nullopt);
  placement_.assign(n_scopes, std::nullopt);
  bool lookups_ok = true;
  for (size_t i = 0; i < n_nodes; ++i) {
    const FrameNode& node = g().nodes[i];
    if (node.kind == FrameNodeKind::World) continue;
    const bool same_as_attached = node.relative_to.name == node.attached_to.name &&
                                  node.relative_to.loc == node.attached_to.loc;
    if (!node.relative_to.empty() && !same_as_attached) {
      relative_to_[i] = Lookup(node.scope, node.relative_to, "relative_to name");
      lookups_ok &= relative_to_[i].has_value();
      if (relative_to_[i] == FrameNodeId(i)) {
        ctx.diags.Report(DiagKind::FrameCycle, node.relative_to.loc,
                         fmt::format("relative_to name '{}' is identical to the name of the "
                                     "frame it places, causing a graph cycle",
                                     m().Text(node.relative_to.name)));
        relative_to_[i].reset();
        lookups_ok = false;
      }
    }
    if (node.kind == FrameNodeKind::Model && node.nested.valid()) {
      const FrameScope& s = g()[node.nested];
      if (!s.canonical_link.empty()) {
        attached_to_[i] = Lookup(node.nested, s.canonical_link, "canonical_link");
        if (attached_to_[i] && g()[*attached_to_[i]].kind != FrameNodeKind::Link) {
          ctx.diags.Report(DiagKind::UnknownReference, s.canonical_link.loc,
                           fmt::format("canonical_link '{}' of model '{}' is not a link",
                                       m().Text(s.canonical_link.name), m().Text(s.name)));
          attached_to_[i].reset();
        }
        lookups_ok &= attached_to_[i].has_value();
      } else if (s.links.empty() && s.children.empty() && !s.is_static) {
        ctx.diags.Report(DiagKind::MissingElement, s.loc,
                         fmt::format("model '{}' must have at least one link: it has no "
                                     "canonical link",
                                     m().Text(s.name)));
        lookups_ok = false;
      } else {
        attached_to_[i] = DefaultAttachment(s);
      }
      if (!s.placement_frame.empty()) {
        placement_[node.nested.index()] =
            Lookup(node.nested, s.placement_frame, "placement_frame");
        lookups_ok &= placement_[node.nested.index()].has_value();
      }
    } else if (node.attached_node.valid()) {
      attached_to_[i] = node.attached_node;
    } else if (!node.attached_to.empty() && node.kind != FrameNodeKind::Link) {
      attached_to_[i] = Lookup(node.scope, node.attached_to,
                               node.kind == FrameNodeKind::Joint ? "child frame" : "attached_to name");
      if (attached_to_[i] == FrameNodeId(i)) {
        ctx.diags.Report(DiagKind::FrameCycle, node.attached_to.loc,
                         fmt::format("'{}' is attached to itself", NodeName(FrameNodeId(i))));
        attached_to_[i].reset();
      }
      lookups_ok &= attached_to_[i].has_value();
    }
    if (same_as_attached) relative_to_[i] = attached_to_[i];
  }
  joint_parents_.assign(g().joints.size(), std::nullopt);
  for (size_t k = 0; k < g().joints.size(); ++k) {
    const ir::JointFrameSpec& spec = g().joints[k];
    // a joint connects links (or frames fixed to them), never a model frame
    const ir::NameRef* child_ref = &g()[spec.node].attached_to;
    for (const ir::NameRef* ref : {&spec.parent, child_ref}) {
      if (m().Text(ref->name) == "__model__") {
        ctx.diags.Report(DiagKind::UnknownReference, ref->loc,
                         fmt::format("joint '{}' names __model__ as its {} frame: a joint must "
                                     "connect links or frames, not the model frame",
                                     m().Text(m()[spec.joint].name),
                                     ref == &spec.parent ? "parent" : "child"));
        lookups_ok = false;
      }
    }
    joint_parents_[k] = Lookup(g()[spec.node].scope, spec.parent, "parent frame");
    lookups_ok &= joint_parents_[k].has_value();
  }
  if (!lookups_ok) return false;

  // attachments
  failed_ = false;
  body_.assign(n_nodes, BodyId{});
  Evaluate(
      "attached_to",
      [&](FrameNodeId n) {
        FrameDeps deps;
        if (auto a = AttachmentOf(g()[n], n)) deps.push_back(*a);
        return deps;
      },
      [&](FrameNodeId n) {
        const FrameNode& node = g()[n];
        if (node.kind == FrameNodeKind::World) {
          body_[n.index()] = ir::kWorldBody;
        } else if (node.kind == FrameNodeKind::Link) {
          body_[n.index()] = BodyId(node.target_index);
        } else if (auto a = AttachmentOf(node, n)) {
          body_[n.index()] = body_[a->index()];
        }
      });
  if (failed_) return false;

  // poses relative to each node's scope frame, then in world
  local_.assign(n_nodes, Transform::Identity());
  Evaluate("relative_to", [&](FrameNodeId n) { return PoseDependencies(n); },
           [&](FrameNodeId n) { EvaluateLocalPose(n); });
  if (failed_) return false;
  world_.assign(n_nodes, Transform::Identity());
  // scope frames top-down (each scope's frame lives in its parent scope)
  for (size_t i = 1; i < n_scopes; ++i) {
    const FrameScope& s = g().scopes[i];
    if (s.is_world) continue;  // each SDFormat file of a compile has its own world scope
    const FrameNodeId f = s.frame;
    world_[f.index()] = world_[g()[s.parent].frame.index()] * local_[f.index()];
  }
  // then every other node, writing each node's result (a model's too: its
  // __model__ frame) in the same sweep: in a scene of many models the nodes
  // outgrow the cache, and each sweep reads them from memory again. A result
  // needs its body's pose, so a node written before its link in the file
  // waits for the end.
  body_pose_.assign(m().bodies.size(), Transform::Identity());
  std::vector<bool> body_posed(m().bodies.size(), false);
  body_posed[ir::kWorldBody.index()] = true;
  std::vector<FrameNodeId> waiting;
  for (size_t i = 0; i < n_nodes; ++i) {
    const FrameNode& node = g().nodes[i];
    if (node.kind == FrameNodeKind::World) continue;
    const bool scope_frame = node.kind == FrameNodeKind::Model && node.nested.valid();
    if (!scope_frame) world_[i] = world_[g()[node.scope].frame.index()] * local_[i];
    if (node.kind == FrameNodeKind::Link) {
      body_pose_[node.target_index] = world_[i];
      body_posed[node.target_index] = true;
      m().bodies[node.target_index].default_pose = world_[i];
    } else if (const BodyId b = body_[i]; b.valid() && HasResult(node)) {
      if (body_posed[b.index()]) {
        WriteResult(FrameNodeId(i));
      } else {
        waiting.push_back(FrameNodeId(i));
      }
    }
  }
  for (FrameNodeId n : waiting) WriteResult(n);
  for (const ir::JointFrameSpec& spec : g().joints) WriteJoint(spec);
  WeldStaticLinks();
  return !failed_ && !ctx.diags.has_errors();
}

}  // namespace

std::unique_ptr<Pass> CreateResolveFramesPass() { return std::make_unique<ResolveFramesPass>(); }

}  // namespace mdlc::passes
