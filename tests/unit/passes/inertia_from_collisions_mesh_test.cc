// Tests of SDFormat's <inertial auto="true"> with mesh collisions
// (SDF-007, BEYOND-001): the exact solid of a closed mesh, its convex hull
// (with a warning) when it is not closed, the hull when declared convex.
#include <gtest/gtest.h>

#include "tests/unit/mesh/mesh_test_util.h"
#include "tests/unit/sdf_test_util.h"

namespace mdlc::testing {
namespace {

std::string LinkWithMesh(std::string_view mesh, std::string_view extra = "",
                         std::string_view scale = "1 1 1") {
  return fmt::format(R"(
  <model name='m'>
    <link name='L'>
      <inertial auto='true'><density>2</density></inertial>
      <collision name='c'>
        <pose>1 0 0 0 0 0</pose>
        <geometry><mesh><uri>{}</uri><scale>{}</scale>{}</mesh></geometry>
      </collision>
    </link>
  </model>)",
                     MeshPath(mesh), scale, extra);
}

const ir::Inertial& InertialOf(const Compilation& c) {
  for (const ir::Body& b : c.module.bodies) {
    if (c.module.Text(b.name) == "L") return *b.inertial;
  }
  ADD_FAILURE() << "no body L";
  return *c.module.bodies[1].inertial;
}

TEST(InertiaFromCollisionsMeshTest, ClosedMeshIsExact) {  // SDF-007, BEYOND-001
  SdfCompileResult r(LinkWithMesh("lshape.obj", "", "0.5 1 2"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  const ir::Inertial& in = InertialOf(r.compilation());
  // the L-prism scaled by (0.5, 1, 2): volume 7 (the same as MuJoCo's
  // inertia="exact"), center of mass shifted by the collision's pose
  EXPECT_NEAR(in.mass, 2 * 7, 1e-12);
  ExpectNear(in.X_BI.p, Eigen::Vector3d(1 + 0.6785714285714285, 1.357142857142857, 1), 1e-12,
             "com");
  EXPECT_NEAR(in.ixx, 2 * 11.773809523809522, 1e-10);
  EXPECT_NEAR(in.ixy, 2 * 2.571428571428572, 1e-10);
}

TEST(InertiaFromCollisionsMeshTest, OpenMeshUsesItsHullWithAWarning) {  // BEYOND-001
  SdfCompileResult r(LinkWithMesh("open_box.obj"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NE(r.Messages().find("convex hull"), std::string::npos) << r.Messages();
  r.ExpectDiagnostic(DiagKind::MeshNotClosed, "its convex hull is used");
  const ir::Inertial& in = InertialOf(r.compilation());
  EXPECT_NEAR(in.mass, 2 * 1, 1e-12);  // the whole box
  ExpectNear(in.X_BI.p, Eigen::Vector3d(2.5, 0.25, 1.25), 1e-12, "com");
}

TEST(InertiaFromCollisionsMeshTest, DeclaredConvexUsesTheHull) {  // BEYOND-001
  SdfCompileResult r(LinkWithMesh("lshape.obj", "<drake:declare_convex/>"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_NEAR(InertialOf(r.compilation()).mass, 2 * 11.5, 1e-12);  // hull of the 4x4 L
}

TEST(InertiaFromCollisionsMeshTest, BadMeshIsAnErrorAtItsUri) {  // BEYOND-001
  SdfCompileResult r(LinkWithMesh("garbage.stl"));
  EXPECT_FALSE(r.ok());
  bool found = false;
  for (const auto& d : r.compilation().diags.diagnostics()) {
    if (d.kind == DiagKind::BadMesh) {
      found = true;
      EXPECT_EQ(d.loc.line, 9u);  // the <uri> line
    }
  }
  EXPECT_TRUE(found) << r.Messages();
  r.ExpectDiagnostic(DiagKind::BadMesh, "cannot read mesh file");
}

}  // namespace
}  // namespace mdlc::testing
