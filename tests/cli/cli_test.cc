// Behaviour of the mdlc command line: exit codes, diagnostics formats and
// policy flags, pass instrumentation, determinism, and inputs that must not
// crash or hang (deep chains, empty files, entity declarations).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_fixture.h"

namespace {

using mdlc::cli_test::CliFixture;
using mdlc::cli_test::Outcome;
using mdlc::cli_test::ReadFile;
namespace fs = std::filesystem;

class CliTest : public CliFixture {};

const char* kPendulum = R"(<?xml version="1.0"?>
<robot name="pendulum">
  <link name="base"/>
  <link name="arm">
    <inertial>
      <origin xyz="0 0 -0.5"/>
      <mass value="2"/>
      <inertia ixx="0.01" iyy="0.01" izz="0.001" ixy="0" ixz="0" iyz="0"/>
    </inertial>
    <visual><geometry><cylinder radius="0.02" length="1"/></geometry></visual>
    <collision><geometry><cylinder radius="0.02" length="1"/></geometry></collision>
  </link>
  <joint name="base_weld" type="fixed"><parent link="world"/><child link="base"/></joint>
  <joint name="theta" type="revolute">
    <parent link="base"/><child link="arm"/>
    <axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="5"/>
  </joint>
</robot>
)";

TEST_F(CliTest, SuccessExitsZeroAndPrintsSummary) {
  Outcome r = Mdlc("compile " + Write("p.urdf", kPendulum).string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("bodies: 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("total mass: 2 kg"), std::string::npos) << r.out;
}

TEST_F(CliTest, BadUsageExitsTwo) {
  EXPECT_EQ(Mdlc("compile").status, 2);
  EXPECT_EQ(Mdlc("compile x.urdf --emit=bogus").status, 2);
}

TEST_F(CliTest, EmptyFileIsALocatedError) {  // COMMON-004
  Outcome r = Mdlc("compile " + Write("empty.urdf", "").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("empty.urdf:1:1: error: the file is empty; an XML model needs a root element"),
            std::string::npos)
      << r.err;
}

TEST_F(CliTest, MissingFileAndUnknownExtensionAreErrors) {  // COMMON-005
  Outcome missing = Mdlc("compile " + (dir_ / "nope.urdf").string());
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("cannot read"), std::string::npos) << missing.err;
  Outcome ext = Mdlc("compile " + Write("model.txt", kPendulum).string());
  EXPECT_EQ(ext.status, 1);
  EXPECT_NE(ext.err.find("extension"), std::string::npos) << ext.err;
}

TEST_F(CliTest, TextDiagnosticsShowSourceLineAndCaretAtTheAttribute) {
  Outcome r = Mdlc("compile " + Write("bad.urdf", R"(<robot name="r">
  <link name="a"><inertial><mass value="heavy"/></inertial></link>
</robot>
)").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("bad.urdf:2:34: error: attribute 'value' of <mass> must be numbers"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("  <link name=\"a\"><inertial><mass value=\"heavy\"/></inertial></link>\n"
                       "                                 ^\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("1 error generated."), std::string::npos);
}

TEST_F(CliTest, JsonDiagnosticsAreOneObjectPerLine) {
  Outcome r = Mdlc("compile --diagnostics-format=json " +
                 Write("bad.urdf", R"(<robot name="r">
  <link name="a"><inertial><mass value="nan"/></inertial></link>
  <lnk/>
</robot>
)").string());
  EXPECT_EQ(r.status, 1);
  std::istringstream lines(r.err);
  std::string line;
  int count = 0;
  while (std::getline(lines, line)) {
    auto j = nlohmann::json::parse(line);
    EXPECT_TRUE(j.contains("severity"));
    EXPECT_TRUE(j.contains("kind"));
    EXPECT_TRUE(j.contains("message"));
    EXPECT_EQ(j["line"].get<int>() >= 2, true);
    EXPECT_GT(j["column"].get<int>(), 0);
    ++count;
  }
  EXPECT_EQ(count, 2) << r.err;
}

TEST_F(CliTest, StrictAndWerrorPromoteWarnings) {  // COMMON-002
  fs::path f = Write("warn.urdf", R"(<robot name="r"><link name="a"/><lnk/></robot>)");
  EXPECT_EQ(Mdlc("compile --emit=none " + f.string()).status, 0);
  Outcome strict = Mdlc("compile --emit=none --strict " + f.string());
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.err.find("error: unknown element <lnk>"), std::string::npos) << strict.err;
  EXPECT_EQ(Mdlc("compile --emit=none -Werror " + f.string()).status, 1);
  EXPECT_EQ(Mdlc("compile --emit=none -Werror=unknown " + f.string()).status, 1);
  EXPECT_EQ(Mdlc("compile --emit=none -Werror=inertia " + f.string()).status, 0);
  Outcome silenced = Mdlc("compile --emit=none -Wno-unknown " + f.string());
  EXPECT_EQ(silenced.status, 0);
  EXPECT_EQ(silenced.err, "");
}

TEST_F(CliTest, NegativeMassWarnsByDefaultAndFailsWhenStrict) {  // COMMON-041
  fs::path f = fs::path(MDLC_DIAG_DIR) / "urdf" / "negative_mass.urdf";
  Outcome lax = Mdlc("compile --emit=plant-json " + f.string());
  EXPECT_EQ(lax.status, 0);
  auto json = nlohmann::json::parse(lax.out);
  // the plausible replacement: mass 1 kg (COMMON-040)
  EXPECT_EQ(json["bodies"][0]["mass"].get<double>(), 1.0);
  Outcome strict = Mdlc("compile --strict --emit=none " + f.string());
  EXPECT_EQ(strict.status, 1);
  EXPECT_NE(strict.err.find("negative_mass.urdf:7:5: error:"), std::string::npos) << strict.err;
}

TEST_F(CliTest, IrDumpAndPlantJsonAreDeterministic) {
  fs::path f = Write("p.urdf", kPendulum);
  Outcome a = Mdlc("compile --emit=ir " + f.string());
  Outcome b = Mdlc("compile --emit=ir " + f.string());
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out.find("joint #1 \"theta\" model=pendulum revolute"), std::string::npos) << a.out;
  Outcome c = Mdlc("compile --emit=plant-json --q theta=0.3 " + f.string());
  Outcome d = Mdlc("compile --emit=plant-json --q theta=0.3 " + f.string());
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(c.out, d.out);
}

TEST_F(CliTest, PlantJsonAtAConfiguration) {
  fs::path f = Write("p.urdf", kPendulum);
  Outcome r = Mdlc("compile --emit=plant-json --q theta=0.5 -o " + (dir_ / "plant.json").string() +
                 " " + f.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto j = nlohmann::json::parse(ReadFile(dir_ / "plant.json"));
  EXPECT_EQ(j["schema"], "mdlc-plant/1");
  ASSERT_EQ(j["dofs"].size(), 1u);
  EXPECT_EQ(j["dofs"][0], "pendulum::theta");
  // M = I_yy + m d^2 about the joint axis
  EXPECT_NEAR(j["mass_matrix"][0][0].get<double>(), 0.01 + 2 * 0.25, 1e-12);
  EXPECT_EQ(Mdlc("compile --emit=plant-json --q nosuch=1 " + f.string()).status, 1);
}

TEST_F(CliTest, PassInstrumentation) {
  Outcome list = Mdlc("--list-passes");
  EXPECT_EQ(list.status, 0);
  for (const char* pass : {"resolve-names", "check-joints", "build-kinematic-tree", "check-inertia"}) {
    EXPECT_NE(list.out.find(pass), std::string::npos) << pass;
  }
  fs::path f = Write("p.urdf", kPendulum);
  Outcome after = Mdlc("compile --emit=none --print-after=resolve-names " + f.string());
  EXPECT_EQ(after.status, 0);
  EXPECT_NE(after.err.find("// ----- IR dump after resolve-names -----"), std::string::npos);
  EXPECT_EQ(after.err.find("IR dump after check-inertia"), std::string::npos);
  Outcome all = Mdlc("compile --emit=none --print-after-all --verify-each " + f.string());
  EXPECT_NE(all.err.find("IR dump after check-inertia"), std::string::npos);
  Outcome timing = Mdlc("compile --emit=none --time-passes " + f.string());
  EXPECT_NE(timing.err.find("pass execution timing"), std::string::npos);
  EXPECT_NE(timing.err.find("build-kinematic-tree"), std::string::npos);
}

TEST_F(CliTest, ModelNameOverride) {  // COMMON-021
  Outcome r = Mdlc("compile --emit=ir --model-name renamed " + Write("p.urdf", kPendulum).string());
  EXPECT_NE(r.out.find("model #2 \"renamed\""), std::string::npos) << r.out;
}

TEST_F(CliTest, TenThousandLinkChainCompiles) {
  // no recursion per nesting level: a deep chain must not overflow the stack
  std::string urdf = "<robot name=\"chain\">\n<link name=\"l0\"/>\n";
  for (int i = 1; i <= 10000; ++i) {
    urdf += "<link name=\"l" + std::to_string(i) +
            "\"><inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\"/>"
            "</inertial></link>\n<joint name=\"j" + std::to_string(i) +
            "\" type=\"continuous\"><parent link=\"l" + std::to_string(i - 1) +
            "\"/><child link=\"l" + std::to_string(i) + "\"/><origin xyz=\"0 0 0.1\"/></joint>\n";
  }
  urdf += "</robot>\n";
  Outcome r = Mdlc("compile --emit=summary " + Write("chain.urdf", urdf).string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("bodies: 10001"), std::string::npos) << r.out;
}

TEST_F(CliTest, AFloodOfWarningsIsPrintedWholeAndInOrder) {
  // the warnings of a flood are gathered into few writes (diagnostic_stream.h);
  // none may be lost or reordered, in text or JSON, with output after them
  // (-fno-collapse: the text shows every repeat of the one warning)
  std::string urdf = "<robot name=\"chain\">\n<link name=\"l0\"/>\n";
  for (int i = 1; i <= 2000; ++i) {
    urdf += fmt::format(
        "<link name=\"l{0}\"/>\n<joint name=\"j{0}\" type=\"revolute\"><parent link=\"l{1}\"/>"
        "<child link=\"l{0}\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>"
        "<gazebo_only/></joint>\n",
        i, i - 1);
  }
  urdf += "</robot>\n";
  const std::string path = Write("chain.urdf", urdf).string();
  for (const std::string format : {"text", "json"}) {
    Outcome r = Mdlc("compile --emit=summary -fno-collapse --diagnostics-format=" + format + " " +
                     path);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("bodies: 2001"), std::string::npos) << r.out;
    // joint j<i> is on line 2 * i + 2 of the file, one warning each
    size_t from = 0;
    for (int i = 1; i <= 2000; ++i) {
      const std::string where = format == "text" ? fmt::format("chain.urdf:{}:", 2 * i + 2)
                                                 : fmt::format("\"line\":{},", 2 * i + 2);
      const size_t at = r.err.find(where, from);
      ASSERT_NE(at, std::string::npos) << format << ": no warning for joint j" << i;
      from = at + where.size();
    }
  }
}

TEST_F(CliTest, DeeplyNestedXmlDoesNotCrash) {
  // 100,000 nested unknown elements: warned about, never recursed into
  std::string deep = "<robot name=\"r\"><link name=\"a\"/>";
  for (int i = 0; i < 100000; ++i) deep += "<x>";
  for (int i = 0; i < 100000; ++i) deep += "</x>";
  deep += "</robot>";
  Outcome r = Mdlc("compile --emit=none " + Write("deep.urdf", deep).string());
  EXPECT_EQ(r.status, 0) << r.err.substr(0, 500);
}

TEST_F(CliTest, LimitsAreSetOnTheCommandLine) {  // issue 16
  std::string deep = "<robot name=\"r\"><link name=\"a\"/>";
  for (int i = 0; i < 100; ++i) deep += "\n<x>";
  for (int i = 0; i < 100; ++i) deep += "</x>";
  deep += "</robot>";
  const std::string path = Write("deep.urdf", deep).string();
  Outcome r = Mdlc("compile --emit=none --limit depth=50 " + path);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("deep.urdf:51:1: error: element nested 51 deep, over the depth limit of "
                       "50 (raise it with --limit depth=N)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(Mdlc("compile --emit=none --limit depth=101 " + path).status, 0);
  r = Mdlc("compile --limit depht=50 " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown limit 'depht'"), std::string::npos) << r.err;
  EXPECT_EQ(Mdlc("compile --limit depth=lots " + path).status, 2);
}

TEST_F(CliTest, ConstraintsCannotReachIntoAnotherModel) {  // EXT-052, COMMON-022
  fs::path first = Write("first.urdf", R"(<robot name="first"><link name="l"/></robot>)");
  fs::path second = Write("second.urdf", R"(<robot name="second" xmlns:drake="http://drake.mit.edu">
  <link name="m"/>
  <drake:ball_constraint>
    <drake:ball_constraint_body_A name="first::l"/>
    <drake:ball_constraint_body_B name="m"/>
    <drake:ball_constraint_p_AP value="0 0 0"/>
    <drake:ball_constraint_p_BQ value="0 0 0"/>
  </drake:ball_constraint>
</robot>
)");
  Outcome r = Mdlc("compile --emit=none " + first.string() + " " + second.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("second.urdf:4:"), std::string::npos) << r.err;
  // the same two files compile when the constraint stays inside its model
  Outcome twice = Mdlc("compile --emit=none " + first.string() + " " + first.string());
  EXPECT_EQ(twice.status, 1);  // COMMON-022: the name 'first' is taken
  EXPECT_NE(twice.err.find("already exists"), std::string::npos) << twice.err;
  EXPECT_EQ(Mdlc("compile --emit=none --auto-rename " + first.string() + " " + first.string()).status, 0);
}

TEST_F(CliTest, EveryDiagnosticFileVerifies) {
  // the same files ctest runs one by one, here also checked for a clean exit
  for (const auto& entry : fs::recursive_directory_iterator(MDLC_DIAG_DIR)) {
    if (!entry.is_regular_file()) continue;
    // directives name their models in the test models' package
    const std::string packages = entry.path().extension() == ".yaml"
                                     ? " --package-path " + std::string(MDLC_TEST_MODELS) + "/dmd"
                                     : "";
    Outcome r = Mdlc("compile --verify-diagnostics " + entry.path().string() + packages);
    EXPECT_EQ(r.status, 0) << entry.path() << "\n" << r.err;
  }
}

// Diagnostics speak in one voice: a message (and each of its notes) begins
// in lower case, unless with a name or an acronym ("URDF"), and ends without
// a full stop. Checked on every message the diagnostic test files draw.
TEST_F(CliTest, EveryDiagnosticSpeaksInOneStyle) {
  size_t checked = 0;
  auto check = [&](const std::string& message, const fs::path& file) {
    ++checked;
    ASSERT_FALSE(message.empty()) << file;
    const bool capitalized_word = message.size() > 1 && std::isupper(uint8_t(message[0])) &&
                                  std::islower(uint8_t(message[1]));
    EXPECT_FALSE(capitalized_word) << file << ": " << message;
    EXPECT_FALSE(message.back() == '.' && !message.ends_with("...")) << file << ": " << message;
  };
  for (const auto& entry : fs::recursive_directory_iterator(MDLC_DIAG_DIR)) {
    if (!entry.is_regular_file()) continue;
    const std::string packages = entry.path().extension() == ".yaml"
                                     ? " --package-path " + std::string(MDLC_TEST_MODELS) + "/dmd"
                                     : "";
    Outcome r = Mdlc("compile --emit=none --max-errors 0 --diagnostics-format json " +
                     entry.path().string() + packages);
    std::istringstream lines(r.err);
    for (std::string line; std::getline(lines, line);) {
      if (line.empty() || line[0] != '{') continue;
      const nlohmann::json d = nlohmann::json::parse(line);
      check(d["message"].get<std::string>(), entry.path());
      for (const nlohmann::json& note : d["notes"]) check(note["message"], entry.path());
    }
  }
  EXPECT_GT(checked, 300u);  // the files draw several hundred
}

// One compile may load files of every format into one plant; a directives
// file among them welds and frames the instances the files before it added
// (DMD-040, COMMON-033).
TEST_F(CliTest, CompositeSceneOfUrdfSdfAndDirectives) {
  fs::path arm = Write("arm.urdf", kPendulum);
  fs::path box = Write("box.sdf", R"(<sdf version="1.9"><model name="box">
  <link name="body">
    <inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
    <collision name="c"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>
  </link>
</model></sdf>
)");
  fs::path scene = Write("scene.dmd.yaml", R"(directives:
- add_frame:
    name: tip
    X_PF: {base_frame: pendulum::arm, translation: [0, 0, -1]}
- add_weld:
    parent: tip
    child: box::body
    X_PC: {rotation: !Rpy {deg: [0, 0, 90]}}
)");
  Outcome r = Mdlc("compile " + arm.string() + " " + box.string() + " " + scene.string() +
                 " --emit=plant-json");
  ASSERT_EQ(r.status, 0) << r.err;
  auto plant = nlohmann::json::parse(r.out);
  EXPECT_EQ(plant["model_instances"],
            nlohmann::json({"WorldModelInstance", "DefaultModelInstance", "pendulum", "box"}));
  bool welded = false;
  for (const auto& j : plant["joints"]) {
    if (j["name"] == "tip_welds_to_body") {
      welded = true;
      EXPECT_EQ(j["model_instance"], "box");
      EXPECT_EQ(j["type"], "weld");
      EXPECT_EQ(j["parent"], "pendulum::arm");
    }
  }
  EXPECT_TRUE(welded) << r.out;
  for (const auto& b : plant["bodies"]) {
    if (b["name"] != "body") continue;
    EXPECT_NEAR(b["X_WB"]["p"][2].get<double>(), -1.0, 1e-12);
    // a quarter turn about z: q = [cos 45deg, 0, 0, sin 45deg]
    EXPECT_NEAR(b["X_WB"]["q"][3].get<double>(), std::sqrt(0.5), 1e-12);
  }
  // a repeatable option takes one value per use, never the files after it
  Outcome options_first = Mdlc("compile --q theta=0.5 --package-path " + dir_.string() + " " +
                             arm.string() + " " + box.string() + " " + scene.string() +
                             " --emit=none");
  EXPECT_EQ(options_first.status, 0) << options_first.err;
  // two SDFormat files in one compile: each keeps its own world scope
  fs::path shelf = Write("shelf.sdf", R"(<sdf version="1.9"><model name="shelf">
  <static>true</static>
  <link name="board"><pose>0 0 0.5 0 0 0</pose></link>
</model></sdf>
)");
  Outcome two = Mdlc("compile " + box.string() + " " + shelf.string() + " --emit=plant-json");
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(nlohmann::json::parse(two.out)["model_instances"].size(), 4u);
  // the directives see only what came before them
  Outcome order = Mdlc("compile --emit=none " + scene.string() + " " + arm.string() + " " +
                     box.string());
  EXPECT_EQ(order.status, 1);
  EXPECT_NE(order.err.find("scene.dmd.yaml:4:24: error: frame 'pendulum::arm'"), std::string::npos) << order.err;
}

// YAML nesting beyond yaml-cpp's depth guard, and aliases that would expand
// exponentially, are located errors, never a crash or a hang.
TEST_F(CliTest, YamlBombsAreLocatedErrors) {
  fs::path deep = Write("deep.dmd.yaml", "directives: " + std::string(100000, '[') + "\n");
  Outcome d = Mdlc("compile --emit=none " + deep.string());
  EXPECT_EQ(d.status, 1);
  EXPECT_NE(d.err.find("deep.dmd.yaml:"), std::string::npos) << d.err;
  EXPECT_NE(d.err.find("malformed YAML"), std::string::npos) << d.err;

  std::string laughs = "l0: &l0 [a, a, a, a, a, a, a, a, a, a]\n";
  for (int i = 1; i < 10; ++i) {
    laughs += fmt::format("l{0}: &l{0} [*l{1}, *l{1}, *l{1}, *l{1}, *l{1}, *l{1}, *l{1}, *l{1}]\n",
                          i, i - 1);
  }
  laughs += "directives: *l9\n";
  fs::path bomb = Write("laughs.dmd.yaml", laughs);
  Outcome b = Mdlc("compile --emit=none " + bomb.string());
  EXPECT_EQ(b.status, 1);
  EXPECT_NE(b.err.find("laughs.dmd.yaml:1:1: error: unknown key 'l0'"), std::string::npos) << b.err;
}

// --- mdlc convert (issue 14) ---

const char* kMjcfWithLosses = R"(<mujoco model="losses">
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1"/>
    <body name="ball" pos="0 0 1">
      <freejoint name="free"/>
      <geom name="shell" type="capsule" size="0.1 0.2" mass="1"/>
    </body>
  </worldbody>
</mujoco>
)";

TEST_F(CliTest, ConvertInfersTheTargetAndReportsWhatIsLost) {
  const fs::path out = dir_ / "out" / "losses.urdf";
  fs::create_directories(out.parent_path());
  Outcome r = Mdlc("convert " + Write("losses.xml", kMjcfWithLosses).string() + " -o " + out.string());
  EXPECT_EQ(r.status, 0) << r.err;
  // the half space and the free body's default pose cannot be written
  EXPECT_NE(r.err.find("losses.xml:3:5: warning: geometry 'floor' is a half space"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("the default pose of free link 'ball' is not written"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("[-Wlossy]"), std::string::npos) << r.err;
  const std::string urdf = ReadFile(out);
  EXPECT_NE(urdf.find("<drake:capsule radius=\"0.1\" length=\"0.4\"/>"), std::string::npos)
      << urdf;
  // and what is written compiles
  Outcome back = Mdlc("compile --emit=none --strict " + out.string());
  EXPECT_EQ(back.status, 0) << back.err;
}

TEST_F(CliTest, ConvertStrictMakesLossesErrors) {
  const fs::path out = dir_ / "strict.urdf";
  Outcome r = Mdlc("convert --strict " + Write("losses.xml", kMjcfWithLosses).string() + " -o " +
                 out.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("error: geometry 'floor' is a half space"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // one group can be silenced: then nothing is lost that --strict minds
  Outcome quiet = Mdlc("convert --strict -Wno-lossy " + (dir_ / "losses.xml").string() + " -o " +
                     out.string());
  EXPECT_EQ(quiet.status, 0) << quiet.err;
}

TEST_F(CliTest, ConvertNeedsATarget) {
  const fs::path in = Write("p.urdf", kPendulum);
  EXPECT_EQ(Mdlc("convert " + in.string() + " -o " + (dir_ / "p.txt").string()).status, 2);
  EXPECT_EQ(Mdlc("convert " + in.string() + " --to step -o -").status, 2);
  // the target follows from the output's extension
  Outcome sdf = Mdlc("convert " + in.string() + " -o " + (dir_ / "p.sdf").string());
  EXPECT_EQ(sdf.status, 0) << sdf.err;
  EXPECT_NE(ReadFile(dir_ / "p.sdf").find("<sdf version=\"1.9\""), std::string::npos);
  Outcome mjcf = Mdlc("convert " + in.string() + " -o " + (dir_ / "p.xml").string());
  EXPECT_EQ(mjcf.status, 0) << mjcf.err;
  EXPECT_NE(ReadFile(dir_ / "p.xml").find("<mujoco model=\"pendulum\""), std::string::npos);
  // directives are read, not written
  EXPECT_EQ(Mdlc("convert " + in.string() + " -o " + (dir_ / "p.dmd.yaml").string()).status, 2);
}

TEST_F(CliTest, ConvertNamesMeshesFromTheOutputAndCopiesThemOnce) {
  const fs::path mesh = fs::path(MDLC_TEST_MODELS) / "meshes" / "box.obj";
  const std::string robot = fmt::format(R"(<robot name="r">
  <link name="a">
    <visual><geometry><mesh filename="{0}"/></geometry></visual>
    <collision><geometry><mesh filename="{0}" scale="2 2 2"/></geometry></collision>
  </link>
</robot>)",
                                        mesh.string());
  const fs::path in = Write("meshy.urdf", robot);
  fs::create_directories(dir_ / "out");
  Outcome plain = Mdlc("convert " + in.string() + " -o " + (dir_ / "out" / "a.urdf").string());
  ASSERT_EQ(plain.status, 0) << plain.err;
  const std::string relative = fs::relative(mesh, dir_ / "out").generic_string();
  EXPECT_NE(ReadFile(dir_ / "out" / "a.urdf").find("filename=\"" + relative + "\""),
            std::string::npos);

  Outcome copied = Mdlc("convert " + in.string() + " -o " + (dir_ / "out" / "b.urdf").string() +
                      " --copy-assets " + (dir_ / "out" / "meshes").string());
  ASSERT_EQ(copied.status, 0) << copied.err;
  std::vector<fs::path> copies;
  for (const auto& e : fs::directory_iterator(dir_ / "out" / "meshes")) copies.push_back(e.path());
  ASSERT_EQ(copies.size(), 1u);  // one file, named twice: one copy
  EXPECT_EQ(ReadFile(copies[0]), ReadFile(mesh));
  const std::string b = ReadFile(dir_ / "out" / "b.urdf");
  EXPECT_NE(b.find("filename=\"meshes/" + copies[0].filename().string() + "\""), std::string::npos)
      << b;
  Outcome back = Mdlc("compile --emit=none " + (dir_ / "out" / "b.urdf").string());
  EXPECT_EQ(back.status, 0) << back.err;
}

// --plain, --fixed-base (issue 58): plain URDF for urdfdom; a URDF root link
// that floats is said in a note when converted to MJCF, and --fixed-base
// welds it (on convert and compile alike).
TEST_F(CliTest, ConvertPlainUrdfAndFixedBase) {
  Outcome plain = Mdlc("convert " + Write("losses.xml", kMjcfWithLosses).string() + " -o " +
                       (dir_ / "plain.urdf").string() + " --plain");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const std::string urdf = ReadFile(dir_ / "plain.urdf");
  EXPECT_EQ(urdf.find("drake:capsule"), std::string::npos) << urdf;
  EXPECT_NE(urdf.find("<cylinder radius=\"0.1\" length=\"0.6"), std::string::npos) << urdf;
  EXPECT_NE(plain.err.find("capsule 'shell' is written as the cylinder that bounds it"),
            std::string::npos)
      << plain.err;
  Outcome not_urdf = Mdlc("convert " + (dir_ / "losses.xml").string() + " -o " +
                          (dir_ / "plain.sdf").string() + " --plain");
  EXPECT_NE(not_urdf.err.find("--plain applies to URDF output"), std::string::npos)
      << not_urdf.err;

  const fs::path arm = Write("arm.urdf", R"(<robot name="arm">
  <link name="base"><inertial><mass value="4"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="shoulder" type="continuous"><parent link="base"/><child link="upper"/><axis xyz="0 0 1"/></joint>
  <link name="upper"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
</robot>
)");
  Outcome floating = Mdlc("convert " + arm.string() + " -o " + (dir_ / "arm.xml").string());
  ASSERT_EQ(floating.status, 0) << floating.err;
  EXPECT_NE(floating.err.find("arm.urdf:2:3: note: root link 'base' of URDF model 'arm' has no "
                              "joint to the world"),
            std::string::npos)
      << floating.err;
  EXPECT_NE(floating.err.find("--fixed-base welds it to the world [-Wjoint]"), std::string::npos)
      << floating.err;
  EXPECT_NE(ReadFile(dir_ / "arm.xml").find("<freejoint"), std::string::npos);
  Outcome fixed =
      Mdlc("convert --fixed-base " + arm.string() + " -o " + (dir_ / "arm_fixed.xml").string());
  ASSERT_EQ(fixed.status, 0) << fixed.err;
  EXPECT_EQ(fixed.err.find("note: root link"), std::string::npos) << fixed.err;
  EXPECT_EQ(ReadFile(dir_ / "arm_fixed.xml").find("<freejoint"), std::string::npos);
  Outcome compiled = Mdlc("compile --fixed-base " + arm.string());
  ASSERT_EQ(compiled.status, 0) << compiled.err;
  EXPECT_NE(compiled.out.find("positions: 1, velocities: 1"), std::string::npos) << compiled.out;
}

// --mesh-reader (issue 16): meshes read in a child process (the default)
// or in mdlc's own give the same plant; --time-passes names the reader.
TEST_F(CliTest, MeshReaderFlag) {  // issue 16
  const std::string model = std::string(MDLC_TEST_MODELS) + "/mjcf/oracle/mesh_geoms.xml";
  Outcome child = Mdlc("compile --no-cache --emit=plant-json --time-passes " + model);
  ASSERT_EQ(child.status, 0) << child.err;
  EXPECT_NE(child.err.find("mesh reader: /"), std::string::npos) << child.err;
  EXPECT_NE(child.err.find("/mdlc-mesh-reader\n"), std::string::npos) << child.err;
  Outcome here = Mdlc("compile --no-cache --emit=plant-json --mesh-reader=in-process " + model);
  ASSERT_EQ(here.status, 0) << here.err;
  EXPECT_EQ(child.out, here.out);
  EXPECT_EQ(Mdlc("compile --mesh-reader=thread " + model).status, 2);
}

// The import module (issue 16): mdlc does not load assimp until a mesh is
// read in its own process, and then through the module, found next to mdlc
// or named by MDLC_MESH_MODULE. A module that is missing, is no shared
// object, or is of another version is an error at each mesh that needed it,
// not a crash; the reader program does not need the module at all.
TEST_F(CliTest, MdlcStartsWithoutAssimp) {  // issue 16
  // the loader lists what the program needs and exits (what ldd does)
  const Outcome needs = Mdlc("--version", "LD_TRACE_LOADED_OBJECTS=1");
  ASSERT_EQ(needs.status, 0) << needs.err;
  EXPECT_NE(needs.out.find("libxml2"), std::string::npos) << needs.out;
  EXPECT_EQ(needs.out.find("libassimp"), std::string::npos) << needs.out;
}

TEST_F(CliTest, MeshImportModule) {  // issue 16
  const std::string model = std::string(MDLC_TEST_MODELS) + "/mjcf/oracle/mesh_geoms.xml";
  const std::string in_process = "compile --no-cache --emit=none --mesh-reader=in-process ";
  const Outcome found = Mdlc(in_process + "--time-passes " + model);
  ASSERT_EQ(found.status, 0) << found.err;
  EXPECT_NE(found.err.find("mesh reader: in this process (asked for), with /"), std::string::npos)
      << found.err;
  EXPECT_NE(found.err.find("/mdlc-mesh-import.so\n"), std::string::npos) << found.err;

  const std::string missing = (dir_ / "missing.so").string();
  const std::string not_elf = Write("not_elf.so", "not a shared object\n").string();
  const std::string other_version = MDLC_OLD_IMPORT_MODULE;
  const std::pair<std::string, std::string> broken[] = {
      {missing, fmt::format("MDLC_MESH_MODULE names '{}', which is not a readable file", missing)},
      {not_elf, fmt::format("cannot open the mesh import module: {}: ", not_elf)},
      {other_version, fmt::format("'{}' is not a mesh import module of this mdlc (it has no "
                                  "mdlc_mesh_import_v2)",
                                  other_version)}};
  for (const auto& [module, why] : broken) {
    const Outcome r = Mdlc(in_process + model, "MDLC_MESH_MODULE=" + module);
    EXPECT_EQ(r.status, 1) << module;
    EXPECT_NE(r.err.find(fmt::format("mesh_geoms.xml:10:11: error: cannot read '{}/mjcf/oracle/"
                                     "meshes/wedge.obj' in this process: {}",
                                     MDLC_TEST_MODELS, why)),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("3 errors generated"), std::string::npos) << r.err;
    // the reader program reads the same meshes without the module
    const Outcome child =
        Mdlc("compile --no-cache --emit=none " + model, "MDLC_MESH_MODULE=" + module);
    EXPECT_EQ(child.status, 0) << child.err;
  }
}

}  // namespace
