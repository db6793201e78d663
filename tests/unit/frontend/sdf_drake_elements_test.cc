// The SDFormat frontend's drake: elements: what each lowers to and which
// inputs it rejects, where SDFormat differs from URDF, and what reaches the
// plant (EXT-001, EXT-003, EXT-004, EXT-010, EXT-012..014, EXT-040, EXT-050,
// EXT-053, EXT-070, SDF-021). What both formats share is tested in both
// spellings in drake_spellings_test.cc.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/unit/sdf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc {
namespace {

using testing::Named;
using testing::SdfCompileResult;
using testing::SdfFrontendResult;

// links a..d, a revolute joint a->b, and `body`
std::string SdfModel(std::string_view body) {
  return fmt::format(R"(<model name='m'>
  <link name='a'/><link name='b'/><link name='c'/><link name='d'/>
  <joint name='rev' type='revolute'><parent>a</parent><child>b</child>
    <axis><xyz>0 0 1</xyz></axis></joint>
  <frame name='fa' attached_to='a'><pose>0 0 1 0 0 0</pose></frame>
{}
</model>)",
                     body);
}

// ------------------------------------------------------- EXT-001, EXT-004

// SDFormat's <drake:joint> has no <axis>: its frames are the links' frames
TEST(SdfDrakeJointTest, PlanarFramesAreTheLinksFrames) {  // EXT-001, EXT-004
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfModel(R"(<drake:joint name='p' type='planar'>
    <drake:parent>b</drake:parent><drake:child>c</drake:child>
    <drake:damping>0.1 0.2 0.3</drake:damping>
  </drake:joint>)")))
      << l.Messages();
  const ir::Joint* j = l.Joint("p");
  ASSERT_NE(j, nullptr);
  EXPECT_TRUE(j->X_PF.IsIdentity());  // F is the parent link's frame
  EXPECT_TRUE(j->X_CM.IsIdentity());  // M is the child link's frame
}

TEST(SdfDrakeJointTest, PlanarNeedsThreeNonNegativeDampings) {  // EXT-004
  for (const char* damping : {"", "<drake:damping>0.1 -0.2 0.3</drake:damping>",
                              "<drake:damping>0.1 0.2</drake:damping>"}) {
    SdfFrontendResult l;
    EXPECT_FALSE(l.Read(SdfModel(fmt::format(R"(<drake:joint name='p' type='planar'>
      <drake:parent>b</drake:parent><drake:child>c</drake:child>{}</drake:joint>)",
                                             damping))))
        << damping;
    EXPECT_EQ(l.Joint("p"), nullptr);
    EXPECT_EQ(l.diags.error_count(), 1u) << l.Messages();
    // the one error, counted above: a missing child, or a bad value
    l.ExpectDiagnostic(*damping ? DiagKind::BadValue : DiagKind::MissingElement, "");
  }
  SdfFrontendResult missing;
  missing.Read(SdfModel(R"(<drake:joint name='p' type='planar'>
      <drake:parent>b</drake:parent><drake:child>c</drake:child></drake:joint>)"));
  EXPECT_TRUE(missing.HasDiagnostic(DiagKind::MissingElement, "<drake:joint> needs a <drake:damping> child"))
      << missing.Messages();
}

// A <drake:joint> shares its model's joint namespace (COMMON-023): a name an
// SDFormat joint or an earlier <drake:joint> holds is an error, whose note
// points at the first holder; a nested model's joints are its own.
TEST(SdfDrakeJointTest, NameTakenByAJointOfTheModelIsAnError) {  // EXT-001, COMMON-023
  auto planar = [](std::string_view name, std::string_view parent, std::string_view child) {
    return fmt::format(
        "<drake:joint name='{}' type='planar'><drake:parent>{}</drake:parent>"
        "<drake:child>{}</drake:child><drake:damping>0 0 0</drake:damping></drake:joint>\n",
        name, parent, child);
  };
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(SdfModel(planar("rev", "c", "d") + planar("p", "b", "c") +
                               planar("p", "c", "d") +
                               "<model name='n'><link name='x'/><link name='y'/>" +
                               planar("p", "x", "y") + "</model>")));
  EXPECT_EQ(l.diags.error_count(), 2u) << l.Messages();
  size_t notes = 0;
  for (const Diagnostic& d : l.diags.diagnostics()) {
    ASSERT_EQ(d.notes.size(), 1u) << d.message;
    // the SDFormat joint 'rev' on line 5, the first <drake:joint> 'p' on line 9
    const bool rev = d.message.find("'rev'") != std::string::npos;
    EXPECT_EQ(d.notes[0].loc.line, rev ? 5u : 9u) << d.message;
    EXPECT_EQ(d.loc.line, rev ? 8u : 10u) << d.message;
    ++notes;
  }
  EXPECT_EQ(notes, 2u);
  l.ExpectDiagnostic(DiagKind::DuplicateName,
                     "the joint name 'rev' is already used by a joint of this model");
  l.ExpectDiagnostic(DiagKind::DuplicateName,
                     "the joint name 'p' is already used by a joint of this model");
  size_t named_p = 0;
  for (const ir::Joint& j : l.module.joints) named_p += l.module.Text(j.name) == "p";
  EXPECT_EQ(named_p, 2u);  // model m's first, and nested model n's own
}

