// Differential test of mdlc's MJCF frontend against MuJoCo 3.3.8 on MuJoCo's
// own test and model files (issue 62): the MJCF files of MuJoCo's test/ and
// model/ folders at google-deepmind/mujoco@6e59f61c70d26a9dc089cdf1b8a3ff6980e5b198,
// the last commit versioned 3.3.8, listed with their expected outcome in
// tests/models/mujoco_suite/manifest.tsv (written and checked by classify.py
// there, which runs both tools; its README says where the files come from).
//
// Per manifest outcome:
//   agree           MuJoCo 3.3.8 must load the file, mdlc must compile it, and
//                   every body, joint and the mass matrix must agree (below);
//   mujoco-rejects  MuJoCo 3.3.8 must still refuse it, and mdlc must refuse it
//                   with a located error (file:line:col: error:) unless the
//                   manifest's note says why mdlc accepts it;
//   not-held:C      mdlc must not crash (exit 0, or 1 with a located error)
//                   and, when it compiles the file, must warn about each
//                   construct C (MuJoCo is not asked);
//   pending:C       compared and reported, not failed: the case is skipped
//                   with its first differences, and passes with a note asking
//                   to mark it `agree` once mdlc agrees.
//
// The comparison is tests/oracle/mujoco_oracle_test.cc's, from
// tests/oracle/mujoco_reference.h (MuJoCo's dump by
// tests/oracle/mujoco_js/mujoco_dump.mjs, mdlc's plant-json by the CLI at
// each configuration, every quantity by name, never by position), with
// Drake's names for what the file leaves unnamed (MJCF-020/022/023): an
// unnamed body is `body<N>`, N the plant's body count when it is created
// (counting the world and the intermediate bodies of earlier bodies); a body
// with k > 1 joints has k-1 massless intermediate bodies `<body>0`, ...; an
// unnamed joint is `<parent>-<child>`; a free joint is its body's
// quaternion_floating joint. Compared, at the base state (the key named
// "home", else the first key, else qpos0) and MDLC_ORACLE_CONFIGS (default 3)
// seeded random configurations of the hinge and slide joints:
//   MJCF-010/020/023  X_WB of every body, to 1e-9 (kKinTol);
//   MJCF-030/031      mass, COM and inertia about the COM of every body, to
//                     1e-6 relative (kMassTol, as mujoco_oracle_test: MuJoCo
//                     re-diagonalises every inertia and keeps mesh vertices in
//                     single precision);
//   MJCF-022/023      every joint's type, parent and child body, world axis
//                     at every configuration, limits where MuJoCo limits it
//                     and default position, to 1e-9;
//   MJCF-022/024/031  the mass matrix on the hinge and slide dofs at every
//                     configuration, to 1e-6 relative to sqrt(M_ii M_jj), with
//                     MuJoCo's armature taken off its diagonal (plant-json's
//                     mass_matrix leaves reflected inertia out).
//
// Configuration (all optional except the suite):
//   env MDLC_MUJOCO_SUITE_DIR      the MuJoCo tree holding test/ and model/ at
//                                  the pinned commit (default: the CMake
//                                  cache variable of that name); without it
//                                  the one case reports itself skipped
//   env MDLC_BINARY, --mdlc=PATH   the mdlc CLI; env MDLC_NODE: Node.js
//   env MDLC_ORACLE_CONFIGS=N      random configurations (default 3)
// Without Node.js or the installed mujoco-js package every case is skipped.
// CTest runs the cases in four shards, MujocoSuiteOracle.shard_N_of_4, each
// one Node.js process.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mujoco_reference.h"
#include "oracle_util.h"

#ifndef MDLC_MUJOCO_SUITE_DIR
#define MDLC_MUJOCO_SUITE_DIR ""
#endif

