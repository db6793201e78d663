// inertia_scaled_gains_test.cc - the MJCF gains MuJoCo derives from the
// joint-space inertia at qpos0: joint springdamper (BEYOND-007) and
// actuator dampratio (BEYOND-008), through the whole pipeline
// (backend/inertia_scaled_gains.h).
//
// Small hand-written MJCF files with closed forms. Numbers marked "MuJoCo
// 3.3.8" were read from mjModel (jnt_stiffness, dof_damping,
// actuator_biasprm) compiled by mujoco-js 0.0.7 from the same XML.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tools/driver/compiler.h"
#include "backend/plant_json.h"
#include "backend/positions.h"
#include "ir/printer.h"

namespace mdlc {
namespace {

/// The whole pipeline on one MJCF file (model.xml in a fresh folder).
class MjcfPipeline {
 public:
  explicit MjcfPipeline(std::string_view xml) {
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_scaled_gains_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    const auto path = dir_ / "model.xml";
    std::ofstream(path) << xml;
    c_.options.inputs = {Input::File(path.string())};
    ok_ = c_.Run();
  }
  ~MjcfPipeline() { std::filesystem::remove_all(dir_); }

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
  /// Diagnostics of `kind` whose message contains `text`.
  size_t Count(DiagKind kind, std::string_view text = "") const {
    size_t n = 0;
    for (const auto& d : c_.diags.diagnostics()) {
      n += d.kind == kind && d.message.find(text) != std::string::npos;
    }
    return n;
  }
  /// The first diagnostic of `kind` (null when none).
  const Diagnostic* First(DiagKind kind) const {
    for (const auto& d : c_.diags.diagnostics()) {
      if (d.kind == kind) return &d;
    }
    return nullptr;
  }
  size_t Warnings() const {
    size_t n = 0;
    for (const auto& d : c_.diags.diagnostics()) n += d.severity == Severity::Warning;
    return n;
  }
  nlohmann::json Json() const {
    return nlohmann::json::parse(
        backend::EmitPlantJson(*c_.model, backend::DefaultPositions(c_.model->plant)));
  }
  std::string Ir() const { return ir::PrintModule(c_.module, c_.sources, {}); }

  const nlohmann::json* Joint(const nlohmann::json& plant, std::string_view name) const {
    for (const auto& j : plant["joints"]) {
      if (j["name"] == name) return &j;
    }
    return nullptr;
  }
  /// The joint springs on `joint` (local name).
  std::vector<nlohmann::json> Springs(const nlohmann::json& plant, std::string_view joint) const {
    std::vector<nlohmann::json> out;
    for (const auto& f : plant.value("force_elements", nlohmann::json::array())) {
      const std::string j = f.value("joint", "");
      if (j.size() >= joint.size() && j.substr(j.size() - joint.size()) == joint &&
          (j.size() == joint.size() || j[j.size() - joint.size() - 1] == ':')) {
        out.push_back(f);
      }
    }
    return out;
  }
  const nlohmann::json* Actuator(const nlohmann::json& plant, std::string_view name) const {
    for (const auto& a : plant["actuators"]) {
      if (a["name"] == name) return &a;
    }
    return nullptr;
  }

