// Tests of the inertia-from-collisions pass (SDF-007: <inertial auto="true">)
// against closed forms.
#include <gtest/gtest.h>

#include <numbers>

#include "tests/unit/sdf_test_util.h"

namespace mdlc::testing {
namespace {

const ir::Inertial& InertialOf(const Compilation& c, std::string_view body) {
  for (const ir::Body& b : c.module.bodies) {
    if (c.module.Text(b.name) == body) return *b.inertial;
  }
  ADD_FAILURE() << "no body " << body;
  return *c.module.bodies[1].inertial;
}

TEST(InertiaFromCollisions, OffsetBoxAndSphereCombine) {  // SDF-007
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='L'>
      <inertial auto='true'><density>2</density></inertial>
      <collision name='box'>
        <pose>1 0 0 0 0 0</pose>
        <geometry><box><size>1 2 3</size></box></geometry>
      </collision>
      <collision name='ball'>
        <pose>-1 0 0 0 0 0</pose>
        <density>3</density>
        <geometry><sphere><radius>0.5</radius></sphere></geometry>
      </collision>
    </link>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Inertial& in = InertialOf(r.compilation(), "L");
  const double m_box = 2 * 6, m_ball = 3 * 4.0 / 3.0 * std::numbers::pi * 0.125;
  EXPECT_NEAR(in.mass, m_box + m_ball, 1e-12);
  const double x_com = (m_box - m_ball) / (m_box + m_ball);
  EXPECT_NEAR(in.X_BI.p.x(), x_com, 1e-12);
  // Izz about the COM: each solid's own moment plus its offset from the COM
  const double izz = m_box * (1 + 4) / 12 + m_box * (1 - x_com) * (1 - x_com) +
                     0.4 * m_ball * 0.25 + m_ball * (1 + x_com) * (1 + x_com);
  EXPECT_NEAR(in.izz, izz, 1e-12);
  EXPECT_NEAR(in.ixx, m_box * (4 + 9) / 12 + 0.4 * m_ball * 0.25, 1e-12);
}

TEST(InertiaFromCollisions, GivenMassScalesTheDistribution) {  // SDF-007
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='L'>
      <inertial auto='true'><mass>6</mass></inertial>
      <collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision>
    </link>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Inertial& in = InertialOf(r.compilation(), "L");
  EXPECT_NEAR(in.mass, 6, 1e-12);
  EXPECT_NEAR(in.ixx, 1, 1e-12);
}

TEST(InertiaFromCollisions, CapsuleMatchesCylinderPlusHemispheres) {  // SDF-007
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='L'>
      <inertial auto='true'><density>1</density></inertial>
      <collision name='c'><geometry><capsule><radius>1</radius><length>2</length></capsule></geometry></collision>
    </link>
  </model>)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Inertial& in = InertialOf(r.compilation(), "L");
  const double pi = std::numbers::pi;
  EXPECT_NEAR(in.mass, pi * 2 + 4.0 / 3.0 * pi, 1e-12);
  EXPECT_NEAR(in.izz, 2 * pi / 2 + (4.0 / 3.0 * pi) * 0.4, 1e-12);
}

TEST(InertiaFromCollisions, NoCollisionIsAnError) {  // SDF-007
  SdfCompileResult r(R"(
  <model name='m'>
    <link name='L'><inertial auto='true'/></link>
  </model>)");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.Messages().find("has no collision with a volume"), std::string::npos)
      << r.Messages();
  r.ExpectDiagnostic(DiagKind::BadValue, "has no collision with a volume");
}

}  // namespace
}  // namespace mdlc::testing
