// inspect_test.cc - `mdlc tree` and `mdlc stats` (issue 15), run as a user
// runs them; stats are checked against the command's own plant-json.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <algorithm>
#include <array>
#include <set>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_fixture.h"

namespace {
namespace fs = std::filesystem;
using nlohmann::json;

using mdlc::cli_test::Outcome;

class InspectTest : public mdlc::cli_test::CliFixture {
 protected:
  static std::string Read(const fs::path& p) { return mdlc::cli_test::ReadFile(p); }
};

const std::string kScara = std::string(MDLC_EXAMPLES_DIR) + "/urdf/scara_arm.urdf";
const std::string kArm = std::string(MDLC_EXAMPLES_DIR) + "/mjcf/arm_with_gripper.xml";

TEST_F(InspectTest, TreeShowsEachJointUnderItsParent) {
  Outcome r = Mdlc("tree " + kScara);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "model instance 'scara_arm': 5 bodies, 4 dofs\n"
            "  column <- weld joint 'base_weld' (on world)\n"
            "  └─ carriage <- prismatic joint 'lift', axis [0 0 1], limits [0, 0.4]\n"
            "     └─ upper_arm <- revolute joint 'shoulder', axis [0 0 1], limits [-2.5, 2.5]\n"
            "        └─ forearm <- revolute joint 'elbow', axis [0 0 1], limits [-2.6, 2.6]\n"
            "           └─ tool <- revolute joint 'wrist', axis [0 0 1]\n");
}

TEST_F(InspectTest, TreeJsonAgreesWithPlantJson) {
  Outcome tree = Mdlc("tree --json " + kArm);
  Outcome plant = Mdlc("compile --emit=plant-json " + kArm);
  ASSERT_EQ(tree.status, 0) << tree.err;
  ASSERT_EQ(plant.status, 0) << plant.err;
  const json t = json::parse(tree.out), p = json::parse(plant.out);
  // every joint of the plant is the inbound joint of the body it moves
  std::map<std::string, std::string> joint_of;
  for (const auto& b : t["bodies"]) {
    if (b.contains("joint")) joint_of[b["name"]] = b["joint"];
  }
  size_t dofs = 0;
  for (const auto& j : p["joints"]) {
    EXPECT_EQ(joint_of[j["child"].get<std::string>()],
              j["model_instance"].get<std::string>() + "::" + j["name"].get<std::string>())
        << j.dump();
    dofs += j["lower"].size();  // one entry per velocity
  }
  EXPECT_EQ(t["dofs"].get<size_t>(), dofs);
}

TEST_F(InspectTest, TreeOfADeepChainStaysReadable) {
  std::string urdf = "<robot name='chain'><link name='l0'/>";
  for (int i = 1; i <= 2000; ++i) {
    urdf += fmt::format(
        "<link name='l{0}'><inertial><mass value='1'/><inertia ixx='1' iyy='1' izz='1' ixy='0' "
        "ixz='0' iyz='0'/></inertial></link><joint name='j{0}' type='continuous'><parent "
        "link='l{1}'/><child link='l{0}'/><axis xyz='0 0 1'/></joint>",
        i, i - 1);
  }
  Outcome r = Mdlc("tree " + Write("chain.urdf", urdf + "</robot>").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("[depth 2000] l2000 <- revolute joint 'j2000'"), std::string::npos);
  // the drawing stops widening past 32 levels
  size_t widest = 0;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) widest = std::max(widest, line.size());
  EXPECT_LT(widest, 200u);
}

