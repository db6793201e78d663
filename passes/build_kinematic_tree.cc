// build_kinematic_tree.cc - the build-kinematic-tree pass: checks that the
// joints form a tree rooted at the world body, and gives every body without
// an inboard joint a floating joint to the world (URDF-017, as Drake's plant
// does at Finalize).
//
// With --fixed-base (CreateFixedBaseKinematicTreePass) such a body is welded
// to the world at its default pose instead: a URDF arm whose root link no
// joint holds stays where it is, as MuJoCo's and ROS's readers keep it.
//
// Reads: resolved joint parent/child ids. Writes: new quaternion_floating
// joints, or welds with --fixed-base (unnamed, named after their body). Afterwards the verifier's Tree
// level holds. Iterative throughout: chains of any depth are fine.
#include <fmt/format.h>

#include <algorithm>

#include <absl/container/flat_hash_set.h>

#include "passes/build_kinematic_tree.h"
#include "passes/floating_joint.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class BuildKinematicTreePass : public Pass {
 public:
  explicit BuildKinematicTreePass(bool weld_free_bodies = false)
      : weld_free_bodies_(weld_free_bodies) {}
  std::string_view name() const override { return "build-kinematic-tree"; }
  std::string_view description() const override {
    return "Check the joints form a tree and add floating joints for free bodies";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Tree; }
  bool Run(PassContext& ctx) override;

 private:
  void ReportLoop(PassContext& ctx, const std::vector<JointId>& inboard, size_t start);
  void AddFloatingJoint(PassContext& ctx, BodyId body);

  static uint64_t Key(ModelId model, Symbol name) {
    return (uint64_t{model.value} << 32) | name.value;
  }
  // every joint's (model, name): a free body's joint name is checked against
  // it, not against every joint (which made a world of N free models O(N^2))
  absl::flat_hash_set<uint64_t> joint_names_;
  const bool weld_free_bodies_;
};

bool BuildKinematicTreePass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  const size_t errors_before = ctx.diags.error_count();
  std::vector<JointId> inboard(m.bodies.size());
  for (size_t i = 0; i < m.joints.size(); ++i) {
    const ir::Joint& j = m.joints[i];
    if (!j.parent.resolved() || !j.child.resolved()) continue;
    if (j.parent.id == j.child.id) {
      ctx.diags.Report(DiagKind::SelfJoint, j.loc,
                       fmt::format("joint '{}' connects link '{}' to itself", m.Text(j.name),
                                   m.Text(m[j.child.id].name)));
      continue;
    }
    if (j.child.id == ir::kWorldBody) {
      ctx.diags.Report(DiagKind::KinematicLoop, j.child.loc,
                       fmt::format("joint '{}' makes the world its child; the world is the root "
                                   "of the kinematic tree and has no parent",
                                   m.Text(j.name)));
      continue;
    }
    JointId& slot = inboard[j.child.id.index()];
    if (slot.valid()) {
      ctx.diags
          .Report(DiagKind::MultipleParents, j.child.loc,
                  fmt::format("link '{}' has a second parent joint '{}'; a kinematic tree gives "
                              "each link one parent (loops are not supported)",
                              m.ScopedName(j.child.id), m.Text(j.name)))
          .Note(m[slot].loc, fmt::format("its first parent joint '{}' is here", m.Text(m[slot].name)));
      continue;
    }
    slot = JointId(i);
  }
  if (ctx.diags.error_count() != errors_before) return false;

  // walk up from every body; a walk that meets itself is a loop
  enum : uint8_t { kUnvisited, kOnPath, kDone };
  std::vector<uint8_t> state(m.bodies.size(), kUnvisited);
  state[0] = kDone;
  std::vector<size_t> path;
  for (size_t start = 1; start < m.bodies.size(); ++start) {
    path.clear();
    size_t b = start;
    bool cycle = false;
    while (state[b] != kDone) {
      if (state[b] == kOnPath) {
        cycle = true;
        break;
      }
      state[b] = kOnPath;
      path.push_back(b);
      if (!inboard[b].valid()) break;  // a root: will get a floating joint
      b = m[inboard[b]].parent.id.index();
    }
    if (cycle) ReportLoop(ctx, inboard, b);
    for (size_t p : path) state[p] = kDone;
  }
  if (ctx.diags.error_count() != errors_before) return false;

  // one floating joint per body without an inboard joint: room for them all
  // at once, rather than the joint table doubling (and moving every joint)
  // as they come (a world of free bodies adds one per model)
  size_t floating = 0;
  for (size_t b = 1; b < inboard.size(); ++b) floating += inboard[b].valid() ? 0 : 1;
  m.joints.reserve(m.joints.size() + floating);
  joint_names_.clear();
  joint_names_.reserve(m.joints.size() + floating);
  for (const ir::Joint& j : m.joints) joint_names_.insert(Key(j.model, j.name));
  for (size_t b = 1; b < inboard.size(); ++b) {
    if (!inboard[b].valid()) AddFloatingJoint(ctx, BodyId(b));
  }
  return true;
}

