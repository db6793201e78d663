// check_model_elements.cc - the check-model-elements pass: rules of
// model-level elements (collision filter groups, constraints) that every
// frontend shares and that need the whole model or resolved references.
//
// - COMMON-050 collision filter group definitions, as Drake's
//   CollisionFilterGroupResolver::AddGroup checks them, in this order: the
//   name is unscoped (`cannot be a scoped name`), unique within its model
//   instance (`already been defined`), and the group has members or member
//   groups (`no members`).
// - EXT-052/053 ball and distance constraints join two distinct bodies
//   (Drake's BallConstraintSpec / DistanceConstraintParams).
// - EXT-054 tendon constraints name distinct single-dof joints (Drake's
//   AddTendonConstraint).
// - EXT-050..054 the bodies, joints and frames a ball, distance or tendon
//   constraint or a bushing or spring-damper names belong to the element's
//   own model instance or one nested in it (Drake looks them up in the
//   element's instance); the world body, which resolve-names accepts by name
//   everywhere (COMMON-032), is allowed.
//
// Reads: resolved filter groups and constraints. Writes nothing.
#include <fmt/format.h>

#include <unordered_map>
#include <variant>

#include "ir/overloaded.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class CheckModelElementsPass : public Pass {
 public:
  std::string_view name() const override { return "check-model-elements"; }
  std::string_view description() const override {
    return "Check collision filter group definitions, constraints and force elements";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Resolved; }
  bool Run(PassContext& ctx) override;

 private:
  void CheckGroups(PassContext& ctx);
  void CheckConstraint(PassContext& ctx, const ir::Constraint& c);
  void CheckForceElement(PassContext& ctx, const ir::ForceElement& f);
  // reports when `target` (an entity of instance `target_model`, written as
  // `name` at `loc`) lies outside instance `own` and the instances nested in it
  void CheckWithin(PassContext& ctx, ModelId own, ModelId target_model, std::string_view what,
                   Symbol name, Loc loc);
};

void CheckModelElementsPass::CheckWithin(PassContext& ctx, ModelId own, ModelId target_model,
                                         std::string_view what, Symbol name, Loc loc) {
  const ir::Module& m = ctx.module;
  // elements of the global scope (world or default instance) may name anything
  if (own == ir::kWorldModel || own == ir::kDefaultModel || target_model == own) return;
  if (own.index() >= m.models.size() || target_model.index() >= m.models.size()) return;
  for (ModelId up = m[target_model].parent; up.valid(); up = m[up].parent) {
    if (up == own) return;  // nested in the element's instance
  }
  // a top-level instance may be named "<own>::..." too (a Model Directives
  // namespace): nested by its name
  const std::string own_name = m.ModelName(own);
  const std::string target_name = m.ModelName(target_model);
  if (target_name.size() > own_name.size() + 2 && target_name.starts_with(own_name) &&
      target_name.substr(own_name.size(), 2) == "::") {
    return;
  }
  ctx.diags.Report(DiagKind::UnknownReference, loc,
                   fmt::format("{} '{}' belongs to model instance '{}': it must be in the "
                               "element's own model instance '{}' (or one nested in it)",
                               what, m.Text(name), target_name, own_name));
}

void CheckModelElementsPass::CheckGroups(PassContext& ctx) {
  const ir::Module& m = ctx.module;
  // first definition of each (model, name)
  std::unordered_map<uint64_t, const ir::CollisionFilterGroup*> first;
  for (const ir::CollisionFilterGroup& g : m.filter_groups) {
    const std::string full = m.ScopedName(g.model, g.name);
    if (m.Text(g.name).find("::") != std::string_view::npos) {
      ctx.diags.Report(DiagKind::InvalidName, g.loc,
                       fmt::format("collision filter group name '{}' cannot be a scoped name",
                                   full));
      continue;
    }
    const uint64_t key = (uint64_t{g.model.value} << 32) | g.name.value;
    auto [it, inserted] = first.emplace(key, &g);
    if (!inserted) {
      ctx.diags
          .Report(DiagKind::DuplicateName, g.loc,
                  fmt::format("collision filter group '{}' has already been defined", full))
          .Note(it->second->loc, fmt::format("the first group named '{}' is here", full));
      continue;
    }
    if (g.members.empty() && g.member_groups.empty()) {
      ctx.diags.Report(DiagKind::BadValue, g.loc,
                       fmt::format("collision filter group '{}' has no members", full));
    }
  }
}

