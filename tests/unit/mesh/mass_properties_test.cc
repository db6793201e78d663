// Tests of mesh mass properties: exact solids and shells against closed
// forms (BEYOND-001), and MuJoCo's mesh@inertia modes against MuJoCo 3.3.8
// itself (MJCF-031).
//
// The MuJoCo numbers came from MuJoCo 3.3.8 (npm package mujoco-js 0.0.7):
// a model with one body holding one mesh geom of density 1 (so body_mass is
// the measure, body_ipos the center of mass, and body_inertia rotated by
// body_iquat the unit-density inertia), loaded with MjModel.loadFromXML.
#include "passes/mesh/mass_properties.h"

#include <gtest/gtest.h>

#include "passes/mesh/convex_hull.h"
#include "passes/mesh/mesh_loader.h"
#include "tests/unit/mesh/mesh_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {
namespace {

mesh::TriangleMesh Load(std::string_view name, Eigen::Vector3d scale = Eigen::Vector3d::Ones()) {
  const mesh::MeshOrError m = mesh::LoadMesh(MeshPath(name));
  EXPECT_TRUE(m.ok()) << m.error;
  return m.ok() ? mesh::Scaled(*m.mesh, scale) : mesh::TriangleMesh{};
}

using testing::Sym;

TEST(SolidMassPropertiesTest, TetrahedronClosedForm) {  // BEYOND-001
  const mesh::MassProperties p = mesh::SolidMassProperties(Load("tetra.obj"));
  EXPECT_NEAR(p.measure, 1.0 / 6.0, 1e-15);
  ExpectNear(p.com, Eigen::Vector3d::Constant(0.25), 1e-15, "com");
  // about the center of mass: Ixx = 1/80, Ixy = +1/480 (the product of
  // inertia's sign flipped into the matrix)
  ExpectNear(p.inertia, Sym(1.0 / 80, 1.0 / 80, 1.0 / 80, 1.0 / 480, 1.0 / 480, 1.0 / 480),
             1e-15, "inertia");
}

TEST(SolidMassPropertiesTest, ScaledBoxClosedForm) {  // BEYOND-001
  // 2 x 1 x 0.5 scaled by (0.5, 2, 3) -> 1 x 2 x 1.5
  const mesh::MassProperties p = mesh::SolidMassProperties(Load("box.obj", {0.5, 2, 3}));
  const double a = 1, b = 2, c = 1.5, v = a * b * c;
  EXPECT_NEAR(p.measure, v, 1e-12);
  ExpectNear(p.com, Eigen::Vector3d(0.75, 0.5, 3.75), 1e-12, "com");
  ExpectNear(p.inertia, Sym(v * (b * b + c * c) / 12, v * (a * a + c * c) / 12,
                            v * (a * a + b * b) / 12, 0, 0, 0),
             1e-12, "inertia");
}

TEST(ShellMassPropertiesTest, BoxClosedForm) {  // BEYOND-001
  const mesh::MassProperties p = mesh::ShellMassProperties(Load("box.obj"));
  EXPECT_NEAR(p.measure, 7, 1e-12);  // 2 (2*1 + 1*0.5 + 0.5*2)
  ExpectNear(p.com, Eigen::Vector3d(1.5, 0.25, 1.25), 1e-12, "com");
  // plates: pairs of faces, each plate's own inertia plus its offset
  const double lx = 2, ly = 1, lz = 0.5;
  const double axy = lx * ly, ayz = ly * lz, azx = lz * lx;
  const double ixx = 2 * (ayz * (ly * ly + lz * lz) / 12 + axy * (ly * ly / 12 + lz * lz / 4) +
                          azx * (lz * lz / 12 + ly * ly / 4));
  EXPECT_NEAR(p.inertia(0, 0), ixx, 1e-12);
  EXPECT_NEAR(p.inertia(0, 0), 1.2291666666666667, 1e-12);  // MuJoCo 3.3.8: 1229.1666 at density 1000
}

TEST(TopologyTest, ClosedOpenAndInconsistent) {  // BEYOND-001
  EXPECT_TRUE(mesh::AnalyzeTopology(Load("lshape.obj")).closed);
  EXPECT_TRUE(mesh::AnalyzeTopology(Load("lshape.obj")).consistently_oriented);
  EXPECT_FALSE(mesh::AnalyzeTopology(Load("open_box.obj")).closed);
  const mesh::MeshTopology flipped = mesh::AnalyzeTopology(Load("flipped.obj"));
  EXPECT_FALSE(flipped.closed && flipped.consistently_oriented);
  EXPECT_FALSE(flipped.consistently_oriented);
}

TEST(ConvexHullTest, HullOfTheLShapeIsItsHexagonalPrism) {  // BEYOND-001
  const auto hull = mesh::ConvexHull(Load("lshape.obj").vertices);
  ASSERT_TRUE(hull);
  EXPECT_TRUE(mesh::AnalyzeTopology(*hull).closed);
  EXPECT_TRUE(mesh::AnalyzeTopology(*hull).consistently_oriented);
  // the L (area 7) plus the triangle (1,4),(4,1),(1,1) of area 4.5, height 1
  EXPECT_NEAR(mesh::SolidMassProperties(*hull).measure, 11.5, 1e-12);
}

TEST(ConvexHullTest, CoplanarPointsFail) {  // BEYOND-001
  std::string why;
  EXPECT_FALSE(mesh::ConvexHull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, &why));
  EXPECT_FALSE(why.empty());
}

