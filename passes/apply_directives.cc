// apply_directives.cc - the apply-directives pass: performs the frames,
// welds and default poses of Model Directives (DMD-011, DMD-012, DMD-030,
// DMD-040, DMD-070), in directive order, once every model's own frames are
// resolved.
//
// Reads: Module::scene_edits, resolved bodies and frames.
// Writes: new frames, weld and quaternion_floating joints, joint default
// positions and free bodies' default poses.
//
// Frame lookup follows Drake's GetScopedFrameByName: "world" is the world
// frame; "inst::f" is the body frame or frame `f` of instance `inst`; an
// unscoped "f" must name exactly one frame across all instances
// (COMMON-033). A lookup only sees the instances that existed when its
// directive ran, and the frames earlier directives added.
#include <fmt/format.h>

#include <unordered_map>

#include "passes/floating_joint.h"
#include "passes/name_index.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

// A frame a directive can name: a body frame or an explicit frame.
struct SceneFrame {
  Symbol name;
  ModelId model;
  BodyId body;
  Transform X_BF;
  Loc loc;
};

class ApplyDirectivesPass : public Pass {
 public:
  std::string_view name() const override { return "apply-directives"; }
  std::string_view description() const override {
    return "Add Model Directives' frames, welds and default poses to the plant";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Resolved; }
  bool Run(PassContext& ctx) override;

 private:
  void Index(ir::Module& m);
  void AddFrame(ModelId model, Symbol name, BodyId body, Transform X_BF, Loc loc);
  std::optional<SceneFrame> Lookup(PassContext& ctx, const ir::DirectiveFrameName& ref,
                                   uint32_t visible_models);
  std::optional<ModelId> LookupModel(PassContext& ctx, std::string_view name, Loc loc,
                                     uint32_t visible_models, std::string_view user);
  std::optional<JointId> FindJoint(ModelId model, Symbol name) const {
    return joints_.Find(model, name);
  }

  void Apply(PassContext& ctx, const ir::AddFrameEdit& e, uint32_t visible);
  void Apply(PassContext& ctx, const ir::AddWeldEdit& e, uint32_t visible);
  void Apply(PassContext& ctx, const ir::DefaultJointPositionsEdit& e, uint32_t visible);
  void Apply(PassContext& ctx, const ir::DefaultFreeBodyPoseEdit& e, uint32_t visible);

  static uint64_t Key(ModelId model, Symbol name) {
    return (uint64_t{model.value} << 32) | name.value;
  }

  std::vector<SceneFrame> frames_;
  std::unordered_map<uint64_t, size_t> by_scoped_name_;
  std::unordered_map<uint32_t, std::vector<size_t>> by_name_;  // Symbol value -> frames_
  NameIndex<JointId> joints_;
  std::optional<ModelIndex> models_;
};

void ApplyDirectivesPass::AddFrame(ModelId model, Symbol name, BodyId body, Transform X_BF,
                                   Loc loc) {
  const size_t index = frames_.size();
  frames_.push_back({name, model, body, X_BF, loc});
  by_scoped_name_.emplace(Key(model, name), index);
  by_name_[name.value].push_back(index);
}

void ApplyDirectivesPass::Index(ir::Module& m) {
  for (size_t b = 1; b < m.bodies.size(); ++b) {
    const ir::Body& body = m.bodies[b];
    AddFrame(body.model, body.name, BodyId(b), {}, body.loc);
  }
  for (const ir::Frame& f : m.frames) {
    if (f.body.resolved()) AddFrame(f.model, f.name, f.body.id, f.X_BF, f.loc);
  }
  for (size_t j = 0; j < m.joints.size(); ++j) joints_.Add(m.joints[j].model, m.joints[j].name, JointId(j));
  models_.emplace(m);
}

std::optional<ModelId> ApplyDirectivesPass::LookupModel(PassContext& ctx, std::string_view name,
                                                        Loc loc, uint32_t visible_models,
                                                        std::string_view user) {
  auto model = models_->Find(name);
  if (model && model->index() < visible_models) return model;
  const ir::Module& m = ctx.module;
  auto diag = ctx.diags.Report(
      DiagKind::UnknownReference, loc,
      model ? fmt::format("{}: model instance '{}' is only added by a later directive", user, name)
            : fmt::format("{}: no model instance named '{}'", user, name));
  if (!model) {
    std::vector<std::string> full_names;
    for (uint32_t i = 0; i < visible_models && i < m.models.size(); ++i) {
      full_names.push_back(m.ModelName(ModelId(i)));
    }
    const std::vector<std::string_view> names(full_names.begin(), full_names.end());
    if (auto best = ClosestName(name, names)) diag.Note(loc, fmt::format("did you mean '{}'?", *best));
  }
  return std::nullopt;
}