// A model nested N deep, each level's link jointed to the one below: each
// instance's tree stops where the next instance's begins, so every body is
// described once and the lines grow with N, not N^2.
TEST_F(InspectTest, TreeOfNestedInstancesDescribesEachBodyOnce) {
  constexpr int kDepth = 60;
  std::string inner;
  for (int i = kDepth; i-- > 0;) {
    const std::string below =
        i + 1 < kDepth ? fmt::format("<joint name='j{}' type='revolute'><parent>link</parent>"
                                     "<child>m{}::link</child><axis><xyz>0 0 1</xyz></axis>"
                                     "</joint>",
                                     i + 1, i + 1)
                       : "";
    inner = fmt::format("<model name='m{}'><link name='link'/>{}{}</model>", i, below, inner);
  }
  Outcome r = Mdlc("tree " + Write("nested.sdf", "<sdf version='1.9'>" + inner + "</sdf>").string());
  ASSERT_EQ(r.status, 0) << r.err;
  size_t lines = 0, described = 0, handed_on = 0;
  std::istringstream text(r.out);
  for (std::string line; std::getline(text, line);) {
    ++lines;
    if (line.find(" <- ") != std::string::npos) ++described;
    if (line.find("└─ link of model instance '") != std::string::npos) ++handed_on;
  }
  EXPECT_EQ(described, static_cast<size_t>(kDepth));
  EXPECT_EQ(handed_on, static_cast<size_t>(kDepth - 1));
  // per instance: heading, its link, the next instance's link, its __model__ frame
  EXPECT_EQ(lines, 4u * kDepth - 1);
  EXPECT_NE(r.out.find("model instance 'm0::m1': 1 body, 1 dof\n"
                       "  link <- revolute joint 'j1', axis [0 0 1] (on m0::link)\n"
                       "  └─ link of model instance 'm0::m1::m2'\n"),
            std::string::npos)
      << r.out.substr(0, 600);
}

TEST_F(InspectTest, StatsAreThePlantsMassProperties) {
  Outcome stats = Mdlc("stats --json " + kArm);
  Outcome plant = Mdlc("compile --emit=plant-json " + kArm);
  ASSERT_EQ(stats.status, 0) << stats.err;
  ASSERT_EQ(plant.status, 0) << plant.err;
  const json s = json::parse(stats.out), p = json::parse(plant.out);
  double total = 0;
  size_t compared = 0;
  for (const auto& b : p["bodies"]) {
    if (b["name"] == "world") continue;
    const std::string name = b["model_instance"].get<std::string>() + "::" +
                             b["name"].get<std::string>();
    for (const auto& sb : s["bodies"]) {
      if (sb["name"] != name) continue;
      EXPECT_EQ(sb["mass"].get<double>(), b["mass"].get<double>()) << name;
      EXPECT_EQ(sb["com"], b["com"]) << name;
      EXPECT_TRUE(sb["physically_valid"].get<bool>()) << name;
      ++compared;
    }
    total += b["mass"].get<double>();
  }
  EXPECT_EQ(compared, s["bodies"].size());
  EXPECT_DOUBLE_EQ(s["total"]["mass"].get<double>(), total);
  EXPECT_EQ(s["total"]["actuators"].get<int>(), static_cast<int>(p["actuators"].size()));
  Outcome text = Mdlc("stats " + kArm);
  EXPECT_NE(text.out.find("total: 6 bodies"), std::string::npos) << text.out;
}

/// An OBJ file's size counted here, without mdlc: distinct vertex
/// positions, and the triangles its faces split into (n - 2 per n-gon).
std::pair<size_t, size_t> ObjSize(const fs::path& obj) {
  std::set<std::array<double, 3>> positions;
  size_t triangles = 0;
  std::ifstream in(obj);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") {
      std::array<double, 3> p{};
      words >> p[0] >> p[1] >> p[2];
      positions.insert(p);
    } else if (tag == "f") {
      size_t corners = 0;
      for (std::string corner; words >> corner;) ++corners;
      triangles += corners - 2;
    }
  }
  return {positions.size(), triangles};
}

