// mjcf_replicate_test.cc - MuJoCo 3's <replicate> and <attach> (with
// <asset><model>), expanded as MuJoCo 3.3.8 expands them (mjcf_replicate.h):
// names and their suffixes or prefixes, nesting, sep, poses, the elements
// outside the tree that refer into a copy, located diagnostics, limits and
// attach cycles. MJCF-091 listed both as unsupported; they are now read.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "tests/unit/mjcf_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc {
namespace {

using testing::kTol;
using testing::LoweredMjcf;

std::string RModel(std::string_view body) {
  return fmt::format(R"(<mujoco model="m">{}</mujoco>)", body);
}

int CountReplicatedActuators(const LoweredMjcf& r, std::string_view name) {
  int n = 0;
  for (const auto& a : r.module.actuators) n += r.module.Text(a.name) == name;
  return n;
}

TEST(MjcfReplicate, NamesGetZeroPaddedSuffixesToTheDigitsOfCount) {
  LoweredMjcf r(RModel(R"(<worldbody><replicate count="12" offset="1 0 0">
      <body name="b"><joint name="j"/><geom name="g" size="0.1"/><site name="s"/></body>
    </replicate></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  for (int i = 0; i < 12; ++i) {
    const std::string s = fmt::format("{:02}", i);
    ASSERT_NE(r.Body("b" + s), nullptr) << s;
    EXPECT_NE(r.Joint("j" + s), nullptr) << s;
    EXPECT_NE(r.Geometry("g" + s, 0xff), nullptr) << s;
  }
  EXPECT_EQ(r.Body("b"), nullptr);
  EXPECT_EQ(r.Body("b12"), nullptr);
}

TEST(MjcfReplicate, NestedSuffixesComeInnermostFirstAfterSep) {
  // MuJoCo's documented example: Alice-10 is inner copy 1 of outer copy 0
  LoweredMjcf r(RModel(R"(<worldbody>
      <replicate count="2" offset="0 1 0" euler="90 0 0">
        <replicate count="2" sep="-" offset="1 0 0" euler="0 90 0">
          <body name="Alice"><freejoint/><geom size=".1"/></body>
        </replicate>
      </replicate></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Body* b10 = r.Body("Alice-10");
  const ir::Body* b01 = r.Body("Alice-01");
  const ir::Body* b11 = r.Body("Alice-11");
  ASSERT_NE(r.Body("Alice-00"), nullptr);
  ASSERT_NE(b10, nullptr);
  ASSERT_NE(b01, nullptr);
  ASSERT_NE(b11, nullptr);
  // poses through the free joints' default positions (w x y z, x y z)
  auto pose_of = [&](std::string_view joint) { return r.Joint(joint)->default_positions; };
  const auto q10 = pose_of("Alice-10");
  EXPECT_NEAR(q10[4], 1, kTol);
  EXPECT_NEAR(std::abs(q10[0]), std::sqrt(0.5), kTol);
  EXPECT_NEAR(std::abs(q10[2]), std::sqrt(0.5), kTol);
  const auto q11 = pose_of("Alice-11");
  EXPECT_NEAR(q11[4], 1, kTol);
  EXPECT_NEAR(q11[5], 1, kTol);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(std::abs(q11[k]), 0.5, kTol) << k;
}

TEST(MjcfReplicate, OffsetTurnsWithEachCopysRotation) {
  // copy i sits at the sum over k < i of R(k euler) offset
  LoweredMjcf r(RModel(R"(<worldbody><replicate count="3" offset="1 0 0" euler="0 0 90">
      <body name="b"><freejoint/><geom size=".1"/></body></replicate></worldbody>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const auto q2 = r.Joint("b2")->default_positions;
  EXPECT_NEAR(q2[4], 1, kTol);  // (1,0,0) + Rz(90)(1,0,0)
  EXPECT_NEAR(q2[5], 1, kTol);
  EXPECT_NEAR(std::abs(q2[0]), 0, kTol);  // Rz(180): w = 0
}

TEST(MjcfReplicate, ReferencesIntoTheSubtreeAreCopiedWithTheCopys) {
  LoweredMjcf r(RModel(R"(<worldbody>
      <body name="fixed"><joint name="k"/><geom size=".1"/></body>
      <replicate count="3" sep="_">
        <body name="b"><joint name="j"/><geom size=".1"/></body>
      </replicate></worldbody>
      <actuator>
        <motor name="m" joint="j"/>
        <motor name="outside" joint="k"/>
      </actuator>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  for (const char* name : {"m_0", "m_1", "m_2"}) EXPECT_EQ(CountReplicatedActuators(r, name), 1) << name;
  EXPECT_EQ(CountReplicatedActuators(r, "m"), 0);
  EXPECT_EQ(CountReplicatedActuators(r, "outside"), 1);  // refers to nothing inside: as written
  for (const auto& a : r.module.actuators) {
    const std::string name(r.module.Text(a.name));
    if (name.starts_with("m_")) {
      EXPECT_EQ(r.module.Text(r.module[a.joint.id].name), "j_" + name.substr(2)) << name;
    }
  }
}

TEST(MjcfReplicate, ElementReferringInsideAndToAnUncopiedNameIsDroppedWithWarning) {
  LoweredMjcf r(RModel(R"(<worldbody>
      <body name="fixed"><joint name="k"/><geom size=".1"/></body>
      <replicate count="2"><body name="b"><joint name="j"/><geom size=".1"/></body></replicate>
      </worldbody>
      <equality><joint joint1="j" joint2="k"/></equality>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_TRUE(r.module.constraints.empty());
  const Diagnostic* d = r.Find(DiagKind::UnsupportedElement, "refers to an element inside");
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 5u);  // at the <joint> equality as written
}

TEST(MjcfReplicate, DiagnosticsOfCopiesPointAtTheOriginal) {
  LoweredMjcf r(RModel("<worldbody>\n<replicate count=\"4\">\n<body>\n"
                      "<geom size=\"0.1\" condim=\"1\"/></body></replicate></worldbody>"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const Diagnostic* d = r.Find(DiagKind::UnsupportedValue, "condim");
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 4u);
  EXPECT_FALSE(r.sources.IsExpansion(d->loc.file));
}

TEST(MjcfReplicate, NestedBombIsALocatedLimitError) {
  LoweredMjcf r(RModel("<worldbody>\n<replicate count=\"1000\"><replicate count=\"1000\">"
                      "<replicate count=\"1000\"><geom size=\"1\"/></replicate></replicate>"
                      "</replicate></worldbody>"));
  EXPECT_FALSE(r.ok());
  const Diagnostic* d = r.Find(DiagKind::LimitExceeded, "elements limit");
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_EQ(d->loc.column, 1u);  // the outermost: its expansion passes the limit
}

constexpr const char* kArm = R"(<mujoco model="arm">
  <default><geom density="100"/><default class="link"><geom size="0.05"/></default></default>
  <worldbody>
    <geom name="ground" type="plane" size="1 1 1"/>
    <body name="base" childclass="link">
      <body name="upper" pos="0 0 1"><joint name="shoulder"/><geom name="g"/>
        <body name="lower" pos="0 0 1"><joint name="elbow"/><geom/></body>
      </body>
    </body>
  </worldbody>
  <actuator><motor name="drive" joint="elbow"/></actuator>
</mujoco>)";

TEST(MjcfAttach, BodySubtreeIsPrefixedWithItsDefaultsAndReferences) {
  LoweredMjcf r(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><body name="torso"><geom size="0.1"/>
        <frame pos="1 0 0"><attach model="arm" body="upper" prefix="l_"/></frame>
      </body></worldbody>)"),
                {{"parts/arm.xml", kArm}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  ASSERT_NE(r.Body("l_upper"), nullptr);
  ASSERT_NE(r.Body("l_lower"), nullptr);
  EXPECT_EQ(r.Body("l_base"), nullptr);
  EXPECT_EQ(r.Body("upper"), nullptr);
  ASSERT_NE(r.Joint("l_shoulder"), nullptr);
  EXPECT_EQ(CountReplicatedActuators(r, "l_drive"), 1);
  // the child's class "link" (childclass of base, above the attached body)
  // with its density: a sphere of radius 0.05 at density 100
  const ir::Body* upper = r.Body("l_upper");
  ASSERT_TRUE(upper->mass_from_geometry);
  const ir::Geometry* g = r.Geometry("l_g", 0xff);
  ASSERT_NE(g, nullptr);
  ASSERT_TRUE(std::holds_alternative<ir::Sphere>(g->shape));
  EXPECT_NEAR(std::get<ir::Sphere>(g->shape).radius, 0.05, kTol);
}

TEST(MjcfAttach, WithoutBodyTheWholeWorldbodyIsAttached) {
  LoweredMjcf r(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><body name="cart"><joint type="slide"/><geom size="0.1"/>
        <attach model="arm" prefix="a_"/></body></worldbody>)"),
                {{"parts/arm.xml", kArm}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Body("a_base"), nullptr);
  EXPECT_NE(r.Body("a_lower"), nullptr);
  const ir::Geometry* ground = r.Geometry("a_ground", 0xff);
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(r.module.Text(r.module[ground->body.id].name), "cart");
}

TEST(MjcfAttach, UnnamedModelAssetIsKnownByItsFilesModelName) {
  LoweredMjcf r(RModel(R"(<asset><model file="parts/arm.xml"/></asset>
      <worldbody><attach model="arm" body="lower" prefix="x"/></worldbody>)"),
                {{"parts/arm.xml", kArm}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Body("xlower"), nullptr);
}

TEST(MjcfAttach, CycleIsALocatedError) {
  LoweredMjcf r(RModel(R"(<asset><model name="a" file="a.xml"/></asset>
      <worldbody><attach model="a" body="x" prefix="p"/></worldbody>)"),
                {{"a.xml", "<mujoco>\n<asset><model name=\"back\" file=\"model.xml\"/></asset>"
                           "<worldbody><body name=\"x\"><geom size=\"1\"/>"
                           "<attach model=\"back\" prefix=\"q\"/></body></worldbody></mujoco>"}});
  EXPECT_FALSE(r.ok());
  const Diagnostic* d = r.Find(DiagKind::IncludeCycle, "attach cycle");
  ASSERT_NE(d, nullptr) << r.Messages();
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_NE(r.sources.Path(d->loc.file).find("a.xml"), std::string::npos);
}

// MuJoCo 3.3.8's mjs_attach adds the attached model's keys after the
// parent's own, a key K named prefix + K (an unnamed key the prefix), its
// values on the attached joints and the parent's other joints at qpos0
// (MJCF-008: the key named "home", else the first, sets the default
// positions; tests/models/mjcf/oracle/attach_keyframe.xml checks the same
// against MuJoCo).
constexpr const char* kArmWithKeys = R"(<mujoco model="arm">
  <worldbody>
    <body name="upper" pos="0 0 1"><joint name="shoulder"/><geom size="0.1"/>
      <body name="lower" pos="0 0 1"><joint name="elbow"/><geom size="0.1"/></body>
    </body>
  </worldbody>
  <keyframe><key name="bent" qpos="0.5 -0.25"/><key qpos="0.125 0.0625"/></keyframe>
</mujoco>)";

double DefaultPosition(const LoweredMjcf& r, std::string_view joint) {
  const ir::Joint* j = r.Joint(joint);
  return j == nullptr || j->default_positions.empty() ? NAN : j->default_positions[0];
}

TEST(MjcfAttach, AttachedKeyPlacesItsValuesOnTheAttachedJoints) {
  LoweredMjcf r(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><body name="cart"><joint name="rail" type="slide" ref="0.3"/><geom size="0.1"/>
        <attach model="arm" body="lower" prefix="a_"/></body></worldbody>)"),
                {{"parts/arm.xml", kArmWithKeys}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  // a_bent, the first key: elbow's value, the rail at its ref
  EXPECT_NEAR(DefaultPosition(r, "a_elbow"), -0.25, kTol);
  EXPECT_NEAR(DefaultPosition(r, "rail"), 0.3, kTol);
  EXPECT_EQ(r.Find(DiagKind::UnsupportedElement, "keyframes"), nullptr) << r.Messages();
}

TEST(MjcfAttach, UnnamedAttachedKeyIsNamedByThePrefix) {
  // the unnamed key becomes "home" and is chosen over a_bent
  LoweredMjcf r(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><attach model="arm" body="upper" prefix="home"/></worldbody>)"),
                {{"parts/arm.xml", kArmWithKeys}});
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NEAR(DefaultPosition(r, "homeshoulder"), 0.125, kTol);
  EXPECT_NEAR(DefaultPosition(r, "homeelbow"), 0.0625, kTol);
}

TEST(MjcfAttach, ParentKeysComeFirstAndARepeatedKeyNameIsAnError) {
  LoweredMjcf first(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><body name="cart"><joint name="rail" type="slide"/><geom size="0.1"/>
        <attach model="arm" body="upper" prefix="a_"/></body></worldbody>
      <keyframe><key name="mine" qpos="0.75"/></keyframe>)"),
                    {{"parts/arm.xml", kArmWithKeys}});
  ASSERT_TRUE(first.ok()) << first.Messages();
  EXPECT_NEAR(DefaultPosition(first, "rail"), 0.75, kTol);
  EXPECT_NEAR(DefaultPosition(first, "a_shoulder"), 0.0, kTol);

  LoweredMjcf repeated(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><attach model="arm" body="upper" prefix="a_"/></worldbody>
      <keyframe><key name="a_bent"/></keyframe>)"),
                       {{"parts/arm.xml", kArmWithKeys}});
  EXPECT_FALSE(repeated.ok());
  EXPECT_NE(repeated.Find(DiagKind::DuplicateName, "repeated name 'a_bent' in key"), nullptr)
      << repeated.Messages();
}

TEST(MjcfAttach, AttachedKeyOfAnotherSizeThanTheModelIsAnError) {
  // MuJoCo 3.3.8 pads a short key of a model it compiles, not of one it attaches
  LoweredMjcf r(RModel(R"(<asset><model name="arm" file="parts/arm.xml"/></asset>
      <worldbody><attach model="arm" body="upper" prefix="a_"/></worldbody>)"),
                {{"parts/arm.xml", R"(<mujoco model="arm"><worldbody>
      <body name="upper"><joint name="shoulder"/><joint name="twist"/><geom size="0.1"/></body>
      </worldbody><keyframe><key name="k" qpos="1"/></keyframe></mujoco>)"}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.Find(DiagKind::BadValue, "invalid qpos size, got 1, should be 2"), nullptr)
      << r.Messages();
}

}  // namespace
}  // namespace mdlc
