// SDFormat <inertial>: what each child lowers to, the defaults, and what the
// reader says about children it does not know (SDF-007).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "tests/unit/sdf_test_util.h"

namespace mdlc {
namespace {

using testing::SdfFrontendResult;
using testing::SdfLink;

const ir::Inertial& OnlyInertial(const SdfFrontendResult& r) {
  EXPECT_EQ(r.module.bodies.size(), 2u);  // the world body and link `a`
  EXPECT_TRUE(r.module.bodies.back().inertial.has_value());
  return *r.module.bodies.back().inertial;
}

/// Mass and moments, in the order ixx, iyy, izz, ixy, ixz, iyz.
void ExpectMassAndMoments(const ir::Inertial& i, double mass, std::array<double, 6> moments) {
  EXPECT_EQ(i.mass, mass);
  const std::array<double, 6> read = {i.ixx, i.iyy, i.izz, i.ixy, i.ixz, i.iyz};
  EXPECT_EQ(read, moments);
}

TEST(SdfInertial, EveryChildIsReadInAnyOrder) {  // SDF-007
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(SdfLink(R"(<inertial>
      <inertia><iyz>0.06</iyz><izz>0.3</izz><ixx>0.1</ixx><ixz>0.05</ixz><iyy>0.2</iyy>
               <ixy>0.04</ixy></inertia>
      <pose>1 2 3 0 0 0</pose>
      <mass>2.5</mass></inertial>)")))
      << r.Messages();
  const ir::Inertial& i = OnlyInertial(r);
  ExpectMassAndMoments(i, 2.5, {0.1, 0.2, 0.3, 0.04, 0.05, 0.06});
  EXPECT_EQ(i.X_BI.p, Eigen::Vector3d(1, 2, 3));
}

TEST(SdfInertial, AbsentChildrenTakeLibsdformatDefaults) {  // SDF-007
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(SdfLink("<inertial><inertia><ixy>0.5</ixy></inertia></inertial>")))
      << r.Messages();
  ExpectMassAndMoments(OnlyInertial(r), 1, {1, 1, 1, 0.5, 0, 0});
}

TEST(SdfInertial, TheFirstOfARepeatedChildCounts) {  // SDF-007
  SdfFrontendResult r;
  ASSERT_TRUE(r.Read(SdfLink(R"(<inertial><mass>3</mass><mass>4</mass>
      <inertia><ixx>0.7</ixx><ixx>0.8</ixx></inertia></inertial>)")))
      << r.Messages();
  const ir::Inertial& i = OnlyInertial(r);
  EXPECT_EQ(i.mass, 3);
  EXPECT_EQ(i.ixx, 0.7);
}

TEST(SdfInertial, UnknownChildrenAreNamedWhereTheyStand) {  // SDF-007
  SdfFrontendResult r;
  r.Read(SdfLink(R"(<inertial><inertia><ixx>1</ixx>
<ijk>2</ijk></inertia>
<moment>3</moment><density>5</density></inertial>)"));
  EXPECT_EQ(r.Count(DiagKind::UnknownSdfElement), 2u) << r.Messages();
  auto d = r.diags.diagnostics();
  ASSERT_EQ(d.size(), 2u);
  std::sort(d.begin(), d.end(), [](const auto& a, const auto& b) { return a.loc.line < b.loc.line; });
  // SdfLink's text starts on line 3
  EXPECT_EQ(d[0].message, "<ijk> is not an SDFormat element of <inertia>");
  EXPECT_EQ(d[0].loc.line, 4u);
  EXPECT_EQ(d[0].loc.column, 1u);
  EXPECT_EQ(d[1].message, "<moment> is not an SDFormat element of <inertial>");
  EXPECT_EQ(d[1].loc.line, 5u);
}

TEST(SdfInertial, ABadMassIsReportedOnceEvenWhenComputedFromCollisions) {  // SDF-007
  SdfFrontendResult r;
  EXPECT_FALSE(r.Read(SdfLink(R"(<inertial auto='true'><mass>heavy</mass></inertial>
      <collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision>)")));
  EXPECT_EQ(r.Count(DiagKind::BadValue), 1u) << r.Messages();
  EXPECT_EQ(r.module.bodies.back().inertia_from_collisions, 1000);
}

}  // namespace
}  // namespace mdlc
