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
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "passes/mesh/mass_properties.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

class CheckInertiaPass : public Pass {
 public:
  std::string_view name() const override { return "check-inertia"; }
  std::string_view description() const override {
    return "Check mass properties are physical; substitute a plausible inertia where not";
  }
  ir::VerifyLevel level_after() const override { return ir::VerifyLevel::Named; }
  bool Run(PassContext& ctx) override;
};

/// The principal moments of a central inertia, ascending. As Drake's
/// RotationalInertia::CalcPrincipalMomentsOfInertia: when every product is
/// within 4 machine epsilons of the largest possible moment (half the trace),
/// the moments are the diagonal itself, so that products such as 1e-35 from
/// CAD exports leave the moments exact.
Eigen::Vector3d PrincipalMoments(const Eigen::Matrix3d& I) {
  const double product_tolerance =
      4 * std::numeric_limits<double>::epsilon() * 0.5 * std::abs(I.trace());
  if (std::abs(I(0, 1)) <= product_tolerance && std::abs(I(0, 2)) <= product_tolerance &&
      std::abs(I(1, 2)) <= product_tolerance) {
    Eigen::Vector3d d = I.diagonal();
    std::sort(d.data(), d.data() + 3);
    return d;
  }
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I, Eigen::EigenvaluesOnly).eigenvalues();
}

/// Why a central inertia is not physical, or empty when it could be: the
/// test of Drake's RotationalInertia::CouldBePhysicallyValid (which
/// SpatialInertia::IsPhysicallyValid applies about the center of mass).
/// Principal moments p0 <= p1 <= p2 must satisfy p0 >= -eps and
/// p0 + p1 >= p2 - eps, with eps = 16 machine epsilons times max(1, trace/2):
/// relative for large inertias and absolute (about 3.6e-15 kg m^2) for small
/// ones, so that round-off never replaces a real link's inertia.
std::string Violation(const ir::Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  if (!I.allFinite()) return "a moment or product of inertia is not finite";
  // The common case without an eigen-decomposition: principal moments all
  // positive (I positive definite) and each less than the sum of the other
  // two (trace/2 - I positive definite: its eigenvalues are
  // (p_i + p_j - p_k) / 2), clearly enough that the test below would pass.
  const double trace = I.trace();
  if (trace > 0 && mesh::ClearlyPositiveDefinite(I, trace) &&
      mesh::ClearlyPositiveDefinite(0.5 * trace * Eigen::Matrix3d::Identity() - I, trace)) {
    return {};
  }
  const Eigen::Vector3d d = PrincipalMoments(I);
  const double eps =
      16 * std::numeric_limits<double>::epsilon() * std::max(1.0, 0.5 * std::abs(trace));
  // "{}" prints the shortest text that reads back as the same double: 0.1,
  // not 0.10000000000000001, and nothing of the value lost
  if (d[0] + eps < 0) {
    return fmt::format("principal moment {} is negative (principal moments {}, {}, {})", d[0],
                       d[0], d[1], d[2]);
  }
  if (d[0] + d[1] + eps < d[2]) {
    return fmt::format("principal moments violate the triangle inequality: {} + {} < {}", d[0],
                       d[1], d[2]);
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
      problem = fmt::format("mass {} is negative; mass must be > 0", in.mass);
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
