// mujoco_eigen.cc - see mujoco_eigen.h.
#include "passes/mesh/mujoco_eigen.h"

#include <Eigen/Geometry>
#include <cmath>

namespace mdlc::mesh {

void MujocoEigen(const Eigen::Matrix3d& A, Eigen::Vector3d* values, Eigen::Matrix3d* axes) {
  constexpr double kEps = 1e-12;
  constexpr int kMaxSweeps = 500;
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  Eigen::Vector3d d = A.diagonal();
  for (int iter = 0; iter < kMaxSweeps; ++iter) {
    const Eigen::Matrix3d R = q.toRotationMatrix();
    const Eigen::Matrix3d D = R.transpose() * A * R;
    d = D.diagonal();
    // the largest off-diagonal entry (r, c); the rotation is about the
    // third axis k. Ties go to (1, 2), then (0, 2).
    int r = 1, c = 2, k = 0;
    const double d01 = std::abs(D(0, 1)), d02 = std::abs(D(0, 2)), d12 = std::abs(D(1, 2));
    if (d01 > d02 && d01 > d12) {
      r = 0, c = 1, k = 2;
    } else if (d02 > d12) {
      r = 0, c = 2, k = 1;
    }
    if (std::abs(D(r, c)) < kEps) break;
    // the 2x2 symmetric Schur rotation that zeroes (r, c)
    const double tau = (D(c, c) - D(r, r)) / (2 * D(r, c));
    const double t = tau >= 0 ? 1 / (tau + std::sqrt(1 + tau * tau))
                              : -1 / (-tau + std::sqrt(1 + tau * tau));
    const double cosine = 1 / std::sqrt(1 + t * t);
    if (cosine > 1 - kEps) break;
    // as a quaternion about axis k: half the angle's sine, its sign by tau
    // and, about y, reversed (the (0, 2) plane turns the other way)
    double s = std::sqrt(0.5 - 0.5 * cosine);
    if (tau >= 0) s = -s;
    if (k == 1) s = -s;
    Eigen::Quaterniond step(std::sqrt(1 - s * s), 0, 0, 0);
    step.coeffs()[k] = s;  // coeffs() is (x, y, z, w)
    q = (q * step.normalized()).normalized();
  }
  // decreasing order by three neighbour swaps (0-1, 1-2, 0-1), each a
  // quarter turn about the third axis
  for (int j = 0; j < 3; ++j) {
    const int a = j % 2;
    if (d[a] + kEps < d[a + 1]) {
      std::swap(d[a], d[a + 1]);
      const double h = std::sqrt(0.5);
      Eigen::Quaterniond turn(h, 0, 0, 0);
      turn.coeffs()[(a + 2) % 3] = h;
      q = (q * turn).normalized();
    }
  }
  *values = d;
  *axes = q.toRotationMatrix();
}

}  // namespace mdlc::mesh
