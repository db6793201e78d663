// The URDF frontend's model-level drake: elements: what each lowers to and
// which inputs it rejects (EXT-040, EXT-050..054). Group semantics and
// reference checks are in tests/unit/passes/collision_filter_groups_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "tests/unit/test_values.h"
#include "tests/unit/urdf_test_util.h"

namespace mdlc {
namespace {

using testing::kInf;
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

TEST(UrdfCollisionFilterGroupTest, LowersMembersGroupsAndIgnoredGroups) {  // EXT-040
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(
  <drake:collision_filter_group name='g'>
    <drake:member link='a'/>
    <drake:member link='b'/>
    <drake:member_group name='h'/>
    <drake:ignored_collision_filter_group name='g'/>
    <drake:ignored_collision_filter_group name='h'/>
  </drake:collision_filter_group>
  <drake:collision_filter_group name='h'><drake:member link='c'/></drake:collision_filter_group>)")))
      << l.Messages();
  ASSERT_EQ(l.module.filter_groups.size(), 2u);
  const ir::CollisionFilterGroup& g = l.module.filter_groups[0];
  EXPECT_EQ(l.module.Text(g.name), "g");
  EXPECT_EQ(g.model, *l.model);
  ASSERT_EQ(g.members.size(), 2u);
  EXPECT_EQ(l.module.Text(g.members[0].name), "a");
  EXPECT_EQ(l.module.Text(g.members[1].name), "b");
  EXPECT_FALSE(g.members[0].resolved());  // names until resolve-names
  EXPECT_EQ(g.members[0].loc.line, 9u);  // the attribute that wrote the name
  ASSERT_EQ(g.member_groups.size(), 1u);
  EXPECT_EQ(l.module.Text(g.member_groups[0].name), "h");
  ASSERT_EQ(g.ignored_groups.size(), 2u);
  EXPECT_EQ(l.module.Text(g.ignored_groups[0].name), "g");
  EXPECT_EQ(l.module.Text(g.ignored_groups[1].name), "h");
}

TEST(UrdfCollisionFilterGroupTest, IgnoreTrueSkipsTheWholeGroup) {  // EXT-040
  Lowered l;
  // even a group that would be broken is skipped without a word
  ASSERT_TRUE(l.Read(Robot(R"(
  <drake:collision_filter_group ignore='true'><drake:member/></drake:collision_filter_group>
  <drake:collision_filter_group name='kept' ignore='false'>
    <drake:member link='a'/></drake:collision_filter_group>)")))
      << l.Messages();
  ASSERT_EQ(l.module.filter_groups.size(), 1u);
  EXPECT_EQ(l.module.Text(l.module.filter_groups[0].name), "kept");
  EXPECT_TRUE(l.diags.diagnostics().empty()) << l.Messages();
}

TEST(UrdfCollisionFilterGroupTest, OnlyTheValueTrueSkips) {  // EXT-040 (Drake compares with "true")
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(<drake:collision_filter_group name='g' ignore='1'>
    <drake:member link='a'/></drake:collision_filter_group>)")))
      << l.Messages();
  EXPECT_EQ(l.module.filter_groups.size(), 1u);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "only 'true' skips the group"));
}

TEST(UrdfCollisionFilterGroupTest, MissingOrEmptyNameIsAnError) {  // EXT-040
  for (const char* group : {"<drake:collision_filter_group><drake:member link='a'/>"
                            "</drake:collision_filter_group>",
                            "<drake:collision_filter_group name=''><drake:member link='a'/>"
                            "</drake:collision_filter_group>"}) {
    Lowered l;
    EXPECT_FALSE(l.Read(Robot(group))) << group;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "name")) << l.Messages();
    EXPECT_TRUE(l.module.filter_groups.empty());
  }
}

