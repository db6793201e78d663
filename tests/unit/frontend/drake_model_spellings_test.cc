// Drake's model elements in both spellings, each test run once per format
// (tests/unit/drake_spellings.h): collision filter groups (EXT-040), the
// linear bushing and spring damper (EXT-050, EXT-051), the ball, distance
// and tendon constraints (EXT-052..054) and <drake:joint> (EXT-001, EXT-003,
// EXT-004), with COMMON-001 and COMMON-050.
#include "tests/unit/drake_spellings.h"

namespace mdlc::drake_spellings {
namespace {

// ------------------------------------------------------------------ EXT-040

class DrakeCollisionFilterGroupTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeCollisionFilterGroupTest);

/// <drake:member> naming `link`: URDF's @link, SDFormat's text.
std::string Member(std::string_view link, Format format) {
  return DrakeName("drake:member", link, format, "link");
}
/// A group `name` holding `children`; `attributes` follow the name.
std::string FilterGroup(std::string_view name, std::string_view children,
                        std::string_view attributes = "") {
  return fmt::format("<drake:collision_filter_group name='{}'{}>{}</drake:collision_filter_group>",
                     name, attributes, children);
}

TEST_P(DrakeCollisionFilterGroupTest, LowersMembersGroupsAndIgnoredGroups) {  // EXT-040
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(Model(
      FilterGroup("g", "\n    " + Member("a", f) + "\n    " + Member("b", f) +
                           DrakeName("drake:member_group", "h", f) +
                           DrakeName("drake:ignored_collision_filter_group", "g", f) +
                           DrakeName("drake:ignored_collision_filter_group", "h", f)) +
          FilterGroup("h", Member("c", f)) +
          FilterGroup("skipped", Member("c", f), " ignore='true'"),
      f)))
      << l.Messages();
  ASSERT_EQ(l.module().filter_groups.size(), 2u);
  const ir::CollisionFilterGroup& g = l.module().filter_groups[0];
  EXPECT_EQ(l.module().Text(g.name), "g");
  EXPECT_EQ(g.model, l.model());
  ASSERT_EQ(g.members.size(), 2u);
  EXPECT_EQ(l.module().Text(g.members[0].name), "a");
  EXPECT_EQ(l.module().Text(g.members[1].name), "b");
  EXPECT_FALSE(g.members[0].resolved());  // names until resolve-names
  EXPECT_EQ(g.members[0].loc.line, 9u);   // where the name is written
  ASSERT_EQ(g.member_groups.size(), 1u);
  EXPECT_EQ(l.module().Text(g.member_groups[0].name), "h");
  ASSERT_EQ(g.ignored_groups.size(), 2u);
  EXPECT_EQ(l.module().Text(g.ignored_groups[0].name), "g");
  EXPECT_EQ(l.module().Text(g.ignored_groups[1].name), "h");
  EXPECT_EQ(l.module().Text(l.module().filter_groups[1].name), "h");
}

TEST_P(DrakeCollisionFilterGroupTest, IgnoreTrueSkipsTheWholeGroup) {  // EXT-040
  Lowering l(format());
  // even a group that would be broken is skipped without a word
  ASSERT_TRUE(l.Read(Model(
      "<drake:collision_filter_group ignore='true'><drake:member/></drake:collision_filter_group>" +
          FilterGroup("kept", Member("a", format()), " ignore='false'"),
      format())))
      << l.Messages();
  ASSERT_EQ(l.module().filter_groups.size(), 1u);
  EXPECT_EQ(l.module().Text(l.module().filter_groups[0].name), "kept");
  EXPECT_TRUE(l.diags().diagnostics().empty()) << l.Messages();
}

// which values skip a group differs (URDF: 'true'; SDFormat: 'true' or '1',
// urdf_drake_elements_test.cc and sdf_drake_elements_test.cc); any other
// value is reported and the group read
TEST_P(DrakeCollisionFilterGroupTest, OtherIgnoreValuesAreReportedAndRead) {  // EXT-040
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(FilterGroup("g", Member("a", format()), " ignore='yes'"), format())))
      << l.Messages();
  EXPECT_EQ(l.module().filter_groups.size(), 1u);
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue,
                              "attribute 'ignore' of <drake:collision_filter_group> is 'yes'"))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedValue, "skips the group, so it is read"));
}