void CheckModelElementsPass::CheckConstraint(PassContext& ctx, const ir::Constraint& c) {
  const ir::Module& m = ctx.module;
  auto distinct_bodies = [&](const ir::Ref<BodyId>& body_A, const ir::Ref<BodyId>& body_B) {
    for (const ir::Ref<BodyId>* ref : {&body_A, &body_B}) {
      if (ref->resolved() && ref->id != ir::kWorldBody && ref->id.index() < m.bodies.size()) {
        CheckWithin(ctx, c.model, m[ref->id].model, "body", ref->name, ref->loc);
      }
    }
    if (body_A.resolved() && body_A.id == body_B.id && body_A.id.index() < m.bodies.size()) {
      ctx.diags.Report(DiagKind::BadValue, body_B.loc.valid() ? body_B.loc : c.loc,
                       fmt::format("{} constraint: body_A and body_B must be two distinct "
                                   "bodies, both are '{}'",
                                   ir::ConstraintTypeName(c.type()), m.ScopedName(body_A.id)));
    }
  };
  auto tendon_joints = [&](const ir::TendonConstraint& k) {
    for (size_t i = 0; i < k.joints.size(); ++i) {
      const ir::Ref<JointId>& ref = k.joints[i];
      if (!ref.resolved() || ref.id.index() >= m.joints.size()) continue;  // not ours to report
      const ir::Joint& joint = m[ref.id];
      CheckWithin(ctx, c.model, joint.model, "joint", ref.name, ref.loc);
      const int nv = ir::JointVelocityCount(joint.type);
      if (nv != 1) {
        ctx.diags.Report(DiagKind::BadValue, ref.loc.valid() ? ref.loc : c.loc,
                         fmt::format("tendon constraint: joint '{}' ({}) has {} degrees of "
                                     "freedom; only single-dof joints can be in a tendon",
                                     m.ScopedName(ref.id), ir::JointTypeName(joint.type), nv));
      }
      for (size_t j = 0; j < i; ++j) {
        if (k.joints[j].id == ref.id) {
          ctx.diags
              .Report(DiagKind::BadValue, ref.loc.valid() ? ref.loc : c.loc,
                      fmt::format("tendon constraint: joint '{}' is listed twice; the joints "
                                  "of a tendon must be distinct",
                                  m.ScopedName(ref.id)))
              .Note(k.joints[j].loc, "first listed here");
          break;
        }
      }
    }
  };
  std::visit(ir::Overloaded{
                 [&](const ir::BallConstraint& k) { distinct_bodies(k.body_A, k.body_B); },
                 [&](const ir::DistanceConstraint& k) { distinct_bodies(k.body_A, k.body_B); },
                 [&](const ir::TendonConstraint& k) { tendon_joints(k); },
                 // couplers are the check-joints pass's; welds have no rule here
                 [](const ir::CouplerConstraint&) {},
                 [](const ir::WeldConstraint&) {},
             },
             c.payload);
}

void CheckModelElementsPass::CheckForceElement(PassContext& ctx, const ir::ForceElement& f) {
  const ir::Module& m = ctx.module;
  std::visit(ir::Overloaded{
                 [&](const ir::LinearBushingRpy& k) {
                   for (const ir::FrameRef* ref : {&k.frame_A, &k.frame_C}) {
                     if (ref->frame.valid() && ref->frame.index() < m.frames.size()) {
                       CheckWithin(ctx, f.model, m[ref->frame].model, "frame", ref->name,
                                   ref->loc);
                     } else if (ref->body.valid() && ref->body != ir::kWorldBody &&
                                ref->body.index() < m.bodies.size()) {
                       CheckWithin(ctx, f.model, m[ref->body].model, "frame", ref->name,
                                   ref->loc);
                     }
                   }
                 },
                 [&](const ir::LinearSpringDamper& k) {
                   for (const ir::Ref<BodyId>* ref : {&k.body_A, &k.body_B}) {
                     if (ref->resolved() && ref->id != ir::kWorldBody &&
                         ref->id.index() < m.bodies.size()) {
                       CheckWithin(ctx, f.model, m[ref->id].model, "body", ref->name, ref->loc);
                     }
                   }
                 },
                 [](const ir::JointSpring&) {},  // its joint's kind is checked where it is made
             },
             f.payload);
}

bool CheckModelElementsPass::Run(PassContext& ctx) {
  CheckGroups(ctx);
  for (const ir::Constraint& c : ctx.module.constraints) CheckConstraint(ctx, c);
  for (const ir::ForceElement& f : ctx.module.force_elements) CheckForceElement(ctx, f);
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateCheckModelElementsPass() {
  return std::make_unique<CheckModelElementsPass>();
}

}  // namespace mdlc::passes