 private:
  std::filesystem::path dir_;
  Compilation c_;
  bool ok_ = false;
};

// BEYOND-007: one hinge, COM 0.5 m off the axis: M = m l^2 + Izz + armature
// = 2 * 0.25 + 0.03 + 0.07 = 0.6; springdamper 0.5 2 gives stiffness
// M / (0.5 * 2)^2 = 0.6 and damping 2 M / 0.5 = 2.4 (MuJoCo 3.3.8: 0.6, 2.4).
TEST(InertiaScaledGains, Beyond007SingleHingeClosedForm) {
  MjcfPipeline m(R"(<mujoco model="sd">
 <worldbody>
  <body name="a" pos="0 0 1">
   <joint name="ja" axis="0 0 1" armature="0.07" springref="30" springdamper="0.5 2"/>
   <inertial pos="0.5 0 0" mass="2" diaginertia="0.01 0.02 0.03"/>
  </body>
 </worldbody>
</mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  // springdamper is supported now: the one warning is that the armature,
  // which the gains count, is not in the mass matrix (no actuator, MJCF-024)
  EXPECT_EQ(m.Warnings(), 1u) << m.Messages();
  EXPECT_NE(m.Messages().find("armature 0.07 of joint 'ja' is left out of the mass matrix"),
            std::string::npos)
      << m.Messages();
  const nlohmann::json plant = m.Json();
  const nlohmann::json* ja = m.Joint(plant, "ja");
  ASSERT_NE(ja, nullptr);
  ASSERT_EQ((*ja)["damping"].size(), 1u);
  EXPECT_NEAR((*ja)["damping"][0].get<double>(), 2.4, 1e-14);
  const auto springs = m.Springs(plant, "ja");
  ASSERT_EQ(springs.size(), 1u) << plant["force_elements"];
  EXPECT_EQ(springs[0]["type"], "revolute_spring");
  EXPECT_NEAR(springs[0]["stiffness"].get<double>(), 0.6, 1e-14);
  EXPECT_NEAR(springs[0]["nominal"].get<double>(), M_PI / 6, 1e-15);  // springref, degrees
}

// BEYOND-007/008: a planar double pendulum (unit masses, COMs 0.5 m out,
// links 1 m, Izz 0.01). Straight, as the XML places it at qpos0 (j2's ref
// of 90 degrees only shifts its coordinate): M11 = 2.52, M12 = 0.76, M22 =
// 0.26, det M = 0.0776. springdamper reads 1 / (M^-1)_kk, not M_kk:
// I1 = det / M22, I2 = det / M11; stiffness I / 0.4^2, damping 2 I / 0.4
// (MuJoCo 3.3.8: stiffness 1.8653846153846156, 0.1924603174603175; damping
// 1.4923076923076928, 0.15396825396825403). dampratio reads M_kk (dof_M0)
// through the gear: p2 kd = 2 * 0.5 * sqrt(50 * 0.26 / 2^2) = sqrt(3.25),
// g1 kd = 2 * 0.8 * sqrt(30 * 2.52) (MuJoCo 3.3.8 biasprm[2]:
// -1.8027756377319946, -13.911721676341863). The home key bends the
// chain; the gains still come from qpos0.
TEST(InertiaScaledGains, Beyond007Beyond008DoublePendulumAtQpos0NotTheKey) {
  MjcfPipeline m(R"(<mujoco model="chain">
 <worldbody>
  <body name="a">
   <joint name="j1" axis="0 0 1" springdamper="0.4 1"/>
   <inertial pos="0.5 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
   <body name="b" pos="1 0 0">
    <joint name="j2" axis="0 0 1" ref="90" springref="45" springdamper="0.4 1"/>
    <inertial pos="0.5 0 0" mass="1" diaginertia="0.01 0.01 0.01"/>
   </body>
  </body>
 </worldbody>
 <actuator>
  <position name="p2" joint="j2" kp="50" dampratio="0.5" gear="2"/>
  <general name="g1" joint="j1" gainprm="30" biastype="affine" biasprm="0 -30 0.8"/>
 </actuator>
 <keyframe><key name="home" qpos="0.3 0"/></keyframe>
</mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_EQ(m.Warnings(), 0u) << m.Messages();
  const nlohmann::json plant = m.Json();
  const double det = 2.52 * 0.26 - 0.76 * 0.76;
  const double I1 = det / 0.26, I2 = det / 2.52;
  const nlohmann::json* j1 = m.Joint(plant, "j1");
  const nlohmann::json* j2 = m.Joint(plant, "j2");
  ASSERT_TRUE(j1 && j2);
  EXPECT_NEAR((*j1)["damping"][0].get<double>(), 2 * I1 / 0.4, 1e-12);
  EXPECT_NEAR((*j2)["damping"][0].get<double>(), 2 * I2 / 0.4, 1e-12);
  EXPECT_NEAR((*j1)["damping"][0].get<double>(), 1.4923076923076928, 1e-12);
  EXPECT_NEAR((*j2)["damping"][0].get<double>(), 0.15396825396825403, 1e-12);
  const auto s1 = m.Springs(plant, "j1"), s2 = m.Springs(plant, "j2");
  ASSERT_EQ(s1.size(), 1u);
  ASSERT_EQ(s2.size(), 1u);
  EXPECT_NEAR(s1[0]["stiffness"].get<double>(), 1.8653846153846156, 1e-12);
  EXPECT_NEAR(s2[0]["stiffness"].get<double>(), 0.1924603174603175, 1e-12);
  EXPECT_NEAR(s1[0]["nominal"].get<double>(), 0, 1e-15);
  EXPECT_NEAR(s2[0]["nominal"].get<double>(), M_PI / 4, 1e-15);
  // the key is the default configuration, not where the gains come from
  EXPECT_NEAR((*j2)["default_positions"][0].get<double>(), 0, 1e-15);

  const nlohmann::json* p2 = m.Actuator(plant, "p2");
  const nlohmann::json* g1 = m.Actuator(plant, "g1");
  ASSERT_TRUE(p2 && g1);
  EXPECT_EQ((*p2)["kp"], 50);
  EXPECT_NEAR((*p2)["kd"].get<double>(), std::sqrt(3.25), 1e-13);
  EXPECT_NEAR((*p2)["kd"].get<double>(), 1.8027756377319946, 1e-13);
  EXPECT_EQ((*g1)["kp"], 30);
  EXPECT_NEAR((*g1)["kd"].get<double>(), 2 * 0.8 * std::sqrt(30 * 2.52), 1e-12);
  EXPECT_NEAR((*g1)["kd"].get<double>(), 13.911721676341863, 1e-12);
}

// BEYOND-007: MuJoCo's "simple" body (parent world, no children, only
// slides at its origin along its axes, inertia frame = body frame) takes
// dof_invweight0 = 1 / mass, leaving the armature out: mass 2, armature 0.5
// gives I = 2, stiffness 2 / 0.5^2 = 8, damping 2 * 2 / 0.5 = 8. With the
// COM 1e-5 off the origin it is not simple: I = 2.5, stiffness and damping
// 10 (MuJoCo 3.3.8: 8, 8 and 10, 10).
TEST(InertiaScaledGains, Beyond007SimpleSlideBodyUsesItsMass) {
  for (const auto& [com, expected] : {std::pair{"0 0 0", 8.0}, std::pair{"0 0 1e-5", 10.0}}) {
    MjcfPipeline m(fmt::format(R"(<mujoco model="s">
 <worldbody>
  <body name="s" pos="0 0 1">
   <joint name="sx" type="slide" axis="1 0 0" armature="0.5" springdamper="0.5 1"/>
   <inertial pos="{}" mass="2" diaginertia="0.1 0.1 0.1"/>
  </body>
 </worldbody>
</mujoco>)",
                               com));
    ASSERT_TRUE(m.ok()) << m.Messages();
    const nlohmann::json plant = m.Json();
    const nlohmann::json* sx = m.Joint(plant, "sx");
    ASSERT_NE(sx, nullptr);
    EXPECT_NEAR((*sx)["damping"][0].get<double>(), expected, 1e-12) << com;
    const auto springs = m.Springs(plant, "sx");
    ASSERT_EQ(springs.size(), 1u);
    EXPECT_EQ(springs[0]["type"], "prismatic_spring");
    EXPECT_NEAR(springs[0]["stiffness"].get<double>(), expected, 1e-12) << com;
  }
  // below a moving parent the body is not simple either: the armature counts
  MjcfPipeline m(R"(<mujoco model="s">
 <worldbody>
  <body name="p"><joint name="pz" type="slide" axis="0 0 1"/><geom size="0.1"/>
   <body name="s"><joint name="sx" type="slide" axis="1 0 0" armature="0.5" springdamper="0.5 1"/>
    <inertial pos="0 0 0" mass="2" diaginertia="0.1 0.1 0.1"/></body>
  </body>
 </worldbody>
</mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  EXPECT_NEAR((*m.Joint(m.Json(), "sx"))["damping"][0].get<double>(), 10, 1e-12);
}

// BEYOND-007: a ball joint's damping is 2 I / timeconst on its three dofs,
// I = 3 / trace of its block of M^-1 (here the body's principal moments
// about its COM at the joint: 3 / (1/0.1 + 1/0.2 + 1/0.3)); the plant has
// no ball-joint stiffness, which is warned about. On a free joint nothing
// is kept, with a warning.
TEST(InertiaScaledGains, Beyond007BallDampingOnlyFreeIgnored) {
  MjcfPipeline m(R"(<mujoco model="b">
 <worldbody>
  <body name="ball" pos="0 0 1">
   <joint name="jb" type="ball" springdamper="0.5 1"/>
   <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.2 0.3"/>
  </body>
  <body name="floater" pos="1 0 1">
   <joint name="jf" type="free" springdamper="0.5 1"/>
   <geom size="0.1"/>
  </body>
 </worldbody>
</mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  const nlohmann::json plant = m.Json();
  const double I = 3 / (10 + 5 + 10.0 / 3);
  const nlohmann::json* jb = m.Joint(plant, "jb");
  ASSERT_NE(jb, nullptr);
  ASSERT_EQ((*jb)["damping"].size(), 3u);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR((*jb)["damping"][k].get<double>(), 2 * I / 0.5, 1e-12);
  EXPECT_TRUE(m.Springs(plant, "jb").empty());
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "<joint type=\"ball\">"), 1u) << m.Messages();
  EXPECT_EQ(m.Count(DiagKind::UnsupportedAttribute, "<joint type=\"free\">"), 1u) << m.Messages();
}

// MuJoCo: springdamper "0 0" (its default) asks for nothing; otherwise both
// values must be positive (a compiler error, here located at the
// attribute). With springdamper in force the joint's own stiffness and
// damping are ignored (MuJoCo overwrites them), with a warning each.
TEST(InertiaScaledGains, Beyond007ZeroNegativeAndOverriddenValues) {
  {
    MjcfPipeline m(R"(<mujoco model="z">
 <worldbody><body><joint name="j" springdamper="0 0" stiffness="3" damping="0.25"/>
  <geom size="0.1" pos="0.3 0 0"/></body></worldbody>
</mujoco>)");
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Warnings(), 0u) << m.Messages();
    const nlohmann::json plant = m.Json();
    EXPECT_EQ((*m.Joint(plant, "j"))["damping"][0], 0.25);
    const auto springs = m.Springs(plant, "j");
    ASSERT_EQ(springs.size(), 1u);
    EXPECT_EQ(springs[0]["stiffness"], 3);
    EXPECT_TRUE(m.module().inertia_scaled_gains.empty());
  }
  for (const char* bad : {"0 1", "0.5 -1", "-1 0"}) {
    MjcfPipeline m(fmt::format(R"(<mujoco model="z">
 <worldbody><body><joint name="j" springdamper="{}"/>
  <geom size="0.1" pos="0.3 0 0"/></body></worldbody>
</mujoco>)",
                               bad));
    EXPECT_FALSE(m.ok()) << bad;
    const Diagnostic* d = m.First(DiagKind::BadValue);
    ASSERT_NE(d, nullptr) << bad << "\n" << m.Messages();
    EXPECT_NE(d->message.find("must both be positive"), std::string::npos) << d->message;
    EXPECT_EQ(d->loc.line, 2u);
    EXPECT_EQ(d->loc.column, 35u) << m.Messages();  // the springdamper attribute
  }
  {
    MjcfPipeline m(R"(<mujoco model="z">
 <worldbody><body><joint name="j" springdamper="0.5 1" stiffness="3" damping="0.25"/>
  <geom size="0.1" pos="0.3 0 0"/></body></worldbody>
</mujoco>)");
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Count(DiagKind::JointWarning, "stiffness is ignored"), 1u) << m.Messages();
    EXPECT_EQ(m.Count(DiagKind::JointWarning, "damping is ignored"), 1u) << m.Messages();
    const nlohmann::json plant = m.Json();
    // one spring, springdamper's: sphere 4/3 pi 0.1^3 1000 at 0.3 m
    const double mass = 4.0 / 3 * M_PI * 1e-3 * 1000;
    const double M = mass * (0.09 + 0.4 * 0.01);
    const auto springs = m.Springs(plant, "j");
    ASSERT_EQ(springs.size(), 1u);
    EXPECT_NEAR(springs[0]["stiffness"].get<double>(), M / 0.25, 1e-12);
    EXPECT_NEAR((*m.Joint(plant, "j"))["damping"][0].get<double>(), 2 * M / 0.5, 1e-12);
  }
}

