// The corpus files that the reference tools reject (urdfdom for URDF,
// libsdformat 12 for SDFormat, MuJoCo 3.3.8 for MJCF), one test for all:
// mdlc accepts each file its table says it accepts, and rejects the others
// with an error that contains the entry's keyword and, unless the entry says
// otherwise, is located (file:line:col). The tables (reference_rejects.h)
// say why for every entry. The ReferenceRejectsTable tests check that each
// table covers the files its reference rejects, so a new corpus file cannot
// slip by.
//
// Test names: <Format>/ReferenceRejects.MdlcFollowsTheTable/<folder>_<stem>_<index>.
// Skipped (reported as skipped) when ../shared is absent.
#include "reference_rejects.h"

#include <gtest/gtest.h>

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

#include "../oracle/oracle_util.h"
#include "shared_corpus.h"

#ifndef MDLC_NODE
#define MDLC_NODE ""
#endif
#ifndef MDLC_MUJOCO_JS_DIR
#define MDLC_MUJOCO_JS_DIR ""
#endif

namespace mdlc::corpus {
namespace {
namespace fs = std::filesystem;

using mdlc::corpus_test::Corpus;
using mdlc::corpus_test::HaveCorpus;

// One entry of one format's table.
struct Case {
  Expectation e;
  // URDF and SDFormat files name packages (package://, model://) that the
  // corpus folder provides; MJCF has no packages.
  bool package_path;
};

// readable test parameters in gtest's failure messages
void PrintTo(const Case& c, std::ostream* os) { *os << c.e.path; }

std::vector<Case> Cases(std::span<const Expectation> table) {
  std::vector<Case> cases;
  for (const auto& e : table) cases.push_back({e, /*package_path=*/true});
  return cases;
}

std::vector<Case> MjcfCases() {
  std::vector<Case> cases;
  for (const auto& m : MjcfReferenceRejects()) {
    cases.push_back({{m.path, m.accepted, m.keyword, m.why, /*located=*/true}, false});
  }
  return cases;
}

oracle::RunResult Compile(const Case& c) {
  std::vector<std::string> argv = {oracle::MdlcBinary(), "compile", (Corpus() / c.e.path).string(),
                                   "--emit=none"};
  if (c.package_path) {
    argv.push_back("--package-path");
    argv.push_back(Corpus().string());
  }
  return oracle::RunProcess(argv, 100.0);
}

// An error line "FILE:LINE:COL: error: ..." (FILE may be an included file)
// whose message contains the keyword.
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

// Any error line (located or not) whose message contains the keyword.
bool HasError(const std::string& err, const std::string& keyword) {
  std::istringstream lines(err);
  std::string line;
  while (std::getline(lines, line)) {
    const auto at = line.find("error: ");
    if (at != std::string::npos && line.find(keyword, at) != std::string::npos) return true;
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

class ReferenceRejects : public ::testing::TestWithParam<Case> {};

TEST_P(ReferenceRejects, MdlcFollowsTheTable) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  const Expectation& e = GetParam().e;
  const oracle::RunResult r = Compile(GetParam());
  ASSERT_TRUE(r.spawn_error.empty()) << r.spawn_error;
  ASSERT_FALSE(r.timed_out) << e.path << ": mdlc timed out";
  if (e.accepted) {
    EXPECT_EQ(r.exit_code, 0) << e.path << " (" << e.why << ")\n" << r.err;
  } else {
    EXPECT_EQ(r.exit_code, 1) << e.path << " (" << e.why << ")\n" << r.err;
    if (e.located) {
      EXPECT_TRUE(HasLocatedError(r.err, e.keyword))
          << e.path << ": no located error containing '" << e.keyword << "'\n" << r.err;
      EXPECT_TRUE(NamesFileWithLine(r.err, e.path))
          << e.path << ": the file is not named with line:col\n" << r.err;
    } else {
      EXPECT_TRUE(HasError(r.err, e.keyword))
          << e.path << ": no error containing '" << e.keyword << "'\n" << r.err;
      EXPECT_NE(r.err.find(e.path), std::string::npos) << r.err;
    }
  }
}

std::string CaseName(const ::testing::TestParamInfo<Case>& info) {
  const fs::path p(info.param.e.path);
  std::string name = p.parent_path().filename().string() + "_" + p.stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Urdf, ReferenceRejects, ::testing::ValuesIn(Cases(UrdfReferenceRejects())),
                         CaseName);
INSTANTIATE_TEST_SUITE_P(Sdf, ReferenceRejects, ::testing::ValuesIn(Cases(SdfReferenceRejects())),
                         CaseName);
INSTANTIATE_TEST_SUITE_P(Mjcf, ReferenceRejects, ::testing::ValuesIn(MjcfCases()), CaseName);

// The manifest's rows of `kind` ("urdf"): path -> loads_in_reference.
std::map<std::string, std::string> ManifestRows(const std::string& kind) {
  std::map<std::string, std::string> rows;
  const auto manifest = oracle::ReadManifest(Corpus() / "manifest.tsv");
  if (!manifest) return rows;
  for (const auto& cols : *manifest) {
    if (cols.size() >= 7 && cols[0] == kind) rows[cols[1]] = cols[6];
  }
  return rows;
}

TEST(ReferenceRejectsTable, UrdfCoversEveryUrdfTheReferenceRejects) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  std::set<std::string> listed;
  for (const auto& e : UrdfReferenceRejects()) listed.insert(e.path);
  for (const auto& [path, verdict] : ManifestRows("urdf")) {
    if (verdict.rfind("no", 0) != 0) continue;
    EXPECT_TRUE(listed.count(path)) << "no expectation for " << path << " (" << verdict << ")";
  }
}

TEST(ReferenceRejectsTable, SdfCoversExactlyTheSdfTheReferenceRejects) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  std::map<std::string, int> listed;
  for (const auto& e : SdfReferenceRejects()) ++listed[e.path];
  for (const auto& [path, count] : listed) EXPECT_EQ(count, 1) << "listed twice: " << path;