TEST_F(InspectTest, StatsCountEachMeshsVerticesAndTriangles) {  // issue 15
  const fs::path meshes = fs::path(MDLC_TEST_MODELS) / "meshes";
  const fs::path robot = Write("r.urdf", fmt::format(R"(<robot name="r">
  <link name="a">
    <visual><geometry><mesh filename="{0}/lshape.obj" scale="2 2 2"/></geometry></visual>
    <collision><geometry><mesh filename="{0}/box.obj"/></geometry></collision>
  </link>
  <link name="b">
    <visual><geometry><mesh filename="{0}/lshape.obj"/></geometry></visual>
    <visual><geometry><box size="1 1 1"/></geometry></visual>
  </link>
  <joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>)",
                                                     meshes.string()));
  const auto [lshape_vertices, lshape_triangles] = ObjSize(meshes / "lshape.obj");
  const auto [box_vertices, box_triangles] = ObjSize(meshes / "box.obj");
  ASSERT_GT(lshape_triangles, 0u);

  Outcome r = Mdlc("stats --json " + robot.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const json s = json::parse(r.out);
  ASSERT_EQ(s["meshes"].size(), 3u) << r.out;
  size_t vertices = 0, triangles = 0;
  for (const json& m : s["meshes"]) {
    const bool lshape = m["file"].get<std::string>().ends_with("lshape.obj");
    EXPECT_EQ(m["vertices"].get<size_t>(), lshape ? lshape_vertices : box_vertices) << m.dump();
    EXPECT_EQ(m["triangles"].get<size_t>(), lshape ? lshape_triangles : box_triangles)
        << m.dump();
    vertices += m["vertices"].get<size_t>();
    triangles += m["triangles"].get<size_t>();
  }
  const json& total = s["total"]["meshes"];
  EXPECT_EQ(total["geometries"], 3);
  EXPECT_EQ(total["files"], 2);
  EXPECT_EQ(total["vertices"].get<size_t>(), 2 * lshape_vertices + box_vertices);
  EXPECT_EQ(total["triangles"].get<size_t>(), 2 * lshape_triangles + box_triangles);
  EXPECT_EQ(total["vertices"].get<size_t>(), vertices);
  EXPECT_EQ(total["triangles"].get<size_t>(), triangles);
  EXPECT_EQ(s["model_instances"][0]["meshes"], total);

  Outcome text = Mdlc("stats " + robot.string());
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_NE(text.out.find(fmt::format("lshape.obj: {} vertices, {} triangles\n",
                                      lshape_vertices, lshape_triangles)),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find(fmt::format("  meshes: 3 geometries of 2 files, {} vertices, {} "
                                      "triangles\n",
                                      2 * lshape_vertices + box_vertices,
                                      2 * lshape_triangles + box_triangles)),
            std::string::npos)
      << text.out;
}

TEST_F(InspectTest, ExitCodes) {
  EXPECT_EQ(Mdlc("tree").status, 2);
  EXPECT_EQ(Mdlc("stats " + Write("bad.urdf", "<robot name='r'><link/></robot>").string()).status,
            1);
}

// every compiling subcommand reports diagnostics the same way (one
// CompileForCli): --diagnostics-format=json gives one JSON object per line
// and no "N errors generated." line for a reader to skip
TEST_F(InspectTest, EverySubcommandHonoursTheDiagnosticsFormat) {
  const std::string bad = Write("bad.urdf", "<robot name='r'><link/></robot>").string();
  for (const char* subcommand : {"tree", "stats", "graph", "compile"}) {
    Outcome r = Mdlc(fmt::format("{} --diagnostics-format=json {}", subcommand, bad));
    EXPECT_EQ(r.status, 1) << subcommand;
    std::istringstream lines(r.err);
    int n = 0;
    for (std::string line; std::getline(lines, line); ++n) {
      const json d = json::parse(line);
      EXPECT_EQ(d["kind"], "missing-attribute") << subcommand;
    }
    EXPECT_EQ(n, 1) << subcommand << ": " << r.err;
    Outcome text = Mdlc(fmt::format("{} {}", subcommand, bad));
    EXPECT_NE(text.err.find("bad.urdf:1:17: error:"), std::string::npos) << text.err;
    EXPECT_NE(text.err.find("1 error generated.\n"), std::string::npos) << text.err;
  }
}

TEST_F(InspectTest, GraphDrawsOneEdgePerJoint) {
  Outcome dot = Mdlc("graph " + kScara);
  ASSERT_EQ(dot.status, 0) << dot.err;
  EXPECT_EQ(dot.out.rfind("digraph kinematic {", 0), 0u) << dot.out;
  EXPECT_NE(dot.out.find("\"scara_arm::upper_arm\" -> \"scara_arm::forearm\" "
                         "[label=\"scara_arm::elbow\\nrevolute\", style=solid];"),
            std::string::npos)
      << dot.out;
  Outcome graph = Mdlc("graph --format json " + kArm);
  Outcome plant = Mdlc("compile --emit=plant-json " + kArm);
  ASSERT_EQ(graph.status, 0) << graph.err;
  const json g = json::parse(graph.out), p = json::parse(plant.out);
  EXPECT_EQ(g["edges"].size(), p["joints"].size());
  EXPECT_EQ(g["nodes"].size(), p["bodies"].size() + 1);  // plant-json lists no world body
}

