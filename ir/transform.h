// transform.h - rigid transforms and the rotation conventions of robot formats.
//
// Transform X_AB is the pose of frame B in frame A: p_AB (translation) and
// R_AB (rotation). Composition follows the monogram rule X_AC = X_AB * X_BC.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mdlc {

struct Transform {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();

  static Transform Identity() { return {}; }
  static Transform FromTranslation(const Eigen::Vector3d& p) { return {Eigen::Matrix3d::Identity(), p}; }
  static Transform FromRotation(const Eigen::Matrix3d& R) { return {R, Eigen::Vector3d::Zero()}; }

  Transform operator*(const Transform& other) const { return {R * other.R, R * other.p + p}; }
  Eigen::Vector3d operator*(const Eigen::Vector3d& v) const { return R * v + p; }
  Transform inverse() const { return {R.transpose(), -(R.transpose() * p)}; }
  bool IsIdentity() const { return R.isIdentity(0) && p.isZero(0); }
};

/// Fixed-axis roll-pitch-yaw (URDF, SDFormat): R = Rz(yaw) * Ry(pitch) * Rx(roll).
Eigen::Matrix3d RotationFromRpy(const Eigen::Vector3d& rpy);
/// Inverse of RotationFromRpy, with pitch in [-pi/2, pi/2].
Eigen::Vector3d RpyFromRotation(const Eigen::Matrix3d& R);
/// Unit quaternion of R with w >= 0 (the canonical sign used in dumps).
Eigen::Quaterniond CanonicalQuaternion(const Eigen::Matrix3d& R);
/// Rotation by `angle` about the unit vector `axis`.
Eigen::Matrix3d RotationAboutAxis(const Eigen::Vector3d& axis, double angle);

}  // namespace mdlc