namespace {

namespace fs = std::filesystem;
using namespace mdlc::oracle;
using namespace mdlc::oracle::mujoco;  // the reference, the plant, the comparisons
using json = nlohmann::json;

// ---------------------------------------------------------------------------
// Cases: the manifest's rows
// ---------------------------------------------------------------------------

struct SuiteCase {
  std::string id;       // gtest parameter name
  std::string rel;      // path below the MuJoCo tree, e.g. model/humanoid/humanoid.xml
  std::string path;     // absolute
  std::string outcome;  // agree, mujoco-rejects, not-held:..., pending:...
  std::string note;     // the manifest's note
  std::string skip_reason;
};

void PrintTo(const SuiteCase& c, std::ostream* os) { *os << c.rel; }

fs::path SuiteManifest() { return TestModels("mujoco_suite") / "manifest.tsv"; }

std::string SuiteDir() {
  if (const char* env = std::getenv("MDLC_MUJOCO_SUITE_DIR"); env && *env) return env;
  return MDLC_MUJOCO_SUITE_DIR;
}

std::vector<std::vector<std::string>> ReadSuiteManifest() {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(SuiteManifest());
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line.rfind("path\t", 0) == 0) continue;
    std::vector<std::string> cols;
    std::stringstream ss(line);
    for (std::string col; std::getline(ss, col, '\t');) cols.push_back(col);
    rows.push_back(cols);
  }
  return rows;
}

std::vector<SuiteCase> SuiteCases() {
  std::vector<SuiteCase> cases;
  const std::string dir = SuiteDir();
  std::string unavailable;
  if (dir.empty()) {
    unavailable = "MDLC_MUJOCO_SUITE_DIR is not set: it names a copy of MuJoCo's test/ and model/ "
                  "at the pinned commit (tests/models/mujoco_suite/README.md)";
  } else if (!fs::is_directory(fs::path(dir) / "model")) {
    unavailable = "MDLC_MUJOCO_SUITE_DIR (" + dir + ") holds no model/ folder";
  }
  const auto rows = ReadSuiteManifest();
  if (rows.empty()) unavailable = "no rows in " + SuiteManifest().string();
  if (!unavailable.empty()) {
    SuiteCase c;
    c.id = "suite_unavailable";
    c.skip_reason = unavailable;
    return {c};
  }
  for (const auto& cols : rows) {
    if (cols.size() < 2) continue;
    SuiteCase c;
    c.rel = cols[0];
    c.id = Sanitize(WithoutSuffix(cols[0], ".xml"));
    c.path = (fs::path(dir) / cols[0]).string();
    c.outcome = cols[1];
    if (cols.size() > 4) c.note = cols[4];
    cases.push_back(c);
  }
  Uniquify(&cases);
  return cases;
}

// The keyword a warning about each not-held construct names it by.
const char* ConstructKeyword(const std::string& construct) {
  static const std::map<std::string, const char*> kKeywords = {
      {"flex", "flex|deformable"}, {"spatial-tendon", "spatial"}, {"plugin", "plugin|<extension>"},
      {"sdf-geom", "sdf"},         {"skin", "skin"},              {"composite", "composite"}};
  const auto it = kKeywords.find(construct);
  return it == kKeywords.end() ? nullptr : it->second;
}

std::vector<std::string> Constructs(const std::string& outcome) {
  std::vector<std::string> out;
  const size_t colon = outcome.find(':');
  if (colon == std::string::npos) return out;
  std::stringstream ss(outcome.substr(colon + 1));
  for (std::string c; std::getline(ss, c, '+');) out.push_back(c);
  return out;
}

std::string Warnings(const std::string& err) {
  std::string out;
  std::stringstream ss(err);
  for (std::string l; std::getline(ss, l);) {
    if (l.find(": warning: ") != std::string::npos) out += l + "\n";
  }
  return out;
}

