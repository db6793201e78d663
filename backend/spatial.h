// spatial.h - the little spatial algebra the backend needs (header-only).
//
// Spatial vectors are Eigen 6-vectors with the angular part first, as in
// Drake: a spatial velocity is [w; v] and a motion subspace has one such
// column per velocity coordinate. "Plücker coordinates about the world
// origin" means: expressed in W, with the linear part being the velocity of
// the body-fixed point that coincides with the world origin. In those
// coordinates the spatial velocities of a tree simply add along a path, and
// every body's spatial inertia can be summed without shifting.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mdlc::backend {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;
/// A motion subspace: one spatial-velocity column per joint velocity (<= 6).
using MotionSubspace = Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 6>;

/// [a]x, the matrix with [a]x b = a x b.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0, -a.z(), a.y(),
       a.z(), 0, -a.x(),
       -a.y(), a.x(), 0;
  return S;
}

/// Spatial inertia about the world origin, in W, of a body of mass m whose
/// center of mass is at c (= p_WBcm) with inertia I_c about it, expressed in W:
///   [ I_c - m [c]x [c]x   m [c]x ]
///   [ -m [c]x             m 1    ]
/// so that the kinetic energy is 1/2 V^T I V for V in Plücker coordinates.
inline Matrix6d SpatialInertiaAboutOrigin(double m, const Eigen::Vector3d& c,
                                          const Eigen::Matrix3d& I_c) {
  const Eigen::Matrix3d cx = Skew(c);
  Matrix6d I;
  I.topLeftCorner<3, 3>() = I_c - m * cx * cx;
  I.topRightCorner<3, 3>() = m * cx;
  I.bottomLeftCorner<3, 3>() = -m * cx;
  I.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
  return I;
}

/// A rigid body's spatial inertia about the world origin in W, held as its
/// ten numbers (mass m, first moment h = m c, rotational inertia I_O about
/// the origin) rather than the 6x6 matrix: applying it to a motion vector
/// then takes a third of the flops.
struct CompactInertia {
  double m = 0;
  Eigen::Vector3d h = Eigen::Vector3d::Zero();
  Eigen::Matrix3d I_O = Eigen::Matrix3d::Zero();
  /// No mass and no rotational inertia: a massless body (MJCF lowers a body
  /// with several hinges to a chain of them), whose products the sweeps skip.
  bool is_zero = true;

  /// The body of mass m with its COM at c and inertia I_c about it, both in W.
  static CompactInertia About(double m, const Eigen::Vector3d& c, const Eigen::Matrix3d& I_c) {
    // the parallel-axis shift -m [c]x [c]x = m (|c|^2 1 - c c^T), without a product
    Eigen::Matrix3d I_O = I_c - m * c * c.transpose();
    I_O.diagonal().array() += m * c.squaredNorm();
    return {m, m * c, I_O, m == 0 && I_c.isZero(0)};
  }
  /// I V = [I_O w + h x v; m v - h x w] for V = [w; v].
  Vector6d operator*(const Vector6d& V) const {
    const Eigen::Vector3d w = V.head<3>(), v = V.tail<3>();
    Vector6d f;
    f.head<3>() = I_O * w + h.cross(v);
    f.tail<3>() = m * v - h.cross(w);
    return f;
  }
  /// Inertias about the same point add (a composite body).
  CompactInertia& operator+=(const CompactInertia& other) {
    m += other.m;
    h += other.h;
    I_O += other.I_O;
    is_zero = is_zero && other.is_zero;
    return *this;
  }
  /// I S, column by column.
  MotionSubspace operator*(const MotionSubspace& S) const {
    MotionSubspace F(6, S.cols());
    for (Eigen::Index k = 0; k < S.cols(); ++k) F.col(k) = *this * Vector6d(S.col(k));
    return F;
  }
  /// The 6x6 matrix (SpatialInertiaAboutOrigin's).
  Matrix6d Matrix() const {
    const Eigen::Matrix3d hx = Skew(h);
    Matrix6d I;
    I.topLeftCorner<3, 3>() = I_O;
    I.topRightCorner<3, 3>() = hx;
    I.bottomLeftCorner<3, 3>() = -hx;
    I.bottomRightCorner<3, 3>() = m * Eigen::Matrix3d::Identity();
    return I;
  }
};

/// Re-expresses a joint's motion-subspace columns, given in its frame F
/// (angular velocity of M in F, and velocity of M's origin in F, both
/// expressed in F), as Plücker columns about the world origin: R_WF is F's
/// orientation in W and p_WMo where M's origin is.
inline MotionSubspace ToWorldPlucker(const MotionSubspace& H, const Eigen::Matrix3d& R_WF,
                                     const Eigen::Vector3d& p_WMo) {
  MotionSubspace S(6, H.cols());
  for (Eigen::Index k = 0; k < H.cols(); ++k) {
    const Eigen::Vector3d w = R_WF * H.col(k).head<3>();
    const Eigen::Vector3d v_Mo = R_WF * H.col(k).tail<3>();
    S.col(k).head<3>() = w;
    S.col(k).tail<3>() = v_Mo + p_WMo.cross(w);  // v_O = v_Mo + w x (O - Mo)
  }
  return S;
}

/// The angular and linear halves of a spatial vector, and the vector of two halves.
inline Eigen::Vector3d Angular(const Vector6d& x) { return x.head<3>(); }
inline Eigen::Vector3d Linear(const Vector6d& x) { return x.tail<3>(); }
inline Vector6d Spatial(const Eigen::Vector3d& angular, const Eigen::Vector3d& linear) {
  Vector6d x;
  x.head<3>() = angular;
  x.tail<3>() = linear;
  return x;
}

/// a x m (crm(a) m): the rate of motion vector m carried by a frame moving
/// with velocity a.
inline Vector6d CrossMotion(const Vector6d& a, const Vector6d& m) {
  return Spatial(Angular(a).cross(Angular(m)),
                 Linear(a).cross(Angular(m)) + Angular(a).cross(Linear(m)));
}

/// a x* f: the same for a force vector f = [moment about O; force].
inline Vector6d CrossForce(const Vector6d& a, const Vector6d& f) {
  return Spatial(Angular(a).cross(Angular(f)) + Linear(a).cross(Linear(f)),
                 Angular(a).cross(Linear(f)));
}

/// The velocity of the body-fixed point at p_W, from a Plücker velocity.
inline Eigen::Vector3d PointVelocity(const Vector6d& V, const Eigen::Vector3d& p_W) {
  return Linear(V) + Angular(V).cross(p_W);
}

}  // namespace mdlc::backend
