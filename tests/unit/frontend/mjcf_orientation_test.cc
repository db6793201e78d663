// mjcf_orientation_test.cc - MuJoCo's orientation forms against hand-worked
// rotations (MJCF-010, MJCF-003).
#include "frontend/mjcf/mjcf_orientation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/test_values.h"

namespace mdlc::frontend::mjcf {
namespace {

using testing::kTol;
const double kHalfPi = M_PI / 2;

Eigen::Matrix3d Ok(const RotationOrError& r) {
  EXPECT_TRUE(std::holds_alternative<Eigen::Matrix3d>(r));
  return std::holds_alternative<Eigen::Matrix3d>(r) ? std::get<Eigen::Matrix3d>(r)
                                                    : Eigen::Matrix3d::Zero();
}
bool IsError(const RotationOrError& r) { return std::holds_alternative<std::string>(r); }

Eigen::Matrix3d M(std::initializer_list<double> rows) {
  Eigen::Matrix3d m;
  auto it = rows.begin();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m(i, j) = *it++;
  return m;
}
const Eigen::Matrix3d kRx90 = M({1, 0, 0, 0, 0, -1, 0, 1, 0});
const Eigen::Matrix3d kRy90 = M({0, 0, 1, 0, 1, 0, -1, 0, 0});
const Eigen::Matrix3d kRz90 = M({0, -1, 0, 1, 0, 0, 0, 0, 1});

TEST(MjcfOrientation, Mjcf010QuatIsNormalised) {
  EXPECT_TRUE(Ok(RotationFromQuat(2, 0, 0, 0)).isIdentity(kTol));
  // (cos 45, 0, 0, sin 45) scaled by 3: 90 degrees about z
  EXPECT_TRUE(Ok(RotationFromQuat(3 * std::sqrt(0.5), 0, 0, 3 * std::sqrt(0.5))).isApprox(kRz90, kTol));
  EXPECT_TRUE(IsError(RotationFromQuat(0, 0, 0, 0)));
}

TEST(MjcfOrientation, Mjcf010AxisAngle) {
  EXPECT_TRUE(Ok(RotationFromAxisAngle({0, 0, 2}, kHalfPi)).isApprox(kRz90, kTol));
  EXPECT_TRUE(Ok(RotationFromAxisAngle({1, 0, 0}, kHalfPi)).isApprox(kRx90, kTol));
  EXPECT_TRUE(IsError(RotationFromAxisAngle({0, 0, 0}, 1)));
}

TEST(MjcfOrientation, Mjcf003EulerIntrinsicPostMultiplies) {
  // "xyz": about x, then about the NEW y: Rx(90) * Ry(90)
  const Eigen::Matrix3d expected = M({0, 0, 1, 1, 0, 0, 0, 1, 0});
  EXPECT_TRUE((kRx90 * kRy90).isApprox(expected, kTol));
  EXPECT_TRUE(Ok(RotationFromEuler({kHalfPi, kHalfPi, 0}, "xyz")).isApprox(expected, kTol));
}

TEST(MjcfOrientation, Mjcf003EulerExtrinsicPreMultiplies) {
  // "XYZ": about x, then about the FIXED y: Ry(90) * Rx(90)
  const Eigen::Matrix3d expected = M({0, 1, 0, 0, 0, -1, -1, 0, 0});
  EXPECT_TRUE((kRy90 * kRx90).isApprox(expected, kTol));
  EXPECT_TRUE(Ok(RotationFromEuler({kHalfPi, kHalfPi, 0}, "XYZ")).isApprox(expected, kTol));
}

TEST(MjcfOrientation, Mjcf003EulerMixedAndRepeatedAxes) {
  // "zyz"-style repeats are legal; "xYz" mixes: ((Rx) pre Ry) post Rz
  EXPECT_TRUE(Ok(RotationFromEuler({kHalfPi, 0, kHalfPi}, "zxz"))
                  .isApprox(Eigen::Matrix3d(kRz90 * kRz90), kTol));
  EXPECT_TRUE(Ok(RotationFromEuler({kHalfPi, kHalfPi, kHalfPi}, "xYz"))
                  .isApprox(Eigen::Matrix3d(kRy90 * kRx90 * kRz90), kTol));
  EXPECT_TRUE(IsError(RotationFromEuler({0, 0, 0}, "xyw")));
  EXPECT_FALSE(IsValidEulerSequence("xy"));
  EXPECT_TRUE(IsValidEulerSequence("ZYX"));
}

TEST(MjcfOrientation, Mjcf010XYAxesGramSchmidt) {
  EXPECT_TRUE(Ok(RotationFromXYAxes({0, 1, 0}, {-1, 0, 0})).isApprox(kRz90, kTol));
  // y not orthogonal to x, and not unit: made so
  EXPECT_TRUE(Ok(RotationFromXYAxes({2, 0, 0}, {1, 3, 0})).isIdentity(kTol));
  EXPECT_TRUE(IsError(RotationFromXYAxes({0, 0, 0}, {0, 1, 0})));
  EXPECT_TRUE(IsError(RotationFromXYAxes({1, 0, 0}, {2, 0, 0})));  // y parallel to x
}

TEST(MjcfOrientation, Mjcf010ZAxisMinimalRotation) {
  EXPECT_TRUE(Ok(RotationFromZAxis({0, 0, 5})).isIdentity(kTol));
  EXPECT_TRUE(Ok(RotationFromZAxis({1, 0, 0})).isApprox(kRy90, kTol));
  EXPECT_TRUE(Ok(RotationFromZAxis({0, -1, 0})).isApprox(kRx90, kTol));
  // anti-parallel: MuJoCo turns half way about +x
  EXPECT_TRUE(Ok(RotationFromZAxis({0, 0, -1})).isApprox(M({1, 0, 0, 0, -1, 0, 0, 0, -1}), kTol));
  EXPECT_TRUE(IsError(RotationFromZAxis({0, 0, 0})));
}

}  // namespace
}  // namespace mdlc::frontend::mjcf