void BuildKinematicTreePass::ReportLoop(PassContext& ctx, const std::vector<JointId>& inboard,
                                        size_t start) {
  ir::Module& m = ctx.module;
  // collect the cycle's joints, from `start` around to itself
  std::vector<JointId> cycle;
  size_t b = start;
  do {
    cycle.push_back(inboard[b]);
    b = m[inboard[b]].parent.id.index();
  } while (b != start && cycle.size() <= m.bodies.size());
  // report at the loop's first joint in document order, whatever body the
  // walk that found it started from: the same input gives the same message
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  std::reverse(cycle.begin() + 1, cycle.end());
  std::string names;
  for (JointId j : cycle) {
    names += fmt::format("{}'{}'", names.empty() ? "" : " -> ", m.Text(m[j].name));
  }
  auto diag = ctx.diags.Report(
      DiagKind::KinematicLoop, m[cycle.front()].loc,
      fmt::format("kinematic loop through joints {}: the plant must be a tree", names));
  for (JointId j : cycle) {
    diag.Note(m[j].loc, fmt::format("joint '{}' connects '{}' to '{}'", m.Text(m[j].name),
                                     m.Text(m[m[j].parent.id].name),
                                     m.Text(m[m[j].child.id].name)));
  }
}

void BuildKinematicTreePass::AddFloatingJoint(PassContext& ctx, BodyId body) {
  ir::Module& m = ctx.module;
  const ir::Body& b = m[body];
  // the joint takes its body's name, already interned, unless a joint of the
  // instance has it (a world of free bodies: one such joint per model)
  Symbol symbol = b.name;
  if (joint_names_.contains(Key(b.model, symbol))) {
    symbol = m.Intern(FloatingJointName(m.Text(b.name), [&](const std::string& n) {
      Symbol s = m.symbols.Find(n);
      return !s.empty() && joint_names_.contains(Key(b.model, s));
    }));
  }
  joint_names_.insert(Key(b.model, symbol));
  ir::Joint joint =
      MakeFloatingJoint(m, symbol, b.loc, ir::kWorldBody, {}, body, {}, b.default_pose);
  if (weld_free_bodies_) {
    // the weld holds the body where the floating joint's default pose put it
    joint.type = ir::JointType::Weld;
    joint.X_PF = b.default_pose.value_or(Transform());
    joint.limits = ir::JointLimits::Unbounded(0);
    joint.damping = {};
    joint.default_positions = {};
  }
  m.Add(std::move(joint));
}

}  // namespace

std::unique_ptr<Pass> CreateBuildKinematicTreePass() {
  return std::make_unique<BuildKinematicTreePass>();
}

std::unique_ptr<Pass> CreateFixedBaseKinematicTreePass() {
  return std::make_unique<BuildKinematicTreePass>(/*weld_free_bodies=*/true);
}

}  // namespace mdlc::passes
