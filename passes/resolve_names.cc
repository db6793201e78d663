// resolve_names.cc - the resolve-names pass: turns every by-name reference
// (joint parent/child, frame body, geometry body, actuator joint, constraint
// joints and bodies) into an id.
//
// Reads: Ref::name and the referring entity's model instance.
// Writes: Ref::id. Afterwards the verifier's Resolved level holds.
// Lookup (COMMON-030..033): "world" is the world body everywhere; an
// unscoped name is looked up in the referring entity's own instance; a
// scoped name "a::x" in the nested instance "<own>::a", then in "a".
// Collision filter groups (COMMON-053, Drake's CollisionFilterGroupResolver)
// are stricter: a member names a body and a member or ignored group names a
// group of the group's own instance or of one nested in it ("<own>::a"), never
// the world body; only groups of the world or default instance (the global
// scope of model directives) name top-level instances ("a::x" in "a").
#include <fmt/format.h>

#include <set>
#include <type_traits>
#include <utility>
#include <variant>

#include "ir/overloaded.h"
#include "passes/name_index.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

// Which entities a "did you mean" draws on: tier 0 first, then tier 1; -1
// never. The default: every entity of the instance, alike.
struct AnyCandidate {
  template <typename Entity>
  int operator()(const Entity&) const {
    return 0;
  }
};

class ResolveNamesPass : public Pass {
 public:
  std::string_view name() const override { return "resolve-names"; }
  std::string_view description() const override {
    return "Resolve by-name references between entities to ids";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Resolved; }
  bool Run(PassContext& ctx) override;

 private:
  // `user` describes the referring entity; it is called only to report an
  // error, as is `tier`, which ranks the suggestions (AnyCandidate)
  template <typename IdT, typename Index, typename Table, typename User,
            typename Tier = AnyCandidate>
  void Resolve(PassContext& ctx, ir::Ref<IdT>& ref, ModelId scope, const Index& index,
               const Table& table, std::string_view kind, const User& user,
               const Tier& tier = {});
  std::optional<ModelId> ScopeFor(PassContext& ctx, ModelId own, std::string_view scope) const;
  template <typename FrameIndex, typename BodyIndex>
  void ResolveFrame(PassContext& ctx, ir::FrameRef& ref, ModelId scope, const FrameIndex& frames,
                    const BodyIndex& bodies, std::string_view user);
  // a reference from collision filter group `group` (COMMON-053)
  template <typename IdT, typename Index, typename Table>
  void ResolveForGroup(PassContext& ctx, ir::Ref<IdT>& ref, const ir::CollisionFilterGroup& group,
                       const Index& index, const Table& table, std::string_view kind);

  std::optional<ModelIndex> models_;
};

std::optional<ModelId> ResolveNamesPass::ScopeFor(PassContext& ctx, ModelId own,
                                                  std::string_view scope) const {
  if (scope.empty()) return own;
  if (auto m = models_->Find(scope, own)) return m;
  return models_->Find(scope);
}

template <typename IdT, typename Index, typename Table, typename User, typename Tier>
void ResolveNamesPass::Resolve(PassContext& ctx, ir::Ref<IdT>& ref, ModelId scope,
                               const Index& index, const Table& table, std::string_view kind,
                               const User& user, const Tier& tier) {
  if (ref.resolved() || ref.name.empty()) return;
  ir::Module& m = ctx.module;
  std::string_view text = m.Text(ref.name);
  if constexpr (std::is_same_v<IdT, BodyId>) {
    if (text == "world") {
      ref.id = ir::kWorldBody;
      return;
    }
  }
  auto split = SplitScopedName(text);
  if (!split) {
    ctx.diags.Report(DiagKind::InvalidName, ref.loc,
                     fmt::format("'{}' is not a valid scoped name", text));
    return;
  }
  std::optional<ModelId> model = ScopeFor(ctx, scope, split->scope);
  if (!model) {
    ctx.diags.Report(DiagKind::UnknownReference, ref.loc,
                     fmt::format("{} names {} '{}' in unknown model instance '{}'", user(), kind,
                                 text, split->scope));
    return;
  }
  Symbol element = m.symbols.Find(split->element);
  if (auto id = element.empty() ? std::nullopt : index.Find(*model, element)) {
    ref.id = *id;
    return;
  }
  auto diag = ctx.diags.Report(
      DiagKind::UnknownReference, ref.loc,
      fmt::format("{} names unknown {} '{}': Could not find {} '{}' in model '{}'", user(),
                  kind, text, kind, split->element, m.ModelName(*model)));
  std::vector<std::string_view> candidates[2];
  for (const auto& entity : table) {
    if (entity.model != *model) continue;
    if (const int t = tier(entity); t >= 0) candidates[t].push_back(m.Text(entity.name));
  }
  std::optional<std::string> best = ClosestName(split->element, candidates[0]);
  if (!best) best = ClosestName(split->element, candidates[1]);
  if (best) diag.Note(ref.loc, fmt::format("did you mean '{}'?", *best));
}

