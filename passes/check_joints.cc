// check_joints.cc - the check-joints pass: joint-level rules that need
// resolved references, chiefly coupler constraints from URDF <mimic>
// (URDF-018).
//
// Reads: resolved joints and constraints. Writes: drops couplers that Drake
// would ignore (with a warning).
#include <fmt/format.h>

#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class CheckJointsPass : public Pass {
 public:
  std::string_view name() const override { return "check-joints"; }
  std::string_view description() const override {
    return "Check coupler (mimic) constraints against the joints they couple";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Resolved; }
  bool Run(PassContext& ctx) override;
};

bool CheckJointsPass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  std::vector<ir::Constraint> kept;
  kept.reserve(m.constraints.size());
  for (ir::Constraint& c : m.constraints) {
    if (c.type() != ir::ConstraintType::Coupler) {
      kept.push_back(std::move(c));
      continue;
    }
    const ir::CouplerConstraint& coupler = c.As<ir::CouplerConstraint>();
    const ir::Joint& follower = m[coupler.joint0.id];
    const ir::Joint& leader = m[coupler.joint1.id];
    const int n_follower = ir::JointVelocityCount(follower.type);
    const int n_leader = ir::JointVelocityCount(leader.type);
    // Drake ignores mimic on a joint that is not single-dof, then requires
    // both joints to have the same number of dofs
    if (n_follower != 1) {
      ctx.diags.Report(DiagKind::JointWarning, c.loc,
                       fmt::format("mimic on joint '{}' is ignored: only single-dof joints can "
                                   "mimic another joint ('{}' has {} dofs)",
                                   m.Text(follower.name), m.Text(follower.name), n_follower));
      continue;
    }
    if (n_follower != n_leader) {
      ctx.diags.Report(DiagKind::BadValue, c.loc,
                       fmt::format("joint '{}' cannot mimic joint '{}': they have different "
                                   "numbers of degrees of freedom ({} and {})",
                                   m.Text(follower.name), m.Text(leader.name), n_follower, n_leader));
      continue;
    }
    kept.push_back(std::move(c));
  }
  m.constraints = std::move(kept);
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateCheckJointsPass() { return std::make_unique<CheckJointsPass>(); }

}  // namespace mdlc::passes