TEST_P(DrakeCollisionFilterGroupTest, MissingOrEmptyNameIsAnError) {  // EXT-040, COMMON-050
  const std::string member = Member("a", format());
  for (const std::string& group :
       {"<drake:collision_filter_group>" + member + "</drake:collision_filter_group>",
        FilterGroup("", member)}) {
    Lowering l(format());
    EXPECT_FALSE(l.Read(Model(group, format()))) << group;
    EXPECT_TRUE(
        l.HasDiagnostic(DiagKind::MissingAttribute, "<drake:collision_filter_group> needs a name"))
        << l.Messages();
    EXPECT_TRUE(l.module().filter_groups.empty());
  }
}

TEST_P(DrakeCollisionFilterGroupTest, ChildWithoutItsNameIsAnError) {  // EXT-040, COMMON-050
  const Format f = format();
  const struct {
    std::string child;
    const char* message;
  } cases[] = {
      {"<drake:member/>", "<drake:member> needs a name"},
      {Member("", f), "<drake:member> needs a name"},
      {"<drake:member_group/>", "<drake:member_group> needs a name"},
      {DrakeName("drake:member_group", "", f), "<drake:member_group> needs a name"},
      {"<drake:ignored_collision_filter_group/>",
       "<drake:ignored_collision_filter_group> needs a name"},
  };
  for (const auto& c : cases) {
    Lowering l(f);
    EXPECT_FALSE(l.Read(Model(FilterGroup("g", Member("a", f) + c.child), f))) << c.child;
    EXPECT_TRUE(l.HasDiagnostic(MissingKind(f), c.message)) << c.child << "\n" << l.Messages();
    EXPECT_TRUE(l.module().filter_groups.empty()) << c.child;
  }
}

TEST_P(DrakeCollisionFilterGroupTest, UnknownChildIsAWarning) {  // EXT-040
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(
      FilterGroup("g", Member("a", format()) + DrakeName("drake:members", "b", format(), "link")),
      format())))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "drake:members"));
  EXPECT_EQ(l.module().filter_groups.at(0).members.size(), 1u);
}

// ---------------------------------------------------------- EXT-050, EXT-051

class DrakeForceElementTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeForceElementTest);

const std::vector<Child> kBushing = {
    {"drake:bushing_frameA", "fa", Child::kName},
    {"drake:bushing_frameC", "c", Child::kName},
    {"drake:bushing_torque_stiffness", "1 2 3"},
    {"drake:bushing_torque_damping", "4 5 6"},
    {"drake:bushing_force_stiffness", "7 8 9"},
    {"drake:bushing_force_damping", "10 11 12"},
};