// Compiles the file at every configuration of MuJoCo's dump and compares;
// the discrepancies go to *rep. False when mdlc gave no plant (why in *rep).
bool CompareAll(const SuiteCase& sc, const Reference& ref, Report* rep) {
  std::map<std::string, std::string> scoped;  // local joint name -> name for --q
  for (size_t c = 0; c < ref.configs.size(); ++c) {
    const JointValues q = ConfigurationQ(ref, ref.configs[c], scoped);
    rep->SetContext("config " + std::to_string(c) + ", " + DescribeQ(q, "base state", "joints"));
    Plant plant;
    // --mass-matrix: plant-json leaves M(q) out above 1000 dofs unless asked
    // (model/replicate/particle.xml has 3000)
    if (const MdlcRun run = RunMdlcPlant(sc.path, q, &plant, {"--mass-matrix"}); !run.ok) {
      rep->Add(run.problem);
      return c > 0;
    }
    // bodies and joints only: mujoco_oracle_test holds mdlc to the rest
    ComparePlant(ref, c, plant, StaticChecks{}, &scoped, rep);
  }
  return true;
}

std::string FirstMessages(const Report& rep, size_t n = 3) {
  std::string out;
  for (size_t i = 0; i < rep.messages().size() && i < n; ++i) out += "\n    " + rep.messages()[i];
  return out;
}

// ---------------------------------------------------------------------------
// The test
// ---------------------------------------------------------------------------

class MujocoSuiteOracle : public ::testing::TestWithParam<SuiteCase> {};

TEST_P(MujocoSuiteOracle, MatchesManifest) {
  const SuiteCase& sc = GetParam();
  if (const std::string why = MujocoSkipReason(sc.skip_reason); !why.empty()) GTEST_SKIP() << why;
  ASSERT_TRUE(fs::is_regular_file(sc.path))
      << sc.rel << " is in the manifest but not in MDLC_MUJOCO_SUITE_DIR (" << SuiteDir() << ")";

  const bool agree = sc.outcome == "agree";
  const bool rejects = sc.outcome == "mujoco-rejects";
  const bool not_held = sc.outcome.rfind("not-held:", 0) == 0;
  const bool pending = sc.outcome.rfind("pending:", 0) == 0;
  ASSERT_TRUE(agree || rejects || not_held || pending) << "unknown outcome '" << sc.outcome << "'";

  if (not_held) {
    // mdlc must not crash, and when it compiles the file it must say what it
    // leaves out. MuJoCo is not asked: what the plant holds of such a file is
    // not MuJoCo's model (and MuJoCo's own dump of some flex models at random
    // configurations takes minutes).
    const RunResult r = RunProcess(PlantJsonCommand(sc.path, "", {}), 120.0);
    ASSERT_EQ(SpawnFailure(r), "");
    ASSERT_FALSE(r.timed_out) << "[" << sc.rel << "] mdlc timed out";
    ASSERT_TRUE(r.exit_code == 0 || (r.exit_code == 1 && HasLocatedError(r.err)))
        << "[" << sc.rel << "] mdlc exited with status " << r.exit_code << " on a file with "
        << sc.outcome << ":" << ErrorExcerpt(r.err);
    if (r.exit_code == 0) {
      const std::string warnings = Warnings(r.err);
      for (const std::string& c : Constructs(sc.outcome)) {
        const char* keyword = ConstructKeyword(c);
        ASSERT_NE(keyword, nullptr) << "unknown construct '" << c << "'";
        EXPECT_TRUE(std::regex_search(warnings, std::regex(keyword, std::regex::icase)))
            << "[" << sc.rel << "] no warning names the " << c << " the plant leaves out; warnings:\n"
            << warnings;
      }
    }
    std::printf("[ not-held ] %s: %s, mdlc exit %d%s\n", sc.rel.c_str(), sc.outcome.c_str(),
                r.exit_code, r.exit_code ? ErrorExcerpt(r.err).c_str() : "");
    return;
  }

  std::string problem;
  const json dump = DumpMujoco3(sc.path, &problem);
  ASSERT_TRUE(problem.empty()) << "[" << sc.rel << "] MuJoCo 3.3.8 dump failed: " << problem;
  const bool mujoco_loads = dump.value("ok", false);
  if ((agree || pending) && !mujoco_loads) {
    FAIL() << "[" << sc.rel << "] stale manifest row (" << sc.outcome << "): MuJoCo 3.3.8 rejects it: "
           << dump.value("error", std::string("?")) << " (rerun classify.py --write)";
  }

  if (rejects) {
    ASSERT_FALSE(mujoco_loads) << "[" << sc.rel << "] stale manifest row: MuJoCo 3.3.8 now loads it";
    const RunResult r = RunProcess(PlantJsonCommand(sc.path, "", {}), 120.0);
    ASSERT_EQ(SpawnFailure(r), "");
    ASSERT_FALSE(r.timed_out) << "[" << sc.rel << "] mdlc timed out";
    if (r.exit_code == 1) {
      EXPECT_TRUE(HasLocatedError(r.err))
          << "[" << sc.rel << "] mdlc rejects it without a located error:" << ErrorExcerpt(r.err);
      return;
    }
    ASSERT_EQ(r.exit_code, 0) << "[" << sc.rel << "] mdlc crashed (status " << r.exit_code << ")";
    EXPECT_EQ(sc.note.rfind("mdlc may accept it", 0), 0u)
        << "[" << sc.rel << "] MuJoCo 3.3.8 rejects it (" << dump.value("error", std::string("?"))
        << ") and mdlc accepts it, and the manifest does not say why";
    return;
  }

  Reference ref;
  try {
    ref = BuildReference(dump);
  } catch (const json::exception& e) {
    FAIL() << "[" << sc.rel << "] unexpected dump layout: " << e.what();
  }
  Report rep(sc.rel, "mujoco3.3.8");
  const bool compiled = CompareAll(sc, ref, &rep);
  if (agree) {
    if (!rep.empty()) ADD_FAILURE() << rep.Text();
    return;
  }
  const std::string result =
      !compiled ? "mdlc gives no plant:" + FirstMessages(rep, 1)
      : rep.empty()
          ? "agrees with MuJoCo in every compared quantity"
          : std::to_string(rep.size()) + " discrepancies, the first:" + FirstMessages(rep);
  // pending
  if (rep.empty()) {
    std::printf("[ pending ] %s: %s now agrees (once every file using it does, take the construct out of PENDING in classify.py)\n",
                sc.rel.c_str(), sc.outcome.c_str());
    return;
  }
  GTEST_SKIP() << sc.outcome << " (not failed): " << result;
}

