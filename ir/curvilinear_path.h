// curvilinear_path.h - a planar path of constant-curvature pieces, the path a
// curvilinear joint moves its child along (Drake's
// PiecewiseConstantCurvatureTrajectory).
//
// The path lives in frame F. At arc length s it defines a frame A(s) with
// x = the unit tangent, z = the plane normal (constant) and y = z × x, which
// the path turns towards when the curvature is positive. A(0) is at F's
// origin with x = initial_tangent. A curvilinear joint's X_FM(q) is X_FA(q).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "ir/transform.h"

namespace mdlc::ir {

struct CurvilinearPath {
  struct Segment {
    double length = 0;     // > 0
    double curvature = 0;  // 1/radius, signed about the plane normal; 0 = straight
  };
  Eigen::Vector3d initial_tangent = Eigen::Vector3d::UnitX();
  Eigen::Vector3d plane_normal = Eigen::Vector3d::UnitZ();
  std::vector<Segment> segments;
  bool periodic = false;  // s wraps around the total length (a closed loop)

  double TotalLength() const;
  /// X_FA(s). Beyond the ends of an open path, the end pieces continue.
  Transform PoseAt(double s) const;
  /// dX_FA/ds as a spatial velocity in F: [curvature(s) * plane_normal; tangent(s)].
  Eigen::Matrix<double, 6, 1> VelocityAt(double s) const;
  /// Curvature of the piece holding s.
  double CurvatureAt(double s) const;
};

}  // namespace mdlc::ir