TEST_P(DrakeForceElementTest, LinearBushingLowersFramesAndGains) {  // EXT-050
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:linear_bushing_rpy", kBushing, format()), format())))
      << l.Messages();
  ir::Module& m = l.module();
  ASSERT_EQ(m.force_elements.size(), 1u);
  ASSERT_EQ(m.force_elements[0].type(), ir::ForceElementType::LinearBushingRpy);
  EXPECT_EQ(m.force_elements[0].model, l.model());
  const auto& f = m.force_elements[0].As<ir::LinearBushingRpy>();
  EXPECT_EQ(m.Text(f.frame_A.name), "fa");
  EXPECT_EQ(m.Text(f.frame_C.name), "c");
  EXPECT_EQ(f.frame_A.loc.line, 9u);  // where the name is written
  EXPECT_EQ(f.torque_stiffness, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.torque_damping, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(f.force_stiffness, Eigen::Vector3d(7, 8, 9));
  EXPECT_EQ(f.force_damping, Eigen::Vector3d(10, 11, 12));
  // a frame and a link's own frame both resolve
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  const auto& resolved = m.force_elements[0].As<ir::LinearBushingRpy>();
  EXPECT_TRUE(resolved.frame_A.frame.valid());
  EXPECT_EQ(m[resolved.frame_A.frame].name, m.Intern("fa"));
  EXPECT_TRUE(resolved.frame_C.body.valid());
  EXPECT_EQ(m[resolved.frame_C.body].name, m.Intern("c"));
}

TEST_P(DrakeForceElementTest, LinearBushingNeedsEveryChildAndNonNegativeGains) {  // EXT-050
  const Format f = format();
  const Broken cases[] = {
      {"drake:bushing_frameA", std::nullopt, DiagKind::MissingElement,
       "<drake:linear_bushing_rpy> needs a <drake:bushing_frameA> child"},
      {"drake:bushing_frameC", std::nullopt, DiagKind::MissingElement,
       "<drake:linear_bushing_rpy> needs a <drake:bushing_frameC> child"},
      {"drake:bushing_torque_damping", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:bushing_torque_damping> child"},
      {"drake:bushing_force_damping", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:bushing_force_damping> child"},
      {"drake:bushing_frameC", "", MissingKind(f), "<drake:bushing_frameC> needs a name"},
      {"drake:bushing_torque_stiffness", "", MissingKind(f),
       "<drake:bushing_torque_stiffness> needs a value"},
      {"drake:bushing_torque_stiffness", "1 2", DiagKind::BadValue, "must hold 3 numbers"},
      {"drake:bushing_force_stiffness", "7 -8 9", DiagKind::BadValue, "must be non-negative"},
      {"drake:bushing_torque_damping", "4 inf 6", DiagKind::NonFinite, "must hold finite numbers"},
  };
  for (const Broken& b : cases) ExpectRejected(f, "drake:linear_bushing_rpy", kBushing, b);
  // a name or a value not written at all: no attribute (URDF), no text (SDFormat)
  for (const char* tag : {"drake:bushing_frameC", "drake:bushing_torque_stiffness"}) {
    std::vector<Child> bare = kBushing;
    for (Child& c : bare) {
      if (c.tag == tag) c = {tag, fmt::format("<{}/>", tag), Child::kAsIs};
    }
    ExpectRejected(f, "drake:linear_bushing_rpy", bare,
                   {tag, fmt::format("<{}/>", tag), MissingKind(f),
                    fmt::format("<{}> needs a", tag)});
  }
}

TEST_P(DrakeForceElementTest, LinearBushingReportsEveryProblem) {  // EXT-050, COMMON-001
  Broken no_frame_C{"drake:bushing_frameC", std::nullopt, DiagKind::MissingElement, ""};
  std::vector<Child> children = Apply(kBushing, no_frame_C);
  children[2].text = "4 -5 6";  // torque damping
  children[3].text = "7 8";     // force stiffness
  Lowering l(format());
  EXPECT_FALSE(
      l.Read(Model(Element("drake:linear_bushing_rpy", children, format()), format())));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingElement,
                              "<drake:linear_bushing_rpy> needs a <drake:bushing_frameC> child"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "must be non-negative"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "must hold 3 numbers"));
  EXPECT_EQ(l.diags().error_count(), 3u) << l.Messages();
  EXPECT_TRUE(l.module().force_elements.empty());
}

TEST_P(DrakeForceElementTest, LinearBushingUnknownFrameIsAnError) {  // EXT-050
  std::vector<Child> children = kBushing;
  children[0].text = "nowhere";
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:linear_bushing_rpy", children, format()), format())))
      << l.Messages();
  EXPECT_FALSE(l.RunPasses());
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference, "unknown frame 'nowhere'"))
      << l.Messages();
}

const std::vector<Child> kSpring = {
    {"drake:linear_spring_damper_body_A", "a", Child::kName},
    {"drake:linear_spring_damper_p_AP", "1 2 3"},
    {"drake:linear_spring_damper_body_B", "c", Child::kName},
    {"drake:linear_spring_damper_p_BQ", "4 5 6"},
    {"drake:linear_spring_damper_free_length", "7"},
    {"drake:linear_spring_damper_stiffness", "8"},
    {"drake:linear_spring_damper_damping", "9"},
};

