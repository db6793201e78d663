// Files whose names do not say their format (issue 55, COMMON-005, DMD-060):
// add_directives reads a directives file of any name, as Drake's
// LoadModelDirectives does; the command line names a top-level file's format
// with -x or --format; without it, an unknown extension is an error that
// says how. Also the inputs a user has (issue 58): standard input, Gazebo's
// .world files and model folders, a xacro file of any name; and --format
// json, the one spelling of machine output on every subcommand.
#include <sys/wait.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "cli_fixture.h"

namespace mdlc::cli_test {
namespace {

class InputFormatTest : public CliFixture {
 protected:
  std::string packages() const {
    return fmt::format("--package-path {}/dmd", MDLC_TEST_MODELS);
  }
  /// The scoped names of the bodies plant-json lists.
  std::vector<std::string> Bodies(const Outcome& r) {
    std::vector<std::string> names;
    const nlohmann::json plant = nlohmann::json::parse(r.out);
    for (const auto& b : plant["bodies"]) {
      names.push_back(b["model_instance"].get<std::string>() + "::" + b["name"].get<std::string>());
    }
    return names;
  }
};

TEST_F(InputFormatTest, AddDirectivesReadsAFileOfAnyName) {  // issue 55, DMD-060
  const fs::path scene = Write("scene.dmd.yaml", R"(directives:
- add_model_instance:
    name: left
- add_directives:
    file: package://mdlc_dmd_models/fragments/boxes.yaml
    model_namespace: left
)");
  const Outcome r = Mdlc("compile --emit=plant-json " + packages() + " " + scene.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(Bodies(r), std::vector<std::string>{"left::box::box"});
}

TEST_F(InputFormatTest, AddDirectivesRefusesAModelFile) {  // DMD-060
  const fs::path scene = Write("scene.dmd.yaml", R"(directives:
- add_directives:
    file: package://mdlc_dmd_models/arm.urdf
)");
  const Outcome r = Mdlc("compile --emit=none " + packages() + " " + scene.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("scene.dmd.yaml:3:11: error: add_directives needs a directives file, not "
                       "the URDF model 'package://mdlc_dmd_models/arm.urdf'; use add_model for a "
                       "model"),
            std::string::npos)
      << r.err;
}

TEST_F(InputFormatTest, DashXNamesTheFormatOfEveryFile) {  // issue 55, COMMON-005
  // Drake's scenes are often plain .yaml; a URDF may be named anything
  const fs::path scene = Write("bimanual.yaml", R"(directives:
- add_model:
    name: box
    file: package://mdlc_dmd_models/box.sdf
)");
  const Outcome dmd = Mdlc("compile --emit=plant-json -x dmd " + packages() + " " + scene.string());
  ASSERT_EQ(dmd.status, 0) << dmd.err;
  EXPECT_EQ(Bodies(dmd), std::vector<std::string>{"box::box"});

  const fs::path robot = Write("robot.description", R"(<robot name="r"><link name="a">
  <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
</link></robot>)");
  const Outcome urdf = Mdlc("compile --emit=plant-json --input-format urdf " + robot.string());
  ASSERT_EQ(urdf.status, 0) << urdf.err;
  EXPECT_EQ(Bodies(urdf), std::vector<std::string>{"r::a"});

  // without -x: an error that says how to name it
  const Outcome unnamed = Mdlc("compile --emit=none " + robot.string());
  EXPECT_EQ(unnamed.status, 1);
  EXPECT_NE(unnamed.err.find("robot.description': unknown file extension; expected .urdf, .sdf, "
                             ".world, .xml (MJCF) or .dmd.yaml, or a format named (urdf, sdf, "
                             "mjcf or dmd)"),
            std::string::npos)
      << unnamed.err;
  // an unknown name is bad usage
  const Outcome bad = Mdlc("compile -x brick " + robot.string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("unknown format 'brick'; expected urdf, sdf, mjcf, dmd or xacro"),
            std::string::npos)
      << bad.err;
}

// --- inputs a user has (issue 58, item 5) ---

constexpr const char* kTwoLinks = R"(<robot name="r"><link name="a"/><link name="b"/>
<joint name="j" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
<limit lower="-1" upper="1"/></joint></robot>)";

TEST_F(InputFormatTest, FormatNamesTheInputOrTheOutput) {
  const std::string robot = Write("robot.description", kTwoLinks).string();
  // --format urdf: the input's format, as -x says it
  const Outcome tree = Mdlc("tree --format urdf " + robot);
  ASSERT_EQ(tree.status, 0) << tree.err;
  EXPECT_NE(tree.out.find("└─ b <- revolute joint 'j'"), std::string::npos) << tree.out;
  // both at once: the names of the two sets differ
  const Outcome json = Mdlc("tree --format urdf --format json " + robot);
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["bodies"].size(), 2u) << json.out;
  // a name of neither set says what each command takes
  const Outcome bad = Mdlc("graph --format svg " + robot);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("unknown format 'svg'; expected dot, json or urdf, sdf, mjcf, dmd or "
                         "xacro"),
            std::string::npos)
      << bad.err;
}

