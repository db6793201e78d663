// The corpus URDFs that urdfdom rejects, one by one: mdlc accepts what Drake
// accepts (Drake extensions, Drake's laxer rules) and rejects what is truly
// broken with a located error. Each entry says why. Entries whose why begins
// "TOLERATED:" are files mdlc accepts on purpose, with a warning, although
// Drake rejects them, for a reason that cannot affect the plant (a
// deliberate difference the README lists). The table must cover every such
// file in the manifest, so a new corpus file cannot slip by.
//
// Skipped (reported as skipped) when ../shared is absent.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace {
namespace fs = std::filesystem;

struct Expectation {
  const char* path;     // relative to corpus/
  bool accepted;        // does mdlc compile it?
  const char* keyword;  // rejected: a word the error must contain
  const char* why;
};

// clang-format off
constexpr Expectation kExpectations[] = {
  {"drake/examples/acrobot/Acrobot.urdf", true, "",
   "URDF-003: a joint may name the link 'world' without defining it; urdfdom needs the link"},
  {"drake/multibody/benchmarking/cassie_v2.urdf", true, "",
   "TOLERATED: COMMON-011: its visual meshes (pelvis.obj, ...) are not in the corpus, an error "
   "for Drake; the plant never reads a visual mesh, so mdlc warns (-Wmissing-asset) and keeps "
   "the visuals. urdfdom's complaint (revolute joints without limits) is fine for Drake"},
  {"drake/multibody/benchmarks/acrobot/acrobot.urdf", true, "",
   "URDF-030: an unnamed inline visual material is fine for Drake"},
  {"drake/multibody/benchmarks/kuka_iiwa_robot/kuka_iiwa_robot.urdf", true, "",
   "URDF-013: a revolute joint without <limit> is unbounded in Drake"},
  {"drake/multibody/parsing/test/links_with_visuals_and_collisions.urdf", true, "",
   "URDF-004: an <inertial> without <inertia> has zero moments in Drake"},
  {"drake/multibody/parsing/test/sdf_parser_test/bad.urdf", false, "Failed to parse XML",
   "COMMON-004: the file is not XML at all"},
  {"drake/multibody/parsing/test/sdf_parser_test/interface_api_test/arm.urdf", true, "",
   "URDF-013: revolute joints without <limit> are unbounded in Drake"},
  {"drake/multibody/parsing/test/urdf_parser_test/collision_filter_group_parsing_test.urdf", true, "",
   "URDF-017: several root links become free bodies in Drake; EXT-040 filter groups"},
  {"drake/multibody/parsing/test/urdf_parser_test/conflicting_materials.urdf", false,
   "defined again with different values", "URDF-030: one material name, two different colors"},
  {"drake/multibody/parsing/test/urdf_parser_test/duplicate_materials.urdf", true, "",
   "URDF-030: identical re-definitions of a material are fine for Drake"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test.urdf", true, "",
   "EXT-001: drake:joint types (ball, universal, screw, planar); unbounded revolute joints"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_missing_screw_thread_pitch.urdf",
   false, "screw_thread_pitch", "EXT-002: a screw joint needs drake:screw_thread_pitch"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_missing_screw_thread_pitch_attribute.urdf",
   false, "screw_thread_pitch", "EXT-002: drake:screw_thread_pitch needs its value"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_tag_mismatch_1.urdf", false,
   "standard joint type", "EXT-001: a standard joint type inside <drake:joint>"},
  {"drake/multibody/parsing/test/urdf_parser_test/joint_parsing_test_tag_mismatch_2.urdf", false,
   "custom joint type", "EXT-001: a Drake joint type (ball) inside a plain <joint>"},
  {"drake/multibody/parsing/test/urdf_parser_test/non_conflicting_materials_2.urdf", true, "",
   "URDF-017: several root links become free bodies in Drake"},
  {"drake_models/pr2_description/urdf/pr2_simplified.urdf", true, "",
   "URDF-013: a prismatic joint without <limit> is unbounded in Drake"},
  {"example-robot-data/robots/ur_description/urdf/ur3.urdf", false, "missing required attribute 'name'",
   "COMMON-021: the robot has no name, so the model instance would have none"},
};
// clang-format on

// readable test parameters in gtest's failure messages
void PrintTo(const Expectation& e, std::ostream* os) { *os << e.path; }

fs::path Corpus() { return fs::path(MDLC_SHARED_DIR) / "corpus"; }

struct Result {
  int status;
  std::string err;
};

Result Compile(const fs::path& file) {
  const fs::path err = fs::temp_directory_path() / ("mdlc_rejects_" + std::to_string(::getpid()));
  const std::string cmd = std::string(MDLC_BINARY) + " compile --emit=none --package-path '" +
                          Corpus().string() + "' '" + file.string() + "' >/dev/null 2>'" +
                          err.string() + "'";
  const int raw = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  fs::remove(err);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), ss.str()};
}

class UrdfReferenceRejects : public ::testing::TestWithParam<Expectation> {};

TEST_P(UrdfReferenceRejects, MdlcFollowsDrake) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  const Expectation& e = GetParam();
  const Result r = Compile(Corpus() / e.path);
  if (e.accepted) {
    EXPECT_EQ(r.status, 0) << e.path << " (" << e.why << ")\n" << r.err;
  } else {
    EXPECT_EQ(r.status, 1) << e.path << " (" << e.why << ")\n" << r.err;
    EXPECT_NE(r.err.find(e.keyword), std::string::npos) << e.path << "\n" << r.err;
    // located: "path:line:col: error:"
    EXPECT_NE(r.err.find(std::string(e.path) + ":"), std::string::npos) << r.err;
  }
}

std::string CaseName(const ::testing::TestParamInfo<Expectation>& info) {
  std::string name = fs::path(info.param.path).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Corpus, UrdfReferenceRejects, ::testing::ValuesIn(kExpectations), CaseName);

TEST(UrdfReferenceRejectsTable, CoversEveryUrdfTheReferenceRejects) {
  const fs::path manifest = Corpus() / "manifest.tsv";
  if (!fs::exists(manifest)) GTEST_SKIP() << "shared corpus not found";
  std::set<std::string> listed;
  for (const auto& e : kExpectations) listed.insert(e.path);
  std::ifstream in(manifest);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string col;
    while (std::getline(ss, col, '\t')) cols.push_back(col);
    if (cols.size() < 7 || cols[0] != "urdf" || cols[6].rfind("no", 0) != 0) continue;
    EXPECT_TRUE(listed.count(cols[1])) << "no expectation for " << cols[1] << " (" << cols[6] << ")";
  }
}

}  // namespace
