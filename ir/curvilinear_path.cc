#include "ir/curvilinear_path.h"

#include <cmath>

namespace mdlc::ir {
namespace {

// A(0) in F: x along the tangent, z along the plane normal
Eigen::Matrix3d InitialRotation(const CurvilinearPath& path) {
  const Eigen::Vector3d z = path.plane_normal.normalized();
  const Eigen::Vector3d x = (path.initial_tangent - path.initial_tangent.dot(z) * z).normalized();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = z.cross(x);
  R.col(2) = z;
  return R;
}

// the displacement and rotation of moving `ds` along a piece of curvature k,
// in the piece's starting frame
Transform Advance(double k, double ds) {
  Transform X;
  if (std::abs(k) < 1e-12) {
    X.p = Eigen::Vector3d(ds, 0, 0);
    return X;
  }
  const double angle = k * ds;
  X.p = Eigen::Vector3d(std::sin(angle) / k, (1 - std::cos(angle)) / k, 0);
  X.R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

}  // namespace

double CurvilinearPath::TotalLength() const {
  double total = 0;
  for (const Segment& s : segments) total += s.length;
  return total;
}

Transform CurvilinearPath::PoseAt(double s) const {
  Transform X = Transform::FromRotation(InitialRotation(*this));
  if (segments.empty()) return X;
  const double total = TotalLength();
  if (periodic && total > 0) {
    s = std::fmod(s, total);
    if (s < 0) s += total;
  }
  if (s < 0) return X * Advance(segments.front().curvature, s);  // before the start
  for (size_t i = 0; i < segments.size(); ++i) {
    const Segment& seg = segments[i];
    const bool last = i + 1 == segments.size();
    if (s <= seg.length || last) return X * Advance(seg.curvature, s);
    X = X * Advance(seg.curvature, seg.length);
    s -= seg.length;
  }
  return X;
}

double CurvilinearPath::CurvatureAt(double s) const {
  if (segments.empty()) return 0;
  const double total = TotalLength();
  if (periodic && total > 0) {
    s = std::fmod(s, total);
    if (s < 0) s += total;
  }
  for (const Segment& seg : segments) {
    if (s < seg.length) return seg.curvature;
    s -= seg.length;
  }
  return segments.back().curvature;
}

Eigen::Matrix<double, 6, 1> CurvilinearPath::VelocityAt(double s) const {
  Eigen::Matrix<double, 6, 1> V = Eigen::Matrix<double, 6, 1>::Zero();
  if (segments.empty()) return V;  // a path of no length does not move
  const Transform X = PoseAt(s);
  V.head<3>() = CurvatureAt(s) * X.R.col(2);
  V.tail<3>() = X.R.col(0);
  return V;
}

}  // namespace mdlc::ir