TEST_P(DrakeForceElementTest, LinearSpringDamperLowersBodiesPointsAndGains) {  // EXT-051
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:linear_spring_damper", kSpring, format()), format())))
      << l.Messages();
  ir::Module& m = l.module();
  ASSERT_EQ(m.force_elements.size(), 1u);
  ASSERT_EQ(m.force_elements[0].type(), ir::ForceElementType::LinearSpringDamper);
  const auto& f = m.force_elements[0].As<ir::LinearSpringDamper>();
  EXPECT_EQ(m.Text(f.body_A.name), "a");
  EXPECT_EQ(m.Text(f.body_B.name), "c");
  EXPECT_EQ(f.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.p_BQ, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(f.free_length, 7);
  EXPECT_EQ(f.stiffness, 8);
  EXPECT_EQ(f.damping, 9);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  const auto& resolved = m.force_elements[0].As<ir::LinearSpringDamper>();
  EXPECT_EQ(m[resolved.body_A.id].name, m.Intern("a"));
  EXPECT_EQ(m[resolved.body_B.id].name, m.Intern("c"));
}

TEST_P(DrakeForceElementTest, LinearSpringDamperNeedsEveryChildAndCheckedValues) {  // EXT-051
  const Format f = format();
  const Broken cases[] = {
      {"drake:linear_spring_damper_body_B", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_body_B> child"},
      {"drake:linear_spring_damper_p_AP", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_p_AP> child"},
      {"drake:linear_spring_damper_stiffness", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:linear_spring_damper_stiffness> child"},
      {"drake:linear_spring_damper_p_AP", "", MissingKind(f),
       "<drake:linear_spring_damper_p_AP> needs a value"},
      {"drake:linear_spring_damper_free_length", "0", DiagKind::BadValue,
       "<drake:linear_spring_damper_free_length> must be positive"},
      {"drake:linear_spring_damper_free_length", "-1", DiagKind::BadValue, "must be positive"},
      {"drake:linear_spring_damper_stiffness", "-8", DiagKind::BadValue,
       "<drake:linear_spring_damper_stiffness> must be non-negative"},
      {"drake:linear_spring_damper_damping", "-0.1", DiagKind::BadValue,
       "<drake:linear_spring_damper_damping> must be non-negative"},
      {"drake:linear_spring_damper_damping", "nan", DiagKind::BadValue, "not NaN"},
      {"drake:linear_spring_damper_stiffness", "inf", DiagKind::BadValue, "must be finite"},
      {"drake:linear_spring_damper_damping", "x", DiagKind::BadValue, "must hold a number"},
      {"drake:linear_spring_damper_body_A", "", MissingKind(f), "needs a name"},
  };
  for (const Broken& b : cases) ExpectRejected(f, "drake:linear_spring_damper", kSpring, b);
}

TEST_P(DrakeForceElementTest, EveryProblemOfOneElementIsReported) {  // COMMON-001
  Lowering l(format());
  EXPECT_FALSE(l.Read(Model(
      Element("drake:linear_spring_damper",
              {{"drake:linear_spring_damper_p_AP", "1 2"},
               {"drake:linear_spring_damper_free_length", "0"}},
              format()),
      format())));
  // body_A, body_B, p_BQ, stiffness and damping missing; p_AP and free length bad
  EXPECT_EQ(l.diags().error_count(), 7u) << l.Messages();
  // the seven errors, counted above: five missing children, two bad values
  l.ExpectDiagnostic(DiagKind::MissingElement, "needs a <drake:linear_spring_damper_");
  l.ExpectDiagnostic(DiagKind::BadValue, "");
  EXPECT_TRUE(l.module().force_elements.empty());
}

// ---------------------------------------------------------- EXT-052..054

class DrakeConstraintTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeConstraintTest);

const std::vector<Child> kBall = {
    {"drake:ball_constraint_body_A", "a", Child::kName},
    {"drake:ball_constraint_body_B", "c", Child::kName},
    {"drake:ball_constraint_p_AP", "1 2 3"},
    {"drake:ball_constraint_p_BQ", "4 5 6"},
};

TEST_P(DrakeConstraintTest, BallLowersBodiesAndPoints) {  // EXT-052
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:ball_constraint", kBall, format()), format())))
      << l.Messages();
  ir::Module& m = l.module();
  ASSERT_EQ(m.constraints.size(), 1u);
  ASSERT_EQ(m.constraints[0].type(), ir::ConstraintType::Ball);
  const auto& c = m.constraints[0].As<ir::BallConstraint>();
  EXPECT_EQ(m.Text(c.body_A.name), "a");
  EXPECT_EQ(m.Text(c.body_B.name), "c");
  EXPECT_EQ(c.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c.p_BQ, Eigen::Vector3d(4, 5, 6));
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
}

TEST_P(DrakeConstraintTest, BallNeedsEveryChild) {  // EXT-052
  const Broken cases[] = {
      {"drake:ball_constraint_body_A", std::nullopt, DiagKind::MissingElement,
       "<drake:ball_constraint> needs a <drake:ball_constraint_body_A> child"},
      {"drake:ball_constraint_body_B", std::nullopt, DiagKind::MissingElement,
       "<drake:ball_constraint> needs a <drake:ball_constraint_body_B> child"},
      {"drake:ball_constraint_p_BQ", std::nullopt, DiagKind::MissingElement,
       "<drake:ball_constraint> needs a <drake:ball_constraint_p_BQ> child"},
      {"drake:ball_constraint_p_BQ", "4 5 6 7", DiagKind::BadValue, "must hold 3 numbers"},
  };
  for (const Broken& b : cases) ExpectRejected(format(), "drake:ball_constraint", kBall, b);
}

TEST_P(DrakeConstraintTest, BallUnknownOrIdenticalBodiesAreErrors) {  // EXT-052
  {
    std::vector<Child> children = kBall;
    children[1].text = "zz";
    Lowering l(format());
    ASSERT_TRUE(l.Read(Model(Element("drake:ball_constraint", children, format()), format())))
        << l.Messages();
    EXPECT_FALSE(l.RunPasses());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownReference,
                                "unknown link 'zz': Could not find link 'zz'"))
        << l.Messages();
    ASSERT_EQ(l.diags().diagnostics().size(), 1u) << l.Messages();
    EXPECT_EQ(l.diags().diagnostics()[0].loc.line, 10u);  // at body_B's name
  }
  {
    std::vector<Child> children = kBall;
    children[1].text = "a";
    Lowering l(format());
    ASSERT_TRUE(l.Read(Model(Element("drake:ball_constraint", children, format()), format())))
        << l.Messages();
    EXPECT_FALSE(l.RunPasses());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "two distinct bodies")) << l.Messages();
  }
}