struct MujocoCase {
  ir::MeshInertia mode;
  double measure;
  Eigen::Vector3d com;
  Eigen::Matrix3d inertia;
};

// The L-shaped prism scaled by (0.5, 1, 2); MuJoCo 3.3.8 (see the top of
// this file). The four modes differ: the hull is larger, legacy counts the
// pyramids of the inner faces positive, the shell weighs the surface.
std::vector<MujocoCase> LShapeCases() {
  using MI = ir::MeshInertia;
  return {
      {MI::Convex, 11.5, {0.8043478260869567, 1.6086956521739135, 1.0000000000000002},
       Sym(16.655797101449277, 7.038949275362341, 16.02807971014497, 2.5679347826086936, 0, 0)},
      {MI::Exact, 7, {0.6785714285714285, 1.357142857142857, 1},
       Sym(11.773809523809522, 4.693452380952391, 11.800595238095273, 2.571428571428572, 0, 0)},
      {MI::Legacy, 8.668425470679939, {0.7238652716153017, 1.3864821921093657, 1.0000000000000002},
       Sym(13.251932685802124, 5.283764825880301, 13.2016606567438, 2.7903631006583716, 0, 0)},
      {MI::Shell, 31, {0.6370967741935482, 1.5645161290322578, 1},
       Sym(65.78763440860212, 28.167338709677484, 63.95497311827973, 12.774193548387093, 0, 0)},
  };
}

TEST(MujocoMeshInertiaTest, EveryModeMatchesMujoco338) {  // MJCF-031
  const mesh::TriangleMesh l = Load("lshape.obj", {0.5, 1, 2});
  for (const MujocoCase& c : LShapeCases()) {
    SCOPED_TRACE(static_cast<int>(c.mode));
    std::string why;
    const auto p = mesh::MujocoMeshMassProperties(l, c.mode, &why);
    ASSERT_TRUE(p) << why;
    EXPECT_NEAR(p->mass.measure, c.measure, 1e-12);
    ExpectNear(p->mass.com, c.com, 1e-12, "com");
    ExpectNear(p->mass.inertia, c.inertia, 1e-11, "inertia");
    // principal moments decreasing, axes right-handed
    EXPECT_GE(p->principal_moments[0], p->principal_moments[1]);
    EXPECT_GE(p->principal_moments[1], p->principal_moments[2]);
    EXPECT_NEAR(p->R_MP.determinant(), 1, 1e-12);
  }
}

