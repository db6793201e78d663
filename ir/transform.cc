#include "ir/transform.h"

#include <cmath>

namespace mdlc {

Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy) {
  // no rotation, as most poses are written: for angles of +0 the product
  // below is exactly the identity (every sine +0, every cosine 1), so it is
  // returned without the six sines and cosines; -0 takes the product, whose
  // zeros may carry its sign
  const auto positive_zero = [](double angle) { return angle == 0 && !std::signbit(angle); };
  if (positive_zero(rpy.x()) && positive_zero(rpy.y()) && positive_zero(rpy.z())) {
    return Eigen::Matrix3d::Identity();
  }
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

Eigen::Vector3d RpyFromRotation(const Eigen::Matrix3d& R) {
  const double pitch = std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0)));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  // roll from what is left once yaw and pitch are taken out, so the three
  // angles rebuild R to rounding even at and near pitch = +-pi/2, where yaw
  // and roll turn about the same axis and atan2(R21, R22) would read noise
  const Eigen::Matrix3d rest = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix()
                                   .transpose() *
                               R;
  const double roll = std::atan2(rest(2, 1), rest(1, 1));
  return {roll, pitch, yaw};
}

Eigen::Quaterniond CanonicalQuaternion(const Eigen::Matrix3d& R) {
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0) q.coeffs() *= -1.0;
  return q;
}

Eigen::Matrix3d RotationAboutAxis(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis).toRotationMatrix();
}

}  // namespace mdlc
