// Files whose names do not say their format (issue 55, COMMON-005, DMD-060):
// add_directives reads a directives file of any name, as Drake's
// LoadModelDirectives does; the command line names a top-level file's format
// with -x; without it, an unknown extension is an error that says how.
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
                             ".xml (MJCF) or .dmd.yaml, or a format named (urdf, sdf, mjcf or dmd)"),
            std::string::npos)
      << unnamed.err;
  // an unknown name is bad usage
  const Outcome bad = Mdlc("compile -x xacro " + robot.string());
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("unknown format 'xacro'; expected urdf, sdf, mjcf or dmd"),
            std::string::npos)
      << bad.err;
}

}  // namespace
}  // namespace mdlc::cli_test
