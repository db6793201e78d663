// Which way is up in a mesh file (issue 55, BEYOND-001, passes/mesh/
// mesh_axes.h): glTF is turned from its Y-up to Z-up as Drake turns it, so
// a glTF mesh lands where its OBJ twin does; a COLLADA file's declared up
// axis is read as written by default, as RViz and Gazebo read it, and
// applied when asked. Both readers (the child process and the import
// module) orient alike.
#include "passes/mesh/io/mesh_axes.h"

#include <gtest/gtest.h>

#include "passes/mesh/reader_pool.h"
#include "passes/mesh/in_process_reader.h"
#include "passes/mesh/mass_properties.h"
#include "passes/mesh/mesh_loader.h"
#include "passes/mesh/reader_location.h"
#include "tests/unit/mesh/mesh_test_util.h"

namespace mdlc::testing {
namespace {

using mesh::ColladaUpAxis;
using mesh::MeshAxes;
using mesh::UpAxis;

const Eigen::Vector3d kBoxCom(1.5, 0.25, 1.25);  // generate.py's box
const Eigen::Vector3d kBoxMin(0.5, -0.25, 1.0), kBoxMax(2.5, 0.75, 1.5);

struct Read {
  mesh::MeshOrError in_child, in_process;
};

/// `name` read both ways, each checked to be a mesh.
Read ReadBothWays(std::string_view name, const MeshAxes& axes) {
  const std::string path = MeshPath(name);
  Read r;
  r.in_process = mesh::LoadMeshInProcess(path, {}, axes);
  const mesh::MeshReaderLocation reader = mesh::FindMeshReader();
  r.in_child = reader.path.empty() ? r.in_process : mesh::LoadMeshInChild(reader.path, path, {}, axes);
  EXPECT_TRUE(r.in_process.ok()) << r.in_process.error;
  EXPECT_TRUE(r.in_child.ok()) << r.in_child.error;
  return r;
}

Eigen::Vector3d Com(const mesh::MeshOrError& m) { return mesh::SolidMassProperties(*m.mesh).com; }

Eigen::AlignedBox3d Bounds(const mesh::TriangleMesh& m) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : m.vertices) box.extend(v);
  return box;
}

TEST(MeshAxesTest, GltfIsTurnedZUpAndLandsOnItsObjTwin) {  // issue 55, BEYOND-001
  const mesh::MeshOrError obj = mesh::LoadMesh(MeshPath("box.obj"));
  ASSERT_TRUE(obj.ok()) << obj.error;
  EXPECT_EQ(obj.mesh->declared_up, UpAxis::kNone);
  EXPECT_FALSE(obj.mesh->turned_to_z_up);
  for (const ColladaUpAxis collada : {ColladaUpAxis::kAsWritten, ColladaUpAxis::kApply}) {
    const Read gltf = ReadBothWays("box.gltf", MeshAxes{collada});
    for (const mesh::MeshOrError* m : {&gltf.in_child, &gltf.in_process}) {
      ASSERT_TRUE(m->ok());
      EXPECT_EQ(m->mesh->declared_up, UpAxis::kY);
      EXPECT_TRUE(m->mesh->turned_to_z_up);
      // the same corners as the OBJ twin, and so the same solid: the turn is
      // a rotation, so the winding still faces out
      const Eigen::AlignedBox3d box = Bounds(*m->mesh);
      ExpectNear(box.min(), kBoxMin, 1e-12, "min");
      ExpectNear(box.max(), kBoxMax, 1e-12, "max");
      ExpectNear(Com(*m), Com(obj), 1e-12, "com");
      EXPECT_NEAR(mesh::SolidMassProperties(*m->mesh).measure, 1.0, 1e-12);
    }
  }
}

TEST(MeshAxesTest, ColladaUpAxisIsReadAsWrittenByDefault) {  // issue 55, BEYOND-001
  // generate.py writes the box in each file's declared axes; read as written
  // it is the box in those axes: Y_UP holds (x, z, -y), X_UP (z, -x, -y)
  const Eigen::Vector3d c = kBoxCom;
  const std::pair<const char*, Eigen::Vector3d> files[] = {
      {"box.dae", c},
      {"box_y_up.dae", Eigen::Vector3d(c.x(), c.z(), -c.y())},
      {"box_x_up.dae", Eigen::Vector3d(c.z(), -c.x(), -c.y())}};
  const UpAxis declared[] = {UpAxis::kZ, UpAxis::kY, UpAxis::kX};
  for (size_t i = 0; i < 3; ++i) {
    const Read r = ReadBothWays(files[i].first, MeshAxes{});
    for (const mesh::MeshOrError* m : {&r.in_child, &r.in_process}) {
      ASSERT_TRUE(m->ok());
      EXPECT_EQ(m->mesh->declared_up, declared[i]) << files[i].first;
      EXPECT_FALSE(m->mesh->turned_to_z_up) << files[i].first;
      ExpectNear(Com(*m), files[i].second, 1e-12, files[i].first);
    }
  }
}

