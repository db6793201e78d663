// inertia-from-collisions pass: SDFormat's <inertial auto="true"> (SDF-007):
// a body's mass properties are those of its collision geometry, solid, at
// the given density (a collision's own <density>, else the inertial's, else
// 1000 kg/m^3).
//
// Reads: Body::inertia_from_collisions, the proximity geometries of such a
// body with their poses (so it runs after resolve-frames). Writes:
// Body::inertial (mass, center of mass, inertia about it in the body frame).
// Shapes without a finite volume (half spaces) and meshes, whose volume needs
// the mesh itself, are reported and left out.
#include <fmt/format.h>

#include <numbers>

#include "passes/pass_registry.h"

namespace mdlc::passes {
namespace {

constexpr double kPi = std::numbers::pi;

/// Volume and unit-density inertia about the shape's center, in its frame.
struct UnitMass {
  double volume = 0;
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // per unit density
};

std::optional<UnitMass> SolidOf(const ir::Shape& shape) {
  UnitMass u;
  if (const auto* box = std::get_if<ir::Box>(&shape)) {
    const Eigen::Vector3d s = box->size;
    u.volume = s.prod();
    u.inertia.diagonal() << s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
        s.x() * s.x() + s.y() * s.y();
    u.inertia *= u.volume / 12;
  } else if (const auto* sphere = std::get_if<ir::Sphere>(&shape)) {
    const double r = sphere->radius;
    u.volume = 4.0 / 3.0 * kPi * r * r * r;
    u.inertia = Eigen::Matrix3d::Identity() * (0.4 * u.volume * r * r);
  } else if (const auto* cyl = std::get_if<ir::Cylinder>(&shape)) {
    const double r = cyl->radius, h = cyl->length;
    u.volume = kPi * r * r * h;
    const double ixx = u.volume * (3 * r * r + h * h) / 12;
    u.inertia.diagonal() << ixx, ixx, u.volume * r * r / 2;
  } else if (const auto* cap = std::get_if<ir::Capsule>(&shape)) {
    // a cylinder and two hemispheres, each hemisphere's center of mass 3r/8
    // from the cylinder's end
    const double r = cap->radius, l = cap->length;
    const double vc = kPi * r * r * l, vh = 4.0 / 3.0 * kPi * r * r * r;
    u.volume = vc + vh;
    const double ixx = vc * (l * l / 12 + r * r / 4) +
                       vh * (2 * r * r / 5 + l * l / 4 + 3 * l * r / 8);
    u.inertia.diagonal() << ixx, ixx, vc * r * r / 2 + vh * 2 * r * r / 5;
  } else if (const auto* e = std::get_if<ir::Ellipsoid>(&shape)) {
    u.volume = 4.0 / 3.0 * kPi * e->a * e->b * e->c;
    u.inertia.diagonal() << e->b * e->b + e->c * e->c, e->a * e->a + e->c * e->c,
        e->a * e->a + e->b * e->b;
    u.inertia *= u.volume / 5;
  } else {
    return std::nullopt;
  }
  return u;
}

class InertiaFromCollisionsPass : public Pass {
 public:
  std::string_view name() const override { return "inertia-from-collisions"; }
  std::string_view description() const override {
    return "Compute mass properties from collision geometry where the file asks (SDFormat "
           "<inertial auto=\"true\">)";
  }
  bool Run(PassContext& ctx) override {
    ir::Module& m = ctx.module;
    bool any = false;
    for (const ir::Body& b : m.bodies) any |= b.inertia_from_collisions.has_value();
    if (!any) return true;
    struct Sum {
      double mass = 0;
      Eigen::Vector3d first_moment = Eigen::Vector3d::Zero();  // sum of m * p_BGcm
      Eigen::Matrix3d inertia_Bo = Eigen::Matrix3d::Zero();     // about Bo, in B
      bool any = false;
    };
    std::vector<Sum> sums(m.bodies.size());
    for (const ir::Geometry& g : m.geometries) {
      if (!(g.roles & ir::kProximityRole) || !g.body.resolved()) continue;
      const ir::Body& b = m[g.body.id];
      if (!b.inertia_from_collisions) continue;
      auto solid = SolidOf(g.shape);
      if (!solid) {
        ctx.diags.Report(DiagKind::NotImplementedYet, g.loc,
                         fmt::format("collision '{}' ({}) is left out of the mass properties of "
                                     "'{}': its volume is not computed",
                                     m.Text(g.name), ir::ShapeTypeName(g.shape), m.Text(b.name)));
        continue;
      }
      const double density = g.density.value_or(*b.inertia_from_collisions);
      const double mass = density * solid->volume;
      const Eigen::Matrix3d& R = g.X_BG.R;
      const Eigen::Vector3d& p = g.X_BG.p;
      // about the geometry's center, in B; then shifted to Bo (parallel axes)
      const Eigen::Matrix3d I_Gcm_B = R * (density * solid->inertia) * R.transpose();
      const Eigen::Matrix3d shift = mass * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose());
      Sum& s = sums[g.body.id.index()];
      s.mass += mass;
      s.first_moment += mass * p;
      s.inertia_Bo += I_Gcm_B + shift;
      s.any = true;
    }
    for (size_t i = 0; i < m.bodies.size(); ++i) {
      ir::Body& b = m.bodies[i];
      if (!b.inertia_from_collisions) continue;
      const Sum& s = sums[i];
      if (!s.any || s.mass <= 0) {
        ctx.diags.Report(DiagKind::BadValue, b.loc,
                         fmt::format("link '{}' asks for mass properties from its collisions "
                                     "(<inertial auto=\"true\">) but has no collision with a "
                                     "volume",
                                     m.Text(b.name)));
        continue;
      }
      const Eigen::Vector3d com = s.first_moment / s.mass;
      Eigen::Matrix3d I_cm =
          s.inertia_Bo - s.mass * (com.squaredNorm() * Eigen::Matrix3d::Identity() -
                                   com * com.transpose());
      double mass = s.mass;
      if (b.inertia_from_collisions_mass) {
        // a given mass wins: the densities only shape the distribution
        I_cm *= *b.inertia_from_collisions_mass / s.mass;
        mass = *b.inertia_from_collisions_mass;
      }
      ir::Inertial in;
      in.loc = b.inertial ? b.inertial->loc : b.loc;
      in.mass = mass;
      in.X_BI = Transform::FromTranslation(com);
      in.ixx = I_cm(0, 0);
      in.iyy = I_cm(1, 1);
      in.izz = I_cm(2, 2);
      in.ixy = I_cm(0, 1);
      in.ixz = I_cm(0, 2);
      in.iyz = I_cm(1, 2);
      b.inertial = in;
    }
    return !ctx.diags.has_errors();
  }
};

}  // namespace

std::unique_ptr<Pass> CreateInertiaFromCollisionsPass() {
  return std::make_unique<InertiaFromCollisionsPass>();
}

}  // namespace mdlc::passes
