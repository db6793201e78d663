// Rotations from roll, pitch and yaw (URDF-004, SDF-010): the shortcut for
// no rotation must give the very bits of the general product.
#include "ir/transform.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

namespace mdlc {
namespace {

Eigen::Matrix3d ProductOfAxisRotations(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

void ExpectSameBits(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(std::bit_cast<uint64_t>(a.data()[i]), std::bit_cast<uint64_t>(b.data()[i]))
        << "entry " << i << ": " << a.data()[i] << " vs " << b.data()[i];
  }
}

TEST(RotationFromRpyTest, NoRotationIsTheIdentityBitForBit) {
  const Eigen::Vector3d zero(0, 0, 0);
  ExpectSameBits(RotationFromRpy(zero), ProductOfAxisRotations(zero));
  ExpectSameBits(RotationFromRpy(zero), Eigen::Matrix3d::Identity());
}

TEST(RotationFromRpyTest, SignedZerosAndSmallAnglesTakeTheProduct) {
  for (const Eigen::Vector3d& rpy :
       {Eigen::Vector3d(-0.0, 0, 0), Eigen::Vector3d(0, -0.0, 0), Eigen::Vector3d(0, 0, -0.0),
        Eigen::Vector3d(1e-300, 0, 0), Eigen::Vector3d(0, 0, 5e-324),
        Eigen::Vector3d(0.3, -1.2, 2.5)}) {
    ExpectSameBits(RotationFromRpy(rpy), ProductOfAxisRotations(rpy));
  }
}

}  // namespace
}  // namespace mdlc