TEST(SdfDrakeJointTest, CurvilinearErrors) {  // EXT-003
  struct Case {
    const char* body;
    const char* message;
  };
  const std::string line = "<drake:line_segment><drake:length>1</drake:length></drake:line_segment>";
  const Case cases[] = {
      {"", "needs a <drake:curves> child"},
      {"<drake:curves/>", "empty <drake:curves> list"},
      {"<drake:curves><drake:line_segment/></drake:curves>",
       "<drake:line_segment> needs a <drake:length> child"},
      {"<drake:curves><drake:line_segment><drake:length>0</drake:length></drake:line_segment>"
       "</drake:curves>",
       "<drake:length> must be positive, got '0'"},
      {"<drake:curves><drake:circular_arc><drake:radius>-2</drake:radius><drake:angle>1"
       "</drake:angle></drake:circular_arc></drake:curves>",
       "<drake:radius> must be positive, got '-2'"},
      {"<drake:curves><drake:circular_arc><drake:radius>2</drake:radius><drake:angle>0"
       "</drake:angle></drake:circular_arc></drake:curves>",
       "<drake:angle> of a <drake:circular_arc> must not be zero"},
      {"<drake:curves><drake:cirQQQcular_arc/></drake:curves>", "is not a path segment"},
      {"<drake:is_periodic>TRUE</drake:is_periodic>LINE", "<drake:is_periodic> must be true or false"},
      {"<drake:damping>-1</drake:damping>LINE", "<drake:damping> must be non-negative, got '-1'"},
      {"<drake:plane_normal><xyz>0 0 0</xyz></drake:plane_normal>LINE", "is zero"},
      {"<drake:initial_tangent><xyz>0 1 1</xyz></drake:initial_tangent>LINE",
       "not perpendicular"},
  };
  for (const Case& c : cases) {
    std::string body = c.body;
    if (auto at = body.find("LINE"); at != std::string::npos) {
      body.replace(at, 4, "<drake:curves>" + line + "</drake:curves>");
    }
    SdfFrontendResult l;
    EXPECT_FALSE(l.Read(SdfModel(fmt::format(R"(<drake:joint name='cv' type='curvilinear'>
      <drake:parent>b</drake:parent><drake:child>c</drake:child>{}</drake:joint>)",
                                             body))))
        << c.body;
    l.ExpectError(c.message);
    bool found = false;
    for (const auto& d : l.diags.diagnostics()) {
      found |= d.severity == Severity::Error && d.message.find(c.message) != std::string::npos;
      EXPECT_TRUE(d.loc.valid()) << d.message;
    }
    EXPECT_TRUE(found) << c.body << "\n" << l.Messages();
    EXPECT_EQ(l.Joint("cv"), nullptr) << c.body;
  }
}

TEST(SdfDrakeJointTest, AttributeTypePoseAndFrameErrors) {  // EXT-001
  struct Case {
    const char* element;
    DiagKind kind;
    const char* message;
  };
  const Case cases[] = {
      {"<drake:joint name='j'/>", DiagKind::MissingAttribute,
       "<drake:joint> needs a 'type' attribute"},
      {"<drake:joint type='planar'/>", DiagKind::MissingAttribute,
       "<drake:joint> needs a name"},
      {"<drake:joint name='j' type='planar'><pose/></drake:joint>", DiagKind::NotImplemented,
       "<pose> in <drake:joint> is not supported yet"},
      {"<drake:joint name='j' type='ball'><drake:parent>a</drake:parent>"
       "<drake:child>c</drake:child></drake:joint>",
       DiagKind::BadValue, "has unknown type 'ball'"},
      {"<drake:joint name='j' type='planar'><drake:child>c</drake:child>"
       "<drake:damping>0 0 0</drake:damping></drake:joint>",
       DiagKind::MissingElement, "<drake:joint> needs a <drake:parent> child"},
      {"<drake:joint name='rev' type='planar'><drake:parent>c</drake:parent>"
       "<drake:child>d</drake:child><drake:damping>0 0 0</drake:damping></drake:joint>",
       DiagKind::DuplicateName, "joint name 'rev' is already used"},
  };
  for (const Case& c : cases) {
    SdfFrontendResult l;
    EXPECT_FALSE(l.Read(SdfModel(c.element))) << c.element;
    EXPECT_TRUE(l.HasDiagnostic(c.kind, c.message)) << c.element << "\n" << l.Messages();
  }
}