TEST(MeshAxesTest, ColladaUpAxisAppliedTurnsEachFileToZUp) {  // issue 55, BEYOND-001
  for (const char* name : {"box.dae", "box_y_up.dae", "box_x_up.dae"}) {
    const Read r = ReadBothWays(name, MeshAxes{ColladaUpAxis::kApply});
    for (const mesh::MeshOrError* m : {&r.in_child, &r.in_process}) {
      ASSERT_TRUE(m->ok());
      // a Z_UP file needs no turn
      EXPECT_EQ(m->mesh->turned_to_z_up, std::string_view(name) != "box.dae") << name;
      const Eigen::AlignedBox3d box = Bounds(*m->mesh);
      ExpectNear(box.min(), kBoxMin, 1e-12, name);
      ExpectNear(box.max(), kBoxMax, 1e-12, name);
      const mesh::MassProperties p = mesh::SolidMassProperties(*m->mesh);
      EXPECT_NEAR(p.measure, 1.0, 1e-12) << name;  // still facing out
      ExpectNear(p.com, kBoxCom, 1e-12, name);
    }
  }
}

TEST(MeshAxesTest, TheTurnsAreRightHandedRotations) {  // BEYOND-001
  for (const UpAxis up : {UpAxis::kNone, UpAxis::kX, UpAxis::kY, UpAxis::kZ}) {
    const Eigen::Matrix3d R = mesh::RotationToZUp(up);
    ExpectNear(R * R.transpose(), Eigen::Matrix3d::Identity(), 0, mesh::UpAxisName(up));
    EXPECT_EQ(R.determinant(), 1.0) << mesh::UpAxisName(up);
  }
  // the declared up axis becomes +z
  ExpectNear(mesh::RotationToZUp(UpAxis::kY) * Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), 0);
  ExpectNear(mesh::RotationToZUp(UpAxis::kX) * Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ(), 0);
  // glTF's turn is Drake's: a point (x, y, z) in Drake is (x, z, -y) in glTF
  ExpectNear(mesh::RotationToZUp(UpAxis::kY) * Eigen::Vector3d(1, 3, -2), Eigen::Vector3d(1, 2, 3), 0);
}

TEST(MeshAxesTest, TheDeclaredAxisIsTheDocumentsOwn) {  // BEYOND-001
  using mesh::ColladaDeclaredUpAxis;
  EXPECT_EQ(ColladaDeclaredUpAxis("<COLLADA><asset><up_axis>Z_UP</up_axis></asset>"), UpAxis::kZ);
  EXPECT_EQ(ColladaDeclaredUpAxis("<COLLADA><asset><up_axis> X_UP\n</up_axis></asset>"), UpAxis::kX);
  EXPECT_EQ(ColladaDeclaredUpAxis("<COLLADA><asset><up_axis>Y_UP</up_axis></asset>"), UpAxis::kY);
  // none declared: COLLADA's default, Y_UP
  EXPECT_EQ(ColladaDeclaredUpAxis("<COLLADA><asset><unit meter='1'/></asset>"), UpAxis::kY);
  EXPECT_EQ(ColladaDeclaredUpAxis(""), UpAxis::kY);
  // an <asset> further on (a node's) is not the document's
  EXPECT_EQ(ColladaDeclaredUpAxis("<COLLADA><asset><unit meter='1'/></asset><library_nodes><node>"
                                  "<asset><up_axis>Z_UP</up_axis></asset>"),
            UpAxis::kY);
}

TEST(MeshAxesTest, ModesHaveCommandLineNames) {  // issue 55
  for (const ColladaUpAxis mode : {ColladaUpAxis::kAsWritten, ColladaUpAxis::kApply}) {
    EXPECT_EQ(mesh::ColladaUpAxisFromName(mesh::ColladaUpAxisName(mode)), mode);
  }
  EXPECT_EQ(mesh::ColladaUpAxisFromName("Y_UP"), std::nullopt);
}

}  // namespace
}  // namespace mdlc::testing
