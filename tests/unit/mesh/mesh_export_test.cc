// A mesh written back out as OBJ (passes/mesh/mesh_export.h, issue 58): the
// file mdlc writes for a target that cannot read the original (MuJoCo and
// COLLADA, glTF or PLY) reads back as exactly the triangles mdlc read from
// the original, and a binary STL's declared face count is read from its
// header (backend/writers/stl_header.h; MuJoCo refuses an STL of more than
// 200000 faces).
#include "passes/mesh/mesh_export.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>

#include "backend/writers/stl_header.h"
#include "passes/mesh/in_process_reader.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

/// Each triangle as its three corners, starting at the smallest (so the
/// winding is kept), the list sorted: the same surface, however the reader
/// numbers the vertices (it numbers them in order of first use).
std::vector<std::array<double, 9>> Surface(const mesh::TriangleMesh& m) {
  std::vector<std::array<double, 9>> out;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    std::array<std::array<double, 3>, 3> c;
    for (int k = 0; k < 3; ++k) c[k] = {m.corner(t, k).x(), m.corner(t, k).y(), m.corner(t, k).z()};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back({c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

class MeshExportTest : public MeshFolderTest {
 protected:
  /// `mesh` written as OBJ into the test's folder and read back.
  mesh::MeshOrError RoundTrip(const mesh::TriangleMesh& mesh) {
    const std::string path = (dir_ / "exported.obj").string();
    std::ofstream(path) << mesh::ObjText(mesh);
    return mesh::LoadMeshInProcess(path);
  }
};

// BEYOND-001: every format mdlc reads becomes an OBJ of the same triangles,
// bit for bit (the shortest text that reads back as the same double), each
// wound as it was.
TEST_F(MeshExportTest, ObjReadsBackAsTheSameTriangles) {
  for (const char* name : {"box.dae", "box.gltf", "box.ply", "box_binary.stl", "lshape.obj"}) {
    SCOPED_TRACE(name);
    const mesh::MeshOrError original = mesh::LoadMeshInProcess(MeshPath(name));
    ASSERT_TRUE(original.ok()) << original.error;
    const mesh::MeshOrError back = RoundTrip(*original.mesh);
    ASSERT_TRUE(back.ok()) << back.error;
    EXPECT_EQ(back.mesh->vertices.size(), original.mesh->vertices.size());
    EXPECT_EQ(Surface(*back.mesh), Surface(*original.mesh));
  }
}

TEST_F(MeshExportTest, ObjTextIsOneLinePerVertexAndTriangle) {
  mesh::TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 0.1, 0}};
  m.triangles = {{0, 1, 2}};
  const std::string text = mesh::ObjText(m);
  EXPECT_NE(text.find("\nv 0 0 0\nv 1 0 0\nv 0 0.1 0\nf 1 2 3\n"), std::string::npos) << text;
}

TEST_F(MeshExportTest, BinaryStlTriangleCountComesFromTheHeader) {
  auto head = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  };
  const std::string binary = head(MeshPath("box_binary.stl"));
  EXPECT_EQ(writers::BinaryStlTriangleCount(binary, binary.size()), 12u);
  const std::string ascii = head(MeshPath("box_ascii.stl"));
  EXPECT_EQ(writers::BinaryStlTriangleCount(ascii, ascii.size()), std::nullopt);
  EXPECT_EQ(writers::BinaryStlTriangleCount("solid", 5), std::nullopt);  // too short
}

}  // namespace
}  // namespace mdlc::testing
