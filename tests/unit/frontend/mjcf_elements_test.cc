// mjcf_elements_test.cc - the MJCF model elements: <equality> (MJCF-080,
// BEYOND-003), <tendon> (BEYOND-005), <actuator> (MJCF-060, MJCF-024,
// BEYOND-008), <contact> (MJCF-070) and <keyframe> (MJCF-008).
//
// Each test compiles a small MJCF file through the whole pipeline and checks
// the IR and the plant-json dump. Numbers marked "MuJoCo 3.3.8" were read
// from mjModel (eq_data, tendon_*, actuator_*) compiled by mujoco-js 0.0.7
// from the same XML.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "backend/plant_json.h"
#include "backend/positions.h"
#include "ir/module.h"
#include "tests/unit/diagnostic_claims.h"
#include "tests/unit/test_values.h"
#include "tools/driver/compiler.h"

namespace mdlc {
namespace {

using testing::kInf;
using testing::kTol;

/// The whole pipeline on one MJCF file (model.xml in a fresh folder).
/// Strict about diagnostics (diagnostic_claims.h): Count and Line claim what
/// they find.
class Mjcf {
 public:
  explicit Mjcf(std::string_view xml) {
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_mjcf_elements_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    const auto path = dir_ / "model.xml";
    std::ofstream(path) << xml;
    c_.options.inputs = {Input::File(path.string())};
    ok_ = c_.Run();
  }
  ~Mjcf() {
    claims_.CheckAtEnd(c_.diags.diagnostics());
    std::filesystem::remove_all(dir_);
  }
  Mjcf(const Mjcf&) = delete;
  Mjcf& operator=(const Mjcf&) = delete;

  bool ok() const { return ok_; }
  const ir::Module& module() const { return c_.module; }
  std::string Messages() const {
    std::string out;
    for (const auto& d : c_.diags.diagnostics()) {
      out += fmt::format("{}:{}: [{}] {}\n", d.loc.line, d.loc.column, InfoFor(d.kind).name,
                         d.message);
    }
    return out;
  }
  size_t DiagCount() const { return c_.diags.diagnostics().size(); }
  /// Diagnostics of `kind` whose message contains `text`; those are claimed.
  size_t Count(DiagKind kind, std::string_view text = "") const {
    size_t n = 0;
    for (const auto& d : c_.diags.diagnostics()) {
      n += d.kind == kind && d.message.find(text) != std::string::npos;
    }
    if (n > 0) claims_.Found(kind, text);
    return n;
  }
  /// The line of the first diagnostic of `kind` (0 when none); claims it.
  uint32_t Line(DiagKind kind) const {
    for (const auto& d : c_.diags.diagnostics()) {
      if (d.kind == kind) {
        claims_.Found(kind, d.message);
        return d.loc.line;
      }
    }
    return 0;
  }
  /// Claims the diagnostics of `kind` holding `text`; at least one must come.
  void ExpectDiagnostic(DiagKind kind, std::string_view text) { claims_.Expect(kind, text); }
  nlohmann::json Json() const {
    return nlohmann::json::parse(
        backend::EmitPlantJson(*c_.model, backend::DefaultPositions(c_.model->plant)));
  }
  const ir::Actuator* Actuator(std::string_view name) const {
    for (const auto& a : c_.module.actuators) {
      if (c_.module.Text(a.name) == name) return &a;
    }
    return nullptr;
  }

