// Tests of the load-meshes and mass-from-geometry passes: MJCF bodies' mass
// properties from their geoms (MJCF-031) and MuJoCo's compiler mass
// corrections (BEYOND-006), against MuJoCo 3.3.8; unreadable meshes are
// errors at the attribute naming them (BEYOND-001).
//
// The expected numbers came from MuJoCo 3.3.8 (npm package mujoco-js
// 0.0.7): the same bodies and geoms written as MJCF, loaded with
// MjModel.loadFromXML, reading body_mass, body_ipos and body_inertia rotated
// by body_iquat (the inertia about the center of mass in the body frame).
#include <gtest/gtest.h>

#include <map>
#include <numbers>

#include "tests/unit/mesh/mesh_test_util.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {
namespace {

using MI = ir::MeshInertia;

using testing::Sym;

struct Expected {
  double mass;
  Eigen::Vector3d com;
  Eigen::Matrix3d inertia;
};

void ExpectBody(const MassFixture& f, BodyId body, const Expected& e, double rel = 1e-12) {
  SCOPED_TRACE(std::string(f.module.Text(f.module[body].name)));
  ASSERT_TRUE(f.module[body].inertial);
  EXPECT_NEAR(f.module[body].inertial->mass, e.mass, rel * e.mass);
  ExpectNear(f.Com(body), e.com, 1e-12, "com");
  ExpectNear(f.InertiaB(body), e.inertia, rel * e.inertia.cwiseAbs().maxCoeff(), "inertia");
}

ir::MassContribution Density(double density, MI mode = MI::Legacy, bool shell = false) {
  ir::MassContribution c;
  c.density = density;
  c.mesh_inertia = mode;
  c.shell = shell;
  return c;
}

// <mesh file="lshape.obj" scale="0.5 1 2" inertia=MODE/>, one geom at
// pos="0.1 0.2 0.3" quat="0.5 0.5 0.5 0.5" density="2" (MuJoCo 3.3.8; its
// default mode, legacy, gave the legacy numbers).
TEST(MassFromGeometryTest, MeshInEveryModeMatchesMujoco338) {  // MJCF-031
  const std::vector<std::pair<MI, Expected>> cases = {
      {MI::Convex,
       {23, {1.1000000000000003, 1.0043478260869567, 1.9086956521739136},
        Sym(32.05615942028994, 33.31159420289864, 14.077898550724715, 0, 0, 5.135869565217394)}},
      {MI::Exact,
       {14, {1.1, 0.8785714285714286, 1.657142857142857},
        Sym(23.601190476190546, 23.5476190476191, 9.386904761904802, 0, 0, 5.1428571428571495)}},
      {MI::Legacy,
       {17.336850941359877, {1.1000000000000003, 0.9238652716153017, 1.6864821921093658},
        Sym(26.4033213134876, 26.503865371604313, 10.567529651760623, 0, 0,
            5.5807262013167485)}},
      {MI::Shell,
       {62, {1.1, 0.8370967741935482, 1.8645161290322578},
        Sym(127.90994623655946, 131.5752688172046, 56.33467741935509, 0, 0,
            25.548387096774224)}},
  };
  for (const auto& [mode, expected] : cases) {
    SCOPED_TRACE(static_cast<int>(mode));
    MassFixture f;
    const BodyId b = f.AddBody("b");
    f.AddGeom(b, f.Mesh("lshape.obj", {0.5, 1, 2}),
              {Quat(0.5, 0.5, 0.5, 0.5), Eigen::Vector3d(0.1, 0.2, 0.3)}, Density(2, mode));
    ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
    ExpectBody(f, b, expected);
  }
}

// Body "e" of the adjustments model below: solid capsule, cylinder
// (euler 0.3 degrees about x), ellipsoid and a visual plane, density 1000.
BodyId AddSolids(MassFixture& f) {
  const BodyId e = f.AddBody("e");
  f.AddGeom(e, ir::Capsule{0.1, 0.4});
  f.AddGeom(e, ir::Cylinder{0.1, 0.6},
            {RotationAboutAxis(Eigen::Vector3d::UnitX(), 0.3 * std::numbers::pi / 180),
             Eigen::Vector3d(0, 0.5, 0)});
  f.AddGeom(e, ir::Ellipsoid{0.1, 0.2, 0.3}, Transform::FromTranslation({0, 0, 0.5}));
  f.AddGeom(e, ir::HalfSpace{});  // planes have no volume: nothing
  return e;
}
// Body "d": the same kinds as shells (shellinertia="true"), plus a box and
// a sphere.
BodyId AddShells(MassFixture& f) {
  const BodyId d = f.AddBody("d");
  const ir::MassContribution shell = Density(1000, MI::Legacy, true);
  f.AddGeom(d, ir::Capsule{0.1, 0.4}, {}, shell);
  f.AddGeom(d, ir::Cylinder{0.1, 0.6}, Transform::FromTranslation({0, 0.5, 0}), shell);
  f.AddGeom(d, ir::Ellipsoid{0.1, 0.2, 0.3}, Transform::FromTranslation({0, 0, 0.5}), shell);
  f.AddGeom(d, ir::Box{Eigen::Vector3d(0.2, 0.4, 0.6)}, Transform::FromTranslation({0.5, 0, 0}),
            shell);
  f.AddGeom(d, ir::Sphere{0.1}, Transform::FromTranslation({-0.5, 0, 0}), shell);
  return d;
}

const Expected kShells = {
    2312.197129414111,
    {0.1631211033566913, 0.09510931527149201, 0.10589913098397095},
    Sym(290.57767059005874, 375.4225938657461, 319.5741618367712, 35.87220412442996,
        39.941778476180204, 23.28843477841984)};
const Expected kSolids = {60.73745796940267,
                          {0.0, 0.15517241379310345, 0.20689655172413793},
                          Sym(8.645337990335634, 5.244603897134987, 3.6750998516141564, 0, 0,
                              1.9526681524529268)};

TEST(MassFromGeometryTest, SolidPrimitivesMatchMujoco338) {  // MJCF-031
  MassFixture f;
  const BodyId e = AddSolids(f);
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  ExpectBody(f, e, kSolids);
}

TEST(MassFromGeometryTest, ShellPrimitivesMatchMujoco338) {  // MJCF-031
  MassFixture f;
  const BodyId d = AddShells(f);
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  // the ellipsoid's shell is MuJoCo's 1e-6 thick layer: a difference of
  // nearly equal numbers, so agreement is to about 1e-9 relative
  ExpectBody(f, d, kShells, 1e-8);
}

TEST(MassFromGeometryTest, GivenMassWinsOverDensity) {  // MJCF-031
  MassFixture f;
  const BodyId b = f.AddBody("b");
  ir::MassContribution c = Density(7);
  c.mass = 3;
  f.AddGeom(b, ir::Box{Eigen::Vector3d(1, 2, 3)}, {}, c);
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  EXPECT_DOUBLE_EQ(f.module[b].inertial->mass, 3);
  EXPECT_NEAR(f.module[b].inertial->ixx, 3 * (4 + 9) / 12.0, 1e-12);
}

TEST(MassFromGeometryTest, OnlyAPlaneLeavesTheBodyMassless) {  // MJCF-031
  MassFixture f;
  const BodyId b = f.AddBody("b");
  ir::MassContribution c;
  c.mass = 5;  // a plane has no volume, so even a given mass gives nothing
  f.AddGeom(b, ir::HalfSpace{}, {}, c);
  f.module[b].inertial = ir::Inertial{};  // overwritten
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  EXPECT_FALSE(f.module[b].inertial);
}

TEST(MassFromGeometryTest, ShellInertiaOnAMeshIsAnErrorAtTheGeom) {  // MJCF-031
  // MuJoCo 3.3.8: "for mesh geoms, inertia should be specified in the mesh asset"
  MassFixture f;
  const BodyId b = f.AddBody("b");
  const GeometryId g = f.AddGeom(b, f.Mesh("box.obj"), {}, Density(1000, MI::Legacy, true));
  EXPECT_FALSE(f.RunMassPipeline());
  const Diagnostic* d = f.Find(DiagKind::BadMassProperties);
  ASSERT_TRUE(d) << f.Messages();
  EXPECT_EQ(d->loc, f.module[g].loc);
}

TEST(MassFromGeometryTest, InconsistentMeshIsAnErrorAtTheGeomForExact) {  // MJCF-031
  MassFixture f;
  const BodyId b = f.AddBody("b");
  const GeometryId g = f.AddGeom(b, f.Mesh("flipped.obj"), {}, Density(1000, MI::Exact));
  EXPECT_FALSE(f.RunMassPipeline());
  const Diagnostic* d = f.Find(DiagKind::BadMassProperties);
  ASSERT_TRUE(d) << f.Messages();
  EXPECT_EQ(d->loc, f.module[g].loc);
  EXPECT_NE(d->message.find("inconsistent orientation"), std::string::npos) << d->message;
}

TEST(LoadMeshesTest, UnreadableMeshesAreErrorsAtTheirUri) {  // BEYOND-001
  MassFixture f;
  const BodyId b = f.AddBody("b");
  const ir::Mesh garbage = f.Mesh("garbage.stl");
  f.AddGeom(b, garbage);
  // points without faces are no error: their convex hull is the mesh (issue 62)
  f.AddGeom(b, f.Mesh("empty.obj"));
  f.AddGeom(b, f.Mesh("box.obj"));
  EXPECT_FALSE(f.Run({"load-meshes"}));
  std::vector<Loc> locs;
  for (const auto& d : f.diags.diagnostics()) {
    EXPECT_EQ(d.kind, DiagKind::BadMesh);
    locs.push_back(d.loc);
  }
  EXPECT_EQ(locs, (std::vector<Loc>{garbage.uri_loc})) << f.Messages();
  f.ExpectDiagnostic(DiagKind::BadMesh, "cannot read mesh file");
}

TEST(LoadMeshesTest, EachFileIsReadOnce) {  // BEYOND-001
  MassFixture f;
  const BodyId b = f.AddBody("b");
  for (int i = 0; i < 6; ++i) {
    f.AddGeom(b, f.Mesh("box.obj", Eigen::Vector3d::Constant(1 + i)));
    f.AddGeom(b, f.Mesh("tetra.obj"));
  }
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  EXPECT_EQ(f.meshes->files_read(), 2u);
}

// <compiler boundmass="0.5" boundinertia="0.01" balanceinertia="true"
// [settotalmass="10"]/> over bodies: a (box + light sphere), b (explicit
// <inertial mass="2" pos="0 0 0.1" diaginertia="0.1 0.1 0.3">, violating
// A + B >= C), c (no geoms), d (shells), e (solids). MuJoCo 3.3.8 numbers.
struct AdjustmentModel {
  MassFixture f;
  BodyId a, b, c, d, e;
  explicit AdjustmentModel(std::optional<double> total_mass) {
    ir::MassAdjustments adj;
    adj.bound_mass = 0.5;
    adj.bound_inertia = 0.01;
    adj.balance_inertia = true;
    adj.total_mass = total_mass;
    f.module[f.model].mass_adjustments = adj;
    a = f.AddBody("a");
    f.AddGeom(a, ir::Box{Eigen::Vector3d(0.1, 0.2, 0.4)}, Transform::FromTranslation({0.1, 0, 0}),
              Density(100));
    ir::MassContribution light;
    light.mass = 0.001;
    f.AddGeom(a, ir::Sphere{0.01}, Transform::FromTranslation({-0.2, 0, 0}), light);
    b = f.AddBody("b", /*from_geometry=*/false);
    ir::Inertial in;
    in.mass = 2;
    in.X_BI = Transform::FromTranslation({0, 0, 0.1});
    in.ixx = 0.1, in.iyy = 0.1, in.izz = 0.3;
    f.module[b].inertial = in;
    c = f.AddBody("c");
    d = AddShells(f);
    e = AddSolids(f);
  }
};

TEST(MassAdjustmentsTest, BoundsAndBalanceMatchMujoco338) {  // BEYOND-006
  AdjustmentModel m(std::nullopt);
  ASSERT_TRUE(m.f.RunMassPipeline()) << m.f.Messages();
  ExpectBody(m.f, m.a, {0.8010000000000002, {0.099625468164794, 0, 0},
                        Sym(0.013333373333333337, 0.011423260973782778, 0.01, 0, 0, 0)});
  ExpectBody(m.f, m.b, {2, {0, 0, 0.1}, Sym(1, 1, 1, 0, 0, 0) * 0.16666666666666666});
  // MuJoCo puts a massless body's bounded mass at the body's offset from
  // its parent (ipos = pos, here 2 0 0); mdlc keeps it at the body origin
  EXPECT_NEAR(m.f.module[m.c].inertial->mass, 0.5, 1e-15);
  ExpectNear(m.f.InertiaB(m.c), Eigen::Matrix3d::Identity() * 0.01, 1e-15, "c");
  ExpectBody(m.f, m.d, kShells, 1e-8);
  ExpectBody(m.f, m.e, kSolids);
}

TEST(MassAdjustmentsTest, SetTotalMassScalesEverythingLast) {  // BEYOND-006
  AdjustmentModel m(10.0);
  ASSERT_TRUE(m.f.RunMassPipeline()) << m.f.Messages();
  ExpectBody(m.f, m.a, {0.003370877888761803, {0.099625468164794, 0, 0},
                        Sym(5.611132753051136e-05, 4.8072931128689116e-05, 4.208336939777531e-05,
                            0, 0, 0)},
             1e-9);
  ExpectBody(m.f, m.b, {0.008416673879555062, {0, 0, 0.1},
                        Sym(1, 1, 1, 0, 0, 0) * 0.0007013894899629218},
             1e-9);
  EXPECT_NEAR(m.f.module[m.c].inertial->mass, 0.0021041684698887655, 1e-12);
  ExpectBody(m.f, m.d, {9.73050459176097,
                        {0.1631211033566913, 0.09510931527149201, 0.10589913098397095},
                        Sym(1.2228487450186512, 1.5799047697923168, 1.3448757502561275,
                            0.15096232172807847, 0.16808846180172027, 0.09800558034762404)},
             1e-8);
  ExpectBody(m.f, m.e, {0.25560368800082245,
                        {0.0, 0.15517241379310345, 0.20689655172413793},
                        Sym(0.03638249522159149, 0.02207106031481437, 0.015466058462918778, 0,
                            0, 0.008217485517094798)},
             1e-9);
  double total = 0;
  for (BodyId id : {m.a, m.b, m.c, m.d, m.e}) total += m.f.module[id].inertial->mass;
  EXPECT_NEAR(total, 10, 1e-9);
}

TEST(MassAdjustmentsTest, DefaultBoundsLeaveAPhysicalInertiaUntouched) {  // BEYOND-006
  // MuJoCo's defaults (no bounds, no balancing) only raise a principal moment
  // below zero: a positive definite inertia keeps every bit, products and all,
  // whether or not the pass decomposes it to find that out
  MassFixture f;
  f.module[f.model].mass_adjustments = ir::MassAdjustments{};
  const BodyId full = f.AddBody("full", /*from_geometry=*/false);
  ir::Inertial in;
  in.mass = 1.25;
  in.ixx = 0.0117757, in.iyy = 0.0175193, in.izz = 0.0216737;
  in.ixy = 0.00307337, in.ixz = -0.00135823, in.iyz = -0.00365907;
  f.module[full].inertial = in;
  // a flat plate: one principal moment is zero, not clearly positive definite
  const BodyId flat = f.AddBody("flat", /*from_geometry=*/false);
  ir::Inertial plate;
  plate.mass = 1;
  plate.ixx = 0.5, plate.iyy = 0.5, plate.izz = 0;
  f.module[flat].inertial = plate;
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  const ir::Inertial& out = *f.module[full].inertial;
  EXPECT_EQ(out.mass, in.mass);
  EXPECT_EQ(f.InertiaB(full), Sym(in.ixx, in.iyy, in.izz, in.ixy, in.ixz, in.iyz));
  EXPECT_EQ(f.InertiaB(flat), Sym(0.5, 0.5, 0, 0, 0, 0));
}

// Each model's corrections and total are its own: two instances' bodies,
// interleaved in the module, each scaled to its model's settotalmass; a
// model without corrections is left alone (BEYOND-006).
TEST(MassAdjustmentsTest, EachModelScalesToItsOwnTotal) {  // BEYOND-006
  MassFixture f;
  ir::MassAdjustments to_ten, to_three;
  to_ten.total_mass = 10;
  to_three.total_mass = 3;
  to_three.bound_mass = 0.5;
  f.module[f.model].mass_adjustments = to_ten;
  const ModelId first = f.model;
  auto add_model = [&](std::string_view name, std::optional<ir::MassAdjustments> adj) {
    ir::ModelInstance mi;
    mi.local_name = f.module.Intern(name);
    mi.format = ir::SourceFormat::Mjcf;
    mi.loc = f.NextLoc();
    mi.mass_adjustments = adj;
    return f.module.Add(mi);
  };
  const ModelId second = add_model("n", to_three), untouched = add_model("o", std::nullopt);
  std::vector<std::pair<BodyId, ModelId>> bodies;
  for (int i = 0; i < 6; ++i) {
    f.model = i % 3 == 0 ? first : i % 3 == 1 ? second : untouched;
    const BodyId b = f.AddBody(fmt::format("b{}", i), /*from_geometry=*/false);
    ir::Inertial in;
    in.mass = i == 4 ? 0.1 : 1.0 + i;  // b4 of model n is raised to boundmass first
    in.ixx = in.iyy = in.izz = 0.1;
    f.module[b].inertial = in;
    bodies.emplace_back(b, f.model);
  }
  ASSERT_TRUE(f.RunMassPipeline()) << f.Messages();
  std::map<uint32_t, double> totals;
  for (const auto& [b, model] : bodies) totals[model.value] += f.module[b].inertial->mass;
  EXPECT_NEAR(totals[first.value], 10, 1e-12);
  EXPECT_NEAR(totals[second.value], 3, 1e-12);
  EXPECT_EQ(totals[untouched.value], 3.0 + 6.0);  // b2 and b5 as given
  // model n: b1 (2 kg) and b4 (bounded to 0.5 kg) in proportion
  EXPECT_NEAR(f.module[bodies[4].first].inertial->mass, 3 * 0.5 / 2.5, 1e-12);
  EXPECT_NEAR(f.module[bodies[4].first].inertial->ixx, 0.1 * 3 / 2.5, 1e-12);
}

}  // namespace
}  // namespace mdlc::testing
