// The on-disk cache of derived mesh data (issue 16): a second compile of a
// mesh-heavy model takes its mass properties from the cache (and
// --time-passes says so), the results are the same bytes with and without
// it, and damaged entries are ignored. Every command here names its cache
// folder, inside the test's own folder.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "cli_fixture.h"

namespace {
namespace fs = std::filesystem;

using mdlc::cli_test::Outcome;

class MeshCacheTest : public mdlc::cli_test::CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    cache_ = dir_ / "cache";
  }
  /// mdlc with `args`, its environment's MDLC_CACHE_DIR set to `env_cache`.
  Outcome Mdlc(const std::string& args, const fs::path& env_cache) {
    return CliFixture::Mdlc(args, "MDLC_CACHE_DIR=" + env_cache.string());
  }
  /// A compile of the mesh model to plant-json, timing its passes.
  Outcome Compile(const std::string& cache_flags) {
    return Mdlc(fmt::format("compile {} --emit=plant-json --time-passes {}", kModel, cache_flags),
                dir_ / "unused");
  }
  /// (hits, misses) from the --time-passes report.
  static std::pair<int, int> HitsAndMisses(const std::string& report) {
    std::smatch m;
    const std::regex line("mesh cache: ([0-9]+) hits?, ([0-9]+) miss(es)?");
    if (!std::regex_search(report, m, line)) {
      ADD_FAILURE() << "no mesh cache line in:\n" << report;
      return {-1, -1};
    }
    return {std::stoi(m[1]), std::stoi(m[2])};
  }
  /// (parsed, hashed, known from the cache, workers started) from the
  /// --time-passes report.
  static std::array<int, 4> MeshCounts(const std::string& report) {
    std::smatch m;
    const std::regex line(
        "meshes: ([0-9]+) parsed, ([0-9]+) hashed, ([0-9]+) known from the cache; ([0-9]+) "
        "reader workers started");
    if (!std::regex_search(report, m, line)) {
      ADD_FAILURE() << "no meshes line in:\n" << report;
      return {-1, -1, -1, -1};
    }
    return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
  }
  size_t Entries() const {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(cache_)) n += e.is_regular_file();
    return n;
  }

  // MJCF mesh geoms whose bodies' mass properties come from the meshes
  const std::string kModel = std::string(MDLC_TEST_MODELS) + "/mjcf/oracle/mesh_geoms.xml";
  fs::path cache_;
};

TEST_F(MeshCacheTest, ASecondCompileHitsTheCacheAndGivesTheSameBytes) {
  const std::string flags = "--cache-dir " + cache_.string();
  Outcome first = Compile(flags);
  ASSERT_EQ(first.status, 0) << first.err;
  const auto [first_hits, first_misses] = HitsAndMisses(first.err);
  EXPECT_GT(first_misses, 0);
  EXPECT_EQ(Entries(), static_cast<size_t>(first_misses));

  Outcome second = Compile(flags);
  ASSERT_EQ(second.status, 0) << second.err;
  const auto [hits, misses] = HitsAndMisses(second.err);
  EXPECT_EQ(misses, 0);
  EXPECT_EQ(hits, first_hits + first_misses);
  EXPECT_EQ(second.out, first.out);

  Outcome uncached = Compile("--no-cache");
  ASSERT_EQ(uncached.status, 0) << uncached.err;
  EXPECT_NE(uncached.err.find("mesh cache: off"), std::string::npos) << uncached.err;
  EXPECT_EQ(uncached.out, first.out);
}

TEST_F(MeshCacheTest, DamagedEntriesAreIgnoredAndRewritten) {
  const std::string flags = "--cache-dir " + cache_.string();
  Outcome first = Compile(flags);
  ASSERT_EQ(first.status, 0) << first.err;
  ASSERT_GE(Entries(), 2u);
  // one entry cut short (a write that stopped), one with a changed byte,
  // and a stray temporary file of a writer that died
  int damaged = 0;
  for (const auto& e : fs::directory_iterator(cache_)) {
    std::string bytes = mdlc::cli_test::ReadFile(e.path());
    if (damaged == 0) {
      bytes.resize(bytes.size() / 2);
    } else if (damaged == 1) {
      bytes[bytes.size() - 20] ^= 0x5a;
    } else {
      break;
    }
    std::ofstream(e.path(), std::ios::binary | std::ios::trunc) << bytes;
    ++damaged;
  }
  std::ofstream(cache_ / ".partial.tmp") << "mdlc-derived";

  Outcome again = Compile(flags);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(again.out, first.out);
  const auto [hits, misses] = HitsAndMisses(again.err);
  EXPECT_EQ(misses, damaged);
  // the damaged entries were computed again and replaced
  Outcome repaired = Compile(flags);
  EXPECT_EQ(HitsAndMisses(repaired.err).second, 0);
  EXPECT_EQ(repaired.out, first.out);
}