TEST(UrdfCollisionFilterGroupTest, ChildWithoutItsNameAttributeIsAnError) {  // EXT-040
  for (const char* child : {"<drake:member/>", "<drake:member name='a'/>", "<drake:member link=''/>",
                            "<drake:member_group/>", "<drake:ignored_collision_filter_group/>"}) {
    Lowered l;
    EXPECT_FALSE(l.Read(Robot(fmt::format(
        "<drake:collision_filter_group name='g'><drake:member link='a'/>{}"
        "</drake:collision_filter_group>",
        child))))
        << child;
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute, "needs a name"))
        << l.Messages();
  }
}

TEST(UrdfCollisionFilterGroupTest, UnknownChildIsAWarning) {  // EXT-040
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(<drake:collision_filter_group name='g'>
    <drake:member link='a'/><drake:members link='b'/></drake:collision_filter_group>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "drake:members"));
  EXPECT_EQ(l.module.filter_groups[0].members.size(), 1u);
}

// ---------------------------------------------------------------- EXT-050

constexpr const char* kBushing = R"(<drake:linear_bushing_rpy>
    <drake:bushing_frameA name='fa'/>
    <drake:bushing_frameC name='c'/>
    <drake:bushing_torque_stiffness value='1 2 3'/>
    <drake:bushing_torque_damping value='4 5 6'/>
    <drake:bushing_force_stiffness value='7 8 9'/>
    <drake:bushing_force_damping value='10 11 12'/>
  </drake:linear_bushing_rpy>)";

TEST(UrdfLinearBushingTest, LowersFramesAndGains) {  // EXT-050
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(kBushing))) << l.Messages();
  ASSERT_EQ(l.module.force_elements.size(), 1u);
  ASSERT_EQ(l.module.force_elements[0].type(), ir::ForceElementType::LinearBushingRpy);
  EXPECT_EQ(l.module.force_elements[0].model, *l.model);
  const auto& f = l.module.force_elements[0].As<ir::LinearBushingRpy>();
  EXPECT_EQ(l.module.Text(f.frame_A.name), "fa");
  EXPECT_EQ(l.module.Text(f.frame_C.name), "c");
  EXPECT_EQ(f.frame_A.loc.line, 8u);
  EXPECT_EQ(f.torque_stiffness, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.torque_damping, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(f.force_stiffness, Eigen::Vector3d(7, 8, 9));
  EXPECT_EQ(f.force_damping, Eigen::Vector3d(10, 11, 12));
  // a <frame> and a link's own frame both resolve
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_TRUE(f.frame_A.frame.valid());
  EXPECT_EQ(l.module[f.frame_A.frame].name, l.module.Intern("fa"));
  EXPECT_TRUE(f.frame_C.body.valid());
  EXPECT_EQ(l.module[f.frame_C.body].name, l.module.Intern("c"));
}

struct Broken {
  std::string from, to;  // replace `from` in the valid element by `to`
  DiagKind kind;
  std::string message;
};

void ExpectRejected(const char* element, const Broken& b) {
  std::string text = element;
  const size_t at = text.find(b.from);
  ASSERT_NE(at, std::string::npos) << b.from;
  text.replace(at, b.from.size(), b.to);
  Lowered l;
  EXPECT_FALSE(l.Read(Robot(text))) << b.from << " -> " << b.to;
  EXPECT_TRUE(l.HasDiagnostic(b.kind, b.message)) << b.to << "\n" << l.Messages();
  EXPECT_TRUE(l.module.force_elements.empty());
  for (const auto& c : l.module.constraints) EXPECT_EQ(c.type(), ir::ConstraintType::Coupler);
}

