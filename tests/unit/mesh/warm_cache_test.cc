// A warm mesh cache reads no mesh (issue 57, passes/mesh/mesh_cache.h): a
// second compile's cache, on the same derived-cache folder, knows each
// file's facts and derived data from the file's content alone; an edited
// file, other reading settings or a file that failed are read again; and
// the results are the same bits either way.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>

#include "passes/mesh/cached_properties.h"
#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/mesh_cache.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

class WarmCacheTest : public MeshFolderTest {
 protected:
  void SetUp() override {
    MeshFolderTest::SetUp();
    derived_ = std::make_shared<mesh::DerivedMeshCache>((dir_ / "cache").string());
  }

  /// A compile's mesh cache on the test's derived-cache folder, reading in
  /// this process, with reading settings `settings`.
  std::unique_ptr<mesh::MeshCache> Cache(const std::string& settings = "s") {
    return std::make_unique<mesh::MeshCache>(
        [](const std::string& path) { return mesh::LoadMeshInProcess(path); }, derived_,
        settings);
  }

  std::shared_ptr<mesh::DerivedMeshCache> derived_;
};

void ExpectSameBits(const mesh::MujocoMeshProperties& a, const mesh::MujocoMeshProperties& b) {
  EXPECT_EQ(a.mass.measure, b.mass.measure);
  EXPECT_EQ(a.mass.com, b.mass.com);
  EXPECT_EQ(a.mass.inertia, b.mass.inertia);
  EXPECT_EQ(a.R_MP, b.R_MP);
  EXPECT_EQ(a.principal_moments, b.principal_moments);
  EXPECT_EQ(a.inertia_box, b.inertia_box);
  EXPECT_EQ(a.aabb_min, b.aabb_min);
  EXPECT_EQ(a.aabb_max, b.aabb_max);
}

TEST_F(WarmCacheTest, ASecondCompileReadsNoMesh) {  // issue 57
  const std::vector<std::string> paths = {Copy("box.obj", "a.obj"), Copy("tetra.obj", "b.obj"),
                                          Copy("box_y_up.dae", "c.dae")};
  const Eigen::Vector3d scale(1, 2, 3);
  auto cold = Cache();
  cold->Survey(paths);
  EXPECT_EQ(cold->files_read(), 3u);
  EXPECT_EQ(cold->facts_from_cache(), 0u);
  std::string error;
  const auto cold_props = mesh::CachedMujocoMeshMassProperties(*cold, paths[0], scale,
                                                               ir::MeshInertia::Convex, &error);
  ASSERT_TRUE(cold_props) << error;
  const mesh::CollisionSolid cold_solid = mesh::CachedCollisionSolid(*cold, paths[1], scale, false);
  ASSERT_TRUE(cold_solid.mass) << cold_solid.error;

  auto warm = Cache();
  warm->Survey(paths);
  EXPECT_EQ(warm->files_read(), 0u);
  EXPECT_EQ(warm->files_hashed(), 3u);
  EXPECT_EQ(warm->facts_from_cache(), 3u);
  for (const std::string& p : paths) {
    const mesh::MeshStatus c = cold->Status(p), w = warm->Status(p);
    ASSERT_TRUE(w.ok()) << p;
    EXPECT_EQ(w.facts->vertices, c.facts->vertices) << p;
    EXPECT_EQ(w.facts->triangles, c.facts->triangles) << p;
    EXPECT_EQ(w.facts->declared_up, c.facts->declared_up) << p;
    EXPECT_EQ(w.facts->turned_to_z_up, c.facts->turned_to_z_up) << p;
  }
  EXPECT_EQ(warm->Status(paths[2]).facts->declared_up, mesh::UpAxis::kY);
  const auto warm_props = mesh::CachedMujocoMeshMassProperties(*warm, paths[0], scale,
                                                               ir::MeshInertia::Convex, &error);
  ASSERT_TRUE(warm_props) << error;
  ExpectSameBits(*warm_props, *cold_props);
  const mesh::CollisionSolid warm_solid = mesh::CachedCollisionSolid(*warm, paths[1], scale, false);
  ASSERT_TRUE(warm_solid.mass);
  EXPECT_EQ(warm_solid.mass->inertia, cold_solid.mass->inertia);
  EXPECT_EQ(warm->files_read(), 0u);

  // what was never computed is computed now, and only then is the mesh read
  ASSERT_TRUE(mesh::CachedMujocoMeshMassProperties(*warm, paths[0], scale * 2,
                                                   ir::MeshInertia::Convex, &error));
  EXPECT_EQ(warm->files_read(), 1u);
}

TEST_F(WarmCacheTest, AnEditedFileIsReadAgain) {  // issue 57
  const std::string path = Copy("box.obj", "part.obj");
  auto first = Cache();
  ASSERT_TRUE(first->Status(path).ok());
  Copy("tetra.obj", "part.obj");
  auto second = Cache();
  const mesh::MeshStatus s = second->Status(path);
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(second->files_read(), 1u);
  EXPECT_EQ(s.facts->triangles, mesh::LoadMeshInProcess(MeshPath("tetra.obj")).mesh->triangles.size());
}

TEST_F(WarmCacheTest, OtherReadingSettingsReadAgain) {  // issue 57
  const std::string path = Copy("box.obj", "part.obj");
  ASSERT_TRUE(Cache("limits A")->Status(path).ok());
  auto other = Cache("limits B");
  ASSERT_TRUE(other->Status(path).ok());
  EXPECT_EQ(other->files_read(), 1u);
  auto same = Cache("limits A");
  ASSERT_TRUE(same->Status(path).ok());
  EXPECT_EQ(same->files_read(), 0u);
}

TEST_F(WarmCacheTest, AFileThatFailedIsReadAgain) {  // issue 57
  const std::string path = Copy("garbage.stl", "bad.stl");
  for (int round = 0; round < 2; ++round) {
    auto cache = Cache();
    EXPECT_FALSE(cache->Status(path).ok());
    EXPECT_EQ(cache->files_read(), 1u) << "round " << round;
  }
}

// The settings a compile's cache keys by are what its reader is asked: the
// limits and the COLLADA up-axis mode.
TEST_F(WarmCacheTest, TheLimitsAndAxesArePartOfTheKey) {  // issue 57
  const std::string path = Copy("box_y_up.dae", "part.dae");
  auto cold = std::make_unique<mesh::MeshCache>(Limits{}, mesh::MeshReading::kInProcess,
                                                mesh::MeshAxes{}, derived_);
  ASSERT_TRUE(cold->Status(path).ok());
  EXPECT_FALSE(cold->Status(path).facts->turned_to_z_up);
  auto turned = std::make_unique<mesh::MeshCache>(
      Limits{}, mesh::MeshReading::kInProcess, mesh::MeshAxes{mesh::ColladaUpAxis::kApply},
      derived_);
  ASSERT_TRUE(turned->Status(path).ok());
  EXPECT_TRUE(turned->Status(path).facts->turned_to_z_up);
  EXPECT_EQ(turned->files_read(), 1u);
  Limits few;
  few.mesh_vertices = 3;
  auto limited = std::make_unique<mesh::MeshCache>(few, mesh::MeshReading::kInProcess,
                                                   mesh::MeshAxes{}, derived_);
  EXPECT_TRUE(limited->Status(path).over_limit);
}

}  // namespace
}  // namespace mdlc::testing
