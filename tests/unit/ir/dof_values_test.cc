// Tests for DofValues, the compact per-coordinate lists of a joint: every
// joint type's coordinates fit, lists behave as the std::vector<double> they
// replaced whichever way they are held (inline, shared constant, heap), and
// asking for more than fits is refused rather than truncated.
#include "ir/dof_values.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ir/entities.h"
#include "tests/unit/test_values.h"

namespace mdlc::ir {
namespace {

TEST(DofValues, EveryJointTypeFits) {
  // the capacity is the invariant the type rests on: it must hold every
  // joint kind's positions and velocities
  size_t most = 0;
  for (int t = 0; t <= static_cast<int>(JointType::RpyFloating); ++t) {
    const auto type = static_cast<JointType>(t);
    most = std::max<size_t>(most, static_cast<size_t>(JointPositionCount(type)));
    most = std::max<size_t>(most, static_cast<size_t>(JointVelocityCount(type)));
  }
  EXPECT_EQ(most, DofValues::kCapacity);
  EXPECT_EQ(static_cast<size_t>(JointPositionCount(JointType::QuaternionFloating)), 7u);
}

TEST(DofValues, BehavesAsTheVectorItReplaced) {
  DofValues v;
  EXPECT_TRUE(v.empty());
  v.assign(3, -1.5);
  EXPECT_EQ(v, (std::vector<double>{-1.5, -1.5, -1.5}));
  v.set(2, 9);
  EXPECT_EQ(v.size(), 3u);
  EXPECT_EQ(v.ToVector(), (std::vector<double>{-1.5, -1.5, 9}));

  const DofValues quaternion_pose = {1, 0, 0, 0, 0.1, 0.2, 0.3};
  std::span<const double> view = quaternion_pose;
  ASSERT_EQ(view.size(), 7u);
  EXPECT_EQ(view[4], 0.1);

  const DofValues from_vector = std::vector<double>{4, 5};
  EXPECT_EQ(from_vector, (DofValues{4, 5}));
  EXPECT_FALSE(from_vector == (DofValues{4, 5, 6}));
  EXPECT_FALSE(from_vector == (std::vector<double>{4}));

  std::ostringstream printed;
  printed << from_vector;
  EXPECT_EQ(printed.str(), "[4, 5]");
}

TEST(DofValues, EqualityIgnoresUnusedSlots) {
  DofValues a = {1, 2, 3};
  a.assign(1, 1.0);  // slots 1 and 2 still hold 2 and 3
  const DofValues b = {1};
  EXPECT_EQ(a, b);
}

TEST(DofValues, RefusesMoreThanAJointHas) {
  DofValues v(7, 0.0);
  EXPECT_THROW(v.assign(8, 0.0), std::length_error);
  EXPECT_THROW(DofValues(std::vector<double>(8, 0.0)), std::length_error);
  EXPECT_THROW((DofValues{1, 2, 3, 4, 5, 6, 7, 8}), std::length_error);
  EXPECT_EQ(v.size(), 7u);  // a refused request leaves the list as it was
}

TEST(DofValues, ConstantFillsAreSharedAndStayCompact) {
  // a floating joint's unbounded limits, zero damping and identity pose are
  // the lists a world of one-link models holds per model: they take no heap
  EXPECT_LE(sizeof(DofValues), 16u);
  using mdlc::testing::kInf;
  EXPECT_TRUE(DofValues(6, kInf).IsShared());
  EXPECT_TRUE(DofValues(6, -kInf).IsShared());
  EXPECT_TRUE(DofValues(6, 0.0).IsShared());
  EXPECT_TRUE((DofValues{1, 0, 0, 0, 0, 0, 0}).IsShared());
  EXPECT_TRUE((DofValues{1, 0, 0, 0}).IsShared());  // a ball joint's identity
  EXPECT_FALSE((DofValues{1, 0, 0, 0.5}).IsShared());
  EXPECT_FALSE(DofValues(1, kInf).IsShared());  // one value is held inline
  // -0.0 equals 0.0 but is not shared as zero, so it prints as written
  const DofValues negative_zeros(2, -0.0);
  EXPECT_FALSE(negative_zeros.IsShared());
  EXPECT_TRUE(std::signbit(negative_zeros[1]));
}

TEST(DofValues, WritingASharedListCopiesItFirst) {
  using mdlc::testing::kInf;
  DofValues limits(3, kInf);
  DofValues other(3, kInf);
  limits.set(1, 2.5);
  EXPECT_FALSE(limits.IsShared());
  EXPECT_EQ(limits, (std::vector<double>{kInf, 2.5, kInf}));
  EXPECT_EQ(other, DofValues(3, kInf));  // the shared table is untouched
  EXPECT_TRUE(other.IsShared());
}

TEST(DofValues, CopiesAndMovesAreIndependent) {
  const DofValues heap = {0.5, 1.5, 2.5};
  DofValues copy = heap;
  copy.set(0, 9);
  EXPECT_EQ(heap, (DofValues{0.5, 1.5, 2.5}));
  EXPECT_EQ(copy, (DofValues{9, 1.5, 2.5}));

  DofValues moved = std::move(copy);
  EXPECT_EQ(moved, (DofValues{9, 1.5, 2.5}));
  copy = moved;  // a moved-from list may be assigned again
  EXPECT_EQ(copy, moved);
  moved = DofValues(1, 4.0);  // heap to inline
  EXPECT_EQ(moved, (DofValues{4}));
  const DofValues& same = copy;
  copy = same;  // self-assignment keeps the values
  EXPECT_EQ(copy, (DofValues{9, 1.5, 2.5}));
  copy.assign(copy.begin() + 1, copy.end());  // from its own values
  EXPECT_EQ(copy, (DofValues{1.5, 2.5}));
}

TEST(DofValues, UnboundedLimitsHaveOneEntryPerVelocity) {
  const JointLimits six = JointLimits::Unbounded(6);
  using mdlc::testing::kInf;
  EXPECT_EQ(six.lower, DofValues(6, -kInf));
  EXPECT_EQ(six.upper, DofValues(6, kInf));
  EXPECT_EQ(six.effort, DofValues(6, kInf));
  EXPECT_TRUE(JointLimits::Unbounded(0).velocity_lower.empty());
}

}  // namespace
}  // namespace mdlc::ir