TEST(UrdfLinearBushingTest, EveryChildIsRequiredAndGainsAreNonNegative) {  // EXT-050
  const Broken cases[] = {
      {"<drake:bushing_frameA name='fa'/>", "", DiagKind::MissingElement,
       "needs a <drake:bushing_frameA> child"},
      {"<drake:bushing_frameC name='c'/>", "", DiagKind::MissingElement,
       "needs a <drake:bushing_frameC> child"},
      {"<drake:bushing_torque_damping value='4 5 6'/>", "", DiagKind::MissingElement,
       "needs a <drake:bushing_torque_damping> child"},
      {"<drake:bushing_force_damping value='10 11 12'/>", "", DiagKind::MissingElement,
       "needs a <drake:bushing_force_damping> child"},
      {"name='c'", "naQQme='c'", DiagKind::MissingAttribute,
       "<drake:bushing_frameC> needs a name"},
      {"value='1 2 3'", "", DiagKind::MissingAttribute,
       "<drake:bushing_torque_stiffness> needs a value"},
      {"value='1 2 3'", "value='1 2'", DiagKind::BadValue, "must hold 3 numbers"},
      {"value='7 8 9'", "value='7 -8 9'", DiagKind::BadValue, "must be non-negative"},
      {"value='4 5 6'", "value='4 inf 6'", DiagKind::NonFinite, "must hold finite numbers"},
  };
  for (const Broken& b : cases) ExpectRejected(kBushing, b);
}

TEST(UrdfLinearBushingTest, UnknownFrameIsAnError) {  // EXT-050
  Lowered l;
  std::string text = kBushing;
  text.replace(text.find("'fa'"), 4, "'nowhere'");
  ASSERT_TRUE(l.Read(Robot(text))) << l.Messages();
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "unknown frame 'nowhere'"))
      << l.Messages();
}

// ---------------------------------------------------------------- EXT-051

constexpr const char* kSpring = R"(<drake:linear_spring_damper>
    <drake:linear_spring_damper_body_A name='a'/>
    <drake:linear_spring_damper_p_AP value='1 2 3'/>
    <drake:linear_spring_damper_body_B name='c'/>
    <drake:linear_spring_damper_p_BQ value='4 5 6'/>
    <drake:linear_spring_damper_free_length value='7'/>
    <drake:linear_spring_damper_stiffness value='8'/>
    <drake:linear_spring_damper_damping value='9'/>
  </drake:linear_spring_damper>)";

TEST(UrdfLinearSpringDamperTest, LowersBodiesPointsAndGains) {  // EXT-051
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(kSpring))) << l.Messages();
  ASSERT_EQ(l.module.force_elements.size(), 1u);
  ASSERT_EQ(l.module.force_elements[0].type(), ir::ForceElementType::LinearSpringDamper);
  const auto& f = l.module.force_elements[0].As<ir::LinearSpringDamper>();
  EXPECT_EQ(l.module.Text(f.body_A.name), "a");
  EXPECT_EQ(l.module.Text(f.body_B.name), "c");
  EXPECT_EQ(f.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.p_BQ, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(f.free_length, 7);
  EXPECT_EQ(f.stiffness, 8);
  EXPECT_EQ(f.damping, 9);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  EXPECT_EQ(f.body_A.id, BodyId(uint32_t{1}));
  EXPECT_EQ(f.body_B.id, BodyId(uint32_t{3}));
}