TEST(SdfDrakeJointTest, DrakePoseIsAnUnsupportedElement) {  // EXT-001, SDF-001
  SdfFrontendResult l;
  EXPECT_TRUE(l.Read(SdfModel(R"(<drake:joint name='p' type='planar'>
    <drake:parent>b</drake:parent><drake:child>c</drake:child>
    <drake:damping>0 0 0</drake:damping><drake:pose>1 0 0 0 0 0</drake:pose>
  </drake:joint>)")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "unknown element <drake:pose>"));
}

TEST(SdfDrakeJointTest, CompilesWithNestedLinksAndPlacesTheChildOnTheParent) {  // EXT-001
  // Drake's DrakeJointNestedParentChild: scoped names into a nested model;
  // the joint's frames are the links' frames, so at q = 0 the child link
  // sits exactly on the parent link, whatever the links' SDFormat poses
  SdfCompileResult c(R"(<model name='good'>
  <model name='nested'>
    <link name='a'><pose>1 2 3 0 0 0</pose></link>
    <link name='b'><pose>-5 0 0 0 0 0</pose></link>
  </model>
  <drake:joint type='planar' name='joint_name'>
    <drake:parent>nested::a</drake:parent>
    <drake:child>nested::b</drake:child>
    <drake:damping>0.1 0.1 0.1</drake:damping>
  </drake:joint>
</model>)");
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json json = c.PlantJson();
  const nlohmann::json joint = Named(json["joints"], "joint_name");
  ASSERT_FALSE(joint.is_null()) << json.dump(1);
  EXPECT_EQ(joint["type"], "planar");
  EXPECT_EQ(joint["parent"], "good::nested::a");
  EXPECT_EQ(joint["child"], "good::nested::b");
  EXPECT_EQ(joint["damping"], nlohmann::json({0.1, 0.1, 0.1}));
  const nlohmann::json a = Named(json["bodies"], "a"), b = Named(json["bodies"], "b");
  EXPECT_EQ(a["X_WB"], b["X_WB"]);
  EXPECT_EQ(a["X_WB"]["p"], nlohmann::json({1.0, 2.0, 3.0}));
}

// ------------------------------------------------------------- EXT-040

// a member's text is trimmed and may be a scoped name; ignore='1' skips a
// group as 'true' does (an SDFormat boolean; URDF skips on 'true' only)
TEST(SdfCollisionFilterGroupTest, MemberTextIsTrimmedAndIgnoreIsABoolean) {  // EXT-040
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(SdfModel(R"(<drake:collision_filter_group name='g'>
    <drake:member>a</drake:member>
    <drake:member> nested::x </drake:member>
  </drake:collision_filter_group>
  <drake:collision_filter_group name='skipped' ignore='1'><drake:member>c</drake:member></drake:collision_filter_group>)")))
      << l.Messages();
  ASSERT_EQ(l.module.filter_groups.size(), 1u);
  const ir::CollisionFilterGroup& g = l.module.filter_groups[0];
  ASSERT_EQ(g.members.size(), 2u);
  EXPECT_EQ(l.module.Text(g.members[0].name), "a");
  EXPECT_EQ(l.module.Text(g.members[1].name), "nested::x");  // trimmed, scoped
}

TEST(SdfCollisionFilterGroupTest, FiltersPairsInThePlant) {  // EXT-040, COMMON-051
  SdfCompileResult c(SdfModel(R"(<drake:collision_filter_group name='g'>
    <drake:member>c</drake:member><drake:member>d</drake:member>
    <drake:ignored_collision_filter_group>g</drake:ignored_collision_filter_group>
  </drake:collision_filter_group>)"));
  ASSERT_TRUE(c.ok()) << c.Messages();
  EXPECT_EQ(c.compilation().module.filter_groups.size(), 1u);
  for (const auto& ref : c.compilation().module.filter_groups[0].members) {
    EXPECT_TRUE(ref.resolved());
  }
}

TEST(SdfCollisionFilterGroupTest, UnknownMemberIsReportedByResolveNames) {  // COMMON-053
  SdfCompileResult c(SdfModel(R"(<drake:collision_filter_group name='g'>
    <drake:member>nope</drake:member></drake:collision_filter_group>)"));
  EXPECT_FALSE(c.ok());
  EXPECT_NE(c.Messages().find("not found"), std::string::npos) << c.Messages();
  c.ExpectDiagnostic(DiagKind::UnknownReference, "");  // its text is checked above
}

// ------------------------------------------------------------- EXT-050

TEST(SdfForceElementTest, LinearBushingRpyReachesThePlant) {  // EXT-050
  SdfCompileResult c(SdfModel(R"(<drake:linear_bushing_rpy>
    <drake:bushing_frameA>fa</drake:bushing_frameA>
    <drake:bushing_frameC>c</drake:bushing_frameC>
    <drake:bushing_torque_stiffness>1 2 3</drake:bushing_torque_stiffness>
    <drake:bushing_torque_damping>4 5 6</drake:bushing_torque_damping>
    <drake:bushing_force_stiffness>7 8 9</drake:bushing_force_stiffness>
    <drake:bushing_force_damping>10 11 12</drake:bushing_force_damping>
  </drake:linear_bushing_rpy>)"));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json json = c.PlantJson();
  ASSERT_EQ(json["force_elements"].size(), 1u) << json.dump(1);
  EXPECT_EQ(json["force_elements"][0]["type"], "linear_bushing_rpy");
  EXPECT_EQ(json["force_elements"][0]["frameA"], "m::fa");
  EXPECT_EQ(json["force_elements"][0]["frameC"], "m::c");
}

// ------------------------------------------------------------- EXT-053

TEST(SdfConstraintTest, DistanceConstraintReachesThePlant) {  // EXT-053
  SdfCompileResult c(SdfModel(R"(<drake:distance_constraint>
    <drake:distance_constraint_body_A>a</drake:distance_constraint_body_A>
    <drake:distance_constraint_body_B>c</drake:distance_constraint_body_B>
    <drake:distance_constraint_p_AP>1 2 3</drake:distance_constraint_p_AP>
    <drake:distance_constraint_p_BQ>4 5 6</drake:distance_constraint_p_BQ>
    <drake:distance_constraint_distance>0.5</drake:distance_constraint_distance>
    <drake:distance_constraint_stiffness>inf</drake:distance_constraint_stiffness>
    <drake:distance_constraint_damping>3</drake:distance_constraint_damping>
  </drake:distance_constraint>)"));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json json = c.PlantJson();
  ASSERT_EQ(json["constraints"].size(), 1u);
  const nlohmann::json& d = json["constraints"][0];
  EXPECT_EQ(d["type"], "distance");
  EXPECT_EQ(d["body_A"], "m::a");
  EXPECT_EQ(d["body_B"], "m::c");
  EXPECT_EQ(d["distance"], 0.5);
  EXPECT_TRUE(d["stiffness"].is_null());  // +inf: rigid
  EXPECT_EQ(d["damping"], 3);
}

TEST(SdfDrakeModelElementTest, UnknownDrakeElementWarns) {  // SDF-001
  SdfFrontendResult l;
  EXPECT_TRUE(l.Read(SdfModel("<drake:flux_capacitor/>"))) << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnknownElement, "<drake:flux_capacitor>"));
}

// ------------------------------------------- EXT-010, EXT-012..014, SDF-021

std::string JointModel(std::string_view extra, std::string_view effort = "") {
  return fmt::format(R"(<model name='m'>
  <link name='a'/><link name='b'/><link name='c'/>
  <joint name='j1' type='revolute'><parent>a</parent><child>b</child>
    <axis><xyz>0 0 1</xyz>{}</axis>{}</joint>
  <joint name='j2' type='revolute'><parent>b</parent><child>c</child>
    <axis><xyz>0 0 1</xyz></axis></joint>
</model>)",
                     effort, extra);
}

TEST(SdfJointDrakeChildrenTest, ActuatorParameters) {  // SDF-021, EXT-012..014
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(JointModel(R"(
    <drake:rotor_inertia>1.5</drake:rotor_inertia>
    <drake:gear_ratio>300</drake:gear_ratio>
    <drake:controller_gains p='10000' d='100'/>)")))
      << l.Messages();
  ASSERT_EQ(l.module.actuators.size(), 2u);
  const ir::Actuator& a = l.module.actuators[0];
  EXPECT_EQ(l.module.Text(a.name), "j1");
  EXPECT_EQ(a.rotor_inertia, 1.5);
  EXPECT_EQ(a.gear_ratio, 300);
  EXPECT_EQ(a.kp, 10000);
  EXPECT_EQ(a.kd, 100);
  EXPECT_FALSE(l.module.actuators[1].kp.has_value());
}

TEST(SdfJointDrakeChildrenTest, ActuatorParameterErrors) {  // EXT-012..014
  SdfFrontendResult l;
  EXPECT_FALSE(l.Read(JointModel(R"(
    <drake:rotor_inertia>-1</drake:rotor_inertia>
    <drake:gear_ratio>x</drake:gear_ratio>
    <drake:controller_gains p='0'/>)")));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "rotor inertia given by <drake:rotor_inertia> "
                                                  "must be non-negative"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "<drake:gear_ratio> must hold a number"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::MissingAttribute,
                              "<drake:controller_gains> needs attribute 'd'"));
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::BadValue, "proportional gain 'p'"));
  const ir::Actuator& a = l.module.actuators[0];
  EXPECT_EQ(a.rotor_inertia, 0);
  EXPECT_EQ(a.gear_ratio, 1);
  EXPECT_FALSE(a.kp.has_value());
}

TEST(SdfJointDrakeChildrenTest, NoActuatorIgnoresTheParameters) {  // SDF-020, SDF-021
  // effort 0: no actuator, and Drake ignores the actuator parameters
  SdfFrontendResult l;
  EXPECT_TRUE(l.Read(JointModel("<drake:gear_ratio>3</drake:gear_ratio>",
                                "<limit><effort>0</effort></limit>")))
      << l.Messages();
  EXPECT_EQ(l.module.actuators.size(), 1u);  // j2's only
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::ActuatorWarning, "has no actuator"));
}

TEST(SdfJointDrakeChildrenTest, ReflectedInertiaInPlantJson) {  // EXT-012, EXT-013
  SdfCompileResult c(JointModel(R"(
    <drake:rotor_inertia>0.5</drake:rotor_inertia>
    <drake:gear_ratio>2</drake:gear_ratio>)"));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json json = c.PlantJson();
  const nlohmann::json a = Named(json["actuators"], "j1");
  EXPECT_EQ(a["rotor_inertia"], 0.5);
  EXPECT_EQ(a["gear_ratio"], 2);
  EXPECT_EQ(json["dofs"][0], "m::j1");
  EXPECT_DOUBLE_EQ(json["reflected_inertia"][0].get<double>(), 2.0);
}

TEST(SdfJointDrakeChildrenTest, MimicIsACouplerConstraint) {  // EXT-010
  SdfFrontendResult l;
  ASSERT_TRUE(l.Read(JointModel("<drake:mimic joint='j2' multiplier='2' offset='0.5'/>")))
      << l.Messages();
  ASSERT_EQ(l.module.constraints.size(), 1u);
  ASSERT_EQ(l.module.constraints[0].type(), ir::ConstraintType::Coupler);
  const auto& c = l.module.constraints[0].As<ir::CouplerConstraint>();
  EXPECT_EQ(l.module.Text(c.joint0.name), "j1");  // the mimicking joint follows
  EXPECT_EQ(l.module.Text(c.joint1.name), "j2");  // the mimicked joint
  EXPECT_EQ(c.gear_ratio, 2);
  EXPECT_EQ(c.offset, 0.5);

  SdfCompileResult compiled(JointModel("<drake:mimic joint='j2' multiplier='2' offset='0.5'/>"));
  ASSERT_TRUE(compiled.ok()) << compiled.Messages();
  const nlohmann::json json = compiled.PlantJson();
  ASSERT_EQ(json["constraints"].size(), 1u);
  EXPECT_EQ(json["constraints"][0]["type"], "coupler");
  EXPECT_EQ(json["constraints"][0]["joint0"], "m::j1");
  EXPECT_EQ(json["constraints"][0]["joint1"], "m::j2");
}

// SDFormat 1.11's <axis><mimic>, read as <drake:mimic> would be written:
// follower = multiplier (leader - reference) + offset
TEST(SdfJointDrakeChildrenTest, Sdformat111MimicIsACouplerToo) {  // issue 55, EXT-010
  {
    SdfFrontendResult l;
    ASSERT_TRUE(l.Read(JointModel("", R"(<mimic joint='j2' axis='axis'><multiplier>2</multiplier>
        <offset>0.5</offset><reference>0.1</reference></mimic>)")))
        << l.Messages();
    ASSERT_EQ(l.module.constraints.size(), 1u);
    const auto& c = l.module.constraints[0].As<ir::CouplerConstraint>();
    EXPECT_EQ(l.module.Text(c.joint0.name), "j1");
    EXPECT_EQ(l.module.Text(c.joint1.name), "j2");
    EXPECT_EQ(c.gear_ratio, 2);
    EXPECT_DOUBLE_EQ(c.offset, 0.5 - 2 * 0.1);
  }
  {  // SDFormat's defaults: multiplier 1, offset 0, reference 0
    SdfCompileResult compiled(JointModel("", "<mimic joint='j2'/>"));
    ASSERT_TRUE(compiled.ok()) << compiled.Messages();
    const nlohmann::json json = compiled.PlantJson();
    ASSERT_EQ(json["constraints"].size(), 1u);
    EXPECT_EQ(json["constraints"][0]["type"], "coupler");
    EXPECT_EQ(json["constraints"][0]["joint0"], "m::j1");
    EXPECT_EQ(json["constraints"][0]["joint1"], "m::j2");
  }
  {  // both: Drake's element is read, the other is ignored with a warning
    SdfFrontendResult l;
    ASSERT_TRUE(l.Read(JointModel("<drake:mimic joint='j2' multiplier='3' offset='0'/>",
                                  "<mimic joint='j2'/>")))
        << l.Messages();
    ASSERT_EQ(l.module.constraints.size(), 1u);
    EXPECT_EQ(l.module.constraints[0].As<ir::CouplerConstraint>().gear_ratio, 3);
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::JointWarning,
                                "<mimic> of joint 'j1' is ignored: the joint's <drake:mimic> is "
                                "read instead"));
  }
  {  // a leader's second axis, and a joint following itself
    SdfFrontendResult l;
    EXPECT_TRUE(l.Read(JointModel("", "<mimic joint='j2' axis='axis2'/>"))) << l.Messages();
    EXPECT_TRUE(l.module.constraints.empty());
    EXPECT_TRUE(l.HasDiagnostic(DiagKind::JointWarning, "it follows the 'axis2' of joint 'j2'"));
    SdfFrontendResult self;
    EXPECT_FALSE(self.Read(JointModel("", "<mimic joint='j1'/>")));
    EXPECT_TRUE(self.HasDiagnostic(DiagKind::BadValue, "a joint cannot follow itself"));
  }
}

TEST(SdfJointDrakeChildrenTest, MimicErrors) {  // EXT-010
  struct Case {
    const char* mimic;
    DiagKind kind;
    const char* message;
  };
  const Case cases[] = {
      {"<drake:mimic multiplier='1' offset='0'/>", DiagKind::MissingAttribute,
       "needs attribute 'joint'"},
      {"<drake:mimic joint='j2' offset='0'/>", DiagKind::MissingAttribute,
       "needs attribute 'multiplier'"},
      {"<drake:mimic joint='j2' multiplier='1'/>", DiagKind::MissingAttribute,
       "needs attribute 'offset'"},
      {"<drake:mimic joint='j1' multiplier='1' offset='0'/>", DiagKind::BadValue,
       "a joint cannot follow itself"},
  };
  for (const Case& c : cases) {
    SdfFrontendResult l;
    EXPECT_FALSE(l.Read(JointModel(c.mimic))) << c.mimic;
    EXPECT_TRUE(l.HasDiagnostic(c.kind, c.message)) << c.mimic << "\n" << l.Messages();
    EXPECT_TRUE(l.module.constraints.empty());
  }
  SdfCompileResult unknown(JointModel("<drake:mimic joint='nope' multiplier='1' offset='0'/>"));
  EXPECT_FALSE(unknown.ok());
  EXPECT_NE(unknown.Messages().find("unknown joint 'nope'"), std::string::npos)
      << unknown.Messages();
  unknown.ExpectDiagnostic(DiagKind::UnknownReference, "");  // its text is checked above
}

// ------------------------------------------------------------- EXT-070

std::string DeformableModel(std::string_view link_body, std::string_view after_link = "") {
  return fmt::format(R"(<model name='deformable'>
  <link name='body'>
{}
  </link>
  <link name='rigid'/>
{}
</model>)",
                     link_body, after_link);
}
constexpr std::string_view kVtkCollision = R"(<collision name='collision'>
      <geometry><mesh><uri>single_tet.vtk</uri></mesh></geometry>
    </collision>)";

