// The URDF frontend's model-level drake: elements, where URDF differs from
// SDFormat (EXT-040, EXT-054): what both formats share is tested in both
// spellings in drake_spellings_test.cc. Group semantics and reference checks
// are in tests/unit/passes/collision_filter_groups_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/unit/urdf_test_util.h"

namespace mdlc {
namespace {

using testing::Lowered;

// three links, a revolute and a prismatic joint, a frame and a planar joint
std::string Robot(std::string_view body) {
  return fmt::format(R"(<robot name='r'>
  <link name='a'/><link name='b'/><link name='c'/><link name='d'/>
  <joint name='rev' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/></joint>
  <joint name='pri' type='prismatic'><parent link='b'/><child link='c'/><axis xyz='1 0 0'/></joint>
  <joint name='pla' type='planar'><parent link='c'/><child link='d'/><axis xyz='0 0 1'/></joint>
  <frame name='fa' link='a' xyz='0 0 1'/>
{}
</robot>)",
                     body);
}

// ---------------------------------------------------------------- EXT-040

// SDFormat's reader takes '1' too (sdf_drake_elements_test.cc)
TEST(UrdfCollisionFilterGroupTest, OnlyTheValueTrueSkips) {  // EXT-040 (Drake compares with "true")
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(<drake:collision_filter_group name='g' ignore='1'>
    <drake:member link='a'/></drake:collision_filter_group>)")))
      << l.Messages();
  EXPECT_EQ(l.module.filter_groups.size(), 1u);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "only 'true' skips the group"));
}

// a member names its link in @link, as Drake's URDF parser reads it
TEST(UrdfCollisionFilterGroupTest, MemberNamesItsLinkInTheLinkAttribute) {  // EXT-040
  Lowered l;
  EXPECT_FALSE(l.Read(Robot("<drake:collision_filter_group name='g'><drake:member link='a'/>"
                            "<drake:member name='a'/></drake:collision_filter_group>")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "<drake:member> needs a name"))
      << l.Messages();
  EXPECT_TRUE(l.module.filter_groups.empty());
}

// ---------------------------------------------------------------- EXT-054

// a planar joint is a URDF joint type only
TEST(UrdfTendonConstraintTest, JointsMustExistBeSingleDofAndDistinct) {  // EXT-054
  const struct {
    const char* joints;
    DiagKind kind;
    const char* message;
  } cases[] = {
      {"<drake:tendon_constraint_joint name='nope' a='1'/>", DiagKind::UnknownReference,
       "Could not find joint 'nope'"},
      {"<drake:tendon_constraint_joint name='pla' a='1'/>", DiagKind::BadValue,
       "only single-dof joints"},
      {"<drake:tendon_constraint_joint name='rev' a='1'/>"
       "<drake:tendon_constraint_joint name='rev' a='2'/>",
       DiagKind::BadValue, "listed twice"},
  };
  for (const auto& t : cases) {
    Lowered l;
    ASSERT_TRUE(l.Read(Robot(fmt::format(
        "<drake:tendon_constraint>{}<drake:tendon_constraint_lower_limit value='0'/>"
        "</drake:tendon_constraint>",
        t.joints))))
        << l.Messages();
    EXPECT_FALSE(l.RunPasses()) << t.joints;
    EXPECT_TRUE(l.HasDiagnostic(t.kind, t.message)) << l.Messages();
  }
}

// ---------------------------------------------------------------- all

TEST(UrdfDrakeElementsTest, ElementsMayNameEntitiesDefinedAfterThem) {  // EXT-040, EXT-050..054
  Lowered l;
  ASSERT_TRUE(l.Read(R"(<robot name='r'>
  <drake:collision_filter_group name='g'><drake:member link='x'/></drake:collision_filter_group>
  <drake:ball_constraint>
    <drake:ball_constraint_body_A name='x'/><drake:ball_constraint_body_B name='y'/>
    <drake:ball_constraint_p_AP value='0 0 0'/><drake:ball_constraint_p_BQ value='0 0 0'/>
  </drake:ball_constraint>
  <drake:tendon_constraint><drake:tendon_constraint_joint name='j' a='1'/>
    <drake:tendon_constraint_upper_limit value='1'/></drake:tendon_constraint>
  <link name='x'/><link name='y'/>
  <joint name='j' type='revolute'><parent link='x'/><child link='y'/></joint>
</robot>)")) << l.Messages();
  EXPECT_TRUE(l.RunPasses()) << l.Messages();
}

}  // namespace
}  // namespace mdlc