TEST_F(InspectTest, FrameGraphHangsEachFrameOnItsBody) {
  Outcome frames = Mdlc("graph --kind frames --format json " + kArm);
  Outcome plant = Mdlc("compile --emit=plant-json " + kArm);
  ASSERT_EQ(frames.status, 0) << frames.err;
  const json g = json::parse(frames.out), p = json::parse(plant.out);
  // bodies, explicit frames and each joint's F and M; an edge per frame, and
  // three per joint (F on the parent, M on the child, F to M)
  EXPECT_EQ(g["nodes"].size(),
            p["bodies"].size() + 1 + p["frames"].size() + 2 * p["joints"].size());
  EXPECT_EQ(g["edges"].size(), p["frames"].size() + 3 * p["joints"].size());
}

TEST_F(InspectTest, GraphRendersWithGraphvizWhenItIsThere) {
  if (std::system("command -v dot >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "Graphviz's dot is not installed (the test set-up installs it)";
  }
  const fs::path svg = dir_ / "tree.svg";
  Outcome r = Mdlc("graph " + kScara + " -o " + svg.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(Read(svg).find("<svg"), std::string::npos);
}

TEST_F(InspectTest, AssetsListsWhatWasFoundAndWhyTheRestWasNot) {
  const fs::path mesh = fs::path(MDLC_TEST_MODELS) / "meshes" / "box.obj";
  const fs::path robot = Write("r.urdf", fmt::format(R"(<robot name="r">
  <link name="a">
    <visual><geometry><mesh filename="{}"/></geometry></visual>
    <collision><geometry><mesh filename="package://nowhere/box.stl"/></geometry></collision>
  </link>
</robot>)",
                                                     mesh.string()));
  Outcome r = Mdlc("assets --json " + robot.string());
  EXPECT_EQ(r.status, 1);  // one file is missing
  const json list = json::parse(r.out);
  ASSERT_EQ(list.size(), 3u) << r.out;
  EXPECT_EQ(list[0]["kind"], "model");
  EXPECT_EQ(list[1]["kind"], "mesh");
  EXPECT_EQ(list[1]["format"], "obj");
  EXPECT_EQ(list[1]["bytes"].get<uintmax_t>(), fs::file_size(mesh));
  EXPECT_EQ(list[2]["uri"], "package://nowhere/box.stl");
  EXPECT_NE(list[2]["error"].get<std::string>().find("nowhere"), std::string::npos) << r.out;
  // the text form, and the error on stderr with its location
  Outcome text = Mdlc("assets " + robot.string());
  EXPECT_NE(text.out.find("mesh     package://nowhere/box.stl: "), std::string::npos) << text.out;
  EXPECT_NE(text.err.find("r.urdf:4:"), std::string::npos) << text.err;
  EXPECT_EQ(Mdlc("assets " + kScara).status, 0);
}

TEST_F(InspectTest, AssetsListEachFileOnceWithMjcfTexturesAndNoManifests) {  // issue 58, item 8
  // one mesh named two ways (package:// and a relative path), a package.xml
  // that found the package
  fs::create_directories(dir_ / "p");
  Write("p/package.xml", "<package><name>p</name></package>");
  fs::copy_file(fs::path(MDLC_TEST_MODELS) / "meshes" / "box.obj", dir_ / "p" / "box.obj");
  const fs::path robot = Write("p/r.urdf", R"(<robot name="r">
  <link name="a"><visual><geometry><mesh filename="package://p/box.obj"/></geometry></visual></link>
  <link name="b"><visual><geometry><mesh filename="box.obj"/></geometry></visual></link>
  <joint name="j" type="fixed"><parent link="a"/><child link="b"/></joint>
</robot>)");
  const Outcome urdf = Mdlc("assets --format json --package-path " + dir_.string() + " " +
                            robot.string());
  ASSERT_EQ(urdf.status, 0) << urdf.err;
  const json list = json::parse(urdf.out);
  ASSERT_EQ(list.size(), 2u) << urdf.out;  // the model and its one mesh; no package.xml
  EXPECT_EQ(list[0]["kind"], "model");
  EXPECT_EQ(list[1]["kind"], "mesh");
  EXPECT_EQ(list[1]["uses"], 2);

  // MJCF textures, found in the compiler's texturedir, or not found
  fs::create_directories(dir_ / "tex");
  Write("tex/wood.png", "not really a png");
  const fs::path scene = Write("scene.xml", R"(<mujoco model="s">
  <compiler texturedir="tex"/>
  <asset>
    <texture name="wood" type="2d" file="wood.png"/>
    <texture name="sky" type="skybox" file="sky.png"/>
    <material name="m" texture="wood"/>
  </asset>
  <worldbody><body name="b"><freejoint/><geom size="0.1" material="m"/></body></worldbody>
</mujoco>)");
  const Outcome mjcf = Mdlc("assets --format json " + scene.string());
  EXPECT_EQ(mjcf.status, 1) << mjcf.err;  // sky.png is missing
  const json textures = json::parse(mjcf.out);
  ASSERT_EQ(textures.size(), 3u) << mjcf.out;
  EXPECT_EQ(textures[1]["kind"], "texture");
  EXPECT_EQ(textures[1]["uri"], "wood.png");
  EXPECT_EQ(textures[1]["path"], (dir_ / "tex" / "wood.png").string());
  EXPECT_EQ(textures[1]["bytes"], 16);
  EXPECT_EQ(textures[2]["uri"], "sky.png");
  EXPECT_EQ(textures[2]["error"], "not found");
}

// --- mdlc check ---

class CheckTest : public InspectTest {
 protected:
  void SetUp() override {
    InspectTest::SetUp();
    fs::create_directories(dir_ / "models" / "sub");
    std::ofstream(dir_ / "models" / "good.urdf") << "<robot name='good'><link name='a'/></robot>";
    std::ofstream(dir_ / "models" / "sub" / "bad.urdf") << "<robot name='bad'><link/></robot>";
    std::ofstream(dir_ / "models" / "sub" / "warn.urdf")
        << "<robot name='warn'><link name='a'><bogus/></link></robot>";
    std::ofstream(dir_ / "models" / "sub" / "arm.xml")
        << "<mujoco model='arm'><worldbody><body name='b'><geom size='0.1'/></body>"
           "</worldbody></mujoco>";
    std::ofstream(dir_ / "models" / "package.xml") << "<package><name>p</name></package>";
  }
  std::string Models() const { return (dir_ / "models").string(); }
};

TEST_F(CheckTest, OneVerdictPerFileAndASummary) {
  Outcome r = Mdlc("check " + Models());
  EXPECT_EQ(r.status, 1) << r.out;  // bad.urdf has an error
  // the folder is walked: URDF files and the MJCF file, not package.xml
  EXPECT_NE(r.out.find("good.urdf: ok\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sub/warn.urdf: ok, 1 warning\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sub/bad.urdf: 1 error, 0 warnings\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sub/arm.xml: ok"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("package.xml"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 files: 3 ok, 1 with errors, 1 warning\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bad.urdf:1:19: error:"), std::string::npos) << r.out;
}

TEST_F(CheckTest, ParallelRunsReportTheSameInFileOrder) {
  Outcome serial = Mdlc("check --format json -j 1 " + Models());
  Outcome parallel = Mdlc("check --format json -j 3 " + Models());
  EXPECT_EQ(serial.out, parallel.out);
  std::istringstream lines(parallel.out);
  int n = 0;
  for (std::string line; std::getline(lines, line); ++n) {
    const json j = json::parse(line);  // JSON Lines: one object per file
    EXPECT_TRUE(j.contains("file") && j.contains("ok") && j.contains("diagnostics")) << line;
  }
  EXPECT_EQ(n, 4);
}

TEST_F(CheckTest, SkipOkResumesFromAnEarlierReport) {
  Outcome first = Mdlc("check --format json " + Models() + " -o " + (dir_ / "r.jsonl").string());
  EXPECT_EQ(first.status, 1);
  Outcome again = Mdlc("check --format json --skip-ok " + (dir_ / "r.jsonl").string() + " " +
                       Models());
  // only the file with errors is compiled again
  EXPECT_EQ(std::count(again.out.begin(), again.out.end(), '\n'), 1) << again.out;
  EXPECT_NE(again.out.find("bad.urdf"), std::string::npos);
  EXPECT_NE(again.err.find("3 skipped as ok before"), std::string::npos) << again.err;
}

TEST_F(CheckTest, IncludedMjcfFilesAreFragmentsOfTheirModel) {  // issue 58, item 4; MJCF-001
  // the fragment uses a default class of the including file: alone it is broken
  std::ofstream(dir_ / "models" / "sub" / "scene.xml")
      << "<mujoco model='scene'><default><default class='waist'><geom size='0.2'/></default>"
         "</default><include file='waist.xml'/></mujoco>";
  std::ofstream(dir_ / "models" / "sub" / "waist.xml")
      << "<mujoco><worldbody><body name='w'><geom class='waist'/></body></worldbody></mujoco>";
  Outcome r = Mdlc("check " + Models() + "/sub/scene.xml " + Models() + "/sub/waist.xml");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("sub/waist.xml: fragment, included by " + Models() + "/sub/scene.xml\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("waist'"), std::string::npos) << r.out;  // no unknown-class error
  EXPECT_NE(r.out.find("2 files: 1 ok, 0 with errors, 1 fragment of others"), std::string::npos)
      << r.out;
  // JSON Lines say it too
  Outcome json_lines = Mdlc("check --format json " + Models() + "/sub/waist.xml " + Models() +
                            "/sub/scene.xml");
  EXPECT_NE(json_lines.out.find("\"included_by\":"), std::string::npos) << json_lines.out;
}

TEST_F(CheckTest, SummaryPrintsOnlyTheTotals) {
  Outcome r = Mdlc("check --summary " + Models());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "4 files: 3 ok, 1 with errors, 1 warning\n");
}

TEST_F(CheckTest, APackageFoundTwiceIsSaidOncePerRun) {  // COMMON-013
  for (const char* copy : {"a", "b"}) {
    fs::create_directories(dir_ / "pkgs" / copy);
    std::ofstream(dir_ / "pkgs" / copy / "package.xml") << "<package><name>twice</name></package>";
  }
  Outcome r = Mdlc("check --package-path " + (dir_ / "pkgs").string() + " " + Models());
  size_t said = 0;
  for (size_t at = 0; (at = r.out.find("package 'twice' found again", at)) != std::string::npos;
       ++at) {
    ++said;
  }
  EXPECT_EQ(said, 1u) << r.out;
  EXPECT_NE(r.out.find("good.urdf: ok\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 files: 3 ok, 1 with errors, 2 warnings\n"), std::string::npos) << r.out;
}

TEST_F(CheckTest, AFileMissingFromTheFirstCopyOfAPackageNamesTheCopyThatHasIt) {  // COMMON-013
  for (const char* copy : {"a", "b"}) {
    fs::create_directories(dir_ / "pkgs" / copy);
    std::ofstream(dir_ / "pkgs" / copy / "package.xml") << "<package><name>twice</name></package>";
  }
  fs::copy_file(fs::path(MDLC_TEST_MODELS) / "meshes" / "box.obj", dir_ / "pkgs" / "b" / "box.obj");
  const fs::path robot = Write("r.urdf", R"(<robot name="r"><link name="a"><collision>
<geometry><mesh filename="package://twice/box.obj"/></geometry></collision></link></robot>)");
  Outcome r = Mdlc("check --package-path " + (dir_ / "pkgs").string() + " " + robot.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("note: '" + (dir_ / "pkgs" / "b" / "box.obj").string() +
                       "' is in another copy of the package, which the package path holds too "
                       "but the first copy found shadows"),
            std::string::npos)
      << r.out;
}

TEST_F(CheckTest, FormatNamesTheFilesFormat) {  // COMMON-005
  const fs::path robot = Write("robot.description", "<robot name='r'><link name='a'/></robot>");
  EXPECT_EQ(Mdlc("check " + robot.string()).status, 1);  // unknown extension
  Outcome r = Mdlc("check --format urdf " + robot.string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("robot.description: ok\n"), std::string::npos) << r.out;
  EXPECT_EQ(Mdlc("check --format xacro " + robot.string()).status, 2);
}

TEST_F(CheckTest, AWalkFindsGazeboWorlds) {
  fs::create_directories(dir_ / "worlds");
  std::ofstream(dir_ / "worlds" / "empty.world")
      << "<sdf version='1.9'><world name='w'><model name='m'><static>true</static>"
         "<link name='l'/></model></world></sdf>";
  Outcome r = Mdlc("check " + (dir_ / "worlds").string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("empty.world: ok"), std::string::npos) << r.out;
}

TEST_F(CheckTest, SarifForCodeHosts) {
  Outcome r = Mdlc("check --format sarif " + Models());
  const json sarif = json::parse(r.out);
  EXPECT_EQ(sarif["version"], "2.1.0");
  const json& results = sarif["runs"][0]["results"];
  ASSERT_EQ(results.size(), 2u) << r.out;  // bad.urdf's error, warn.urdf's warning
  bool error_seen = false;
  for (const json& res : results) {
    const json& where = res["locations"][0]["physicalLocation"];
    EXPECT_GT(where["region"]["startLine"].get<int>(), 0);
    if (res["level"] == "error") {
      error_seen = true;
      EXPECT_NE(where["artifactLocation"]["uri"].get<std::string>().find("bad.urdf"),
                std::string::npos);
      EXPECT_EQ(res["ruleId"], "missing-attribute");
    }
  }
  EXPECT_TRUE(error_seen);
}

// `mdlc view`: the page itself (the browser test, view_test.py, opens it)
class ViewTest : public InspectTest {
 protected:
  /// The model JSON the page embeds.
  json PageModel(const std::string& page) {
    const std::string open = R"(<script type="application/json" id="mdlc-model">)";
    const size_t begin = page.find(open);
    EXPECT_NE(begin, std::string::npos);
    const size_t end = page.find("</script>", begin);
    return json::parse(page.substr(begin + open.size(), end - begin - open.size()));
  }
};

TEST_F(ViewTest, WritesOneSelfContainedPage) {
  const fs::path page_path = dir_ / "scara.html";
  Outcome r = Mdlc(fmt::format("view {} -o {}", kScara, page_path.string()));
  if (r.status == 1 && r.err.find("without the viewer") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = Read(page_path);
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>"));
  // nothing is fetched when it is viewed
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
  EXPECT_NE(page.find(R"(id="mdlc-three")"), std::string::npos);
  const json model = PageModel(page);
  ASSERT_EQ(model["bodies"].size(), 6u);  // world and five links
  EXPECT_EQ(model["bodies"][0]["scoped_name"], "world");
  EXPECT_EQ(model["num_positions"], 4);
  bool found_shoulder = false;
  for (const json& joint : model["joints"]) {
    if (joint["name"] != "shoulder") continue;
    found_shoulder = true;
    EXPECT_EQ(joint["type"], "revolute");
    EXPECT_EQ(joint["nq"], 1);
    EXPECT_TRUE(joint["source"].get<std::string>().find("scara_arm.urdf:") != std::string::npos);
  }
  EXPECT_TRUE(found_shoulder);
  for (const json& body : model["bodies"]) {
    if (body["scoped_name"] == "world") continue;
    EXPECT_TRUE(body["source"].get<std::string>().find("scara_arm.urdf:") != std::string::npos)
        << body["scoped_name"];
  }
  EXPECT_GE(model["geometries"].size(), 5u);
}

TEST_F(ViewTest, NeedsAnOutputFile) {
  EXPECT_EQ(Mdlc("view " + kScara).status, 2);
}

TEST_F(ViewTest, ABrokenModelWritesNoPage) {
  const fs::path bad = Write("bad.urdf", "<robot name='r'><link name='a'/><joint/></robot>");
  Outcome r = Mdlc(fmt::format("view {} -o {}", bad.string(), (dir_ / "bad.html").string()));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("error:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "bad.html"));
}

}  // namespace