TEST(SdfDeformableTest, DefaultsAndValues) {  // EXT-070
  SdfFrontendResult minimal;
  ASSERT_TRUE(minimal.Read(
      DeformableModel(fmt::format("{}<drake:deformable_properties/>", kVtkCollision))))
      << minimal.Messages();
  const ir::Body* body = minimal.Body("body");
  ASSERT_NE(body, nullptr);
  ASSERT_TRUE(body->deformable.has_value());
  EXPECT_FALSE(body->inertial.has_value());  // no mass in the rigid plant
  EXPECT_EQ(body->deformable->youngs_modulus, 1e8);  // DeformableBodyConfig's defaults
  EXPECT_EQ(body->deformable->poissons_ratio, 0.49);
  EXPECT_EQ(body->deformable->mass_density, 1.5e3);
  EXPECT_EQ(body->deformable->material_model, "linear_corotated");
  EXPECT_FALSE(body->deformable->resolution_hint.has_value());
  EXPECT_FALSE(minimal.Body("rigid")->deformable.has_value());

  SdfFrontendResult full;
  ASSERT_TRUE(full.Read(DeformableModel(fmt::format(R"({}
    <drake:deformable_properties>
      <drake:youngs_modulus>100.0</drake:youngs_modulus>
      <drake:poissons_ratio>0.3</drake:poissons_ratio>
      <drake:mass_damping>0.01</drake:mass_damping>
      <drake:stiffness_damping>0.02</drake:stiffness_damping>
      <drake:mass_density>800.0</drake:mass_density>
      <drake:material_model> corotated </drake:material_model>
    </drake:deformable_properties>
    <drake:wall_boundary_condition>
      <drake:point_on_plane>0 0 -10</drake:point_on_plane>
      <drake:outward_normal>0 0 2</drake:outward_normal>
    </drake:wall_boundary_condition>)",
                                                    kVtkCollision))))
      << full.Messages();
  const ir::DeformableProperties& d = *full.Body("body")->deformable;
  EXPECT_EQ(d.youngs_modulus, 100);
  EXPECT_EQ(d.poissons_ratio, 0.3);
  EXPECT_EQ(d.mass_damping, 0.01);
  EXPECT_EQ(d.stiffness_damping, 0.02);
  EXPECT_EQ(d.mass_density, 800);
  EXPECT_EQ(d.material_model, "corotated");
  ASSERT_EQ(d.wall_boundary_conditions.size(), 1u);
  EXPECT_EQ(d.wall_boundary_conditions[0].point_on_plane, Eigen::Vector3d(0, 0, -10));
  EXPECT_EQ(d.wall_boundary_conditions[0].outward_normal, Eigen::Vector3d(0, 0, 1));
}

