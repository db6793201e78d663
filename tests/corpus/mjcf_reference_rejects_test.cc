// The corpus MJCF files that MuJoCo 3.3.8 (the reference MJCF compiler; the
// MuJoCo oracle test compares every file it loads) rejects, one by one: mdlc
// rejects what is truly broken with a located error (`file:line:col: error:`
// containing a keyword), and accepts, with the reason recorded, what Drake
// accepts or what is no model of its own (MuJoCo 2 models that MuJoCo 3 no
// longer reads, fragments meant to be included). Each entry cites the feature
// that decides it. Entries whose why begins "DISAGREE:" are files mdlc accepts
// although MuJoCo 3 rejects them for a reason mdlc should share: the table
// records what mdlc does today, the prefix marks it to be fixed. Entries whose
// why begins "TOLERATED:" are files mdlc accepts on purpose, with a warning,
// although MuJoCo 3 rejects them, for a reason that cannot affect the plant
// (a deliberate difference the README lists).
//
// The table must cover exactly the corpus MJCF files MuJoCo 3.3.8 rejects:
// MjcfReferenceRejectsTable.CoversExactlyWhatMujoco338Rejects runs MuJoCo
// 3.3.8 (tests/oracle/mujoco_js/mujoco_dump.mjs under Node.js) over every
// mjcf row of the manifest, so a new corpus file cannot slip by. Each entry
// also records whether MuJoCo 2.2.2 loads the file, checked against the
// manifest's loads_in_reference column (a MuJoCo 2.2.2 verdict).
//
// Together with the oracle test this covers MJCF-092: every dm_control suite
// model and every Menagerie model of the corpus that MuJoCo 3.3.8 loads
// compiles (the STL meshes and sizes-from-meshes Drake fails on included),
// and agrees with MuJoCo; none of them is listed here.
//
// Skipped (reported as skipped) when ../shared is absent; the coverage check
// is skipped without Node.js or the mujoco-js package (`npm ci` in
// tests/oracle/mujoco_js, which tools/setup.sh test runs).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef MDLC_NODE
#define MDLC_NODE ""
#endif
#ifndef MDLC_MUJOCO_JS_DIR
#define MDLC_MUJOCO_JS_DIR ""
#endif

namespace {
namespace fs = std::filesystem;

struct Expectation {
  const char* path;     // relative to corpus/
  bool mujoco222;       // does MuJoCo 2.2.2 load it? (manifest loads_in_reference)
  bool accepted;        // does mdlc compile it?
  const char* keyword;  // rejected: a word the located error must contain
  const char* why;
};

// clang-format off
constexpr Expectation kExpectations[] = {
  {"drake/multibody/parsing/dm_control/suite/acrobot.xml", false, false, "cannot read the included file",
   "MJCF-001: ./common/visual.xml (and the other common/ includes) are not beside this copy of the "
   "dm_control acrobot; MuJoCo 3.3.8 cannot open them either"},
  {"drake/multibody/parsing/test/mujoco_parser_test/pendulum_geom.xml", false, true, "",
   "MJCF-001/008: a fragment (a bare <geom> under <mujoco>) that Drake's test includes inside a "
   "body; MuJoCo's schema rejects the geom at top level, mdlc warns that it is not a top-level "
   "MJCF element and compiles an empty model"},
  {"drake/multibody/parsing/test/mujoco_parser_test/scene.xml", false, false, "already included",
   "MJCF-001: pendulum.xml is included twice (directly and through nested.xml); MuJoCo includes "
   "each file at most once"},
  {"mujoco_menagerie/leap_hand/left_hand.xml", false, true, "",
   "TOLERATED: MJCF-006/050, COMMON-011: the mesh file assets/palm_left.obj is not in the corpus "
   "(only palm_right.obj is), which MuJoCo cannot open; only the visual-only geom palm_visual "
   "(contype=conaffinity=0) of a body with an <inertial> uses it, so the plant never reads it: "
   "mdlc warns (-Wmissing-asset) and keeps the geom"},
  {"mujoco_menagerie/leap_hand/scene_left.xml", false, true, "",
   "TOLERATED: MJCF-006/050, COMMON-011: includes left_hand.xml, whose mesh file "
   "assets/palm_left.obj is not in the corpus; only a visual-only geom uses it, so mdlc warns "
   "(-Wmissing-asset)"},
  {"mujoco_menagerie/shadow_hand/keyframes.xml", false, false, "qpos",
   "MJCF-008: a fragment of keyframes meant to be included after a hand; alone, its keys give 24 "
   "qpos values for a model with none"},
  {"mujoco/model/adhesion/active_adhesion.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/cloth.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/grid2pin.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/loop.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/particle.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/rope.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/composite/softbox.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/flag/flag.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
  {"mujoco/model/hammock/hammock.xml", true, true, "",
   "MJCF-091: a MuJoCo 2 <composite> (MuJoCo 3 renamed its attributes: 'spacing'); Drake and mdlc "
   "warn that composite is unsupported and compile the rest; the MuJoCo oracle compares it with "
   "MuJoCo 2.2.2"},
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
  const fs::path err =
      fs::temp_directory_path() / ("mdlc_mjcf_rejects_" + std::to_string(::getpid()));
  const std::string cmd = std::string(MDLC_BINARY) + " compile '" + file.string() +
                          "' --emit=none >/dev/null 2>'" + err.string() + "'";
  const int raw = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  fs::remove(err);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw), ss.str()};
}

