// unique_names_test.cc - the unique-names pass and the verifier's Named
// level: a name the compiler makes never takes a name the file gave, and
// plant-json never holds two entities of a kind with one (instance, name)
// (MJCF-020, MJCF-021, MJCF-023, COMMON-020, COMMON-042).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "ir/verifier.h"
#include "tests/unit/compile_test_util.h"

namespace mdlc {
namespace {

using testing::CompiledText;
using testing::Entry;

// Every compiler-made MJCF name next to an entity the file named the same:
//   vertebra_C1 has two joints, so the body between them is `vertebra_C10`,
//     which the file also names;
//   the unnamed fifth body is `body5`, the name of the file's fourth body;
//   body5 has no joint, so its weld is `world_welds_to_body5`, a joint the
//     file names;
//   the first geom of vertebra_C10 is `geom0`, as its second is named;
//   the first camera is `camera0`, the second's name; the first motor is
//   `motor0`, the second's name.
constexpr const char* kSpine = R"(<mujoco model="spine">
 <worldbody>
  <body name="vertebra_C1" pos="0 0 1">
   <joint name="flex" axis="1 0 0"/>
   <joint name="twist" axis="0 0 1"/>
   <geom size="0.05"/>
   <body name="vertebra_C10" pos="0 0 0.1">
    <joint name="world_welds_to_body5" axis="0 1 0"/>
    <geom size="0.03"/>
    <geom name="geom0" size="0.02" pos="0 0 0.05"/>
   </body>
  </body>
  <body name="body5" pos="1 0 0">
   <geom size="0.1"/>
   <camera pos="0 0 1"/>
   <camera name="camera0" pos="0 0 2"/>
  </body>
  <body pos="2 0 0"><freejoint/><geom size="0.1"/></body>
 </worldbody>
 <actuator>
  <motor joint="flex"/>
  <motor name="motor0" joint="twist"/>
 </actuator>
</mujoco>
)";

// (instance, name) of every entry of a plant-json list, counted
std::map<std::pair<std::string, std::string>, int> Names(const nlohmann::json& list) {
  std::map<std::pair<std::string, std::string>, int> names;
  for (const auto& e : list) ++names[{e.value("model_instance", ""), e.value("name", "")}];
  return names;
}

TEST(UniqueNames, MadeNamesGiveWayToTheFilesNames) {  // MJCF-020, MJCF-021, MJCF-023
  CompiledText c("spine.xml", kSpine);
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json j = c.Json();

  // the file's names are kept; the made ones take the next free name
  const nlohmann::json* inserted = Entry(j["bodies"], "vertebra_C10_1", "spine");
  ASSERT_NE(inserted, nullptr) << j["bodies"].dump(1);
  EXPECT_EQ(inserted->value("unnamed", false), true);
  EXPECT_EQ(inserted->value("mass", -1.0), 0.0);  // the massless body between the joints
  ASSERT_NE(Entry(j["bodies"], "vertebra_C10", "spine"), nullptr);
  EXPECT_FALSE(Entry(j["bodies"], "vertebra_C10", "spine")->contains("unnamed"));
  ASSERT_NE(Entry(j["bodies"], "body5_1", "spine"), nullptr);
  EXPECT_EQ(Entry(j["bodies"], "body5_1", "spine")->value("unnamed", false), true);
  EXPECT_FALSE(Entry(j["bodies"], "body5", "spine")->contains("unnamed"));

  // the joints: twist now connects the inserted body; the weld and the free
  // joint (named after its renamed body) are made, flex and the file's
  // `world_welds_to_body5` are not
  const nlohmann::json* flex = Entry(j["joints"], "flex", "spine");
  ASSERT_NE(flex, nullptr);
  EXPECT_EQ(flex->value("child", ""), "spine::vertebra_C10_1");
  EXPECT_EQ(Entry(j["joints"], "twist", "spine")->value("parent", ""), "spine::vertebra_C10_1");
  EXPECT_EQ(Entry(j["joints"], "world_welds_to_body5", "spine")->value("child", ""),
            "spine::vertebra_C10");
  const nlohmann::json* weld = Entry(j["joints"], "world_welds_to_body5_1", "spine");
  ASSERT_NE(weld, nullptr) << j["joints"].dump(1);
  EXPECT_EQ(weld->value("type", ""), "weld");
  EXPECT_EQ(weld->value("unnamed", false), true);
  const nlohmann::json* free = Entry(j["joints"], "body5_1", "spine");
  ASSERT_NE(free, nullptr) << j["joints"].dump(1);
  EXPECT_EQ(free->value("type", ""), "quaternion_floating");
  EXPECT_EQ(free->value("child", ""), "spine::body5_1");

  // geometry, camera and actuator
  std::set<std::string> c10_geoms;
  for (const auto& g : j["geometries"]) {
    if (g.value("body", "") == "spine::vertebra_C10") c10_geoms.insert(g.value("name", ""));
  }
  EXPECT_EQ(c10_geoms, (std::set<std::string>{"geom0", "geom0_1"}));
  for (const auto& g : j["geometries"]) {
    if (g.value("body", "") != "spine::vertebra_C10") continue;
    EXPECT_EQ(g.value("unnamed", false), g.value("name", "") != "geom0") << g.dump();
  }
  ASSERT_NE(Entry(j["cameras"], "spine/camera0_1", "spine"), nullptr) << j["cameras"].dump(1);
  EXPECT_EQ(Entry(j["cameras"], "spine/camera0_1", "spine")->value("unnamed", false), true);
  EXPECT_FALSE(Entry(j["cameras"], "spine/camera0", "spine")->contains("unnamed"));
  ASSERT_NE(Entry(j["actuators"], "motor0_1", "spine"), nullptr);
  EXPECT_EQ(Entry(j["actuators"], "motor0_1", "spine")->value("joint", ""), "spine::flex");
  EXPECT_EQ(Entry(j["actuators"], "motor0", "spine")->value("joint", ""), "spine::twist");

  // no (instance, name) twice in any list but geometries, whose visual and
  // collision registrations share a name
  for (const char* list : {"bodies", "joints", "frames", "actuators", "cameras"}) {
    for (const auto& [key, n] : Names(j[list])) {
      EXPECT_EQ(n, 1) << list << " " << key.first << "::" << key.second;
    }
  }

  // each made name that gave way is noted
  for (const char* name : {"body name 'vertebra_C10'", "body name 'body5'",
                           "joint name 'world_welds_to_body5'", "actuator name 'motor0'",
                           "camera name 'spine/camera0'", "geometry name 'geom0'"}) {
    c.ExpectDiagnostic(DiagKind::SynthesizedNameTaken, name);
  }
  // one note for the <geom>, though it is registered twice (visual, collision)
  EXPECT_EQ(c.Find(DiagKind::SynthesizedNameTaken, "geometry name 'geom0'").size(), 1u);
}

TEST(UniqueNames, EachRenameIsANoteAtTheMadeEntity) {
  CompiledText c("spine.xml", kSpine);
  ASSERT_TRUE(c.ok()) << c.Messages();
  const auto notes = c.Find(DiagKind::SynthesizedNameTaken);
  // the inserted body, the unnamed body, the weld, the unnamed geom (once for
  // its two registrations), the camera and the motor
  std::multiset<std::string> renamed;
  for (const Diagnostic* d : notes) {
    EXPECT_EQ(d->severity, Severity::Note);
    renamed.insert(d->message.substr(d->message.rfind(" named '")));
  }
  EXPECT_EQ(renamed, (std::multiset<std::string>{
                         " named 'vertebra_C10_1'", " named 'body5_1'",
                         " named 'world_welds_to_body5_1'", " named 'geom0_1'",
                         " named 'spine/camera0_1'", " named 'motor0_1'"}))
      << c.Messages();
  const auto body = c.Find(DiagKind::SynthesizedNameTaken, "'vertebra_C10'");
  ASSERT_EQ(body.size(), 1u);
  EXPECT_EQ(body[0]->message,
            "the body name 'vertebra_C10' that mdlc made is already used in model instance "
            "'spine'; this body is named 'vertebra_C10_1'");
  EXPECT_EQ(body[0]->loc.line, 4u);  // the first joint, where the inserted body begins
  EXPECT_EQ(c.diagnostics().size(), notes.size()) << c.Messages();  // nothing else to say
}

TEST(UniqueNames, WithoutAClashNothingIsRenamed) {
  CompiledText c("chain.xml", R"(<mujoco model="chain">
 <worldbody>
  <body name="link" pos="0 0 1">
   <joint name="a" axis="1 0 0"/><joint name="b" axis="0 1 0"/><geom size="0.05"/>
  </body>
 </worldbody>
</mujoco>
)");
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json j = c.Json();
  ASSERT_NE(Entry(j["bodies"], "link0", "chain"), nullptr) << j["bodies"].dump(1);
  EXPECT_EQ(Entry(j["bodies"], "link0", "chain")->value("unnamed", false), true);  // MJCF-023
  EXPECT_TRUE(c.Find(DiagKind::SynthesizedNameTaken).empty());
}

// Four unnamed bodies of three slides each: the bodies between the joints of
// body1 are body10 and body11, so the fourth body, made `body10`, is renamed
// `body10_1`; the bodies between its joints and its unnamed joints are named
// after it as renamed (`body10_10`, not `body100`, which would be the name
// of the intermediates of a later unnamed body100 too) (MJCF-020, MJCF-023)
TEST(UniqueNames, NamesMadeFromARenamedBodyFollowIt) {
  std::string xml = "<mujoco model=\"grid\">\n <worldbody>\n";
  for (int i = 0; i < 4; ++i) {
    xml += "  <body pos=\"" + std::to_string(i) + " 0 0\"><joint type=\"slide\" axis=\"1 0 0\"/>"
           "<joint type=\"slide\" axis=\"0 1 0\"/><joint type=\"slide\" axis=\"0 0 1\"/>"
           "<geom size=\"0.1\"/></body>\n";
  }
  xml += " </worldbody>\n</mujoco>\n";
  CompiledText c("grid.xml", xml);
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json j = c.Json();
  std::vector<std::string> bodies;
  for (const auto& b : j["bodies"]) {
    if (b.value("name", "") != "world") bodies.push_back(b.value("name", ""));
  }
  EXPECT_EQ(bodies, (std::vector<std::string>{"body1", "body10", "body11", "body4", "body40",
                                              "body41", "body7", "body70", "body71", "body10_1",
                                              "body10_10", "body10_11"}));
  for (const auto& [name, parent, child] :
       {std::tuple{"world-body10_10", "world", "grid::body10_10"},
        std::tuple{"body10_10-body10_11", "grid::body10_10", "grid::body10_11"},
        std::tuple{"body10_11-body10_1", "grid::body10_11", "grid::body10_1"},
        std::tuple{"body10-body11", "grid::body10", "grid::body11"}}) {
    const nlohmann::json* joint = Entry(j["joints"], name, "grid");
    ASSERT_NE(joint, nullptr) << name << "\n" << j["joints"].dump(1);
    EXPECT_EQ(joint->value("parent", ""), parent) << name;
    EXPECT_EQ(joint->value("child", ""), child) << name;
  }
  // the one name that gave way is noted; those following it are not
  const auto notes = c.Find(DiagKind::SynthesizedNameTaken);
  ASSERT_EQ(notes.size(), 1u) << c.Messages();
  EXPECT_EQ(notes[0]->message,
            "the body name 'body10' that mdlc made is already used in model instance 'grid'; "
            "this body is named 'body10_1'");
}

TEST(UniqueNames, UrdfFloatingJointKeepsDrakesUnderscoreRule) {  // URDF-017
  // Drake names a free body's joint after the body, prefixing '_' while a
  // joint has the name: that rule is kept, and no note is needed
  CompiledText c("r.urdf", R"(<robot name="r">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="a" type="fixed"><parent link="b"/><child link="c"/></joint>
</robot>
)");
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json j = c.Json();
  ASSERT_NE(Entry(j["joints"], "_a", "r"), nullptr) << j["joints"].dump(1);
  EXPECT_EQ(Entry(j["joints"], "_a", "r")->value("unnamed", false), true);
  EXPECT_TRUE(c.Find(DiagKind::SynthesizedNameTaken).empty());
}

// --- the verifier (ir/verifier.h, VerifyLevel::Named) ------------------------

ir::Module TwoBodies(std::string_view first, std::string_view second,
                     bool second_in_another_instance = false) {
  ir::Module m;
  const ModelId other =
      m.Add(ir::ModelInstance{m.Intern("other"), {}, ir::SourceFormat::Internal, {}, {}});
  for (auto [name, model] : {std::pair{first, ir::kDefaultModel},
                             std::pair{second, second_in_another_instance ? other
                                                                          : ir::kDefaultModel}}) {
    ir::Body b;
    b.name = m.Intern(name);
    b.model = model;
    const BodyId id = m.Add(b);
    ir::Joint j;
    j.name = m.Intern(name);
    j.model = model;
    j.type = ir::JointType::Weld;
    j.parent = {m.Intern("world"), {}, ir::kWorldBody};
    j.child = {b.name, {}, id};
    m.Add(j);
  }
  return m;
}

TEST(VerifierNamed, TwoBodiesOfOneNameInOneInstanceFail) {
  DiagnosticEngine diags;
  const ir::Module same = TwoBodies("a", "a");
  EXPECT_TRUE(ir::VerifyModule(same, ir::VerifyLevel::Tree, diags));  // not checked before
  EXPECT_FALSE(ir::VerifyModule(same, ir::VerifyLevel::Named, diags));
  ASSERT_FALSE(diags.diagnostics().empty());
  EXPECT_EQ(diags.diagnostics()[0].kind, DiagKind::VerifierFailure);
  EXPECT_NE(diags.diagnostics()[0].message.find("two body entities are named 'a'"),
            std::string::npos)
      << diags.diagnostics()[0].message;

  DiagnosticEngine fine;
  EXPECT_TRUE(ir::VerifyModule(TwoBodies("a", "b"), ir::VerifyLevel::Named, fine));
  // one name in two instances is two scoped names
  EXPECT_TRUE(ir::VerifyModule(TwoBodies("a", "a", true), ir::VerifyLevel::Named, fine));
}

TEST(VerifierNamed, GeometriesAreUniquePerBodyAndRole) {
  ir::Module m = TwoBodies("a", "b");
  auto add = [&](uint32_t body, uint8_t roles) {
    ir::Geometry g;
    g.name = m.Intern("shape");
    g.model = ir::kDefaultModel;
    g.body = {m.bodies[body].name, {}, BodyId(body)};
    g.roles = roles;
    m.Add(g);
  };
  add(1, ir::kProximityRole);
  add(1, ir::kIllustrationRole);  // a visual and a collision of one name: fine
  add(2, ir::kProximityRole);     // another body: fine
  DiagnosticEngine diags;
  EXPECT_TRUE(ir::VerifyModule(m, ir::VerifyLevel::Named, diags));
  add(1, ir::kIllustrationRole | ir::kPerceptionRole);  // a second visual of that name
  EXPECT_FALSE(ir::VerifyModule(m, ir::VerifyLevel::Named, diags));
}

}  // namespace
}  // namespace mdlc