TEST(UrdfLinearSpringDamperTest, EveryChildIsRequiredAndValuesAreChecked) {  // EXT-051
  const Broken cases[] = {
      {"<drake:linear_spring_damper_body_B name='c'/>", "", DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_body_B> child"},
      {"<drake:linear_spring_damper_p_AP value='1 2 3'/>", "", DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_p_AP> child"},
      {"<drake:linear_spring_damper_stiffness value='8'/>", "", DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_stiffness> child"},
      {"value='1 2 3'", "", DiagKind::MissingAttribute,
       "<drake:linear_spring_damper_p_AP> needs a value"},
      {"value='7'", "value='0'", DiagKind::BadValue, "must be positive"},
      {"value='7'", "value='-1'", DiagKind::BadValue, "must be positive"},
      {"value='8'", "value='-8'", DiagKind::BadValue, "must be non-negative"},
      {"value='9'", "value='-0.1'", DiagKind::BadValue, "must be non-negative"},
      {"value='9'", "value='nan'", DiagKind::BadValue, "not NaN"},
      {"value='8'", "value='inf'", DiagKind::BadValue, "must be finite"},
      {"value='9'", "value='x'", DiagKind::BadValue, "must hold a number"},
      {"name='a'", "name=''", DiagKind::MissingAttribute, "needs a name"},
  };
  for (const Broken& b : cases) ExpectRejected(kSpring, b);
}

// ---------------------------------------------------------------- EXT-052

constexpr const char* kBall = R"(<drake:ball_constraint>
    <drake:ball_constraint_body_A name='a'/>
    <drake:ball_constraint_body_B name='c'/>
    <drake:ball_constraint_p_AP value='1 2 3'/>
    <drake:ball_constraint_p_BQ value='4 5 6'/>
  </drake:ball_constraint>)";

TEST(UrdfBallConstraintTest, LowersBodiesAndPoints) {  // EXT-052
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(kBall))) << l.Messages();
  ASSERT_EQ(l.module.constraints.size(), 1u);
  ASSERT_EQ(l.module.constraints[0].type(), ir::ConstraintType::Ball);
  const auto& c = l.module.constraints[0].As<ir::BallConstraint>();
  EXPECT_EQ(l.module.Text(c.body_A.name), "a");
  EXPECT_EQ(l.module.Text(c.body_B.name), "c");
  EXPECT_EQ(c.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c.p_BQ, Eigen::Vector3d(4, 5, 6));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
}

TEST(UrdfBallConstraintTest, EveryChildIsRequired) {  // EXT-052
  const Broken cases[] = {
      {"<drake:ball_constraint_body_A name='a'/>", "", DiagKind::MissingElement,
       "needs a <drake:ball_constraint_body_A> child"},
      {"<drake:ball_constraint_p_BQ value='4 5 6'/>", "", DiagKind::MissingElement,
       "needs a <drake:ball_constraint_p_BQ> child"},
      {"value='4 5 6'", "value='4 5 6 7'", DiagKind::BadValue, "must hold 3 numbers"},
  };
  for (const Broken& b : cases) ExpectRejected(kBall, b);
}

TEST(UrdfBallConstraintTest, UnknownOrIdenticalBodiesAreErrors) {  // EXT-052
  {
    Lowered l;
    std::string text = kBall;
    text.replace(text.find("'c'"), 3, "'zz'");
    ASSERT_TRUE(l.Read(Robot(text)));
    EXPECT_FALSE(l.RunPasses());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "Could not find link 'zz'"))
        << l.Messages();
    EXPECT_EQ(l.diags.diagnostics()[0].loc.line, 9u);  // at body_B's name
  }
  {
    Lowered l;
    std::string text = kBall;
    text.replace(text.find("'c'"), 3, "'a'");
    ASSERT_TRUE(l.Read(Robot(text)));
    EXPECT_FALSE(l.RunPasses());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "two distinct bodies")) << l.Messages();
  }
}

// ---------------------------------------------------------------- EXT-053

constexpr const char* kDistance = R"(<drake:distance_constraint>
    <drake:distance_constraint_body_A name='a'/>
    <drake:distance_constraint_p_AP value='1 2 3'/>
    <drake:distance_constraint_body_B name='c'/>
    <drake:distance_constraint_p_BQ value='4 5 6'/>
    <drake:distance_constraint_distance value='0.5'/>
    <drake:distance_constraint_stiffness value='100'/>
    <drake:distance_constraint_damping value='0'/>
  </drake:distance_constraint>)";

TEST(UrdfDistanceConstraintTest, LowersEveryParameter) {  // EXT-053
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(kDistance))) << l.Messages();
  ASSERT_EQ(l.module.constraints.size(), 1u);
  ASSERT_EQ(l.module.constraints[0].type(), ir::ConstraintType::Distance);
  const auto& c = l.module.constraints[0].As<ir::DistanceConstraint>();
  EXPECT_EQ(l.module.Text(c.body_A.name), "a");
  EXPECT_EQ(l.module.Text(c.body_B.name), "c");
  EXPECT_EQ(c.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c.p_BQ, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(c.distance, 0.5);
  EXPECT_EQ(c.stiffness, 100);
  EXPECT_EQ(c.damping, 0);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
}

