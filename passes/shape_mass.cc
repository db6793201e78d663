#include "passes/shape_mass.h"

#include <cmath>
#include <numbers>

namespace mdlc::passes {
namespace {
constexpr double kPi = std::numbers::pi;

Eigen::Matrix3d Diagonal(double x, double y, double z) {
  return Eigen::Vector3d(x, y, z).asDiagonal();
}
}  // namespace

std::optional<UnitMass> SolidOf(const ir::Shape& shape) {
  UnitMass u;
  if (const auto* box = std::get_if<ir::Box>(&shape)) {
    const Eigen::Vector3d s = box->size;
    u.measure = s.prod();
    u.inertia = Diagonal(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                         s.x() * s.x() + s.y() * s.y()) *
                (u.measure / 12);
  } else if (const auto* sphere = std::get_if<ir::Sphere>(&shape)) {
    const double r = sphere->radius;
    u.measure = 4.0 / 3.0 * kPi * r * r * r;
    u.inertia = Eigen::Matrix3d::Identity() * (0.4 * u.measure * r * r);
  } else if (const auto* cyl = std::get_if<ir::Cylinder>(&shape)) {
    const double r = cyl->radius, h = cyl->length;
    u.measure = kPi * r * r * h;
    const double ixx = u.measure * (3 * r * r + h * h) / 12;
    u.inertia = Diagonal(ixx, ixx, u.measure * r * r / 2);
  } else if (const auto* cap = std::get_if<ir::Capsule>(&shape)) {
    // a cylinder and two hemispheres, each hemisphere's center of mass 3r/8
    // from the cylinder's end
    const double r = cap->radius, l = cap->length;
    const double vc = kPi * r * r * l, vh = 4.0 / 3.0 * kPi * r * r * r;
    u.measure = vc + vh;
    const double ixx = vc * (l * l / 12 + r * r / 4) +
                       vh * (2 * r * r / 5 + l * l / 4 + 3 * l * r / 8);
    u.inertia = Diagonal(ixx, ixx, vc * r * r / 2 + vh * 2 * r * r / 5);
  } else if (const auto* e = std::get_if<ir::Ellipsoid>(&shape)) {
    u.measure = 4.0 / 3.0 * kPi * e->a * e->b * e->c;
    u.inertia = Diagonal(e->b * e->b + e->c * e->c, e->a * e->a + e->c * e->c,
                         e->a * e->a + e->b * e->b) *
                (u.measure / 5);
  } else {
    return std::nullopt;
  }
  return u;
}

std::optional<UnitMass> MujocoShellOf(const ir::Shape& shape) {
  UnitMass u;
  if (const auto* box = std::get_if<ir::Box>(&shape)) {
    // three pairs of plates, each plate's own inertia plus its offset
    const Eigen::Vector3d l = box->size;
    const double axy = l.x() * l.y(), ayz = l.y() * l.z(), azx = l.z() * l.x();
    u.measure = 2 * (axy + ayz + azx);
    auto plate = [](double area, double w, double h, double offset, int normal) {
      // a w x h plate in the plane normal to axis `normal`, `offset` from the center
      Eigen::Vector3d d;
      const int i = (normal + 1) % 3, j = (normal + 2) % 3;  // in-plane axes (w along i)
      d[i] = area * (h * h / 12 + offset * offset);
      d[j] = area * (w * w / 12 + offset * offset);
      d[normal] = area * (w * w + h * h) / 12;
      return d;
    };
    const Eigen::Vector3d sum = plate(ayz, l.y(), l.z(), l.x() / 2, 0) +
                                plate(azx, l.z(), l.x(), l.y() / 2, 1) +
                                plate(axy, l.x(), l.y(), l.z() / 2, 2);
    u.inertia = (2 * sum).asDiagonal();
  } else if (const auto* sphere = std::get_if<ir::Sphere>(&shape)) {
    const double r = sphere->radius;
    u.measure = 4 * kPi * r * r;
    u.inertia = Eigen::Matrix3d::Identity() * (2.0 / 3.0 * u.measure * r * r);
  } else if (const auto* cyl = std::get_if<ir::Cylinder>(&shape)) {
    // a tube and two disks at its ends
    const double r = cyl->radius, h = cyl->length;
    const double tube = 2 * kPi * r * h, disk = kPi * r * r;
    u.measure = tube + 2 * disk;
    const double ixx = tube * (6 * r * r + h * h) / 12 + 2 * disk * (r * r / 4 + h * h / 4);
    u.inertia = Diagonal(ixx, ixx, tube * r * r + 2 * disk * r * r / 2);
  } else if (const auto* cap = std::get_if<ir::Capsule>(&shape)) {
    // a tube and two hemispherical shells, whose centroids are r/2 from the
    // tube's ends
    const double r = cap->radius, h = cap->length;
    const double tube = 2 * kPi * r * h, sphere = 4 * kPi * r * r;
    u.measure = tube + sphere;
    const double at = h / 2 + r / 2, own = r / 2;
    const double ixx = tube * (6 * r * r + h * h) / 12 + sphere * 2 * r * r / 3 +
                       sphere * (at * at - own * own);
    u.inertia = Diagonal(ixx, ixx, tube * r * r + sphere * 2 * r * r / 3);
  } else if (const auto* e = std::get_if<ir::Ellipsoid>(&shape)) {
    // area: Thomsen's formula; inertia: a thin layer (solid grown by 1e-6
    // minus solid), with the layer's mass set to the area
    constexpr double p = 1.6075, eps = 1e-6;
    const double a = e->a, b = e->b, c = e->c;
    u.measure = 4 * kPi *
                std::pow((std::pow(a * b, p) + std::pow(b * c, p) + std::pow(c * a, p)) / 3,
                         1 / p);
    const double va = 4 * kPi * a * b * c / 3;
    const double A = a + eps, B = b + eps, C = c + eps;
    const double vb = 4 * kPi * A * B * C / 3;
    const double density = u.measure / (vb - va);
    const double ma = va * density, mb = vb * density;
    u.inertia = Diagonal(mb * (B * B + C * C) - ma * (b * b + c * c),
                         mb * (A * A + C * C) - ma * (a * a + c * c),
                         mb * (A * A + B * B) - ma * (a * a + b * b)) /
                5;
  } else {
    return std::nullopt;
  }
  return u;
}

namespace {
/// m * (|p|^2 1 - p p^T): the parallel-axis term.
Eigen::Matrix3d Shift(double mass, const Eigen::Vector3d& p) {
  return mass * (p.squaredNorm() * Eigen::Matrix3d::Identity() - p * p.transpose());
}
}  // namespace

void MassSum::Add(double mass, const Transform& X_BG, const Eigen::Vector3d& p_GGcm,
                  const Eigen::Matrix3d& I_Gcm_G) {
  const Eigen::Vector3d p = X_BG * p_GGcm;
  ++parts_;
  mass_ += mass;
  first_moment_ += mass * p;
  inertia_Bo_ += X_BG.R * I_Gcm_G * X_BG.R.transpose() + Shift(mass, p);
}

Eigen::Matrix3d MassSum::inertia_about_com() const { return inertia_Bo_ - Shift(mass_, com()); }

ir::Inertial MassSum::ToInertial(Loc loc) const {
  ir::Inertial in;
  in.loc = loc;
  in.mass = mass_;
  in.X_BI = Transform::FromTranslation(com());
  SetInertiaMatrix(in, inertia_about_com());
  return in;
}

Eigen::Matrix3d InertiaMatrix(const ir::Inertial& in) {
  Eigen::Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  return I;
}

void SetInertiaMatrix(ir::Inertial& in, const Eigen::Matrix3d& I) {
  in.ixx = I(0, 0);
  in.iyy = I(1, 1);
  in.izz = I(2, 2);
  in.ixy = I(0, 1);
  in.ixz = I(0, 2);
  in.iyz = I(1, 2);
}

}  // namespace mdlc::passes