std::optional<SceneFrame> ApplyDirectivesPass::Lookup(PassContext& ctx,
                                                      const ir::DirectiveFrameName& ref,
                                                      uint32_t visible_models) {
  const ir::Module& m = ctx.module;
  const std::string_view text = m.Text(ref.name);
  if (text == "world") return SceneFrame{ref.name, ir::kWorldModel, ir::kWorldBody, {}, {}};
  auto split = SplitScopedName(text);
  if (!split) {
    ctx.diags.Report(DiagKind::InvalidName, ref.loc,
                     fmt::format("'{}' is not a valid scoped name", text));
    return std::nullopt;
  }
  const Symbol element = m.symbols.Find(split->element);
  if (!split->scope.empty()) {
    auto model = LookupModel(ctx, split->scope, ref.loc, visible_models,
                             fmt::format("frame '{}'", text));
    if (!model) return std::nullopt;
    if (auto it = by_scoped_name_.find(Key(*model, element));
        !element.empty() && it != by_scoped_name_.end()) {
      return frames_[it->second];
    }
    auto diag = ctx.diags.Report(
        DiagKind::UnknownReference, ref.loc,
        fmt::format("model instance '{}' has no frame named '{}'", split->scope, split->element));
    std::vector<std::string_view> names;
    for (const SceneFrame& f : frames_) {
      if (f.model == *model) names.push_back(m.Text(f.name));
    }
    if (auto best = ClosestName(split->element, names)) {
      diag.Note(ref.loc, fmt::format("did you mean '{}::{}'?", split->scope, *best));
    }
    return std::nullopt;
  }
  // unscoped: exactly one frame of that name among the visible instances
  std::vector<size_t> found;
  if (auto it = by_name_.find(element.value); !element.empty() && it != by_name_.end()) {
    for (size_t i : it->second) {
      if (frames_[i].model.index() < visible_models) found.push_back(i);
    }
  }
  if (found.size() == 1) return frames_[found[0]];
  if (found.empty()) {
    ctx.diags.Report(DiagKind::UnknownReference, ref.loc,
                     fmt::format("no frame named '{}' in any model instance; scoped names "
                                 "('instance::frame') name a frame of one instance",
                                 text));
    return std::nullopt;
  }
  auto diag = ctx.diags.Report(
      DiagKind::UnknownReference, ref.loc,
      fmt::format("frame name '{}' is ambiguous: {} model instances have a frame of that name; "
                  "write it scoped ('instance::{}')",
                  text, found.size(), text));
  for (size_t i : found) {
    diag.Note(frames_[i].loc, fmt::format("'{}' is defined here",
                                          m.ScopedName(frames_[i].model, frames_[i].name)));
  }
  return std::nullopt;
}

void ApplyDirectivesPass::Apply(PassContext& ctx, const ir::AddFrameEdit& e, uint32_t visible) {
  ir::Module& m = ctx.module;
  auto base = Lookup(ctx, e.base_frame, visible);
  if (!base) return;
  ModelId model = base->model;
  if (!e.instance.empty()) {
    auto scoped = LookupModel(ctx, m.Text(e.instance), e.name_loc, visible,
                              fmt::format("add_frame '{}'", m.Text(e.name)));
    if (!scoped) return;
    model = *scoped;
  }
  if (auto it = by_scoped_name_.find(Key(model, e.name)); it != by_scoped_name_.end()) {
    ctx.diags
        .Report(DiagKind::DuplicateName, e.name_loc,
                fmt::format("model instance '{}' already has a frame named '{}'",
                            m.ModelName(model), m.Text(e.name)))
        .Note(frames_[it->second].loc, "the existing frame is defined here");
    return;
  }
  ir::Frame frame;
  frame.name = e.name;
  frame.model = model;
  frame.loc = e.name_loc;
  frame.body = {m[base->body].name, e.base_frame.loc, base->body};
  frame.X_BF = base->X_BF * e.X_PF;
  AddFrame(model, frame.name, frame.body.id, frame.X_BF, frame.loc);
  m.Add(std::move(frame));
}

void ApplyDirectivesPass::Apply(PassContext& ctx, const ir::AddWeldEdit& e, uint32_t visible) {
  ir::Module& m = ctx.module;
  auto parent = Lookup(ctx, e.parent, visible);
  auto child = Lookup(ctx, e.child, visible);
  if (!parent || !child) return;
  // DMD-070: Drake's WeldFrames names the joint after both frames and puts
  // it in the child's instance
  const Symbol name =
      m.Intern(fmt::format("{}_welds_to_{}", m.Text(parent->name), m.Text(child->name)));
  if (auto existing = FindJoint(child->model, name)) {
    ctx.diags
        .Report(DiagKind::DuplicateName, e.loc,
                fmt::format("model instance '{}' already has a joint named '{}'",
                            m.ModelName(child->model), m.Text(name)))
        .Note(m[*existing].loc, "the existing joint is defined here");
    return;
  }
  ir::Joint j;
  j.name = name;
  j.model = child->model;
  j.loc = e.loc;
  j.type = ir::JointType::Weld;
  j.parent = {m[parent->body].name, e.parent.loc, parent->body};
  j.child = {m[child->body].name, e.child.loc, child->body};
  j.X_PF = parent->X_BF * e.X_PC;
  j.X_CM = child->X_BF;
  j.limits = ir::JointLimits::Unbounded(0);
  j.unnamed = true;
  joints_.Add(j.model, j.name, JointId(m.joints.size()));
  m.Add(std::move(j));
}

