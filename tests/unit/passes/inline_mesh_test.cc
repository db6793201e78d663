// Tests of MJCF meshes written in the file and of meshes without faces
// (issue 62, item 3; MJCF-050, BEYOND-001/002): an inline mesh with faces
// gives the same mass properties as the same mesh read from a file, an
// inline point cloud or an OBJ of `v` lines only is its convex hull (as
// MuJoCo 3.3.8 takes it), refpos/refquat place the vertices, and an inline
// mesh is kept in the mesh cache without a file or a reader. The MuJoCo
// oracle (tests/models/mjcf/oracle/inline_meshes.xml) compares the same
// against MuJoCo 3.3.8 itself.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "passes/mesh/mesh_cache.h"
#include "passes/mesh/point_cloud.h"
#include "tests/unit/compile_test_util.h"

namespace mdlc::testing {
namespace {

const nlohmann::json& BodyNamed(const nlohmann::json& plant, std::string_view name) {
  for (const auto& b : plant["bodies"]) {
    if (b["name"] == name) return b;
  }
  static const nlohmann::json none;
  ADD_FAILURE() << "no body " << name;
  return none;
}

void ExpectSameMass(const nlohmann::json& a, const nlohmann::json& b, double tol) {
  ASSERT_TRUE(a.contains("mass") && b.contains("mass")) << a << "\n" << b;
  EXPECT_NEAR(a["mass"].get<double>(), b["mass"].get<double>(), tol) << a << "\n" << b;
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(a["com"][k].get<double>(), b["com"][k].get<double>(), tol) << a << "\n" << b;
  }
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_NEAR(a["inertia"][k].get<double>(), b["inertia"][k].get<double>(), tol)
        << a << "\n" << b;
  }
}

// A cube of side 0.2 written as its 8 corners and two interior points, no
// faces: the hull is the cube, so the body weighs what a 0.2 box weighs.
constexpr const char* kCubeCloud =
    "0 0 0  0.2 0 0  0.2 0.2 0  0 0.2 0  0 0 0.2  0.2 0 0.2  0.2 0.2 0.2  0 0.2 0.2"
    "  0.1 0.1 0.1  0.05 0.02 0.07";