TEST_F(InputFormatTest, XacroByName) {
  const std::string robot = Write("robot.in", R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
<xacro:property name="n" value="b"/><link name="a"/><link name="${n}"/>
<joint name="j" type="fixed"><parent link="a"/><child link="${n}"/></joint></robot>)")
                                .string();
  const Outcome r = Mdlc("tree --format xacro " + robot);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("└─ b <- weld joint 'j'"), std::string::npos) << r.out;
}

TEST_F(InputFormatTest, ModelOnStandardInput) {
  Write("robot.txt", kTwoLinks);
  // the fixture closes standard input: feed it here
  auto run = [&](const std::string& args) {
    const std::string command = fmt::format("cd {} && {} {} <robot.txt >out.txt 2>err.txt",
                                            dir_.string(), MDLC_BINARY, args);
    const int raw = std::system(command.c_str());
    return Outcome{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(dir_ / "out.txt"),
                   ReadFile(dir_ / "err.txt")};
  };
  // the root element names the format; --format may too
  for (const char* args : {"tree -", "tree --format urdf -"}) {
    const Outcome r = run(args);
    ASSERT_EQ(r.status, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("model instance 'r': 2 bodies"), std::string::npos) << r.out;
  }
  // diagnostics name it <stdin>
  Write("robot.txt", "<robot name='r'><link/></robot>");
  const Outcome bad = run("compile -");
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("<stdin>:1:"), std::string::npos) << bad.err;
  Write("robot.txt", "solid nothing\n");
  const Outcome unknown = run("compile -");
  EXPECT_EQ(unknown.status, 1);
  EXPECT_NE(unknown.err.find("name its format with --format"), std::string::npos) << unknown.err;
}

TEST_F(InputFormatTest, GazeboWorldFilesAndModelFolders) {  // COMMON-005, and Gazebo's names
  const char* model = R"(<sdf version="1.9"><model name="table"><link name="top">
<inertial><mass>1</mass></inertial></link></model></sdf>)";
  const Outcome world = Mdlc("tree " + Write("empty.world", std::string(R"(<sdf version="1.9">
<world name="w"><model name="table"><static>true</static><link name="top"/></model></world></sdf>)"))
                                           .string());
  ASSERT_EQ(world.status, 0) << world.err;
  EXPECT_NE(world.out.find("model instance 'table'"), std::string::npos) << world.out;

  // a Gazebo model folder: model.config names the file of the newest version mdlc reads
  fs::create_directories(dir_ / "table");
  Write("table/model.config", R"(<?xml version="1.0"?><model><name>table</name>
<sdf version="1.6">old.sdf</sdf><sdf version="1.9">table.sdf</sdf></model>)");
  Write("table/table.sdf", model);
  const Outcome folder = Mdlc("tree " + (dir_ / "table").string());
  ASSERT_EQ(folder.status, 0) << folder.err;
  EXPECT_NE(folder.out.find("model instance 'table': 1 body"), std::string::npos) << folder.out;

  // a folder without one says so
  fs::create_directories(dir_ / "empty");
  const Outcome none = Mdlc("tree " + (dir_ / "empty").string());
  EXPECT_EQ(none.status, 1);
  EXPECT_NE(none.err.find("is a folder without a model.config naming its model file"),
            std::string::npos)
      << none.err;
}

// --- one spelling for machine output (issue 58, item 9) ---

TEST_F(InputFormatTest, FormatJsonOnEverySubcommandAndTheOldFlags) {
  const std::string robot = Write("r.urdf", kTwoLinks).string();
  for (const char* command : {"tree", "stats", "assets", "graph", "compile", "check"}) {
    const Outcome r = Mdlc(fmt::format("{} --format json {}", command, robot));
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    // check writes JSON Lines: its one line is one object
    EXPECT_NO_THROW((void)nlohmann::json::parse(r.out)) << command << ": " << r.out;
  }
  for (const char* command : {"tree", "stats", "assets", "check"}) {
    EXPECT_EQ(Mdlc(fmt::format("{} --json {}", command, robot)).out,
              Mdlc(fmt::format("{} --format json {}", command, robot)).out)
        << command;
  }
  // the usage line names the program, not the folder it is in
  const Outcome help = Mdlc("--help");
  EXPECT_NE(help.out.find("Usage: mdlc "), std::string::npos) << help.out;
}

}  // namespace
}  // namespace mdlc::cli_test
