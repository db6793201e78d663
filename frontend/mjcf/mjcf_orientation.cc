// mjcf_orientation.cc - MuJoCo's orientation forms (see mjcf_orientation.h).
#include "frontend/mjcf/mjcf_orientation.h"

#include <Eigen/Geometry>
#include <cmath>

namespace mdlc::frontend::mjcf {
namespace {
// MuJoCo's mjEPS: below this an axis is "too small"
constexpr double kEps = 1e-14;
}  // namespace

RotationOrError RotationFromQuat(double w, double x, double y, double z) {
  Eigen::Quaterniond q(w, x, y, z);
  if (q.norm() < kEps) return std::string("zero quaternion is not allowed");
  return Eigen::Matrix3d(q.normalized().toRotationMatrix());
}

RotationOrError RotationFromAxisAngle(const Eigen::Vector3d& axis, double angle) {
  if (axis.norm() < kEps) return std::string("axisangle too small");
  return Eigen::Matrix3d(Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix());
}

bool IsValidEulerSequence(std::string_view sequence) {
  if (sequence.size() != 3) return false;
  for (char c : sequence) {
    if (std::string_view("xyzXYZ").find(c) == std::string_view::npos) return false;
  }
  return true;
}

RotationOrError RotationFromEuler(const Eigen::Vector3d& angles, std::string_view sequence) {
  if (!IsValidEulerSequence(sequence)) {
    return std::string("euler sequence must be three of x, y, z, X, Y, Z");
  }
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (int i = 0; i < 3; ++i) {
    const char c = sequence[i];
    const char lower = static_cast<char>(c | 0x20);
    const Eigen::Vector3d axis = lower == 'x'   ? Eigen::Vector3d::UnitX()
                                 : lower == 'y' ? Eigen::Vector3d::UnitY()
                                                : Eigen::Vector3d::UnitZ();
    const Eigen::Quaterniond step(Eigen::AngleAxisd(angles[i], axis));
    // lowercase: about the rotated (moving) axes, i.e. post-multiplied;
    // uppercase: about the fixed axes, pre-multiplied
    q = (c == lower) ? q * step : step * q;
  }
  return Eigen::Matrix3d(q.normalized().toRotationMatrix());
}

RotationOrError RotationFromXYAxes(const Eigen::Vector3d& x_in, const Eigen::Vector3d& y_in) {
  if (x_in.norm() < kEps) return std::string("xaxis too small");
  const Eigen::Vector3d x = x_in.normalized();
  Eigen::Vector3d y = y_in - x.dot(y_in) * x;
  if (y.norm() < kEps) return std::string("yaxis too small");
  y.normalize();
  Eigen::Vector3d z = x.cross(y);
  if (z.norm() < kEps) return std::string("cross(xaxis, yaxis) too small");
  z.normalize();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = y;
  R.col(2) = z;
  return R;
}

RotationOrError RotationFromZAxis(const Eigen::Vector3d& z_in) {
  if (z_in.norm() < kEps) return std::string("zaxis too small");
  const Eigen::Vector3d z = z_in.normalized();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(z);
  const double s = axis.norm();
  // parallel or anti-parallel to +z: MuJoCo rotates about +x (by 0 or pi)
  axis = s < 1e-10 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d(axis / s);
  const double angle = std::atan2(s, z.z());
  return Eigen::Matrix3d(Eigen::AngleAxisd(angle, axis).toRotationMatrix());
}

}  // namespace mdlc::frontend::mjcf