// a frame reference names an explicit frame, or else a body's own frame
template <typename FrameIndex, typename BodyIndex>
void ResolveNamesPass::ResolveFrame(PassContext& ctx, ir::FrameRef& ref, ModelId scope,
                                    const FrameIndex& frames, const BodyIndex& bodies,
                                    std::string_view user) {
  if (ref.resolved() || ref.name.empty()) return;
  ir::Module& m = ctx.module;
  std::string_view text = m.Text(ref.name);
  if (text == "world") {
    ref.body = ir::kWorldBody;
    return;
  }
  auto split = SplitScopedName(text);
  std::optional<ModelId> model = split ? ScopeFor(ctx, scope, split->scope) : std::nullopt;
  const Symbol element = split ? m.symbols.Find(split->element) : Symbol{};
  if (model && !element.empty()) {
    if (auto f = frames.Find(*model, element)) {
      ref.frame = *f;
      return;
    }
    if (auto b = bodies.Find(*model, element)) {
      ref.body = *b;
      return;
    }
  }
  ctx.diags.Report(DiagKind::UnknownReference, ref.loc,
                   fmt::format("{} names unknown frame '{}': no frame or link of that name", user,
                               text));
}

template <typename IdT, typename Index, typename Table>
void ResolveNamesPass::ResolveForGroup(PassContext& ctx, ir::Ref<IdT>& ref,
                                       const ir::CollisionFilterGroup& group, const Index& index,
                                       const Table& table, std::string_view kind) {
  if (ref.resolved()) return;
  ir::Module& m = ctx.module;
  const std::string group_name = m.ScopedName(group.model, group.name);
  std::string_view text = m.Text(ref.name);
  auto split = SplitScopedName(text);
  if (!split || split->element.empty()) {
    ctx.diags.Report(DiagKind::InvalidName, ref.loc,
                     fmt::format("collision filter group '{}': '{}' is not a valid scoped name",
                                 group_name, text));
    return;
  }
  const bool global = group.model == ir::kWorldModel || group.model == ir::kDefaultModel;
  std::optional<ModelId> model = group.model;
  if (!split->scope.empty()) {
    model = global ? models_->Find(split->scope)
                   : models_->Find(split->scope, group.model);
  }
  if (model) {
    const Symbol element = m.symbols.Find(split->element);
    if (auto id = element.empty() ? std::nullopt : index.Find(*model, element)) {
      ref.id = *id;
      return;
    }
  }
  // Drake qualifies the name with the group's instance before looking it up
  const std::string full = model    ? fmt::format("{}::{}", m.ModelName(*model), split->element)
                           : global ? std::string(text)
                                    : fmt::format("{}::{}", m.ModelName(group.model), text);
  auto diag = ctx.diags.Report(
      DiagKind::UnknownReference, ref.loc,
      fmt::format("collision filter group '{}' names unknown {} '{}': {} with name '{}' not found",
                  group_name, kind, text, kind, full));
  if constexpr (std::is_same_v<IdT, BodyId>) {
    if (text == "world") {
      diag.Note(ref.loc, "the world body belongs to no model instance's collision filter groups");
      return;
    }
  }
  if (!model) return;
  std::vector<std::string_view> candidates;
  for (const auto& entity : table) {
    if (entity.model == *model) candidates.push_back(m.Text(entity.name));
  }
  if (auto best = ClosestName(split->element, candidates)) {
    diag.Note(ref.loc, fmt::format("did you mean '{}'?", *best));
  }
}