  std::set<std::string> rejected;  // sdf rows whose loads_in_reference is not "yes..."
  for (const auto& [path, verdict] : ManifestRows("sdf")) {
    if (verdict.rfind("yes", 0) == 0) continue;
    rejected.insert(path);
    EXPECT_TRUE(listed.count(path)) << "no expectation for " << path << " (" << verdict << ")";
  }
  for (const auto& [path, count] : listed) {
    EXPECT_TRUE(rejected.count(path))
        << path << " is listed but is not an sdf file that the reference rejects";
  }
}

TEST(ReferenceRejectsTable, MjcfEntriesAreManifestMjcfWithMujoco222Verdicts) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  const auto rows = ManifestRows("mjcf");
  std::map<std::string, int> listed;
  for (const auto& e : MjcfReferenceRejects()) {
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

// CMake leaves "<VAR>-NOTFOUND" when it finds no program.
std::string Found(const std::string& s) {
  return s.size() >= 9 && s.compare(s.size() - 9, 9, "-NOTFOUND") == 0 ? "" : s;
}

// MuJoCo 3.3.8 over every corpus MJCF (one Node.js process, ~20 s): the files
// it rejects are exactly the MJCF table's.
TEST(ReferenceRejectsTable, MjcfCoversExactlyWhatMujoco338Rejects) {
  if (!HaveCorpus()) GTEST_SKIP() << "shared corpus not found";
  std::string node = Found(MDLC_NODE);
  if (const char* env = std::getenv("MDLC_NODE"); env && *env) node = env;
  const fs::path js = MDLC_MUJOCO_JS_DIR;
  if (node.empty()) GTEST_SKIP() << "Node.js not found at configure time";
  if (!fs::exists(js / "node_modules" / "mujoco-js" / "package.json")) {
    GTEST_SKIP() << "mujoco-js not installed: run `npm ci` in tests/oracle/mujoco_js";
  }
  const auto rows = ManifestRows("mjcf");
  ASSERT_FALSE(rows.empty());
  std::vector<std::string> argv = {node, (js / "mujoco_dump.mjs").string(), "--brief"};
  for (const auto& [path, verdict] : rows) argv.push_back((Corpus() / path).string());
  const oracle::RunResult r = oracle::RunProcess(argv, 110.0);
  ASSERT_TRUE(r.spawn_error.empty()) << r.spawn_error;
  ASSERT_EQ(r.exit_code, 0) << oracle::Quote(argv).substr(0, 300) << "\n" << r.err.substr(0, 2000);
  std::set<std::string> rejected;
  size_t lines = 0;
  // the dump prints absolute paths, not canonical ones (../shared may be a
  // symbolic link): compare both canonical
  const std::string prefix = fs::weakly_canonical(Corpus()).string() + "/";
  static const std::regex kLine(R"re(^\{"file":"([^"]*)","ok":(true|false))re");
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
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
  EXPECT_EQ(lines, rows.size());
  std::set<std::string> listed;
  for (const auto& e : MjcfReferenceRejects()) listed.insert(e.path);
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
}  // namespace mdlc::corpus
