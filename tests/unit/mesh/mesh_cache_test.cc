// Tests of the mesh cache (BEYOND-001): each file read once per compile,
// however many users and threads ask for it.
#include "passes/mesh/mesh_cache.h"

#include <gtest/gtest.h>

#include <atomic>
#include <map>
#include <mutex>
#include <set>
#include <thread>

#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

TEST(MeshCacheTest, ReadsEachFileOnce) {  // BEYOND-001
  mesh::MeshCache cache;
  for (int i = 0; i < 5; ++i) {
    EXPECT_TRUE(cache.Get(MeshPath("box.obj")).ok());
    EXPECT_TRUE(cache.Get(MeshPath("tetra.obj")).ok());
  }
  EXPECT_EQ(cache.files_read(), 2u);
  // the same mesh object is shared
  EXPECT_EQ(cache.Get(MeshPath("box.obj")).mesh, cache.Get(MeshPath("box.obj")).mesh);
}

TEST(MeshCacheTest, ErrorsAreCachedToo) {  // BEYOND-001
  mesh::MeshCache cache;
  EXPECT_FALSE(cache.Get(MeshPath("garbage.stl")).ok());
  EXPECT_FALSE(cache.Get(MeshPath("garbage.stl")).ok());
  EXPECT_EQ(cache.files_read(), 1u);
}

TEST(MeshCacheTest, PrefetchLoadsInParallelAndOnce) {  // BEYOND-001
  std::mutex mutex;
  std::map<std::string, int> reads;
  std::set<std::thread::id> threads;
  mesh::MeshCache cache([&](const std::string& path) {
    {
      std::lock_guard lock(mutex);
      ++reads[path];
      threads.insert(std::this_thread::get_id());
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return mesh::MeshOrError{std::make_shared<mesh::TriangleMesh>(), {}};
  });
  std::vector<std::string> paths;
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 8; ++i) paths.push_back(fmt::format("file{}", i));
  }
  cache.Prefetch(paths);
  EXPECT_EQ(reads.size(), 8u);
  for (const auto& [path, n] : reads) EXPECT_EQ(n, 1) << path;
  if (std::thread::hardware_concurrency() > 1) {
    EXPECT_GT(threads.size(), 1u);
  }
  // later Gets, also from several threads at once, read nothing more
  std::vector<std::thread> pool;
  for (int t = 0; t < 4; ++t) {
    pool.emplace_back([&] {
      for (const std::string& p : paths) EXPECT_TRUE(cache.Get(p).ok());
    });
  }
  for (auto& t : pool) t.join();
  EXPECT_EQ(cache.files_read(), 8u);
}

}  // namespace
}  // namespace mdlc::testing
