// Tests of the fit-to-mesh pass (BEYOND-002): MJCF primitives sized and
// placed from a mesh, for every primitive type, with the equivalent-inertia
// fit and with fitaabb, against MuJoCo 3.3.8.
//
// The expected numbers came from MuJoCo 3.3.8 (npm package mujoco-js
// 0.0.7): <mesh file="lshape.obj" scale="0.5 1 2" inertia=MODE/> and one
// body holding <geom type=TYPE mesh=... pos="0.1 0.2 0.3"
// quat="0.5 0.5 0.5 0.5" fitscale="1.2"/> (density 1000), with
// compiler@fitaabb false/true; read back: geom_size (half sizes, converted
// here to Drake's full lengths), geom_pos, geom_quat (as a matrix) and
// body_mass (the fitted primitive's mass, so mass-from-geometry is checked
// end to end). MuJoCo 3.3.8 fails on inertia="convex" meshes used only by
// fitted primitives (it never builds their hull), so convex is not here.
#include <gtest/gtest.h>

#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

using MI = ir::MeshInertia;

struct FitCase {
  const char* type;
  MI mode;
  bool aabb;
  std::vector<double> size;  // Drake's: box full sizes, radius + full length, radii
  Eigen::Vector3d pos;
  std::array<double, 9> R;  // row-major
  double body_mass;
};

