// How the command line reports diagnostics (issue 58): a warning that
// repeats is shown once and counted in a note at the end (-fno-collapse shows
// them all; JSON always has every one); the run ends with "N warnings and M
// errors generated."; --list-warnings names every -W group; a file that
// cannot be written says why; counts agree with their nouns ("1 body").
#include <nlohmann/json.hpp>

#include <sstream>

#include "cli_fixture.h"
#include "repeated_warnings.h"
#include "warning_groups.h"

namespace mdlc::cli_test {
namespace {

using cli::RepeatedWarnings;

size_t Count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(RepeatedWarningsTest, ShowsTheFirstOfEachWarningAndCountsTheRest) {
  RepeatedWarnings repeated;
  EXPECT_TRUE(repeated.FirstOfItsKind("unsupported", "element <a> is ignored", "m.sdf:3:5"));
  EXPECT_FALSE(repeated.FirstOfItsKind("unsupported", "element <a> is ignored", "m.sdf:9:5"));
  EXPECT_FALSE(repeated.FirstOfItsKind("unsupported", "element <a> is ignored", "m.sdf:12:5"));
  // the same text in another group, and another text, are other warnings
  EXPECT_TRUE(repeated.FirstOfItsKind("unknown", "element <a> is ignored", "m.sdf:4:5"));
  EXPECT_TRUE(repeated.FirstOfItsKind("unsupported", "element <b> is ignored", "m.sdf:5:5"));
  EXPECT_FALSE(repeated.FirstOfItsKind("unsupported", "element <b> is ignored", "m.sdf:6:5"));
  EXPECT_EQ(repeated.hidden(), 3u);
  EXPECT_EQ(repeated.Notes(),
            "m.sdf:3:5: note: 2 more warnings 'element <a> is ignored' were not shown "
            "[-fno-collapse shows them]\n"
            "m.sdf:5:5: note: 1 more warning 'element <b> is ignored' was not shown "
            "[-fno-collapse shows it]\n");
}

TEST(RepeatedWarningsTest, NothingRepeatedNeedsNoNote) {
  RepeatedWarnings repeated;
  EXPECT_TRUE(repeated.FirstOfItsKind("names", "x", "a"));
  EXPECT_EQ(repeated.Notes(), "");
}

TEST(WarningGroupsTest, EveryGroupOfTheDefinitionsIsDescribed) {
  const std::vector<cli::WarningGroup> groups = cli::WarningGroups();
  EXPECT_GT(groups.size(), 20u);
  for (const cli::WarningGroup& g : groups) {
    EXPECT_FALSE(g.description.empty()) << "group '" << g.name
                                        << "' needs a line in tools/mdlc/warning_groups.cc";
  }
}

class DiagnosticsOutputTest : public CliFixture {
 protected:
  // three links, each with the same unknown element: one warning, three times
  fs::path ThreeRepeats() {
    return Write("repeats.urdf", R"(<robot name="r">
  <link name="a"><gazebo_only/></link>
  <link name="b"><gazebo_only/></link>
  <link name="c"><gazebo_only/></link>
  <joint name="ab" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="bc" type="fixed"><parent link="b"/><child link="c"/></joint>
</robot>
)");
  }
};

TEST_F(DiagnosticsOutputTest, ARepeatedWarningIsShownOnceAndCounted) {
  const fs::path model = ThreeRepeats();
  const Outcome r = Mdlc("compile --emit=none " + model.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Count(r.err, "warning: unknown element <gazebo_only> in <link> is ignored"), 1u)
      << r.err;
  EXPECT_NE(r.err.find(model.string() + ":2:18: note: 2 more warnings 'unknown element "
                                        "<gazebo_only> in <link> is ignored' were not shown "
                                        "[-fno-collapse shows them]\n"),
            std::string::npos)
      << r.err;
  // the closing count is of every warning reported, shown or not
  EXPECT_TRUE(r.err.ends_with("\n3 warnings generated.\n")) << r.err;
}

TEST_F(DiagnosticsOutputTest, NoCollapseShowsEveryRepeat) {
  const Outcome r = Mdlc("compile --emit=none -fno-collapse " + ThreeRepeats().string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Count(r.err, "warning: unknown element <gazebo_only>"), 3u) << r.err;
  EXPECT_EQ(r.err.find("not shown"), std::string::npos) << r.err;
  EXPECT_TRUE(r.err.ends_with("\n3 warnings generated.\n")) << r.err;
}

TEST_F(DiagnosticsOutputTest, JsonDiagnosticsAreNeverCollapsedNorCounted) {
  const Outcome r = Mdlc("compile --emit=none --diagnostics-format=json " + ThreeRepeats().string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.err);
  size_t warnings = 0;
  for (std::string line; std::getline(lines, line);) {
    const nlohmann::json d = nlohmann::json::parse(line);  // every line is one diagnostic
    warnings += d["severity"] == "warning";
  }
  EXPECT_EQ(warnings, 3u) << r.err;
}

TEST_F(DiagnosticsOutputTest, TheRunEndsWithWarningsAndErrorsCounted) {
  const fs::path model = Write("bad.urdf", R"(<robot name="r">
  <link name="a"><gazebo_only/></link>
  <joint name="j" type="fixed"><parent link="a"/><child link="nowhere"/></joint>
</robot>
)");
  const Outcome r = Mdlc("compile --emit=none " + model.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(r.err.ends_with("\n1 warning and 1 error generated.\n")) << r.err;
}

TEST_F(DiagnosticsOutputTest, ListWarningsNamesEveryGroup) {
  const Outcome r = Mdlc("--list-warnings");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const cli::WarningGroup& g : cli::WarningGroups()) {
    EXPECT_NE(r.out.find(fmt::format("\n  {} ", g.name)), std::string::npos) << g.name;
  }
  EXPECT_NE(r.out.find("  lossy          convert: what the target format cannot hold"),
            std::string::npos)
      << r.out;
}

TEST_F(DiagnosticsOutputTest, AFileThatCannotBeWrittenSaysWhy) {
  const Outcome r = Mdlc(fmt::format("compile {}/urdf/floating_joint.urdf -o {}/no/such/dir/x.txt",
                                     MDLC_TEST_MODELS, dir_.string()));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/no/such/dir/x.txt': No such file or directory"), std::string::npos)
      << r.err;
}

TEST_F(DiagnosticsOutputTest, ACountAgreesWithItsNoun) {
  const fs::path model = Write("one.urdf", R"(<robot name="one">
  <link name="a"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
</robot>
)");
  const Outcome r = Mdlc("compile " + model.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("one: 1 body, 1 joint, mass 1 kg"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace mdlc::cli_test
