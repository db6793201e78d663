// Tests of the mesh loader (BEYOND-001): every format assimp reads gives the
// same 2 x 1 x 0.5 box (tests/models/meshes/generate.py), closed after
// welding; unreadable and empty files are errors.
#include "passes/mesh/mesh_loader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "passes/mesh/mass_properties.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

class MeshFormatTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshFormatTest, LoadsTheClosedBox) {  // BEYOND-001
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath(GetParam()));
  ASSERT_TRUE(m.ok()) << m.error;
  EXPECT_EQ(m.mesh->vertices.size(), 8u);
  EXPECT_EQ(m.mesh->triangles.size(), 12u);
  const mesh::MeshTopology topo = mesh::AnalyzeTopology(*m.mesh);
  EXPECT_TRUE(topo.closed);
  EXPECT_TRUE(topo.consistently_oriented);
  const mesh::MassProperties p = mesh::SolidMassProperties(*m.mesh);
  EXPECT_NEAR(p.measure, 1.0, 1e-12);
  ExpectNear(p.com, Eigen::Vector3d(1.5, 0.25, 1.25), 1e-12, "com");
}

// OBJ with quads and a missing .mtl; ASCII and binary STL (triangle soups,
// welded); PLY; DAE; glTF whose node transform places the vertices.
INSTANTIATE_TEST_SUITE_P(Formats, MeshFormatTest,
                         ::testing::Values("box.obj", "box_ascii.stl", "box_binary.stl", "box.ply",
                                           "box.dae", "box.gltf"));

// The files' material colours, for `mdlc view` (issue 58): OBJ's .mtl
// (two materials, a run each), COLLADA's Phong diffuse, glTF's base colour;
// a file without materials has none (the model's colour applies).
TEST(MeshLoaderTest, MaterialColorsComeInTriangleRuns) {  // BEYOND-001
  const std::string dir = std::string(MDLC_TEST_MODELS) + "/urdf/mesh_colors/";
  const mesh::MeshOrError obj = mesh::LoadMesh(dir + "two_colors.obj");
  ASSERT_TRUE(obj.ok()) << obj.error;
  ASSERT_EQ(obj.mesh->colors.size(), 2u);
  EXPECT_EQ(obj.mesh->colors[0].first_triangle, 0u);
  EXPECT_EQ(obj.mesh->colors[1].first_triangle, 6u);
  // red and green, in some order (assimp groups faces by material)
  std::vector<Eigen::Vector4d> seen = {obj.mesh->colors[0].rgba, obj.mesh->colors[1].rgba};
  if (seen[0].x() < seen[1].x()) std::swap(seen[0], seen[1]);
  ExpectNear(seen[0], Eigen::Vector4d(0.9, 0.1, 0.1, 1), 1e-6, "red");
  ExpectNear(seen[1], Eigen::Vector4d(0.1, 0.8, 0.2, 1), 1e-6, "green");
  for (const auto& [file, rgba] : {std::pair{"blue.dae", Eigen::Vector4d(0.1, 0.2, 0.9, 1)},
                                   std::pair{"yellow.gltf", Eigen::Vector4d(0.9, 0.8, 0.1, 1)}}) {
    const mesh::MeshOrError m = mesh::LoadMesh(dir + file);
    ASSERT_TRUE(m.ok()) << m.error;
    ASSERT_EQ(m.mesh->colors.size(), 1u) << file;
    EXPECT_EQ(m.mesh->colors[0].first_triangle, 0u);
    ExpectNear(m.mesh->colors[0].rgba, rgba, 1e-6, file);
  }
  for (const char* plain : {"box.obj", "box.dae", "box.gltf", "box_binary.stl"}) {
    const mesh::MeshOrError m = mesh::LoadMesh(MeshPath(plain));
    ASSERT_TRUE(m.ok()) << m.error;
    EXPECT_TRUE(m.mesh->colors.empty()) << plain;
  }
}

TEST(MeshLoaderTest, MissingFileIsAnError) {  // BEYOND-001
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath("no_such_mesh.obj"));
  EXPECT_FALSE(m.ok());
  EXPECT_NE(m.error.find("cannot read"), std::string::npos) << m.error;
}

TEST(MeshLoaderTest, GarbageIsAnError) {  // BEYOND-001
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath("garbage.stl"));
  EXPECT_FALSE(m.ok());
  EXPECT_FALSE(m.error.empty());
}

// A malformed PLY header on which assimp's reader never returns (found by
// fuzz_mesh: tests/fuzz/regressions/mesh/ply_header_hang, whose first byte
// is the harness's file-type selector) is an error, not a hang.
TEST(MeshLoaderTest, MalformedPlyHeaderIsAnErrorNotAHang) {  // BEYOND-001
  std::ifstream in(std::string(MDLC_TEST_MODELS) + "/../fuzz/regressions/mesh/ply_header_hang",
                   std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1u);
  const std::string path = ::testing::TempDir() + "mdlc_ply_header_hang.ply";
  std::ofstream(path, std::ios::binary) << bytes.substr(1);
  const mesh::MeshOrError m = mesh::LoadMesh(path);
  EXPECT_FALSE(m.ok());
  EXPECT_NE(m.error.find("gives no element count"), std::string::npos) << m.error;
  // a well-formed PLY still loads
  EXPECT_TRUE(mesh::LoadMesh(MeshPath("box.ply")).ok());
}

// A PLY whose faces name vertices it does not have (found by fuzz_mesh:
// tests/fuzz/regressions/mesh/ply_face_index_out_of_range) is an error;
// assimp's triangulation would have read past the vertex array.
TEST(MeshLoaderTest, FaceNamingAMissingVertexIsAnError) {  // BEYOND-001
  std::ifstream in(
      std::string(MDLC_TEST_MODELS) + "/../fuzz/regressions/mesh/ply_face_index_out_of_range",
      std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1u);
  const std::string path = ::testing::TempDir() + "mdlc_ply_face_index.ply";
  std::ofstream(path, std::ios::binary) << bytes.substr(1);
  const mesh::MeshOrError m = mesh::LoadMesh(path);
  EXPECT_FALSE(m.ok());
  EXPECT_NE(m.error.find("but there are only 4 vertices"), std::string::npos) << m.error;
}

TEST(MeshLoaderTest, PointsWithoutTrianglesGiveTheirConvexHull) {  // BEYOND-001
  // empty.obj: a box's 8 corners and no faces; MuJoCo 3.3.8 takes the hull
  // of such a point cloud (issue 62)
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath("empty.obj"));
  ASSERT_TRUE(m.ok()) << m.error;
  EXPECT_EQ(m.mesh->vertices.size(), 8u);
  EXPECT_EQ(m.mesh->triangles.size(), 12u);
  EXPECT_NEAR(mesh::SolidMassProperties(*m.mesh).measure, 2.0 * 1.0 * 0.5, 1e-12);
}

TEST(MeshLoaderTest, MirroringScaleKeepsTheSurfaceOutward) {  // BEYOND-001
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath("tetra.obj"));
  ASSERT_TRUE(m.ok()) << m.error;
  const mesh::TriangleMesh mirrored = mesh::Scaled(*m.mesh, Eigen::Vector3d(-2, 1, 1));
  const mesh::MassProperties p = mesh::SolidMassProperties(mirrored);
  EXPECT_NEAR(p.measure, 2.0 / 6.0, 1e-12);
  ExpectNear(p.com, Eigen::Vector3d(-0.5, 0.25, 0.25), 1e-12, "com");
}

}  // namespace
}  // namespace mdlc::testing