TEST_P(DrakeConstraintTest, UnknownAndRepeatedChildrenAreWarnings) {  // EXT-050..054
  std::vector<Child> children = kBall;
  children.push_back({"drake:ball_constraint_p_AP", "9 9 9"});
  children.push_back({"drake:extra", "<drake:extra/>", Child::kAsIs});
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:ball_constraint", children, format()), format())))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "unknown element <drake:extra> in <drake:ball_constraint>"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement,
                              "<drake:ball_constraint_p_AP> is repeated in "
                              "<drake:ball_constraint>; only the first one is used"));
  EXPECT_EQ(l.module().constraints.at(0).As<ir::BallConstraint>().p_AP,
            Eigen::Vector3d(1, 2, 3));  // Drake: the first
}

const std::vector<Child> kDistance = {
    {"drake:distance_constraint_body_A", "a", Child::kName},
    {"drake:distance_constraint_p_AP", "1 2 3"},
    {"drake:distance_constraint_body_B", "c", Child::kName},
    {"drake:distance_constraint_p_BQ", "4 5 6"},
    {"drake:distance_constraint_distance", "0.5"},
    {"drake:distance_constraint_stiffness", "100"},
    {"drake:distance_constraint_damping", "0"},
};

TEST_P(DrakeConstraintTest, DistanceLowersEveryParameter) {  // EXT-053
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:distance_constraint", kDistance, format()), format())))
      << l.Messages();
  ir::Module& m = l.module();
  ASSERT_EQ(m.constraints.size(), 1u);
  ASSERT_EQ(m.constraints[0].type(), ir::ConstraintType::Distance);
  const auto& c = m.constraints[0].As<ir::DistanceConstraint>();
  EXPECT_EQ(m.Text(c.body_A.name), "a");
  EXPECT_EQ(m.Text(c.body_B.name), "c");
  EXPECT_EQ(c.p_AP, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(c.p_BQ, Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(c.distance, 0.5);
  EXPECT_EQ(c.stiffness, 100);
  EXPECT_EQ(c.damping, 0);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
}

TEST_P(DrakeConstraintTest, DistanceWithInfiniteStiffnessIsRigid) {  // EXT-053
  std::vector<Child> children = kDistance;
  children[5].text = "inf";
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:distance_constraint", children, format()), format())))
      << l.Messages();
  EXPECT_EQ(l.module().constraints.at(0).As<ir::DistanceConstraint>().stiffness, kInf);
}

TEST_P(DrakeConstraintTest, DistanceNeedsEveryChildAndCheckedValues) {  // EXT-053
  const Broken cases[] = {
      {"drake:distance_constraint_distance", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:distance_constraint_distance> child"},
      {"drake:distance_constraint_stiffness", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:distance_constraint_stiffness> child"},
      {"drake:distance_constraint_damping", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:distance_constraint_damping> child"},
      {"drake:distance_constraint_body_B", std::nullopt, DiagKind::MissingElement,
       "needs a <drake:distance_constraint_body_B> child"},
      {"drake:distance_constraint_distance", "0", DiagKind::BadValue,
       "<drake:distance_constraint_distance> must be positive"},
      {"drake:distance_constraint_stiffness", "0", DiagKind::BadValue,
       "<drake:distance_constraint_stiffness> must be positive"},
      {"drake:distance_constraint_damping", "-1", DiagKind::BadValue,
       "<drake:distance_constraint_damping> must be non-negative"},
      {"drake:distance_constraint_distance", "inf", DiagKind::BadValue, "must be finite"},
  };
  for (const Broken& b : cases) {
    ExpectRejected(format(), "drake:distance_constraint", kDistance, b);
  }
}

// the joints are attributes in both spellings (Drake reads them so from both)
const std::vector<Child> kTendon = {
    {"joint rev", "<drake:tendon_constraint_joint name='rev' a='10'/>",
     Child::kAsIs},
    {"joint pri", "<drake:tendon_constraint_joint name='pri' a='-20'/>",
     Child::kAsIs},
    {"drake:tendon_constraint_offset", "0.3"},
    {"drake:tendon_constraint_lower_limit", "-5"},
    {"drake:tendon_constraint_upper_limit", "5"},
    {"drake:tendon_constraint_stiffness", "0.4"},
    {"drake:tendon_constraint_damping", "0.09"},
};

TEST_P(DrakeConstraintTest, TendonLowersJointsCoefficientsAndParameters) {  // EXT-054
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(Element("drake:tendon_constraint", kTendon, format()), format())))
      << l.Messages();
  ir::Module& m = l.module();
  ASSERT_EQ(m.constraints.size(), 1u);
  ASSERT_EQ(m.constraints[0].type(), ir::ConstraintType::Tendon);
  const auto& c = m.constraints[0].As<ir::TendonConstraint>();
  ASSERT_EQ(c.joints.size(), 2u);
  EXPECT_EQ(m.Text(c.joints[0].name), "rev");
  EXPECT_EQ(m.Text(c.joints[1].name), "pri");
  EXPECT_EQ(c.a, (std::vector<double>{10, -20}));
  EXPECT_EQ(c.offset, 0.3);
  EXPECT_EQ(c.lower, -5);
  EXPECT_EQ(c.upper, 5);
  EXPECT_EQ(c.stiffness, 0.4);
  EXPECT_EQ(c.damping, 0.09);
  ASSERT_TRUE(l.RunPasses()) << l.Messages();
  // check-joints rebuilds the table
  const auto& resolved = m.constraints[0].As<ir::TendonConstraint>();
  EXPECT_EQ(m[resolved.joints[0].id].name, m.Intern("rev"));
  EXPECT_EQ(m[resolved.joints[1].id].name, m.Intern("pri"));
}

TEST_P(DrakeConstraintTest, TendonOptionalParametersTakeAddTendonConstraintDefaults) {  // EXT-054
  // AddTendonConstraint: offset 0, limits -inf/+inf, stiffness +inf, damping 0;
  // one finite bound is required
  Lowering l(format());
  ASSERT_TRUE(l.Read(Model(
      Element("drake:tendon_constraint",
              {kTendon[0], {"drake:tendon_constraint_upper_limit", "0.5"}}, format()),
      format())))
      << l.Messages();
  const auto& c = l.module().constraints.at(0).As<ir::TendonConstraint>();
  EXPECT_EQ(c.offset, 0);
  EXPECT_EQ(c.lower, -kInf);
  EXPECT_EQ(c.upper, 0.5);
  EXPECT_EQ(c.stiffness, kInf);
  EXPECT_EQ(c.damping, 0);
}

TEST_P(DrakeConstraintTest, TendonRejectsWhatAddTendonConstraintRejects) {  // EXT-054
  const std::vector<Child> tendon = {
      {"joint rev", "<drake:tendon_constraint_joint name='rev' a='1'/>",
       Child::kAsIs},
      {"drake:tendon_constraint_lower_limit", "-1"},
      {"drake:tendon_constraint_upper_limit", "1"},
      {"drake:tendon_constraint_stiffness", "3"},
      {"drake:tendon_constraint_damping", "4"},
  };
  const Broken cases[] = {
      {"joint rev", std::nullopt, DiagKind::MissingElement,
       "needs at least one <drake:tendon_constraint_joint>"},
      {"joint rev", "<drake:tendon_constraint_joint a='1'/>",
       DiagKind::MissingAttribute, "<drake:tendon_constraint_joint> needs a name"},
      {"joint rev", "<drake:tendon_constraint_joint name='rev'/>",
       DiagKind::MissingAttribute, "<drake:tendon_constraint_joint> needs its 'a' attribute"},
      {"joint rev", "<drake:tendon_constraint_joint name='rev' a='inf'/>",
       DiagKind::BadValue, "must be finite"},
      {"drake:tendon_constraint_lower_limit", "2", DiagKind::BadValue,
       "greater than upper limit"},
      {"drake:tendon_constraint_lower_limit", "inf", DiagKind::BadValue, "must be finite or -inf"},
      {"drake:tendon_constraint_upper_limit", "-inf", DiagKind::BadValue, "must be finite or inf"},
      {"drake:tendon_constraint_stiffness", "0", DiagKind::BadValue, "must be positive"},
      {"drake:tendon_constraint_damping", "-4", DiagKind::BadValue, "must be non-negative"},
      {"drake:tendon_constraint_damping", "nan", DiagKind::BadValue, "not NaN"},
  };
  for (const Broken& b : cases) ExpectRejected(format(), "drake:tendon_constraint", tendon, b);

  // neither bound
  Lowering l(format());
  EXPECT_FALSE(l.Read(Model(
      Element("drake:tendon_constraint", {tendon[0], tendon[3], tendon[4]}, format()), format())));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "needs a finite bound")) << l.Messages();
  EXPECT_TRUE(l.module().constraints.empty());
}

// ------------------------------------------ EXT-001, EXT-003, EXT-004: drake:joint

class DrakeJointSpellingTest : public DrakeSpellingTest {};
MDLC_BOTH_SPELLINGS(DrakeJointSpellingTest);

/// <drake:joint> `name` of `type` from link d to link e with `children`:
/// URDF names the links as its <joint> does (<parent link='d'/>), SDFormat
/// in <drake:parent> and <drake:child>.
std::string DrakeJoint(std::string_view name, std::string_view type, std::string_view children,
                       Format format) {
  const std::string links = format == Format::Urdf
                                ? "<parent link='d'/><child link='e'/>"
                                : "<drake:parent>d</drake:parent><drake:child>e</drake:child>";
  return fmt::format("<drake:joint name='{}' type='{}'>{}{}</drake:joint>", name, type, links,
                     children);
}
/// The joint's damping: URDF's <dynamics damping=...>, SDFormat's <drake:damping>.
std::string JointDamping(std::string_view values, Format format) {
  return format == Format::Urdf ? fmt::format("<dynamics damping='{}'/>", values)
                                : DrakeValue("drake:damping", values, format);
}
/// A path segment: URDF writes its numbers in attributes, SDFormat in
/// child elements.
std::string LineSegment(std::string_view length, Format format) {
  return format == Format::Urdf
             ? fmt::format("<drake:line_segment length='{}'/>", length)
             : fmt::format("<drake:line_segment><drake:length>{}</drake:length></drake:line_segment>",
                           length);
}
std::string CircularArc(std::string_view radius, std::string_view angle, Format format) {
  return format == Format::Urdf
             ? fmt::format("<drake:circular_arc radius='{}' angle='{}'/>", radius, angle)
             : fmt::format("<drake:circular_arc><drake:radius>{}</drake:radius>"
                           "<drake:angle>{}</drake:angle></drake:circular_arc>",
                           radius, angle);
}
/// A direction of the path's plane: URDF's @xyz, SDFormat's <xyz> child.
std::string PathDirection(std::string_view tag, std::string_view xyz, Format format) {
  return format == Format::Urdf ? fmt::format("<{} xyz='{}'/>", tag, xyz)
                                : fmt::format("<{0}><xyz>{1}</xyz></{0}>", tag, xyz);
}

TEST_P(DrakeJointSpellingTest, PlanarJointBetweenLinks) {  // EXT-001, EXT-004
  Lowering l(format());
  ASSERT_TRUE(l.Read(
      Model(DrakeJoint("p", "planar", JointDamping("0.1 0.2 0.3", format()), format()), format())))
      << l.Messages();
  const ir::Joint* j = l.Joint("p");
  ASSERT_NE(j, nullptr);
  EXPECT_EQ(j->type, ir::JointType::Planar);
  EXPECT_EQ(ir::JointPositionCount(j->type), 3);
  EXPECT_EQ(l.module().Text(j->parent.name), "d");
  EXPECT_EQ(l.module().Text(j->child.name), "e");
  EXPECT_EQ(j->damping, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(j->limits.lower, (std::vector<double>{-kInf, -kInf, -kInf}));
  EXPECT_EQ(j->limits.upper, (std::vector<double>{kInf, kInf, kInf}));
}

TEST_P(DrakeJointSpellingTest, CurvilinearPathDefaultsAndSegments) {  // EXT-001, EXT-003
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(Model(
      DrakeJoint("cv", "curvilinear",
                 JointDamping("0.1", f) + "<drake:curves>" + LineSegment("1.0", f) +
                     CircularArc("2.0", "1.5707963267948966", f) + CircularArc("0.5", "-3", f) +
                     "</drake:curves>",
                 f),
      f)))
      << l.Messages();
  const ir::Joint* c = l.Joint("cv");
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->type, ir::JointType::Curvilinear);
  EXPECT_EQ(ir::JointPositionCount(c->type), 1);
  EXPECT_EQ(ir::JointVelocityCount(c->type), 1);
  const ir::CurvilinearPath& path = c->curvilinear_path;
  EXPECT_EQ(path.plane_normal, Eigen::Vector3d::UnitZ());
  EXPECT_EQ(path.initial_tangent, Eigen::Vector3d::UnitX());
  EXPECT_FALSE(path.periodic);
  ASSERT_EQ(path.segments.size(), 3u);
  EXPECT_EQ(path.segments[0].length, 1.0);
  EXPECT_EQ(path.segments[0].curvature, 0.0);
  EXPECT_DOUBLE_EQ(path.segments[1].length, kPi);  // radius * |angle|
  EXPECT_DOUBLE_EQ(path.segments[1].curvature, 0.5);
  EXPECT_DOUBLE_EQ(path.segments[2].length, 1.5);
  EXPECT_DOUBLE_EQ(path.segments[2].curvature, -2.0);  // a negative angle turns right
  EXPECT_EQ(c->damping, (std::vector<double>{0.1}));
  // Drake limits an open path's joint to the path's ends
  EXPECT_EQ(c->limits.lower[0], 0.0);
  EXPECT_DOUBLE_EQ(c->limits.upper[0], 1.0 + kPi + 1.5);
  EXPECT_EQ(c->limits.velocity_upper[0], kInf);
}