TEST(MujocoMeshInertiaTest, OpenSurfaceModesMatchMujoco338) {  // MJCF-031
  // MuJoCo does not detect an open surface: exact and legacy integrate what
  // is there, convex takes the hull (the whole box), shell the five faces.
  // MuJoCo 3.3.8 at density 1000: exact/legacy mass 800.3623188405796,
  // com z 1.2005434782608695; convex 1000; shell 5000, com z 1.15.
  const mesh::TriangleMesh open = Load("open_box.obj");
  using MI = ir::MeshInertia;
  std::string why;
  auto exact = mesh::MujocoMeshMassProperties(open, MI::Exact, &why);
  ASSERT_TRUE(exact) << why;
  EXPECT_NEAR(exact->mass.measure, 0.8003623188405796, 1e-13);
  EXPECT_NEAR(exact->mass.com.z(), 1.2005434782608695, 1e-13);
  EXPECT_NEAR(exact->mass.inertia(0, 0) * 1000, 85.88931953491065, 1e-9);
  auto legacy = mesh::MujocoMeshMassProperties(open, MI::Legacy, &why);
  ASSERT_TRUE(legacy) << why;
  EXPECT_NEAR(legacy->mass.measure, 0.8003623188405796, 1e-13);
  auto convex = mesh::MujocoMeshMassProperties(open, MI::Convex, &why);
  ASSERT_TRUE(convex) << why;
  EXPECT_NEAR(convex->mass.measure, 1, 1e-13);
  auto shell = mesh::MujocoMeshMassProperties(open, MI::Shell, &why);
  ASSERT_TRUE(shell) << why;
  EXPECT_NEAR(shell->mass.measure, 5, 1e-13);
  EXPECT_NEAR(shell->mass.com.z(), 1.15, 1e-13);
  EXPECT_NEAR(shell->mass.inertia(0, 0) * 1000, 887.500000000007, 1e-9);
}

TEST(MujocoMeshInertiaTest, TetrahedronShellMatchesMujoco338) {  // MJCF-031
  // MuJoCo 3.3.8 at density 1000: mass 2366.0254037844384, ipos 0.26289171153160434,
  // principal moments 394.3375672974064, 245.28130608117195 (twice)
  std::string why;
  auto p = mesh::MujocoMeshMassProperties(Load("tetra.obj"), ir::MeshInertia::Shell, &why);
  ASSERT_TRUE(p) << why;
  EXPECT_NEAR(p->mass.measure * 1000, 2366.0254037844384, 1e-9);
  ExpectNear(p->mass.com, Eigen::Vector3d::Constant(0.26289171153160434), 1e-13, "com");
  ExpectNear(p->principal_moments * 1000,
             Eigen::Vector3d(394.3375672974064, 245.28130608117195, 245.28130608117195), 1e-9,
             "moments");
}

TEST(MujocoMeshInertiaTest, InconsistentOrientationFailsOnlyForExact) {  // MJCF-031
  // MuJoCo 3.3.8 refuses flipped.obj with inertia="exact" and accepts it
  // otherwise (convex and legacy: mass 1000 at density 1000)
  const mesh::TriangleMesh flipped = Load("flipped.obj");
  std::string why;
  EXPECT_FALSE(mesh::MujocoMeshMassProperties(flipped, ir::MeshInertia::Exact, &why));
  EXPECT_NE(why.find("inconsistent orientation"), std::string::npos) << why;
  for (auto mode : {ir::MeshInertia::Convex, ir::MeshInertia::Legacy}) {
    auto p = mesh::MujocoMeshMassProperties(flipped, mode, &why);
    ASSERT_TRUE(p) << why;
    EXPECT_NEAR(p->mass.measure, 1, 1e-12);
  }
}

TEST(MujocoMeshInertiaTest, InsideOutMeshHasNegativeVolume) {  // MJCF-031
  mesh::TriangleMesh inside_out = Load("box.obj");
  for (auto& t : inside_out.triangles) std::swap(t[1], t[2]);
  std::string why;
  EXPECT_FALSE(mesh::MujocoMeshMassProperties(inside_out, ir::MeshInertia::Exact, &why));
  EXPECT_NE(why.find("negative"), std::string::npos) << why;
}

TEST(MujocoMeshInertiaTest, EquivalentBoxOfABoxIsTheBox) {  // BEYOND-002
  std::string why;
  auto p = mesh::MujocoMeshMassProperties(Load("box.obj"), ir::MeshInertia::Exact, &why);
  ASSERT_TRUE(p) << why;
  // moments decreasing: the box's long axis (x, 2 m) is P's z axis
  ExpectNear(p->inertia_box, Eigen::Vector3d(0.25, 0.5, 1), 1e-12, "box");
  ExpectNear(p->aabb_max - p->aabb_min, Eigen::Vector3d(0.5, 1, 2), 1e-12, "aabb");
  EXPECT_NEAR(std::abs(p->R_MP(0, 2)), 1, 1e-12);
}

}  // namespace
}  // namespace mdlc::testing