// An error line "FILE:LINE:COL: error: ..." whose message contains the keyword.
bool HasLocatedError(const std::string& err, const std::string& keyword) {
  static const std::regex kLocated(R"(:[0-9]+:[0-9]+: error: )");
  std::istringstream lines(err);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_search(line, m, kLocated) &&
        line.find(keyword, m.position(0)) != std::string::npos) {
      return true;
    }
  }
  return false;
}

// The file itself is named with a line and column: as the error's location, or
// in the "in file included from FILE:LINE:COL:" chain of an error raised in a
// file it includes.
bool NamesFileWithLine(const std::string& err, const std::string& path) {
  static const std::regex kLineCol(R"(^:[0-9]+:[0-9]+:)");
  for (auto at = err.find(path); at != std::string::npos; at = err.find(path, at + 1)) {
    const std::string rest = err.substr(at + path.size(), 32);
    if (std::regex_search(rest, kLineCol)) return true;
  }
  return false;
}

class MjcfReferenceRejects : public ::testing::TestWithParam<Expectation> {};

TEST_P(MjcfReferenceRejects, MdlcFollowsMujocoOrRecordsWhy) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  const Expectation& e = GetParam();
  const Result r = Compile(Corpus() / e.path);
  if (e.accepted) {
    EXPECT_EQ(r.status, 0) << e.path << " (" << e.why << ")\n" << r.err;
  } else {
    EXPECT_EQ(r.status, 1) << e.path << " (" << e.why << ")\n" << r.err;
    EXPECT_TRUE(HasLocatedError(r.err, e.keyword))
        << e.path << ": no located error containing '" << e.keyword << "'\n" << r.err;
    EXPECT_TRUE(NamesFileWithLine(r.err, e.path))
        << e.path << ": the file is not named with line:col\n" << r.err;
  }
}

std::string CaseName(const ::testing::TestParamInfo<Expectation>& info) {
  const fs::path p(info.param.path);
  std::string name = p.parent_path().filename().string() + "_" + p.stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Corpus, MjcfReferenceRejects, ::testing::ValuesIn(kExpectations), CaseName);

// The manifest's mjcf rows: path -> loads_in_reference (MuJoCo 2.2.2's verdict).
std::map<std::string, std::string> ManifestMjcf() {
  std::map<std::string, std::string> rows;
  std::ifstream in(Corpus() / "manifest.tsv");
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string col; std::getline(ss, col, '\t');) cols.push_back(col);
    if (cols.size() >= 7 && cols[0] == "mjcf") rows[cols[1]] = cols[6];
  }
  return rows;
}