INSTANTIATE_TEST_SUITE_P(Suite, MujocoSuiteOracle, ::testing::ValuesIn(SuiteCases()), CaseName());

// The manifest is classify.py's: every outcome is one the test knows, every
// construct one it can look for in mdlc's warnings.
TEST(MujocoSuiteOracleSelfCheck, ManifestOutcomesAreKnown) {
  const auto rows = ReadSuiteManifest();
  ASSERT_FALSE(rows.empty()) << SuiteManifest();
  std::set<std::string> paths;
  for (const auto& cols : rows) {
    ASSERT_GE(cols.size(), 4u) << cols.at(0);
    EXPECT_TRUE(paths.insert(cols[0]).second) << "listed twice: " << cols[0];
    const std::string& o = cols[1];
    if (o == "agree" || o == "mujoco-rejects" || o.rfind("pending:", 0) == 0) continue;
    ASSERT_EQ(o.rfind("not-held:", 0), 0u) << cols[0] << ": " << o;
    for (const std::string& c : Constructs(o)) EXPECT_NE(ConstructKeyword(c), nullptr) << cols[0] << ": " << c;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ParseMdlcFlag(argc, argv);
  // every shard says so when there is nothing to compare, so that ctest
  // (SKIP_REGULAR_EXPRESSION) reports each one skipped rather than passed
  if (const auto cases = SuiteCases(); cases.size() == 1 && cases[0].id == "suite_unavailable") {
    std::printf("mujoco suite unavailable: %s\n", cases[0].skip_reason.c_str());
  }
  return RUN_ALL_TESTS();
}
