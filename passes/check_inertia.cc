// check-inertia pass: physical validity of every body's mass properties
// (COMMON-040, COMMON-041).
//
// Reads: Body::inertial. Writes: replaces a non-physical inertial with
// Drake's plausible stand-in (a solid sphere of density 1000 kg/m^3 at the
// given center of mass, of the given mass when positive, else 1 kg), after a
// warning that names the body, the violated condition and the numbers at
// full precision.
#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class CheckInertiaPass : public Pass {
 public:
  std::string_view name() const override { return "check-inertia"; }
  std::string_view description() const override {
    return "Check mass properties are physical; substitute a plausible inertia where not";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Tree; }
  bool Run(PassContext& ctx) override;
};

/// Why an inertia is not physical, or empty when it is.
std::string Violation(const ir::Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(I, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d d = solver.eigenvalues();  // ascending
  const double scale = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  const double tol = 16 * std::numeric_limits<double>::epsilon() * scale;
  if (d[0] < -tol) {
    return fmt::format("principal moment {:.17g} is negative (principal moments {:.17g}, {:.17g}, "
                       "{:.17g})",
                       d[0], d[0], d[1], d[2]);
  }
  if (d[0] + d[1] < d[2] - tol) {
    return fmt::format("principal moments violate the triangle inequality: {:.17g} + {:.17g} < "
                       "{:.17g}",
                       d[0], d[1], d[2]);
  }
  return {};
}

void ReplaceWithSphere(ir::Inertial& in) {
  const double mass = (std::isfinite(in.mass) && in.mass > 0) ? in.mass : 1.0;
  const double density = 1000.0;
  const double radius = std::cbrt(3 * mass / (4 * std::numbers::pi * density));
  const double moment = 0.4 * mass * radius * radius;
  in.mass = mass;
  in.X_BI = Transform::FromTranslation(in.X_BI.p);
  in.ixx = in.iyy = in.izz = moment;
  in.ixy = in.ixz = in.iyz = 0;
}

bool CheckInertiaPass::Run(PassContext& ctx) {
  ir::Module& m = ctx.module;
  for (ir::Body& body : m.bodies) {
    if (!body.inertial) continue;
    ir::Inertial& in = *body.inertial;
    const bool zero_inertia = in.ixx == 0 && in.iyy == 0 && in.izz == 0 && in.ixy == 0 &&
                              in.ixz == 0 && in.iyz == 0;
    std::string problem;
    DiagKind kind = DiagKind::NonPhysicalInertia;
    if (in.mass < 0) {
      problem = fmt::format("mass {:.17g} is negative; mass must be > 0", in.mass);
      kind = DiagKind::NonPositiveMass;
    } else if (in.mass == 0 && !zero_inertia) {
      problem = "mass is zero but the inertia is not; mass must be > 0 for a body with inertia";
      kind = DiagKind::NonPositiveMass;
    } else {
      problem = Violation(in);
    }
    if (problem.empty()) continue;
    ReplaceWithSphere(in);
    ctx.diags.Report(kind, in.loc,
                     fmt::format("body '{}' has non-physical inertia: {}; using a solid sphere "
                                 "of mass {} and density 1000 kg/m^3 instead",
                                 m.ScopedName(body.model, body.name),
                                 problem, in.mass));
  }
  return true;
}

}  // namespace

std::unique_ptr<Pass> CreateCheckInertiaPass() { return std::make_unique<CheckInertiaPass>(); }

}  // namespace mdlc::passes