TEST_P(DrakeJointSpellingTest, CurvilinearPathInAGivenPlane) {  // EXT-003
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(Model(
      DrakeJoint("cv", "curvilinear",
                 PathDirection("drake:initial_tangent", "0 0 1", f) +
                     PathDirection("drake:plane_normal", "1 0 0", f) +
                     DrakeValue("drake:is_periodic", "false", f) + "<drake:curves>" +
                     LineSegment("1.0", f) + CircularArc("2.0", "1.5707963267948966", f) +
                     CircularArc("2.0", "-1.5707963267948966", f) + "</drake:curves>",
                 f),
      f)))
      << l.Messages();
  const ir::Joint* j = l.Joint("cv");
  ASSERT_NE(j, nullptr);
  const ir::CurvilinearPath& path = j->curvilinear_path;
  EXPECT_EQ(path.initial_tangent, Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(path.plane_normal, Eigen::Vector3d(1, 0, 0));
  EXPECT_FALSE(path.periodic);
  ASSERT_EQ(path.segments.size(), 3u);
  EXPECT_DOUBLE_EQ(path.segments[1].length, kPi);
  EXPECT_DOUBLE_EQ(path.segments[1].curvature, 0.5);
  EXPECT_DOUBLE_EQ(path.segments[2].curvature, -0.5);
  EXPECT_DOUBLE_EQ(path.TotalLength(), 1 + 2 * kPi);
  EXPECT_DOUBLE_EQ(j->limits.lower[0], 0.0);
  EXPECT_DOUBLE_EQ(j->limits.upper[0], 1.0 + 2 * kPi);
}

TEST_P(DrakeJointSpellingTest, PeriodicCurvilinearPathIsUnlimited) {  // EXT-003
  const Format f = format();
  Lowering l(f);
  ASSERT_TRUE(l.Read(Model(DrakeJoint("cv", "curvilinear",
                                      DrakeValue("drake:is_periodic", "true", f) +
                                          "<drake:curves>" +
                                          CircularArc("1", "6.283185307179586", f) +
                                          "</drake:curves>",
                                      f),
                           f)))
      << l.Messages();
  const ir::Joint* j = l.Joint("cv");
  ASSERT_NE(j, nullptr);
  EXPECT_TRUE(j->curvilinear_path.periodic);
  EXPECT_EQ(j->limits.lower[0], -kInf);
  EXPECT_EQ(j->limits.upper[0], kInf);
}

}  // namespace
}  // namespace mdlc::drake_spellings