TEST(InlineMeshTest, PointCloudIsItsConvexHull) {  // MJCF-050, BEYOND-001
  CompiledText c("cloud.xml", fmt::format(R"(<mujoco model="m">
  <asset><mesh name="cube" vertex="{}"/></asset>
  <worldbody>
    <body name="cloud"><joint/><geom type="mesh" mesh="cube"/></body>
    <body name="box"><joint/><geom type="box" size="0.1 0.1 0.1" pos="0.1 0.1 0.1"/></body>
  </worldbody>
</mujoco>)", kCubeCloud));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json plant = c.Json();
  // the box's numbers are exact; the cloud's vertices are floats (0.2f)
  ExpectSameMass(BodyNamed(plant, "cloud"), BodyNamed(plant, "box"), 1e-6);
  EXPECT_NEAR(BodyNamed(plant, "cloud")["mass"].get<double>(), 8.0, 1e-5);
}

/// A folder of its own holding `files` ({name, text}), removed at the end.
class MeshFolder {
 public:
  explicit MeshFolder(std::vector<std::pair<std::string, std::string>> files) {
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("mdlc_inline_mesh_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    for (const auto& [name, text] : files) std::ofstream(dir_ / name) << text;
  }
  ~MeshFolder() { std::filesystem::remove_all(dir_); }
  std::string path() const { return dir_.string(); }

 private:
  std::filesystem::path dir_;
};

TEST(InlineMeshTest, FacesGiveWhatTheSameFileGives) {  // MJCF-050, BEYOND-002
  // a wedge (a triangular prism), outward faces; the OBJ numbers from 1
  const MeshFolder meshes({{std::string("wedge.obj"),
                            "v 0 0 0\nv 0.3 0 0\nv 0 0.2 0\nv 0 0 0.1\nv 0.3 0 0.1\nv 0 0.2 0.1\n"
                            "f 1 3 2\nf 4 5 6\nf 1 2 5\nf 1 5 4\nf 2 3 6\nf 2 6 5\nf 1 4 6\n"
                            "f 1 6 3\n"}});
  const std::string wedge =
      R"(vertex="0 0 0  0.3 0 0  0 0.2 0  0 0 0.1  0.3 0 0.1  0 0.2 0.1"
         face="0 2 1  3 4 5  0 1 4  0 4 3  1 2 5  1 5 4  0 3 5  0 5 2")";
  CompiledText c("wedge.xml", fmt::format(R"(<mujoco model="m">
  <compiler meshdir="{0}"/>
  <asset>
    <mesh name="inline" {1} scale="1 2 3"/>
    <mesh name="shell" {1} inertia="shell"/>
    <mesh name="exact" {1} inertia="exact"/>
    <mesh name="file" file="wedge.obj" scale="1 2 3"/>
    <mesh name="file_shell" file="wedge.obj" inertia="shell"/>
    <mesh name="file_exact" file="wedge.obj" inertia="exact"/>
  </asset>
  <worldbody>
    <body name="a"><joint/><geom type="mesh" mesh="inline" euler="10 20 30"/></body>
    <body name="b"><joint/><geom type="mesh" mesh="file" euler="10 20 30"/></body>
    <body name="c"><joint/><geom type="mesh" mesh="shell"/></body>
    <body name="d"><joint/><geom type="mesh" mesh="file_shell"/></body>
    <body name="e"><joint/><geom type="box" mesh="inline" fitscale="1.5"/></body>
    <body name="f"><joint/><geom type="box" mesh="file" fitscale="1.5"/></body>
    <body name="g"><joint/><geom type="mesh" mesh="exact"/></body>
    <body name="h"><joint/><geom type="mesh" mesh="file_exact"/></body>
  </worldbody>
</mujoco>)", meshes.path(), wedge));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json plant = c.Json();
  for (auto [x, y] : {std::pair{"a", "b"}, {"c", "d"}, {"e", "f"}, {"g", "h"}}) {
    SCOPED_TRACE(fmt::format("{} against {}", x, y));
    ExpectSameMass(BodyNamed(plant, x), BodyNamed(plant, y), 1e-12);
  }
}

TEST(InlineMeshTest, ObjOfVerticesOnlyIsTheHullOfItsPoints) {  // BEYOND-001
  std::string obj;
  std::istringstream points(kCubeCloud);
  for (double x, y, z; points >> x >> y >> z;) obj += fmt::format("v {} {} {}\n", x, y, z);
  const MeshFolder meshes({{std::string("cloud.obj"), obj}});
  CompiledText c("cloud.xml", fmt::format(R"(<mujoco model="m">
  <compiler meshdir="{}"/>
  <asset>
    <mesh file="cloud.obj" scale="2 1 1"/>
    <mesh name="inline" vertex="{}" scale="2 1 1"/>
  </asset>
  <worldbody>
    <body name="file"><joint/><geom type="mesh" mesh="cloud"/></body>
    <body name="inline"><joint/><geom type="mesh" mesh="inline"/></body>
    <body name="fit"><joint/><geom type="sphere" mesh="cloud"/></body>
    <body name="fit_inline"><joint/><geom type="sphere" mesh="inline"/></body>
  </worldbody>
</mujoco>)", meshes.path(), kCubeCloud));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json plant = c.Json();
  ExpectSameMass(BodyNamed(plant, "file"), BodyNamed(plant, "inline"), 1e-12);
  ExpectSameMass(BodyNamed(plant, "fit"), BodyNamed(plant, "fit_inline"), 1e-12);
  EXPECT_NEAR(BodyNamed(plant, "file")["mass"].get<double>(), 16.0, 1e-5);
}

TEST(InlineMeshTest, RefposAndRefquatPlaceTheVertices) {  // MJCF-050
  // the same cube moved by (1, 2, 3) and turned a quarter about z: refpos
  // and refquat (v' = R^T (v - refpos)) bring it back to where it was
  std::string moved;
  std::istringstream points(kCubeCloud);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).matrix();
  for (double x, y, z; points >> x >> y >> z;) {
    const Eigen::Vector3d v = R * Eigen::Vector3d(x, y, z) + Eigen::Vector3d(1, 2, 3);
    moved += fmt::format("{} {} {}  ", v.x(), v.y(), v.z());
  }
  CompiledText c("moved.xml", fmt::format(R"(<mujoco model="m">
  <asset>
    <mesh name="cube" vertex="{}"/>
    <mesh name="moved" vertex="{}" refpos="1 2 3" refquat="0.7071067811865476 0 0 0.7071067811865476"/>
  </asset>
  <worldbody>
    <body name="a"><joint/><geom type="mesh" mesh="cube"/></body>
    <body name="b"><joint/><geom type="mesh" mesh="moved"/></body>
  </worldbody>
</mujoco>)", kCubeCloud, moved));
  ASSERT_TRUE(c.ok()) << c.Messages();
  const nlohmann::json plant = c.Json();
  // the moved vertices were rounded to floats far from the origin
  ExpectSameMass(BodyNamed(plant, "a"), BodyNamed(plant, "b"), 1e-5);
}

TEST(InlineMeshTest, CacheKeepsAProvidedMeshWithoutReading) {  // BEYOND-001
  std::atomic<int> reads{0};
  mesh::MeshCache cache([&](const std::string&) {
    ++reads;
    return mesh::MeshOrError{nullptr, "no files here"};
  });
  ir::InlineMesh cube;
  std::istringstream points(kCubeCloud);
  for (double x, y, z; points >> x >> y >> z;) cube.vertices.emplace_back(x, y, z);
  cache.Provide("<inline mesh 'cube' of model 1>",
                mesh::TrianglesOfInlineMesh(cube, "mesh 'cube'"));
  cache.Survey({"<inline mesh 'cube' of model 1>"});
  const mesh::MeshStatus status = cache.Status("<inline mesh 'cube' of model 1>");
  ASSERT_TRUE(status.ok()) << status.error;
  EXPECT_EQ(status.facts->triangles, 12u);  // the cube's hull: 6 squares, 2 triangles each
  EXPECT_EQ(cache.Get("<inline mesh 'cube' of model 1>").mesh->vertices.size(), 8u);
  EXPECT_EQ(reads.load(), 0);
  EXPECT_EQ(cache.files_read(), 0u);
  EXPECT_EQ(cache.files_hashed(), 0u);
}

TEST(InlineMeshTest, PointsWithoutVolumeHaveNoHull) {  // BEYOND-001
  auto points = std::make_shared<mesh::TriangleMesh>();
  points->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh::MeshOrError few = mesh::HullOfPointCloud({points, {}}, "mesh file 'a.obj'");
  EXPECT_FALSE(few.ok());
  EXPECT_NE(few.error.find("mesh file 'a.obj' holds 3 points and no triangles"),
            std::string::npos) << few.error;
  auto flat = std::make_shared<mesh::TriangleMesh>(*points);
  flat->vertices.emplace_back(1, 1, 0);
  mesh::MeshOrError coplanar = mesh::HullOfPointCloud({flat, {}}, "mesh 'flat'");
  EXPECT_FALSE(coplanar.ok());
  EXPECT_NE(coplanar.error.find("span no volume"), std::string::npos) << coplanar.error;
  // a mesh with triangles passes through untouched
  auto tetra = std::make_shared<mesh::TriangleMesh>(*points);
  tetra->vertices.emplace_back(0, 0, 1);
  tetra->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  mesh::MeshOrError same = mesh::HullOfPointCloud({tetra, {}}, "mesh 'tetra'");
  EXPECT_EQ(same.mesh, tetra);
}

}  // namespace
}  // namespace mdlc::testing