TEST(SdfDeformableTest, SphereNeedsAPositiveResolutionHint) {  // EXT-070
  auto sphere = [](std::string_view proximity) {
    return fmt::format(R"(<collision name='collision'>
      <geometry><sphere><radius>0.1</radius></sphere></geometry>{}
    </collision><drake:deformable_properties/>)",
                       proximity);
  };
  SdfFrontendResult ok;
  ASSERT_TRUE(ok.Read(DeformableModel(sphere(
      "<drake:proximity_properties><drake:mesh_resolution_hint>0.05</drake:mesh_resolution_hint>"
      "</drake:proximity_properties>"))))
      << ok.Messages();
  EXPECT_EQ(ok.Body("body")->deformable->resolution_hint, 0.05);

  SdfFrontendResult missing;
  EXPECT_FALSE(missing.Read(DeformableModel(sphere(""))));
  EXPECT_TRUE(missing.HasDiagnostic(DiagKind::MissingElement,
                                    "<sphere> needs a <drake:mesh_resolution_hint>"))
      << missing.Messages();
  EXPECT_FALSE(missing.Body("body")->deformable.has_value());
}

TEST(SdfDeformableTest, PropertyAndLinkErrors) {  // EXT-070
  struct Case {
    std::string link_body, after_link, message;
  };
  const std::string props = "<drake:deformable_properties/>";
  const std::string coll(kVtkCollision);
  const std::vector<Case> cases = {
      {coll + "<drake:deformable_properties><drake:youngs_modulus>0</drake:youngs_modulus>"
              "</drake:deformable_properties>",
       "", "<drake:youngs_modulus> must be positive"},
      {coll + "<drake:deformable_properties><drake:poissons_ratio>0.5</drake:poissons_ratio>"
              "</drake:deformable_properties>",
       "", "<drake:poissons_ratio> must lie in (-1, 0.5)"},
      {coll + "<drake:deformable_properties><drake:mass_damping>-1</drake:mass_damping>"
              "</drake:deformable_properties>",
       "", "<drake:mass_damping> must be non-negative"},
      {coll + "<drake:deformable_properties><drake:stiffness_damping>-1"
              "</drake:stiffness_damping></drake:deformable_properties>",
       "", "<drake:stiffness_damping> must be non-negative"},
      {coll + "<drake:deformable_properties><drake:mass_density>-1</drake:mass_density>"
              "</drake:deformable_properties>",
       "", "<drake:mass_density> must be positive"},
      {coll + "<drake:deformable_properties><drake:material_model>jelly</drake:material_model>"
              "</drake:deformable_properties>",
       "", "<drake:material_model> 'jelly' is none of"},
      {props, "", "has 0 <collision> elements; a deformable link has exactly one"},
      {coll + coll + props, "", "has 2 <collision> elements"},
      {coll + "<visual name='v1'/><visual name='v2'/>" + props, "", "at most one <visual>"},
      {"<collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision>" +
           props,
       "", "it must be a <sphere> or a"},
      {"<collision name='c'><geometry><mesh><uri>x.obj</uri></mesh></geometry></collision>" +
           props,
       "", "it must name a .vtk file"},
      {coll + "<inertial><mass>1</mass></inertial>" + props, "", "must not have an <inertial>"},
      {coll + props,
       "<joint name='j' type='fixed'><parent>rigid</parent><child>body</child></joint>",
       "cannot be the child of joint 'j'"},
      {coll + props, "<frame name='f' attached_to='body'/>",
       "cannot be attached to deformable link 'body'"},
      {coll + props +
           "<drake:wall_boundary_condition><drake:point_on_plane>1 2 3</drake:point_on_plane>"
           "</drake:wall_boundary_condition>",
       "", "<drake:wall_boundary_condition> needs a <drake:outward_normal>"},
      {coll + props +
           "<drake:wall_boundary_condition><drake:point_on_plane>1 2 3</drake:point_on_plane>"
           "<drake:outward_normal>0 0 0</drake:outward_normal></drake:wall_boundary_condition>",
       "", "<drake:outward_normal> must not be zero"},
  };
  for (const Case& c : cases) {
    SdfFrontendResult l;
    EXPECT_FALSE(l.Read(DeformableModel(c.link_body, c.after_link))) << c.link_body;
    l.ExpectError(c.message);
    // what two collisions of one name and two visuals without a geometry say
    // besides the case's error
    if (c.link_body.find(coll + coll) != std::string::npos) {
      l.ExpectDiagnostic(DiagKind::DuplicateName, "is already used by another collision");
    }
    if (c.link_body.find("<visual name='v1'/>") != std::string::npos) {
      l.ExpectDiagnostic(DiagKind::EmptyGeometry, "has no <geometry>");
    }
    bool found = false;
    for (const auto& d : l.diags.diagnostics()) {
      found |= d.severity == Severity::Error && d.message.find(c.message) != std::string::npos;
    }
    EXPECT_TRUE(found) << c.message << "\n" << l.Messages();
    if (const ir::Body* b = l.Body("body")) {
      EXPECT_FALSE(b->deformable.has_value());
    }
  }
}

TEST(SdfDeformableTest, MeshWithResolutionHintWarns) {  // EXT-070
  SdfFrontendResult l;
  EXPECT_TRUE(l.Read(DeformableModel(R"(<collision name='collision'>
      <geometry><mesh><uri>single_tet.vtk</uri></mesh></geometry>
      <drake:proximity_properties><drake:mesh_resolution_hint>0.1</drake:mesh_resolution_hint></drake:proximity_properties>
    </collision><drake:deformable_properties/>)")))
      << l.Messages();
  EXPECT_TRUE(l.HasDiagnostic(DiagKind::UnsupportedElement, "<mesh> is ignored: the mesh is used as given"));
  EXPECT_FALSE(l.Body("body")->deformable->resolution_hint.has_value());
}

}  // namespace
}  // namespace mdlc
