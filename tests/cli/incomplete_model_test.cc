// incomplete_model_test.cc - the inspection commands answer for a model that
// did not compile whole (issue 58, item 3): as check_urdf prints a robot's
// tree whose meshes it cannot find, `mdlc tree`, `graph` and `stats` print
// what compiled after the errors, and exit 1.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_fixture.h"

namespace mdlc::cli_test {
namespace {

using nlohmann::json;

// two links; the collision mesh of the second is in a package no path
// names: an error, as the plant needs the file (COMMON-010)
constexpr const char* kArmWithUnknownPackage = R"(<robot name="arm">
  <link name="base"/>
  <link name="upper">
    <inertial><mass value="2"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="package://missing_pkg/upper.stl"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><axis xyz="0 0 1"/><limit lower="-1" upper="1"/>
  </joint>
</robot>)";

class IncompleteModelTest : public CliFixture {
 protected:
  std::string Arm() { return Write("arm.urdf", kArmWithUnknownPackage).string(); }
};

TEST_F(IncompleteModelTest, TreePrintsTheTreeAfterTheErrors) {
  const Outcome r = Mdlc("tree " + Arm());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("error: unknown package 'missing_pkg'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 error generated."), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("mdlc: note: tree of the model as far as it compiled"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("model instance 'arm': 2 bodies, 7 dofs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("└─ upper <- revolute joint 'shoulder', axis [0 0 1], limits [-1, 1]"),
            std::string::npos)
      << r.out;
}

TEST_F(IncompleteModelTest, GraphAndStatsToo) {
  const Outcome graph = Mdlc("graph --format json " + Arm());
  EXPECT_EQ(graph.status, 1) << graph.err;
  EXPECT_EQ(json::parse(graph.out)["edges"].size(), 2u) << graph.out;  // floating + shoulder

  const Outcome stats = Mdlc("stats --format json " + Arm());
  EXPECT_EQ(stats.status, 1) << stats.err;
  const json s = json::parse(stats.out);
  EXPECT_NE(stats.out.find("\"mass\":2"), std::string::npos) << stats.out;
  EXPECT_TRUE(s.is_object());
}

TEST_F(IncompleteModelTest, NothingToPrintWhenTheFileDoesNotParse) {
  const Outcome r = Mdlc("tree " + Write("broken.urdf", "<robot name='x'><link").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err.find("as far as it compiled"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mdlc::cli_test