// Two hinges that move a body alike make M singular: MuJoCo's factorization
// divides by about 0 (its jnt_stiffness is 4e15 here); mdlc reports it at
// the springdamper.
TEST(InertiaScaledGains, Beyond007SingularInertiaIsLocatedError) {
  MjcfPipeline m(R"(<mujoco model="s">
 <worldbody><body name="a">
  <joint name="h1" springdamper="0.5 1"/><joint name="h2"/>
  <geom size="0.1" pos="0.2 0 0"/></body></worldbody>
</mujoco>)");
  EXPECT_FALSE(m.ok());
  const Diagnostic* d = m.First(DiagKind::BadMassProperties);
  ASSERT_NE(d, nullptr) << m.Messages();
  EXPECT_NE(d->message.find("model 's' at qpos0 is singular"), std::string::npos) << d->message;
  EXPECT_EQ(d->loc.line, 3u);
  EXPECT_EQ(d->loc.column, 20u);
}

// BEYOND-008: a position's dampratio is read from its default class and
// turned into kd (M_kk of a single hinge: 0.6 as above, kd = 2 * 0.7 *
// sqrt(20 * 0.6)); kp 0 leaves no gains (MuJoCo: 2 dampratio sqrt(0) = 0);
// kv and dampratio together stay an error.
TEST(InertiaScaledGains, Beyond008PositionDampratioFromDefaultClass) {
  const std::string body = R"(<worldbody>
  <body name="a" pos="0 0 1">
   <joint name="ja" axis="0 0 1" armature="0.07"/>
   <inertial pos="0.5 0 0" mass="2" diaginertia="0.01 0.02 0.03"/>
  </body>
 </worldbody>)";
  {
    MjcfPipeline m(
        R"(<mujoco model="p"><default><position kp="20" dampratio="0.7"/></default>)" + body +
        R"(<actuator><position name="servo" joint="ja"/><position name="limp" joint="ja" kp="0"/></actuator></mujoco>)");
    ASSERT_TRUE(m.ok()) << m.Messages();
    EXPECT_EQ(m.Warnings(), 0u) << m.Messages();
    const nlohmann::json plant = m.Json();
    const nlohmann::json* servo = m.Actuator(plant, "servo");
    ASSERT_NE(servo, nullptr);
    EXPECT_EQ((*servo)["kp"], 20);
    EXPECT_NEAR((*servo)["kd"].get<double>(), 2 * 0.7 * std::sqrt(20 * 0.6), 1e-12);
    const nlohmann::json* limp = m.Actuator(plant, "limp");
    ASSERT_NE(limp, nullptr);
    EXPECT_TRUE((*limp)["kp"].is_null());
    EXPECT_TRUE((*limp)["kd"].is_null());
  }
  {
    MjcfPipeline m(R"(<mujoco model="p">)" + body +
                   R"(<actuator><position joint="ja" kv="1" dampratio="1"/></actuator></mujoco>)");
    EXPECT_FALSE(m.ok());
    EXPECT_EQ(m.Count(DiagKind::BadValue, "kv and dampratio cannot both be defined"), 1u)
        << m.Messages();
  }
}

// The request is in the IR until the backend computes it (--emit=ir).
TEST(InertiaScaledGains, IrPrinterShowsRequests) {
  MjcfPipeline m(R"(<mujoco model="chain">
 <worldbody>
  <body name="a"><joint name="j1" axis="0 0 1" ref="10" armature="0.5" springdamper="0.4 1"/>
   <inertial pos="0.5 0 0" mass="1" diaginertia="0.01 0.01 0.01"/></body>
 </worldbody>
 <actuator><position name="p" joint="j1" kp="5" dampratio="0.5"/></actuator>
</mujoco>)");
  ASSERT_TRUE(m.ok()) << m.Messages();
  const std::string ir = m.Ir();
  EXPECT_NE(ir.find("inertia_scaled_gains model=chain joints=[chain::j1@0.17453292519943295"
                    "+armature=0.5]"),
            std::string::npos)
      << ir;
  EXPECT_NE(ir.find("springdamper joint=chain::j1 timeconst=0.4 dampratio=1 springref=0"),
            std::string::npos)
      << ir;
  EXPECT_NE(ir.find("dampratio actuator=\"p\" dampratio=0.5"), std::string::npos) << ir;
}

}  // namespace
}  // namespace mdlc
