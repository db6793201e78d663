// DerivedMeshCache (issue 16): keys name the file's content and the
// options, entries round-trip exactly, and damaged entries are misses.
#include "passes/mesh/derived_cache.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace mdlc::mesh {
namespace {
namespace fs = std::filesystem;

class DerivedCacheTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mdlc_derived_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
};

TEST_F(DerivedCacheTest, KeysNameTheBytesAndTheOptionsNotThePath) {
  const std::string a = Write("a.obj", "v 0 0 0\n");
  const std::string b = Write("b.obj", "v 0 0 0\n");
  const auto key = DerivedMeshCache::Key(a, "mass|scale=1");
  ASSERT_TRUE(key);
  EXPECT_EQ(DerivedMeshCache::Key(b, "mass|scale=1"), key);  // same bytes elsewhere
  EXPECT_NE(DerivedMeshCache::Key(a, "mass|scale=2"), key);  // other options
  Write("a.obj", "v 0 0 1\n");                                // the file edited
  EXPECT_NE(DerivedMeshCache::Key(a, "mass|scale=1"), key);
  EXPECT_FALSE(DerivedMeshCache::Key((dir_ / "missing.obj").string(), "mass"));
}

TEST_F(DerivedCacheTest, ValuesRoundTripBitForBit) {
  DerivedMeshCache cache((dir_ / "cache").string());
  const std::vector<double> values = {1.0 / 3.0, -0.0, 1e-310, std::nextafter(1.0, 2.0),
                                      std::numeric_limits<double>::max()};
  EXPECT_FALSE(cache.Load("k"));  // nothing yet: a miss
  cache.Store("k", values);
  const auto loaded = cache.Load("k");
  ASSERT_TRUE(loaded);
  ASSERT_EQ(loaded->size(), values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(std::signbit((*loaded)[i]), std::signbit(values[i]));
    EXPECT_EQ((*loaded)[i], values[i]);
  }
  EXPECT_EQ(cache.hits(), 1u);
  EXPECT_EQ(cache.misses(), 1u);
  // no temporary file is left behind
  size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "cache")) files += e.is_regular_file();
  EXPECT_EQ(files, 1u);
}

TEST_F(DerivedCacheTest, AnEntryUnderAnotherKeyOrDamagedIsAMiss) {
  DerivedMeshCache cache((dir_ / "cache").string());
  cache.Store("k", {1, 2, 3});
  // an entry copied to another key's name does not answer for that key
  fs::copy_file(dir_ / "cache" / "k", dir_ / "cache" / "other");
  EXPECT_FALSE(cache.Load("other"));
  // every truncation of a good entry is a miss
  const fs::path entry = dir_ / "cache" / "k";
  std::ifstream in(entry, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  for (size_t n = 0; n < bytes.size(); ++n) {
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes.substr(0, n);
    EXPECT_FALSE(cache.Load("k")) << n << " bytes";
  }
  std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_TRUE(cache.Load("k"));
}

}  // namespace
}  // namespace mdlc::mesh
