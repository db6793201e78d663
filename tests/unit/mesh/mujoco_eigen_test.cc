// Tests of MujocoEigen (mujoco_eigen.h): the principal axes MuJoCo 3.3.8's
// compiler finds for a mesh, whose signs fitted primitives take (issue 62).
// The frames themselves are checked against MuJoCo by the fit-to-mesh tests
// (MuJoCo's numbers) and the oracle (tests/models/mjcf/oracle/inline_meshes.xml).
#include "passes/mesh/mujoco_eigen.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

namespace mdlc::testing {
namespace {

TEST(MujocoEigenTest, DiagonalizesWithDecreasingValuesInARotation) {  // BEYOND-002
  const Eigen::Matrix3d R =
      (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ())).matrix();
  const Eigen::Matrix3d A = R * Eigen::Vector3d(1.0, 3.0, 2.0).asDiagonal() * R.transpose();
  Eigen::Vector3d values;
  Eigen::Matrix3d axes;
  mesh::MujocoEigen(A, &values, &axes);
  EXPECT_NEAR(values[0], 3.0, 1e-9);
  EXPECT_NEAR(values[1], 2.0, 1e-9);
  EXPECT_NEAR(values[2], 1.0, 1e-9);
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
  EXPECT_TRUE((axes.transpose() * axes).isIdentity(1e-12));
  // MuJoCo stops once a rotation's cosine is within 1e-12 of 1: an angle
  // of up to about 1.4e-6 may be left, and as much off the diagonal
  const Eigen::Matrix3d D = axes.transpose() * A * axes;
  EXPECT_LT((D - Eigen::Matrix3d(values.asDiagonal())).norm(), 1e-5) << D;
}

TEST(MujocoEigenTest, AnOrderedDiagonalKeepsTheIdentity) {  // BEYOND-002
  Eigen::Vector3d values;
  Eigen::Matrix3d axes;
  mesh::MujocoEigen(Eigen::Vector3d(3, 2, 1).asDiagonal(), &values, &axes);
  EXPECT_EQ(values, Eigen::Vector3d(3, 2, 1));
  EXPECT_TRUE(axes.isIdentity(0));
  // increasing: quarter turns reorder it, still a rotation
  mesh::MujocoEigen(Eigen::Vector3d(1, 2, 3).asDiagonal(), &values, &axes);
  EXPECT_EQ(values, Eigen::Vector3d(3, 2, 1));
  EXPECT_NEAR(axes.determinant(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(axes(2, 0)), 1.0, 1e-12);  // the largest value's axis is z
}

}  // namespace
}  // namespace mdlc::testing