bool ResolveNamesPass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  models_.emplace(m);
  // each index is built by the first reference that needs it (the world
  // body, index 0, is found by its name "world", never through the index);
  // a duplicate group name is reported by check-model-elements, the first wins
  LazyNameIndex<BodyId, decltype(m.bodies)> bodies(m.bodies, 1);
  LazyNameIndex<JointId, decltype(m.joints)> joints(m.joints, 0);
  LazyNameIndex<FrameId, decltype(m.frames)> frames(m.frames, 0);
  LazyNameIndex<FilterGroupId, decltype(m.filter_groups)> groups(m.filter_groups, 0);

  auto described = [&](const char* what, Symbol name) {
    return [&m, what, name] { return fmt::format("{} '{}'", what, m.Text(name)); };
  };
  // A joint's misspelled child is most likely a link no joint has as its
  // child yet (an orphan), and never the joint's own parent: suggest those
  // first, so "link3" next to "link1" (the parent) and "link2" (an orphan)
  // suggests "link2".
  std::set<std::pair<uint32_t, uint32_t>> child_names;  // (model, name) named as a child
  for (const ir::Joint& j : m.joints) child_names.emplace(j.model.value, j.child.name.value);
  for (ir::Joint& j : m.joints) {
    Resolve(ctx, j.parent, j.model, bodies, m.bodies, "link", described("joint", j.name));
    auto child_tier = [&child_names, &j](const ir::Body& b) {
      if (b.name == j.parent.name) return -1;
      return child_names.contains({b.model.value, b.name.value}) ? 1 : 0;
    };
    Resolve(ctx, j.child, j.model, bodies, m.bodies, "link", described("joint", j.name),
            child_tier);
  }
  for (ir::Frame& f : m.frames) {
    Resolve(ctx, f.body, f.model, bodies, m.bodies, "link", described("frame", f.name));
  }
  for (ir::Geometry& g : m.geometries) {
    Resolve(ctx, g.body, g.model, bodies, m.bodies, "link", described("geometry", g.name));
  }
  for (ir::Actuator& a : m.actuators) {
    Resolve(ctx, a.joint, a.model, joints, m.joints, "joint", described("actuator", a.name));
  }
  for (ir::Constraint& c : m.constraints) {
    auto user = [&c] { return fmt::format("{} constraint", ir::ConstraintTypeName(c.type())); };
    std::visit(ir::Overloaded{
                   [&](ir::CouplerConstraint& k) {
                     Resolve(ctx, k.joint0, c.model, joints, m.joints, "joint", user);
                     Resolve(ctx, k.joint1, c.model, joints, m.joints, "joint", user);
                   },
                   [&](ir::TendonConstraint& k) {
                     for (auto& jr : k.joints) {
                       Resolve(ctx, jr, c.model, joints, m.joints, "joint", user);
                     }
                   },
                   [&](auto& between_bodies) {  // ball, distance, weld
                     Resolve(ctx, between_bodies.body_A, c.model, bodies, m.bodies, "link", user);
                     Resolve(ctx, between_bodies.body_B, c.model, bodies, m.bodies, "link", user);
                   },
               },
               c.payload);
  }
  for (ir::ForceElement& f : m.force_elements) {
    auto user = [] { return std::string("force element"); };
    std::visit(ir::Overloaded{
                   [&](ir::LinearBushingRpy& k) {
                     ResolveFrame(ctx, k.frame_A, f.model, frames, bodies, "force element");
                     ResolveFrame(ctx, k.frame_C, f.model, frames, bodies, "force element");
                   },
                   [&](ir::LinearSpringDamper& k) {
                     Resolve(ctx, k.body_A, f.model, bodies, m.bodies, "link", user);
                     Resolve(ctx, k.body_B, f.model, bodies, m.bodies, "link", user);
                   },
                   [&](ir::JointSpring& k) {
                     Resolve(ctx, k.joint, f.model, joints, m.joints, "joint", user);
                   },
               },
               f.payload);
  }
  // groups may name groups defined later, in this file or another (COMMON-055)
  for (ir::CollisionFilterGroup& g : m.filter_groups) {
    for (auto& ref : g.members) ResolveForGroup(ctx, ref, g, bodies, m.bodies, "body");
    for (auto& ref : g.member_groups) {
      ResolveForGroup(ctx, ref, g, groups, m.filter_groups, "collision filter group");
    }
    for (auto& ref : g.ignored_groups) {
      ResolveForGroup(ctx, ref, g, groups, m.filter_groups, "collision filter group");
    }
  }
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateResolveNamesPass() { return std::make_unique<ResolveNamesPass>(); }

}  // namespace mdlc::passes