TEST(UrdfDistanceConstraintTest, InfiniteStiffnessIsARigidConstraint) {  // EXT-053
  Lowered l;
  std::string text = kDistance;
  text.replace(text.find("'100'"), 5, "'inf'");
  ASSERT_TRUE(l.Read(Robot(text))) << l.Messages();
  EXPECT_EQ(l.module.constraints[0].As<ir::DistanceConstraint>().stiffness, kInf);
}

TEST(UrdfDistanceConstraintTest, EveryChildIsRequiredAndValuesAreChecked) {  // EXT-053
  const Broken cases[] = {
      {"<drake:distance_constraint_distance value='0.5'/>", "", DiagKind::MissingElement,
       "needs a <drake:distance_constraint_distance> child"},
      {"<drake:distance_constraint_stiffness value='100'/>", "", DiagKind::MissingElement,
       "needs a <drake:distance_constraint_stiffness> child"},
      {"<drake:distance_constraint_damping value='0'/>", "", DiagKind::MissingElement,
       "needs a <drake:distance_constraint_damping> child"},
      {"<drake:distance_constraint_body_B name='c'/>", "", DiagKind::MissingElement,
       "needs a <drake:distance_constraint_body_B> child"},
      {"value='0.5'", "value='0'", DiagKind::BadValue, "must be positive"},
      {"value='100'", "value='0'", DiagKind::BadValue, "must be positive"},
      {"value='0'/>\n  </drake", "value='-1'/>\n  </drake", DiagKind::BadValue,
       "must be non-negative"},
      {"value='0.5'", "value='inf'", DiagKind::BadValue, "must be finite"},
  };
  for (const Broken& b : cases) ExpectRejected(kDistance, b);
}

// ---------------------------------------------------------------- EXT-054

TEST(UrdfTendonConstraintTest, LowersJointsCoefficientsAndParameters) {  // EXT-054
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(<drake:tendon_constraint>
    <drake:tendon_constraint_joint name='rev' a='10'/>
    <drake:tendon_constraint_joint name='pri' a='-20'/>
    <drake:tendon_constraint_offset value='0.3'/>
    <drake:tendon_constraint_lower_limit value='-5'/>
    <drake:tendon_constraint_upper_limit value='5'/>
    <drake:tendon_constraint_stiffness value='0.4'/>
    <drake:tendon_constraint_damping value='0.09'/>
  </drake:tendon_constraint>)")))
      << l.Messages();
  ASSERT_EQ(l.module.constraints.size(), 1u);
  ASSERT_EQ(l.module.constraints[0].type(), ir::ConstraintType::Tendon);
  const auto& c = l.module.constraints[0].As<ir::TendonConstraint>();
  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(l.module.Text(c.joints[0].name), "rev");
  EXPECT_EQ(l.module.Text(c.joints[1].name), "pri");
  EXPECT_EQ(c.a, (std::vector<double>{10, -20}));
  EXPECT_EQ(c.offset, 0.3);
  EXPECT_EQ(c.lower, -5);
  EXPECT_EQ(c.upper, 5);
  EXPECT_EQ(c.stiffness, 0.4);
  EXPECT_EQ(c.damping, 0.09);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  // check-joints rebuilds the table
  const auto& resolved = l.module.constraints[0].As<ir::TendonConstraint>();
  EXPECT_EQ(l.module[resolved.joints[0].id].name, l.module.Intern("rev"));
  EXPECT_EQ(l.module[resolved.joints[1].id].name, l.module.Intern("pri"));
}