void ApplyDirectivesPass::Apply(PassContext& ctx, const ir::DefaultJointPositionsEdit& e,
                                uint32_t) {
  ir::Module& m = ctx.module;
  auto joint = FindJoint(e.model, e.joint);
  if (!joint) {
    auto diag = ctx.diags.Report(
        DiagKind::UnknownReference, e.loc,
        fmt::format("default_joint_positions: model instance '{}' has no joint named '{}'",
                    m.ModelName(e.model), m.Text(e.joint)));
    std::vector<std::string_view> names;
    for (const ir::Joint& j : m.joints) {
      if (j.model == e.model) names.push_back(m.Text(j.name));
    }
    if (auto best = ClosestName(m.Text(e.joint), names)) {
      diag.Note(e.loc, fmt::format("did you mean '{}'?", *best));
    }
    return;
  }
  ir::Joint& j = m[*joint];
  const size_t nq = static_cast<size_t>(ir::JointPositionCount(j.type));
  if (e.positions.size() != nq) {
    ctx.diags
        .Report(DiagKind::BadValue, e.values_loc,
                fmt::format("default_joint_positions: joint '{}' ({}) has {} position{}, not {}",
                            m.Text(j.name), ir::JointTypeName(j.type), nq, nq == 1 ? "" : "s",
                            e.positions.size()))
        .Note(j.loc, "the joint is defined here");
    return;
  }
  j.default_positions = e.positions;
}

void ApplyDirectivesPass::Apply(PassContext& ctx, const ir::DefaultFreeBodyPoseEdit& e,
                                uint32_t visible) {
  ir::Module& m = ctx.module;
  const std::string model_name(m.ModelName(e.model));
  // the frame to pose: an unscoped name in the added model, or "" for its
  // only body (DMD-012)
  std::optional<SceneFrame> child;
  if (e.frame.empty() || m.Text(e.frame).empty()) {
    std::vector<BodyId> bodies;
    for (size_t b = 1; b < m.bodies.size(); ++b) {
      if (m.bodies[b].model == e.model) bodies.push_back(BodyId(b));
    }
    if (bodies.size() != 1) {
      ctx.diags.Report(DiagKind::BadValue, e.loc,
                       fmt::format("default_free_body_pose: model instance '{}' has {} bodies "
                                   "(not 1), so the empty name does not pick one; name the body",
                                   model_name, bodies.size()));
      return;
    }
    child = frames_[by_scoped_name_.at(Key(e.model, m[bodies[0]].name))];
  } else if (auto it = by_scoped_name_.find(Key(e.model, e.frame)); it != by_scoped_name_.end()) {
    child = frames_[it->second];
  } else {
    ctx.diags.Report(DiagKind::UnknownReference, e.loc,
                     fmt::format("default_free_body_pose: model instance '{}' has no body or "
                                 "frame named '{}'",
                                 model_name, m.Text(e.frame)));
    return;
  }
  std::optional<SceneFrame> base;
  if (e.base_frame) {
    base = Lookup(ctx, *e.base_frame, visible);
    if (!base) return;
  }
  // the world frame itself, not merely a frame fixed to the world (Drake
  // compares the frames, not their poses)
  const bool in_world = !base || (base->body == ir::kWorldBody && m.Text(base->name) == "world");
  ir::Body& body = m[child->body];
  if (body.deformable) {
    // a deformable body has no joint; only its pose in the world can be set
    if (!in_world) {
      ctx.diags.Report(DiagKind::BadValue, e.base_frame->loc,
                       fmt::format("default_free_body_pose: deformable body '{}' can only be "
                                   "posed in the world frame",
                                   m.Text(body.name)));
      return;
    }
    body.default_pose = e.X_PC;
    return;
  }
  if (in_world && child->X_BF.IsIdentity()) {
    body.default_pose = e.X_PC;  // the free body's own floating joint starts there
    return;
  }
  // posed in another frame, or by a frame offset from the body: Drake adds a
  // 6-dof joint from the base frame to that frame, starting at X_PC
  const std::string name = FloatingJointName(m.Text(body.name), [&](const std::string& n) {
    Symbol s = m.symbols.Find(n);
    return !s.empty() && FindJoint(body.model, s).has_value();
  });
  const BodyId parent = base ? base->body : ir::kWorldBody;
  const Transform X_PF = base ? base->X_BF : Transform{};
  ir::Joint j = MakeFloatingJoint(m, m.Intern(name), e.loc, parent, X_PF, child->body,
                                  child->X_BF, e.X_PC);
  joints_.Add(j.model, j.name, JointId(m.joints.size()));
  m.Add(std::move(j));
}

bool ApplyDirectivesPass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  if (m.scene_edits.empty()) return true;
  Index(m);
  for (const ir::SceneEdit& edit : m.scene_edits) {
    std::visit([&](const auto& e) { Apply(ctx, e, edit.visible_models); }, edit.edit);
  }
  m.scene_edits.clear();
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateApplyDirectivesPass() {
  return std::make_unique<ApplyDirectivesPass>();
}

}  // namespace mdlc::passes