 private:
  std::filesystem::path dir_;
  Compilation c_;
  bool ok_ = false;
  mutable testing::DiagnosticClaims claims_;
};

// A chain a (hinge ja, ref 30 degrees) -> b (slide jb, ref 0.25), a free
// body c; `ja_extra` adds attributes to ja.
std::string Doc(std::string_view after_worldbody, std::string_view ja_extra = "") {
  return fmt::format(R"(<mujoco model="m">
 <worldbody>
  <body name="a" pos="0 0 1" euler="0 0 90">
   <joint name="ja" type="hinge" axis="0 1 0" ref="30" range="-90 90" {}/>
   <geom size="0.1"/>
   <body name="b" pos="1 0 0" euler="90 0 0">
    <joint name="jb" type="slide" ref="0.25" range="-1 3"/>
    <geom size="0.1"/>
   </body>
  </body>
  <body name="c" pos="2 0 0"><freejoint/><geom size="0.1"/></body>
 </worldbody>
{}
</mujoco>
)",
                     ja_extra, after_worldbody);
}

void ExpectVector(const nlohmann::json& v, std::initializer_list<double> expected,
                  double tol = 1e-9) {
  ASSERT_EQ(v.size(), expected.size()) << v;
  size_t i = 0;
  for (double e : expected) EXPECT_NEAR(v[i++].get<double>(), e, tol) << v;
}

// --- equality (MJCF-080, BEYOND-003) -----------------------------------------

TEST(MjcfEquality, ConnectBodyFormCompletesQAtQpos0) {
  // MJCF-080: P = anchor in body1; Q = the same point in body2 at qpos0.
  // MuJoCo 3.3.8 eq_data[3:6] = 1.1 -0.3 0.2.
  Mjcf m(Doc(R"(<equality><connect body1="b" body2="a" anchor="0.1 0.2 0.3"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"];
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0]["type"], "ball");
  EXPECT_EQ(c[0]["body_A"], "m::b");
  EXPECT_EQ(c[0]["body_B"], "m::a");
  ExpectVector(c[0]["p_AP"], {0.1, 0.2, 0.3});
  ExpectVector(c[0]["p_BQ"], {1.1, -0.3, 0.2});
}