TEST(UrdfTendonConstraintTest, OptionalParametersTakeAddTendonConstraintDefaults) {  // EXT-054
  // AddTendonConstraint: offset 0, limits -inf/+inf, stiffness +inf, damping 0;
  // one finite bound is required
  Lowered l;
  ASSERT_TRUE(l.Read(Robot(R"(<drake:tendon_constraint>
    <drake:tendon_constraint_joint name='rev' a='1'/>
    <drake:tendon_constraint_upper_limit value='0.5'/>
  </drake:tendon_constraint>)")))
      << l.Messages();
  const auto& c = l.module.constraints[0].As<ir::TendonConstraint>();
  EXPECT_EQ(c.offset, 0);
  EXPECT_EQ(c.lower, -kInf);
  EXPECT_EQ(c.upper, 0.5);
  EXPECT_EQ(c.stiffness, kInf);
  EXPECT_EQ(c.damping, 0);
}

TEST(UrdfTendonConstraintTest, RejectsWhatAddTendonConstraintRejects) {  // EXT-054
  constexpr const char* kTendon = R"(<drake:tendon_constraint>
    <drake:tendon_constraint_joint name='rev' a='1'/>
    <drake:tendon_constraint_lower_limit value='-1'/>
    <drake:tendon_constraint_upper_limit value='1'/>
    <drake:tendon_constraint_stiffness value='3'/>
    <drake:tendon_constraint_damping value='4'/>
  </drake:tendon_constraint>)";
  const Broken cases[] = {
      {"<drake:tendon_constraint_joint name='rev' a='1'/>", "", DiagKind::MissingElement,
       "needs at least one <drake:tendon_constraint_joint>"},
      {"name='rev' a='1'", "a='1'", DiagKind::MissingAttribute,
       "<drake:tendon_constraint_joint> needs a name"},
      {"name='rev' a='1'", "name='rev'", DiagKind::MissingAttribute,
       "<drake:tendon_constraint_joint> needs its 'a' attribute"},
      {"a='1'", "a='inf'", DiagKind::BadValue, "must be finite"},
      {"value='-1'", "value='2'", DiagKind::BadValue, "greater than upper limit"},
      {"value='-1'", "value='inf'", DiagKind::BadValue, "must be finite or -inf"},
      {"value='1'", "value='-inf'", DiagKind::BadValue, "must be finite or inf"},
      {"value='3'", "value='0'", DiagKind::BadValue, "must be positive"},
      {"value='4'", "value='-4'", DiagKind::BadValue, "must be non-negative"},
      {"value='4'", "value='nan'", DiagKind::BadValue, "not NaN"},
      {"<drake:tendon_constraint_lower_limit value='-1'/>\n    "
       "<drake:tendon_constraint_upper_limit value='1'/>",
       "", DiagKind::BadValue, "needs a finite bound"},
  };
  for (const Broken& b : cases) ExpectRejected(kTendon, b);
}

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

TEST(UrdfDrakeElementsTest, UnknownAndRepeatedChildrenAreWarnings) {  // EXT-050..054
  Lowered l;
  std::string text = kBall;
  text.replace(text.find("</drake:ball_constraint>"), 0,
               "<drake:ball_constraint_p_AP value='9 9 9'/><drake:extra/>");
  ASSERT_TRUE(l.Read(Robot(text))) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "<drake:extra>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "only the first one is used"));
  EXPECT_EQ(l.module.constraints[0].As<ir::BallConstraint>().p_AP,
            Eigen::Vector3d(1, 2, 3));  // Drake: the first
}

TEST(UrdfDrakeElementsTest, EveryProblemOfOneElementIsReported) {  // COMMON-001
  Lowered l;
  EXPECT_FALSE(l.Read(Robot(R"(<drake:linear_spring_damper>
    <drake:linear_spring_damper_p_AP value='1 2'/>
    <drake:linear_spring_damper_free_length value='0'/>
  </drake:linear_spring_damper>)")));
  // body_A, body_B, p_BQ, stiffness and damping missing; p_AP and free length bad
  EXPECT_EQ(l.diags.error_count(), 7u) << l.Messages();
  // the seven errors, counted above: five missing children, two bad values
  l.ExpectDiagnostic(DiagKind::MissingElement, "needs a <drake:linear_spring_damper_");
  l.ExpectDiagnostic(DiagKind::BadValue, "");
  EXPECT_TRUE(l.module.force_elements.empty());
}

}  // namespace
}  // namespace mdlc