TEST_F(MeshCacheTest, TheEnvironmentNamesTheDefaultFolder) {
  Outcome r = Mdlc(fmt::format("compile {} --emit=none --time-passes", kModel), cache_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("(" + cache_.string() + ")"), std::string::npos) << r.err;
  EXPECT_GT(Entries(), 0u);
}

}  // namespace

// A second compile of an unchanged model hashes its meshes and reads none:
// no worker is started (issue 57).
TEST_F(MeshCacheTest, AWarmCompileReadsNoMeshAndStartsNoWorker) {
  const std::string flags = "--cache-dir " + cache_.string();
  Outcome cold = Compile(flags);
  ASSERT_EQ(cold.status, 0) << cold.err;
  const auto [parsed, hashed, known, workers] = MeshCounts(cold.err);
  EXPECT_GT(parsed, 1);
  EXPECT_EQ(hashed, parsed);
  EXPECT_EQ(known, 0);
  EXPECT_GE(workers, 1);
  // a worker per reading thread, each reading several files
  EXPECT_LT(workers, parsed);

  Outcome warm = Compile(flags);
  ASSERT_EQ(warm.status, 0) << warm.err;
  EXPECT_EQ(MeshCounts(warm.err), (std::array<int, 4>{0, parsed, parsed, 0})) << warm.err;
  EXPECT_EQ(warm.out, cold.out);
}

// A mesh that only a visual names is not read: a compile checks that the
// file is there, and nothing it outputs comes from its triangles (issue 57).
TEST_F(MeshCacheTest, AVisualOnlyMeshIsNotParsed) {
  fs::copy_file(std::string(MDLC_TEST_MODELS) + "/meshes/garbage.stl", dir_ / "looks.stl");
  const fs::path urdf = dir_ / "robot.urdf";
  std::ofstream(urdf) << R"(<robot name="r">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><mesh filename="looks.stl"/></geometry></visual>
  </link>
</robot>
)";
  Outcome r = Mdlc(fmt::format("compile {} --emit=none --time-passes --cache-dir {}",
                               urdf.string(), cache_.string()),
                   dir_ / "unused");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(MeshCounts(r.err), (std::array<int, 4>{0, 0, 0, 0})) << r.err;
}

// A compile of many meshes in which the reader crashes on one: that mesh
// gets one located error, and every other mesh loads (issue 57). The
// stand-in reader crashes on any file whose name says "crash".
TEST_F(MeshCacheTest, ACrashOnOneMeshOfManyLosesOnlyThatMesh) {
  std::string bodies, assets;
  for (int i = 0; i < 12; ++i) {
    const std::string name = i == 7 ? "crash" : fmt::format("part{}", i);
    fs::copy_file(std::string(MDLC_TEST_MODELS) + "/meshes/box.obj", dir_ / (name + ".obj"));
    assets += fmt::format("    <mesh name=\"{0}\" file=\"{0}.obj\"/>\n", name);
    bodies += fmt::format(
        "    <body name=\"b{0}\" pos=\"{0} 0 0\"><freejoint/><geom type=\"mesh\" "
        "mesh=\"{1}\"/></body>\n",
        i, name);
  }
  const fs::path model = dir_ / "many.xml";
  std::ofstream(model) << "<mujoco model=\"many\">\n  <asset>\n"
                       << assets << "  </asset>\n  <worldbody>\n"
                       << bodies << "  </worldbody>\n</mujoco>\n";
  Outcome r = CliFixture::Mdlc(
      fmt::format("compile {} --emit=none --time-passes --no-cache", model.string()),
      fmt::format("MDLC_MESH_READER={}", MDLC_FAULTY_MESH_READER));
  EXPECT_NE(r.status, 0);
  // one error, at the crash mesh's file attribute (line 10 of the model)
  const std::regex located(
      "many\\.xml:10:[0-9]+: error: the mesh reader crashed \\(signal 11, SIGSEGV\\) reading "
      "'[^']*crash\\.obj'");
  EXPECT_TRUE(std::regex_search(r.err, located)) << r.err;
  size_t errors = 0;
  for (size_t at = r.err.find(": error: "); at != std::string::npos;
       at = r.err.find(": error: ", at + 1)) {
    ++errors;
  }
  EXPECT_EQ(errors, 1u) << r.err;
  // all twelve were read: the eleven after a crash by the same or a fresh worker
  EXPECT_EQ(MeshCounts(r.err)[0], 12) << r.err;
}