TEST(MjcfEquality, ConnectBody2DefaultsToWorld) {
  Mjcf m(Doc(R"(<equality><connect body1="a" anchor="0 0 0.5"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  EXPECT_EQ(c["body_B"], "world");
  ExpectVector(c["p_BQ"], {0, 0, 1.5});
}

TEST(MjcfEquality, ConnectSiteForm) {
  // BEYOND-003: the site1/site2 form holds the two sites together
  Mjcf m(R"(<mujoco model="m"><worldbody>
  <body name="a"><joint name="j"/><geom size="0.1"/><site name="s1" pos="0 0 0.2"/></body>
  <body name="b" pos="1 0 0"><joint name="k"/><geom size="0.1"/><site name="s2" pos="0.5 0 0"/></body>
 </worldbody>
 <equality><connect site1="s1" site2="s2"/></equality></mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  EXPECT_EQ(c["body_A"], "m::a");
  EXPECT_EQ(c["body_B"], "m::b");
  ExpectVector(c["p_AP"], {0, 0, 0.2});
  ExpectVector(c["p_BQ"], {0.5, 0, 0});
}

TEST(MjcfEquality, ConnectErrors) {
  {  // MJCF-080: missing anchor E
    Mjcf m(Doc(R"(<equality><connect body1="a"/></equality>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::MissingAttribute, "anchor"), 1u) << m.Messages();
  }
  {  // unknown body: E at the attribute (line 13 of Doc's text)
    Mjcf m(Doc(R"(<equality><connect body1="nope" anchor="0 0 0"/></equality>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::UnknownReference, "nope"), 1u) << m.Messages();
    EXPECT_EQ(m.Line(DiagKind::UnknownReference), 13u);
  }
  {  // both body1 and site1: E
    Mjcf m(Doc(R"(<equality><connect body1="a" anchor="0 0 0" site1="x" site2="y"/></equality>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::BadValue, "not both"), 1u) << m.Messages();
  }
}

TEST(MjcfEquality, WeldRelativePoseAtQpos0) {
  // BEYOND-003, MuJoCo 3 semantics: no relpose -> the relative pose at qpos0.
  // MuJoCo 3.3.8 eq_data: anchor 0.3 0 0; relpose pos -1 -1 2.3,
  // quat 0.5 -0.5 -0.5 -0.5.
  Mjcf m(Doc(R"(<equality><weld body1="b" body2="c" anchor="0.3 0 0"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  EXPECT_EQ(c["type"], "weld");
  EXPECT_EQ(c["body_A"], "m::b");
  EXPECT_EQ(c["body_B"], "m::c");
  ExpectVector(c["X_AP"]["p"], {-1, -1, 2.3});
  ExpectVector(c["X_AP"]["q"], {0.5, -0.5, -0.5, -0.5});
  ExpectVector(c["X_BQ"]["p"], {0.3, 0, 0});
  ExpectVector(c["X_BQ"]["q"], {1, 0, 0, 0});
}

TEST(MjcfEquality, WeldGivenRelpose) {
  // MuJoCo 3.3.8 keeps a relpose with a nonzero quaternion (normalized)
  Mjcf m(Doc(R"(<equality><weld body1="a" body2="c" relpose="1 2 3 0 2 0 0" torquescale="2"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  ExpectVector(c["X_AP"]["p"], {1, 2, 3});
  ExpectVector(c["X_AP"]["q"], {0, 1, 0, 0});
  ExpectVector(c["X_BQ"]["p"], {0, 0, 0});
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "torquescale"), 1u) << m.Messages();
}

TEST(MjcfEquality, JointBecomesCouplerWithRefs) {
  // MuJoCo: ja - ref_a = 0.1 + 2 (jb - ref_b) -> ja = 2 jb + 0.1 + ref_a - 2 ref_b
  Mjcf m(Doc(R"(<equality><joint joint1="ja" joint2="jb" polycoef="0.1 2"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  EXPECT_EQ(c["type"], "coupler");
  // Drake's orientation: joint0 (MJCF joint1) = gear * joint1 (MJCF joint2) + offset
  EXPECT_EQ(c["joint0"], "m::ja");
  EXPECT_EQ(c["joint1"], "m::jb");
  EXPECT_NEAR(c["gear_ratio"].get<double>(), 2, kTol);
  EXPECT_NEAR(c["offset"].get<double>(), 0.1 + M_PI / 6 - 0.5, 1e-12);
}

TEST(MjcfEquality, JointHigherOrderWarnsAndSingleJointPins) {
  Mjcf m(Doc(R"(<equality><joint joint1="ja" joint2="jb" polycoef="0 1 0.5"/>
  <joint joint1="jb" polycoef="0.5"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedValue, "higher-order"), 1u) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"];
  ASSERT_EQ(c.size(), 2u);
  // jb alone is held at ref + c0 = 0.75: 1 * jb - 0.75 in [0, 0]
  EXPECT_EQ(c[1]["type"], "tendon");
  EXPECT_EQ(c[1]["joints"][0], "m::jb");
  EXPECT_NEAR(c[1]["offset"].get<double>(), -0.75, kTol);
  EXPECT_EQ(c[1]["lower"], 0);
  EXPECT_EQ(c[1]["upper"], 0);
}

TEST(MjcfEquality, InactiveAndUnsupportedKinds) {
  Mjcf m(Doc(R"(<equality>
  <connect body1="a" anchor="0 0 0" active="false"/>
  <connect body1="b" anchor="0 0 0" active="false"/>
  <tendon tendon1="t"/>
  <flex flex="f"/>
  <connect body1="a" anchor="0 0 0" solref="0.02 1" solimp="0.9 0.95 0.001"/>
 </equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.module().constraints.size(), 1u);  // only the active one
  EXPECT_EQ(m.Count(DiagKind::UnsupportedValue, "active"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "<tendon>"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "<flex>"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "solref"), 0u) << m.Messages();
}

TEST(MjcfEquality, ActiveFromDefaultClass) {
  Mjcf m(Doc(R"(<default><equality active="false"/></default>
 <equality><connect body1="a" anchor="0 0 0"/></equality>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_TRUE(m.module().constraints.empty());
  m.ExpectDiagnostic(DiagKind::UnsupportedValue,
                     "active=\"false\": MuJoCo starts this constraint disabled");
}

TEST(MjcfEquality, DistanceBetweenSpheres) {
  // BEYOND-003 (MuJoCo 2.x): the surface distance plus both radii, between centers
  Mjcf m(R"(<mujoco model="m"><worldbody>
  <body name="a"><joint name="j"/><geom name="g1" size="0.1" pos="0 0 0.5"/></body>
  <body name="b" pos="1 0 0"><joint name="k"/><geom name="g2" size="0.2"/></body>
 </worldbody>
 <equality><distance geom1="g1" geom2="g2" distance="0.3"/></equality></mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"][0];
  EXPECT_EQ(c["type"], "distance");
  ExpectVector(c["p_AP"], {0, 0, 0.5});
  ExpectVector(c["p_BQ"], {0, 0, 0});
  EXPECT_NEAR(c["distance"].get<double>(), 0.6, kTol);
  EXPECT_EQ(m.Count(DiagKind::UnsupportedValue, "removed in MuJoCo 2.2.2"), 1u) << m.Messages();
}

// --- tendon (BEYOND-005) ------------------------------------------------------

TEST(MjcfTendon, FixedLimitsAndSpring) {
  // MuJoCo 3.3.8: tendon_range -1 2 (limited), lengthspring 0 0 (at
  // qpos_spring), stiffness 5, damping 0.5; second tendon lengthspring 0.1 0.4
  Mjcf m(Doc(R"(<tendon>
  <fixed name="t" limited="true" range="-1 2" stiffness="5" damping="0.5">
   <joint joint="ja" coef="2"/><joint joint="jb" coef="-1"/></fixed>
  <fixed name="t2" stiffness="3" springlength="0.1 0.4"><joint joint="ja" coef="1"/></fixed>
  <fixed name="t3" range="0 1"><joint joint="jb" coef="1"/></fixed>
  <spatial name="s"><site site="x"/></spatial>
 </tendon>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json c = m.Json()["constraints"];
  ASSERT_EQ(c.size(), 4u) << c;
  // t: the limits, rigid
  EXPECT_EQ(c[0]["joints"], nlohmann::json({"m::ja", "m::jb"}));
  ExpectVector(c[0]["a"], {2, -1});
  EXPECT_EQ(c[0]["lower"], -1);
  EXPECT_EQ(c[0]["upper"], 2);
  EXPECT_TRUE(c[0]["stiffness"].is_null());  // infinite
  EXPECT_EQ(c[0]["damping"], 0);
  // t: the spring about the length at qpos_spring (0)
  EXPECT_EQ(c[1]["lower"], 0);
  EXPECT_EQ(c[1]["upper"], 0);
  EXPECT_EQ(c[1]["stiffness"], 5);
  EXPECT_EQ(c[1]["damping"], 0.5);
  // t2: dead-band spring
  EXPECT_EQ(c[2]["lower"], 0.1);
  EXPECT_EQ(c[2]["upper"], 0.4);
  EXPECT_EQ(c[2]["stiffness"], 3);
  // t3: autolimits
  EXPECT_EQ(c[3]["lower"], 0);
  EXPECT_EQ(c[3]["upper"], 1);
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "spatial"), 1u) << m.Messages();
}

TEST(MjcfTendon, Errors) {
  {
    Mjcf m(Doc(R"(<tendon><fixed><joint joint="zz" coef="1"/></fixed></tendon>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::UnknownReference, "zz"), 1u) << m.Messages();
  }
  {
    Mjcf m(Doc(R"(<tendon><fixed limited="true" range="2 1"><joint joint="ja" coef="1"/></fixed></tendon>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::BadValue, "invalid limits"), 1u) << m.Messages();
  }
  {
    Mjcf m(Doc(R"(<tendon><fixed damping="1"><joint joint="ja" coef="1"/></fixed></tendon>)"));
    EXPECT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "pure damper"), 1u) << m.Messages();
    EXPECT_TRUE(m.module().constraints.empty());
  }
}

// --- actuator (MJCF-060, MJCF-024, BEYOND-008) ----------------------------------

TEST(MjcfActuator, MotorDefaultsNamesAndRotorInertia) {
  // Drake's order: motors, then positions; unnamed -> motor<N>
  Mjcf m(Doc(R"(<actuator>
  <position joint="jb"/>
  <motor joint="ja" gear="2" ctrlrange="-3 3"/>
  <motor name="named" joint="jb" ctrlrange="-1 2" forcerange="-1.5 1.5"/>
 </actuator>)",
             R"(armature="0.5")"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json a = m.Json()["actuators"];
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0]["name"], "motor0");
  EXPECT_EQ(a[0]["joint"], "m::ja");
  EXPECT_EQ(a[0]["gear_ratio"], 2);
  EXPECT_EQ(a[0]["effort_limit"], 3);
  // MJCF-024: armature 0.5 / gear^2
  EXPECT_NEAR(a[0]["rotor_inertia"].get<double>(), 0.125, kTol);
  EXPECT_TRUE(a[0]["kp"].is_null());
  // asymmetric ctrlrange: the larger bound, then min with forcerange (W)
  EXPECT_EQ(a[1]["name"], "named");
  EXPECT_EQ(a[1]["effort_limit"], 1.5);
  EXPECT_EQ(m.Count(DiagKind::ActuatorWarning, "asymmetric 'ctrlrange'"), 1u) << m.Messages();
  // the position comes last: motor2, kp 1 kd 0 (MuJoCo's defaults)
  EXPECT_EQ(a[2]["name"], "motor2");
  EXPECT_EQ(a[2]["kp"], 1);
  EXPECT_EQ(a[2]["kd"], 0);
  EXPECT_TRUE(a[2]["effort_limit"].is_null());
}

TEST(MjcfActuator, PositionVelocityGeneralGains) {
  // MuJoCo 3.3.8: position kp 7 kv 2 -> gainprm 7, biasprm 0 -7 -2;
  // velocity kv 4 -> gainprm 4, biasprm 0 0 -4; general 9 / 0 -9 -1.5
  Mjcf m(Doc(R"(<actuator>
  <position name="p" joint="jb" kp="7" kv="2" forcerange="-5 5"/>
  <velocity name="v" joint="ja" kv="4" ctrlrange="-10 10"/>
  <general name="g" joint="jb" gaintype="fixed" biastype="affine" gainprm="9" biasprm="0 -9 -1.5"/>
  <general name="gv" joint="ja" biastype="affine" gainprm="3" biasprm="0 0 -3"/>
  <general name="gm" joint="ja" ctrlrange="-2 2"/>
 </actuator>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const auto* p = m.Actuator("p");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(*p->kp, 7);
  EXPECT_EQ(*p->kd, 2);
  EXPECT_EQ(p->effort_limit, 5);
  const auto* v = m.Actuator("v");
  EXPECT_EQ(*v->kp, 0);
  EXPECT_EQ(*v->kd, 4);
  EXPECT_EQ(v->effort_limit, kInf);  // a velocity's ctrlrange is no force
  const auto* g = m.Actuator("g");
  EXPECT_EQ(*g->kp, 9);
  EXPECT_EQ(*g->kd, 1.5);
  const auto* gv = m.Actuator("gv");
  EXPECT_EQ(*gv->kp, 0);
  EXPECT_EQ(*gv->kd, 3);
  const auto* gm = m.Actuator("gm");
  EXPECT_FALSE(gm->kp.has_value());
  EXPECT_EQ(gm->effort_limit, 2);
}

TEST(MjcfActuator, DefaultClassesPerKindAndInheritRange) {
  Mjcf m(Doc(R"(<default><position kp="20" forcerange="-4 4"/><motor gear="3"/></default>
 <actuator><position name="p" joint="ja" inheritrange="0.5"/><motor name="mo" joint="jb"/></actuator>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const auto* p = m.Actuator("p");
  EXPECT_EQ(*p->kp, 20);
  // inheritrange 0.5 of [-pi/2, pi/2] -> ctrlrange +-pi/4, a range of
  // positions: the effort limit is the default class's forcerange
  EXPECT_EQ(p->effort_limit, 4);
  EXPECT_EQ(m.Actuator("mo")->gear_ratio, 3);
}

// Menagerie panda's fingers move through a tendon: no actuator takes their
// armature as rotor inertia, so the mass matrix lacks what MuJoCo's has
TEST(MjcfActuator, ArmatureNoActuatorTakesIsWarned) {  // issue 55, MJCF-024
  {
    Mjcf m(Doc("", R"(armature="0.5")"));
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute,
                      "armature 0.5 of joint 'ja' is left out of the mass matrix: the plant holds "
                      "armature only as the rotor inertia of an actuator on the joint"),
              1u)
        << m.Messages();
    EXPECT_EQ(m.Line(DiagKind::UnsupportedAttribute), 4u);  // at the attribute
  }
  {  // from a default class: at the default's attribute; 0 says nothing
    Mjcf m(R"(<mujoco model="m">
 <default><joint armature="0.1"/><default class="none"><joint armature="0"/></default></default>
 <worldbody>
  <body name="a"><joint name="ja" axis="0 1 0"/><geom size="0.1"/>
   <body name="b"><joint name="jb" class="none"/><geom size="0.1"/></body>
  </body>
 </worldbody>
</mujoco>)");
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "armature 0.1 of joint 'ja'"), 1u)
        << m.Messages();
    EXPECT_EQ(m.Line(DiagKind::UnsupportedAttribute), 2u);
  }
  {  // a motor on the joint takes it: no warning
    Mjcf m(Doc(R"(<actuator><motor joint="ja"/></actuator>)", R"(armature="0.5")"));
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.DiagCount(), 0u) << m.Messages();
  }
}

// anymal_c's actuators: Drake's parser reads a position's ctrlrange, a range
// of positions, as an effort limit (6.28 here); mdlc reads forcerange
TEST(MjcfActuator, APositionsEffortLimitIsItsForceRange) {  // issue 55, MJCF-060
  Mjcf m(Doc(R"(<actuator>
  <position name="limited" joint="ja" kp="100" ctrlrange="-6.28 6.28" forcerange="-80 80"/>
  <position name="free" joint="jb" kp="100" ctrlrange="-6.28 0.5"/>
  <motor name="motor" joint="ja" ctrlrange="-6.28 6.28" forcerange="-80 80"/>
 </actuator>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Actuator("limited")->effort_limit, 80);
  // no forcerange: unlimited, and an asymmetric range of positions is no news
  EXPECT_EQ(m.Actuator("free")->effort_limit, kInf);
  EXPECT_EQ(m.Count(DiagKind::ActuatorWarning, "asymmetric"), 0u) << m.Messages();
  // a motor's ctrlrange is a range of forces, as Drake reads it
  EXPECT_NEAR(m.Actuator("motor")->effort_limit, 6.28, 1e-15);
}

TEST(MjcfActuator, UnsupportedKindsAndTransmissions) {
  Mjcf m(Doc(R"(<actuator>
  <damper joint="ja" kv="1" ctrlrange="0 1"/>
  <damper joint="jb" kv="1" ctrlrange="0 1"/>
  <muscle joint="ja"/>
  <motor tendon="t"/>
  <motor joint="ja" group="2"/>
  <motor joint="jb" group="2"/>
  <position joint="ja" dampratio="1"/>
  <motor joint="ja" gear="1 2"/>
 </actuator>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "damper"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "muscle"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "acts through 'tendon'"), 1u)
      << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "'group'"), 1u) << m.Messages();
  // BEYOND-008: dampratio is supported (kd from the inertia at qpos0)
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "'dampratio'"), 0u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::ActuatorWarning, "attribute 'gear' has 1 or 6 values"), 1u)
      << m.Messages();
  // motor, motor, motor (gear "1 2": first value), position
  EXPECT_EQ(m.module().actuators.size(), 4u);
}

TEST(MjcfActuator, UnknownJointAndAutolimitsOff) {
  {
    Mjcf m(Doc(R"(<actuator><motor joint="nope"/></actuator>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::UnknownReference, "nope"), 1u) << m.Messages();
  }
  {  // MJCF-004: a range under limited="auto" with autolimits off is E
    Mjcf m(Doc(R"(<compiler autolimits="false"/>
 <actuator><motor joint="ja" ctrlrange="-1 1"/></actuator>)"));
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::BadValue, "attribute 'ctrlrange' sets no limit while <compiler "
                                          "autolimits> is false; give 'ctrllimited'"),
              1u)
        << m.Messages();
    // with autolimits off, the ranged joints of Doc() are errors too
    m.ExpectDiagnostic(DiagKind::BadValue, "the joint 'range' is given but 'limited' is not");
  }
}

TEST(MjcfActuator, UnknownAttributeAndIncludeInsideSection) {
  // an <include> inside <actuator> is expanded in place; a misspelt attribute
  // gets its own (unknown-attribute) warning
  const std::string main = Doc(R"(<actuator><include file="acts.xml"/></actuator>)");
  const auto dir = std::filesystem::temp_directory_path() /
                   fmt::format("mdlc_mjcf_elements_inc_{}", ::getpid());
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "acts.xml")
      << R"(<mujoco><motor name="inc" joint="ja" ctrlrang="-1 1"/></mujoco>)";
  std::ofstream(dir / "model.xml") << main;
  Compilation c;
  c.options.inputs = {Input::File((dir / "model.xml").string())};
  const bool ok = c.Run();
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(ok);
  ASSERT_EQ(c.module.actuators.size(), 1u);
  EXPECT_EQ(c.module.Text(c.module.actuators[0].name), "inc");
  size_t unknown = 0;
  for (const auto& d : c.diags.diagnostics()) unknown += d.kind == DiagKind::UnknownAttribute;
  EXPECT_EQ(unknown, 1u);
}

// --- contact (MJCF-070) --------------------------------------------------------

TEST(MjcfContact, ExcludeFiltersExactlyThatPair) {
  Mjcf m(R"(<mujoco model="m"><worldbody>
  <body name="a"><freejoint/><geom size="0.1"/></body>
  <body name="b" pos="1 0 0"><freejoint/><geom size="0.1"/></body>
  <body name="c" pos="2 0 0"><freejoint/><geom size="0.1"/></body>
 </worldbody>
 <contact><exclude body1="a" body2="c"/><exclude body1="a"/></contact></mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Json()["collision_filters"], nlohmann::json::parse(R"([["m::a", "m::c"]])"));
  EXPECT_EQ(m.Count(DiagKind::UnsupportedElement, "exclude"), 1u) << m.Messages();
}

TEST(MjcfContact, PairWarnings) {
  Mjcf m(R"(<mujoco model="m"><worldbody>
  <body name="a"><geom name="ga" size="0.1"/>
   <body name="b"><joint/><geom name="gb" size="0.1"/></body></body>
  <body name="c" pos="2 0 0"><freejoint/><geom name="gc" size="0.1" contype="0" conaffinity="0"/></body>
 </worldbody>
 <contact>
  <pair geom1="ga" geom2="gb" condim="1"/>
  <pair geom1="ga" geom2="gc"/>
  <pair geom1="ga" geom2="nope"/>
 </contact></mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedValue, "joined by a joint"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedValue, "collision role"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "condim"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::IgnoredReference, "nope"), 1u) << m.Messages();
}

// --- keyframe (MJCF-008) -------------------------------------------------------

// The rule (MJCF-008, the issue's "keyframe (default positions)" item): the
// key named "home" if there is one, else the first <key>, sets the default
// configuration. Its qpos, in MuJoCo's layout over the joints in document
// order (hinge/slide 1 value, ball 4 (w x y z), free 7 (x y z, w x y z)),
// becomes each joint's default_positions, so the plant starts where MuJoCo's
// mj_resetDataKeyframe puts it. Hinge and slide values are the joint
// coordinate itself (qpos0 = ref, radians whatever <compiler angle> says);
// a ball's quaternion becomes roll-pitch-yaw, a free joint's pose
// [w x y z x y z]. Applying it is silent; other keys are only checked.

const nlohmann::json* JointJson(const nlohmann::json& plant, std::string_view name) {
  for (const auto& j : plant["joints"]) {
    if (j["name"] == name) return &j;
  }
  return nullptr;
}

TEST(MjcfKeyframe, HomeIsChosenOverTheFirstKey) {
  // nq = 1 + 1 + 7 (ja, jb, c's free joint): MuJoCo's layout
  Mjcf m(Doc(R"(<keyframe><key name="other" qpos="0 0 0 0 0 1 0 0 0"/>
  <key name="home" qpos="0.1 0.2 2 0.5 -1 1 0 0 0" qvel="0 0 1 0 0 0 0 0"/></keyframe>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.DiagCount(), 0u) << m.Messages();  // applied without a diagnostic
  const nlohmann::json plant = m.Json();
  // ja: 0.1 rad (the key is not in degrees, and not relative to ref = 30 deg)
  ExpectVector((*JointJson(plant, "ja"))["default_positions"], {0.1});
  ExpectVector((*JointJson(plant, "jb"))["default_positions"], {0.2});
  // c's free joint: x y z, w x y z -> [w x y z x y z]
  ExpectVector((*JointJson(plant, "c"))["default_positions"], {1, 0, 0, 0, 2, 0.5, -1});
  // the free body's default pose follows the key
  const ir::Module& mod = m.module();
  for (const auto& b : mod.bodies) {
    if (mod.Text(b.name) != "c") continue;
    ASSERT_TRUE(b.default_pose.has_value());
    EXPECT_TRUE(b.default_pose->p.isApprox(Eigen::Vector3d(2, 0.5, -1)));
  }
}

TEST(MjcfKeyframe, FirstKeyWithoutHome) {
  Mjcf m(Doc(R"(<keyframe><key name="a" qpos="-0.3 1.5 0 0 0 1 0 0 0"/>
  <key name="b" qpos="0 0 0 0 0 1 0 0 0"/></keyframe>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.DiagCount(), 0u) << m.Messages();
  const nlohmann::json plant = m.Json();
  ExpectVector((*JointJson(plant, "ja"))["default_positions"], {-0.3});
  ExpectVector((*JointJson(plant, "jb"))["default_positions"], {1.5});
  ExpectVector((*JointJson(plant, "c"))["default_positions"], {1, 0, 0, 0, 0, 0, 0});
}

TEST(MjcfKeyframe, KeyWithoutQposLeavesQpos0) {
  // "home" has no qpos: MuJoCo fills it with qpos0, so nothing moves (the
  // first key's qpos is not used either)
  Mjcf m(Doc(R"(<keyframe><key name="first" qpos="0 0 0 0 0 1 0 0 0"/>
  <key name="home" qvel="0 0 0 0 0 0 0 0"/></keyframe>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json plant = m.Json();
  ExpectVector((*JointJson(plant, "ja"))["default_positions"], {M_PI / 6});
  ExpectVector((*JointJson(plant, "jb"))["default_positions"], {0.25});
  ExpectVector((*JointJson(plant, "c"))["default_positions"], {1, 0, 0, 0, 2, 0, 0});
}

TEST(MjcfKeyframe, FreeBallHingeSlideLayout) {
  // qpos: free f (7: x y z, w x y z), ball s (4: w x y z), hinge h (1),
  // slide p (1, ref 0.1); the free quaternion is not normalized (MuJoCo's
  // kinematics normalizes it): w 0, z 2 is a half turn about z.
  const double c = std::cos(M_PI / 4), s = std::sin(M_PI / 4);
  Mjcf m(fmt::format(R"(<mujoco model="m">
 <compiler angle="degree"/>
 <worldbody>
  <body name="f" pos="0 0 1"><freejoint name="ff"/><geom size="0.1"/>
   <body name="ballb" pos="0.5 0 0"><joint name="s" type="ball"/><geom size="0.1"/>
    <body name="hb" pos="0.5 0 0"><joint name="h" axis="0 1 0" ref="10"/><geom size="0.1"/>
     <body name="pb" pos="0.5 0 0"><joint name="p" type="slide" ref="0.1"/><geom size="0.1"/></body>
    </body>
   </body>
  </body>
 </worldbody>
 <keyframe><key name="home" qpos="1 2 3 0 0 0 2 {} {} 0 0 0.7 0.4"/></keyframe>
</mujoco>
)",
                     c, s));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json plant = m.Json();
  ExpectVector((*JointJson(plant, "f"))["default_positions"], {0, 0, 0, 1, 1, 2, 3});
  // the ball's quarter turn about x is roll pi/2 (Drake's BallRpyJoint)
  ExpectVector((*JointJson(plant, "s"))["default_positions"], {M_PI / 2, 0, 0});
  ExpectVector((*JointJson(plant, "h"))["default_positions"], {0.7});  // radians
  ExpectVector((*JointJson(plant, "p"))["default_positions"], {0.4});
}

TEST(MjcfKeyframe, TooLongIsALocatedError) {
  // issue 62: only a key longer than nq, nv or nu is an error (a shorter one
  // is padded, below)
  Mjcf m(Doc(R"(<keyframe>
  <key name="k" qpos="0 0 0 0 0 0 0 0 0 0"/>
  <key qvel="1 1 1 1 1 1 1 1 1" ctrl="1"/>
  <key qpos="0 0" qvel="1 1" ctrl=""/>
 </keyframe>)"));
  EXPECT_FALSE(m.ok());
  EXPECT_EQ(m.Count(DiagKind::BadValue, "keyframe 'k': invalid qpos size, expected 9, got 10"),
            1u)
      << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::BadValue, "invalid qvel size, expected 8, got 9"), 1u)
      << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::BadValue, "invalid ctrl size, expected 0, got 1"), 1u)
      << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::BadValue), 3u) << m.Messages();
  EXPECT_EQ(m.Line(DiagKind::BadValue), 14u);
  // the chosen key (the first: no "home") has too long a qpos: not applied
  for (const auto& j : m.module().joints) {
    if (m.module().Text(j.name) == "ja") ExpectVector(j.default_positions, {M_PI / 6});
  }
}

TEST(MjcfKeyframe, ShortKeyIsPaddedAsMujoco338) {
  // issue 62: MuJoCo 3.3.8 pads a short key from the joints as written: the
  // slide's ref, and the free joint's zero pose (not its body's), as the
  // oracle shows (tests/models/mjcf/oracle/keyframe_short*.xml)
  Mjcf m(Doc(R"(<keyframe><key qpos="0.5" qvel="1"/></keyframe>)"));
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json plant = m.Json();
  ExpectVector((*JointJson(plant, "ja"))["default_positions"], {0.5});
  ExpectVector((*JointJson(plant, "jb"))["default_positions"], {0.25});
  ExpectVector((*JointJson(plant, "c"))["default_positions"], {1, 0, 0, 0, 0, 0, 0});
}

}  // namespace
}  // namespace mdlc