TEST(MjcfReferenceRejectsTable, EntriesAreManifestMjcfWithMujoco222Verdicts) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  const auto rows = ManifestMjcf();
  std::map<std::string, int> listed;
  for (const auto& e : kExpectations) {
    EXPECT_EQ(++listed[e.path], 1) << "listed twice: " << e.path;
    const auto it = rows.find(e.path);
    if (it == rows.end()) {
      ADD_FAILURE() << e.path << " is listed but is no mjcf row of the manifest";
      continue;
    }
    EXPECT_EQ(e.mujoco222, it->second.rfind("yes", 0) == 0)
        << e.path << ": the manifest says MuJoCo 2.2.2 " << it->second;
  }
}

std::string Found(const std::string& s) {
  return s.size() >= 9 && s.compare(s.size() - 9, 9, "-NOTFOUND") == 0 ? "" : s;
}

// MuJoCo 3.3.8 over every corpus MJCF (one Node.js process, ~20 s): the files
// it rejects are exactly the table's.
TEST(MjcfReferenceRejectsTable, CoversExactlyWhatMujoco338Rejects) {
  if (!fs::exists(Corpus() / "manifest.tsv")) GTEST_SKIP() << "shared corpus not found";
  std::string node = Found(MDLC_NODE);
  if (const char* env = std::getenv("MDLC_NODE"); env && *env) node = env;
  const fs::path js = MDLC_MUJOCO_JS_DIR;
  if (node.empty()) GTEST_SKIP() << "Node.js not found at configure time";
  if (!fs::exists(js / "node_modules" / "mujoco-js" / "package.json")) {
    GTEST_SKIP() << "mujoco-js not installed: run `npm ci` in tests/oracle/mujoco_js";
  }
  const auto rows = ManifestMjcf();
  ASSERT_FALSE(rows.empty());
  const fs::path list = fs::temp_directory_path() / ("mdlc_mjcf_list_" + std::to_string(::getpid()));
  std::string cmd = "'" + node + "' '" + (js / "mujoco_dump.mjs").string() + "' --brief";
  for (const auto& [path, verdict] : rows) cmd += " '" + (Corpus() / path).string() + "'";
  cmd += " >'" + list.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(list);
  std::set<std::string> rejected;
  size_t lines = 0;
  // the dump prints absolute paths, not canonical ones (../shared may be a
  // symbolic link): compare both canonical
  const std::string prefix = fs::weakly_canonical(Corpus()).string() + "/";
  static const std::regex kLine(R"re(^\{"file":"([^"]*)","ok":(true|false))re");
  for (std::string line; std::getline(in, line);) {
    std::smatch m;
    ASSERT_TRUE(std::regex_search(line, m, kLine)) << line.substr(0, 300);
    ++lines;
    std::string file = fs::weakly_canonical(m[1].str()).string();
    if (file.rfind(prefix, 0) == 0) file = file.substr(prefix.size());
    if (m[2].str() == "false") {
      rejected.insert(file);
      std::printf("[ note ] MuJoCo 3.3.8 rejects %s\n", line.substr(0, 400).c_str());
    }
  }
  fs::remove(list);
  EXPECT_EQ(lines, rows.size());
  std::set<std::string> listed;
  for (const auto& e : kExpectations) listed.insert(e.path);
  for (const auto& f : rejected) {
    EXPECT_TRUE(listed.count(f)) << "MuJoCo 3.3.8 rejects " << f << " but the table has no entry";
  }
  for (const auto& f : listed) {
    EXPECT_TRUE(rejected.count(f)) << f << " is listed but MuJoCo 3.3.8 loads it";
  }
  std::printf("[ note ] MuJoCo 3.3.8 loads %zu of %zu corpus MJCF files\n",
              rows.size() - rejected.size(), rows.size());
}

}  // namespace