std::vector<FitCase> Cases() {
  return {
      {"box", MI::Legacy, false, {1.8606870003134754, 2.3057635394420126, 4.78064676804871},
       {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 20510.42911628669},
      {"sphere", MI::Legacy, false, {1.491182884634033},
       {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 13889.331399378905},
      {"capsule", MI::Legacy, false, {1.0416126349388721, 3.739034133109838},
       {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 17478.2419522642},
      {"cylinder", MI::Legacy, false, {1.0416126349388721, 4.78064676804871},
       {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 16294.798977413955},
      {"ellipsoid", MI::Legacy, false, {0.9303435001567377, 1.1528817697210063, 2.390323384024355},
       {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 10739.23557228341},
      {"box", MI::Shell, false, {2.2694607338709445, 2.891589584048995, 5.52261603153219},
       {1.1, 0.8370967741935482, 1.8645161290322578},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 36241.333899431316},
      {"sphere", MI::Shell, false, {1.7806110582420218},
       {1.1, 0.8370967741935482, 1.8645161290322578},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 23648.07574835936},
      {"capsule", MI::Shell, false, {1.290262579479985, 4.232353452052206},
       {1.1, 0.8370967741935482, 1.8645161290322578},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 31132.95414504196},
      {"cylinder", MI::Shell, false, {1.290262579479985, 5.52261603153219},
       {1.1, 0.8370967741935482, 1.8645161290322578},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 28883.57365596672},
      {"ellipsoid", MI::Shell, false, {1.1347303669354722, 1.4457947920244976, 2.761308015766095},
       {1.1, 0.8370967741935482, 1.8645161290322578},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 18975.918055791364},
      {"box", MI::Legacy, true, {2.6497917551324908, 2.4000000000000026, 5.29958351026498},
       {1.1000000000000008, 0.7697475782889767, 2.164314946596452},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 33702.70245872703},
      {"sphere", MI::Legacy, true, {2.64979175513249},
       {1.1000000000000008, 0.7697475782889767, 2.164314946596452},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 77933.43930369883},
      {"capsule", MI::Legacy, true, {1.3248958775662454, 2.6497917551324894},
       {1.1000000000000008, 0.7697475782889767, 2.164314946596452},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 24354.199782405904},
      {"cylinder", MI::Legacy, true, {1.3248958775662454, 5.29958351026498},
       {1.1000000000000008, 0.7697475782889767, 2.164314946596452},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 29225.039738887088},
      {"ellipsoid", MI::Legacy, true, {1.3248958775662454, 1.2000000000000013, 2.64979175513249},
       {1.1000000000000008, 0.7697475782889767, 2.164314946596452},
       {-1.1102230246251565e-15, 1.000000000000001, 0.0, 0.9536997943435709, -1.1102230246251565e-15, 0.30076020725659997, 0.30076020725659997, 0.0, -0.9536997943435721}, 17646.69374174325},
      {"box", MI::Shell, true, {2.646677999146474, 2.400000000000003, 5.293355998292948},
       {1.1000000000000005, 0.7786443933794827, 2.170451007549715},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 33623.54126959675},
      {"sphere", MI::Shell, true, {2.646677999146474},
       {1.1000000000000005, 0.7786443933794827, 2.170451007549715},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 77659.02452842615},
      {"capsule", MI::Shell, true, {1.323338999573237, 2.646677999146474},
       {1.1000000000000005, 0.7786443933794827, 2.170451007549715},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 24268.445165133173},
      {"cylinder", MI::Shell, true, {1.323338999573237, 5.293355998292948},
       {1.1000000000000005, 0.7786443933794827, 2.170451007549715},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 29122.1341981598},
      {"ellipsoid", MI::Shell, true, {1.323338999573237, 1.2000000000000015, 2.646677999146474},
       {1.1000000000000005, 0.7786443933794827, 2.170451007549715},
       {-1.3322676295501878e-15, 1.0000000000000013, 0.0, 0.9558420397916936, -1.3322676295501878e-15, 0.29388091970534125, 0.29388091970534125, 0.0, -0.9558420397916949}, 17605.245040039732},
  };
}

ir::Shape Unsized(std::string_view type) {
  if (type == "box") return ir::Box{};
  if (type == "sphere") return ir::Sphere{};
  if (type == "capsule") return ir::Capsule{};
  if (type == "cylinder") return ir::Cylinder{};
  return ir::Ellipsoid{};
}

std::vector<double> SizeOf(const ir::Shape& s) {
  if (const auto* b = std::get_if<ir::Box>(&s)) return {b->size.x(), b->size.y(), b->size.z()};
  if (const auto* b = std::get_if<ir::Sphere>(&s)) return {b->radius};
  if (const auto* b = std::get_if<ir::Capsule>(&s)) return {b->radius, b->length};
  if (const auto* b = std::get_if<ir::Cylinder>(&s)) return {b->radius, b->length};
  if (const auto* b = std::get_if<ir::Ellipsoid>(&s)) return {b->a, b->b, b->c};
  return {};
}

TEST(FitToMeshTest, EveryTypeAndFitMatchesMujoco338) {  // BEYOND-002, MJCF-031
  for (const FitCase& c : Cases()) {
    SCOPED_TRACE(fmt::format("{} mode {} aabb {}", c.type, static_cast<int>(c.mode), c.aabb));
    MassFixture f;
    const BodyId body = f.AddBody("b");
    const Transform X_BG{Quat(0.5, 0.5, 0.5, 0.5), Eigen::Vector3d(0.1, 0.2, 0.3)};
    const GeometryId g = f.AddGeom(body, Unsized(c.type), X_BG);
    ir::MeshFit fit;
    fit.mesh = f.Mesh("lshape.obj", {0.5, 1, 2});
    fit.aabb = c.aabb;
    fit.fitscale = 1.2;
    fit.mesh_inertia = c.mode;
    f.module[g].fit_to_mesh = fit;
    ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
    const ir::Geometry& geom = f.module[g];
    EXPECT_FALSE(geom.fit_to_mesh);  // consumed
    const std::vector<double> size = SizeOf(geom.shape);
    ASSERT_EQ(size.size(), c.size.size());
    for (size_t i = 0; i < size.size(); ++i) EXPECT_NEAR(size[i], c.size[i], 1e-12) << i;
    ExpectNear(geom.X_BG.p, c.pos, 1e-12, "pos");
    // principal axes are defined up to sign (the primitives are symmetric)
    const Eigen::Matrix3d R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(
        c.R.data());
    ExpectNear(geom.X_BG.R.cwiseAbs(), R.cwiseAbs(), 1e-12, "rotation");
    // the fitted primitive's own mass at density 1000
    ASSERT_TRUE(f.module[body].inertial);
    EXPECT_NEAR(f.module[body].inertial->mass, c.body_mass, 1e-8 * c.body_mass);
    ExpectNear(f.Com(body), c.pos, 1e-12, "com");
  }
}

TEST(FitToMeshTest, ConvexModeFitsTheHull) {  // BEYOND-002
  // MuJoCo 3.3.8 (a box fitted to lshape.obj with inertia="convex", the
  // mesh also used by a collidable mesh geom so that MuJoCo builds its
  // hull): half sizes 0.5000000000000014 1.4160503125640218 2.164435863844353
  MassFixture f;
  const BodyId body = f.AddBody("b");
  const GeometryId g = f.AddGeom(body, ir::Box{});
  ir::MeshFit fit;
  fit.mesh = f.Mesh("lshape.obj");
  fit.mesh_inertia = MI::Convex;
  f.module[g].fit_to_mesh = fit;
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  const auto* box = std::get_if<ir::Box>(&f.module[g].shape);
  ASSERT_TRUE(box);
  ExpectNear(box->size / 2, Eigen::Vector3d(0.5000000000000014, 1.4160503125640218,
                                             2.164435863844353),
             1e-12, "half sizes");
  ExpectNear(f.module[g].X_BG.p, Eigen::Vector3d(1.608695652173913, 1.6086956521739133, 0.5),
             1e-12, "pos");
}

TEST(FitToMeshTest, UnreadableMeshIsALocatedError) {  // BEYOND-001, BEYOND-002
  MassFixture f;
  const BodyId body = f.AddBody("b");
  const GeometryId g = f.AddGeom(body, ir::Box{});
  ir::MeshFit fit;
  fit.mesh = f.Mesh("garbage.stl");
  f.module[g].fit_to_mesh = fit;
  EXPECT_FALSE(f.RunMassPipeline());
  const Diagnostic* d = f.Find(DiagKind::BadMesh);
  ASSERT_TRUE(d) << f.Messages();
  EXPECT_EQ(d->loc, fit.mesh.uri_loc);
}

}  // namespace
}  // namespace mdlc::testing
