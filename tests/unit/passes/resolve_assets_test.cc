// Mesh files that do not exist, in every format (COMMON-011, relaxed for
// visuals; MJCF-050, MJCF-031, BEYOND-002): an error when the plant needs the
// file (a collision geometry, a geometry with mass whose mass properties come
// from it, a primitive sized from it), a warning (-Wmissing-asset) at the
// URI when only visual geometry uses it, the geometry then kept as written.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "tools/driver/compiler.h"

namespace mdlc::testing {
namespace {
namespace fs = std::filesystem;

/// The whole pipeline on one model file written into a fresh folder.
class Compiled {
 public:
  Compiled(std::string_view file_name, std::string_view text) {
    dir_ = fs::temp_directory_path() /
           fmt::format("mdlc_assets_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / file_name) << text;
    c_.options.inputs = {Input::File((dir_ / file_name).string())};
    ok_ = c_.Run();
  }
  ~Compiled() { fs::remove_all(dir_); }
  Compiled(const Compiled&) = delete;
  Compiled& operator=(const Compiled&) = delete;

  bool ok() const { return ok_; }
  const Compilation& c() const { return c_; }
  std::string Messages() const {
    std::string out;
    for (const auto& d : c_.diags.diagnostics()) {
      out += fmt::format("{}:{}: {}: [{}] {}\n", d.loc.line, d.loc.column,
                         SeverityName(d.severity), InfoFor(d.kind).name, d.message);
      for (const auto& n : d.notes) out += fmt::format("  {}: note: {}\n", n.loc.line, n.message);
    }
    return out;
  }
  std::vector<const Diagnostic*> All(DiagKind kind) const {
    std::vector<const Diagnostic*> out;
    for (const auto& d : c_.diags.diagnostics()) {
      if (d.kind == kind) out.push_back(&d);
    }
    return out;
  }
  /// The registration of geometry `name` with any of `roles`.
  const ir::Geometry* Geometry(std::string_view name, uint8_t roles) const {
    for (const auto& g : c_.module.geometries) {
      if (c_.module.Text(g.name) == name && (g.roles & roles)) return &g;
    }
    return nullptr;
  }

 private:
  fs::path dir_;
  Compilation c_;
  bool ok_ = false;
};

constexpr uint8_t kVisualRoles = ir::kIllustrationRole | ir::kPerceptionRole;

// --- URDF ---

TEST(ResolveAssetsTest, UrdfVisualMeshMissingIsAWarningAndTheGeometryStays) {  // COMMON-011, URDF-032
  Compiled r("robot.urdf", R"(<robot name="r">
  <link name="a">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual name="shell">
      <geometry><mesh filename="meshes/missing.obj" scale="2 2 2"/></geometry>
    </visual>
    <collision><geometry><box size="1 1 1"/></geometry></collision>
  </link>
</robot>
)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const auto warnings = r.All(DiagKind::MissingAsset);
  ASSERT_EQ(warnings.size(), 1u) << r.Messages();
  EXPECT_EQ(warnings[0]->severity, Severity::Warning);
  EXPECT_EQ(warnings[0]->loc.line, 5u) << r.Messages();  // at the filename
  EXPECT_NE(warnings[0]->message.find("'meshes/missing.obj' resolves to"), std::string::npos);
  EXPECT_NE(warnings[0]->message.find("visual geometry 'shell' of body 'a' is kept"),
            std::string::npos)
      << warnings[0]->message;
  EXPECT_EQ(InfoFor(DiagKind::MissingAsset).group, "missing-asset");
  // kept as written: the plant and scene graph have it
  const ir::Geometry* g = r.Geometry("shell", kVisualRoles);
  ASSERT_NE(g, nullptr);
  const auto* mesh = std::get_if<ir::Mesh>(&g->shape);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->uri, "meshes/missing.obj");
  EXPECT_EQ(mesh->scale, Eigen::Vector3d(2, 2, 2));
  EXPECT_TRUE(mesh->resolved.empty());
  ASSERT_TRUE(r.c().model.has_value());
  EXPECT_EQ(r.c().model->scene.geometries.size(), 2u);
}

TEST(ResolveAssetsTest, UrdfCollisionMeshMissingIsAnError) {  // COMMON-011
  Compiled r("robot.urdf", R"(<robot name="r">
  <link name="a">
    <collision name="hull">
      <geometry><mesh filename="meshes/missing.obj"/></geometry>
    </collision>
  </link>
</robot>
)");
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  EXPECT_EQ(errors[0]->loc.line, 4u);
  EXPECT_NE(errors[0]->message.find("does not exist"), std::string::npos);
  ASSERT_EQ(errors[0]->notes.size(), 1u);
  EXPECT_NE(errors[0]->notes[0].message.find("collision geometry 'hull' of body 'a'"),
            std::string::npos)
      << r.Messages();
  EXPECT_TRUE(r.All(DiagKind::MissingAsset).empty()) << r.Messages();
}

TEST(ResolveAssetsTest, UrdfFileSharedByVisualAndCollisionIsOneErrorAtTheCollision) {  // COMMON-011
  Compiled r("robot.urdf", R"(<robot name="r">
  <link name="a">
    <visual>
      <geometry><mesh filename="meshes/missing.obj"/></geometry>
    </visual>
    <collision>
      <geometry><mesh filename="meshes/missing.obj"/></geometry>
    </collision>
  </link>
</robot>
)");
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  EXPECT_EQ(errors[0]->loc.line, 7u) << r.Messages();
  EXPECT_TRUE(r.All(DiagKind::MissingAsset).empty()) << r.Messages();
}

// a visual mesh's unknown package is the case of its missing file: the plant
// never reads it, so both are warnings and the geometry is kept (issue 55);
// where the plant reads the file, an unknown package stays an error
TEST(ResolveAssetsTest, UnknownPackageOfAVisualIsAWarningLikeAMissingFile) {  // issue 55, COMMON-011
  Compiled r("robot.urdf", R"(<robot name="r">
  <link name="a">
    <visual><geometry><mesh filename="package://nowhere/a.obj"/></geometry></visual>
    <visual><geometry><mesh filename="missing.obj"/></geometry></visual>
  </link>
</robot>
)");
  EXPECT_TRUE(r.ok()) << r.Messages();
  const auto warnings = r.All(DiagKind::MissingAsset);
  ASSERT_EQ(warnings.size(), 2u) << r.Messages();
  EXPECT_NE(warnings[0]->message.find("unknown package 'nowhere' in 'package://nowhere/a.obj'; "
                                      "visual geometry 'Mesh' of body 'a' is kept without its "
                                      "mesh file, which the plant never reads"),
            std::string::npos)
      << r.Messages();
  EXPECT_FALSE(warnings[0]->notes.empty());  // where it looked
  EXPECT_NE(r.Geometry("Mesh", kVisualRoles), nullptr);
  EXPECT_NE(r.Geometry("Mesh_1", kVisualRoles), nullptr);

  Compiled collision("robot.urdf", R"(<robot name="r">
  <link name="a">
    <collision><geometry><mesh filename="package://nowhere/a.obj"/></geometry></collision>
  </link>
</robot>
)");
  EXPECT_FALSE(collision.ok());
  ASSERT_EQ(collision.All(DiagKind::FileNotFound).size(), 1u) << collision.Messages();
  EXPECT_NE(collision.All(DiagKind::FileNotFound)[0]->message.find("unknown package 'nowhere'"),
            std::string::npos);
}

TEST(ResolveAssetsTest, StrictTurnsTheMissingVisualIntoAnError) {  // COMMON-002
  const fs::path dir = fs::temp_directory_path() / fmt::format("mdlc_assets_strict_{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "robot.urdf") << R"(<robot name="r">
  <link name="a">
    <visual><geometry><mesh filename="missing.obj"/></geometry></visual>
  </link>
</robot>
)";
  DiagnosticPolicy strict;
  strict.warnings_as_errors = true;
  Compilation c(strict);
  c.options.inputs = {Input::File((dir / "robot.urdf").string())};
  EXPECT_FALSE(c.Run());
  fs::remove_all(dir);
}

// package:///NAME/path, as Pinocchio-era URDFs write their meshes: read as
// package://NAME/path, with a warning at the URI
TEST(ResolveAssetsTest, UrdfPackageUriWithThreeSlashesResolvesWithAWarning) {  // COMMON-010
  const fs::path dir =
      fs::temp_directory_path() / fmt::format("mdlc_assets_three_slashes_{}", ::getpid());
  fs::remove_all(dir);
  fs::create_directories(dir / "robot_description/meshes");
  std::ofstream(dir / "robot_description/package.xml")
      << "<package><name>robot_description</name></package>";
  std::ofstream(dir / "robot_description/meshes/base.stl") << "";
  std::ofstream(dir / "robot_description/robot.urdf") << R"(<robot name="r">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual>
      <geometry><mesh filename="package:///robot_description/meshes/base.stl"/></geometry>
    </visual>
  </link>
</robot>
)";
  Compilation c;
  c.packages.PopulateFromFolder(dir.string(), c.sources, c.diags);
  c.options.inputs = {Input::File((dir / "robot_description/robot.urdf").string())};
  EXPECT_TRUE(c.Run());
  ASSERT_EQ(c.diags.diagnostics().size(), 1u);
  const Diagnostic& d = c.diags.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::MalformedUri);
  EXPECT_EQ(d.loc.line, 5u);
  EXPECT_NE(d.message.find("read as 'package://robot_description/meshes/base.stl'"),
            std::string::npos)
      << d.message;
  const auto& mesh = std::get<ir::Mesh>(c.module.geometries.at(0).shape);
  EXPECT_EQ(fs::weakly_canonical(mesh.resolved),
            fs::weakly_canonical(dir / "robot_description/meshes/base.stl"));
  fs::remove_all(dir);
}

// --- SDFormat ---

TEST(ResolveAssetsTest, SdfVisualMeshMissingIsAWarning) {  // COMMON-011, SDF-041
  Compiled r("model.sdf", R"(<?xml version="1.0"?>
<sdf version="1.9">
  <model name="m">
    <link name="a">
      <visual name="v">
        <geometry><mesh><uri>meshes/missing.dae</uri></mesh></geometry>
      </visual>
    </link>
  </model>
</sdf>
)");
  ASSERT_TRUE(r.ok()) << r.Messages();
  const auto warnings = r.All(DiagKind::MissingAsset);
  ASSERT_EQ(warnings.size(), 1u) << r.Messages();
  EXPECT_EQ(warnings[0]->loc.line, 6u);
  EXPECT_NE(r.Geometry("v", kVisualRoles), nullptr);
}

TEST(ResolveAssetsTest, SdfInertiaFromAMissingCollisionMeshIsAnError) {  // COMMON-011, SDF-007
  Compiled r("model.sdf", R"(<?xml version="1.0"?>
<sdf version="1.11">
  <model name="m">
    <link name="a">
      <inertial auto="true"/>
      <collision name="c">
        <geometry><mesh><uri>meshes/missing.obj</uri></mesh></geometry>
      </collision>
      <visual name="v">
        <geometry><mesh><uri>meshes/missing.obj</uri></mesh></geometry>
      </visual>
    </link>
  </model>
</sdf>
)");
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  EXPECT_EQ(errors[0]->loc.line, 7u) << r.Messages();
}

// --- MJCF: visual-only means no collision, no mass, no size from the mesh ---

constexpr std::string_view kMjcfAssets = R"(<mujoco model="m">
  <asset>
    <mesh name="ghost" file="missing.obj"/>
    <mesh name="unused" file="also_missing.stl"/>
  </asset>
  <default>
    <default class="visual"><geom type="mesh" group="2" contype="0" conaffinity="0"/></default>
  </default>
  <worldbody>
)";

std::string Mjcf(std::string_view body) {
  return fmt::format("{}{}\n  </worldbody>\n</mujoco>\n", kMjcfAssets, body);
}

TEST(ResolveAssetsTest, MjcfVisualOnlyGeomOfAMissingMeshIsAWarning) {  // MJCF-050, MJCF-043
  // the body's mass is given; the geom is drawn only (Menagerie's visual class)
  Compiled r("model.xml", Mjcf(R"(    <body name="a">
      <joint/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom name="look" class="visual" mesh="ghost"/>
    </body>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  auto warnings = r.All(DiagKind::MissingAsset);
  ASSERT_EQ(warnings.size(), 2u) << r.Messages();
  // at the asset's file attribute: the used one, and the unused one
  std::sort(warnings.begin(), warnings.end(),
            [](const Diagnostic* a, const Diagnostic* b) { return a->loc.line < b->loc.line; });
  EXPECT_EQ(warnings[0]->loc.line, 3u);
  EXPECT_NE(warnings[0]->message.find("visual geometry 'look' of body 'a' is kept"),
            std::string::npos)
      << r.Messages();
  EXPECT_EQ(warnings[1]->loc.line, 4u);
  EXPECT_NE(warnings[1]->message.find("mesh 'unused' is kept"), std::string::npos)
      << r.Messages();
  const ir::Geometry* g = r.Geometry("look", kVisualRoles);
  ASSERT_NE(g, nullptr);
  ASSERT_NE(std::get_if<ir::Mesh>(&g->shape), nullptr);
  EXPECT_EQ(std::get<ir::Mesh>(g->shape).uri, "missing.obj");
}

TEST(ResolveAssetsTest, MjcfVisualOnlyGeomWithZeroDensityIsAWarning) {  // MJCF-031
  // mass from geometry, but this geom weighs nothing: its volume is irrelevant
  Compiled r("model.xml", Mjcf(R"(    <body name="a">
      <joint/>
      <geom name="look" class="visual" mesh="ghost" density="0"/>
      <geom name="core" size="0.1"/>
    </body>)"));
  ASSERT_TRUE(r.ok()) << r.Messages();
  EXPECT_EQ(r.All(DiagKind::MissingAsset).size(), 2u) << r.Messages();
}

TEST(ResolveAssetsTest, MjcfGeomWhoseMassComesFromAMissingMeshIsAnError) {  // MJCF-031
  Compiled r("model.xml", Mjcf(R"(    <body name="a">
      <joint/>
      <geom name="look" class="visual" mesh="ghost"/>
    </body>)"));
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  EXPECT_EQ(errors[0]->loc.line, 3u);
  ASSERT_EQ(errors[0]->notes.size(), 1u);
  EXPECT_NE(errors[0]->notes[0].message.find("mass properties of geometry 'look'"),
            std::string::npos)
      << r.Messages();
}

TEST(ResolveAssetsTest, MjcfPrimitiveSizedFromAMissingMeshIsAnError) {  // BEYOND-002
  Compiled r("model.xml", Mjcf(R"(    <body name="a">
      <joint/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom name="fit" type="box" mesh="ghost" contype="0" conaffinity="0"/>
    </body>)"));
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  ASSERT_EQ(errors[0]->notes.size(), 1u);
  EXPECT_NE(errors[0]->notes[0].message.find("geometry 'fit' of body 'a' takes its size"),
            std::string::npos)
      << r.Messages();
}

TEST(ResolveAssetsTest, MjcfCollisionGeomOfAMissingMeshIsAnError) {  // MJCF-050, MJCF-043
  Compiled r("model.xml", Mjcf(R"(    <body name="a">
      <joint/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom name="hit" type="mesh" mesh="ghost"/>
    </body>)"));
  EXPECT_FALSE(r.ok());
  const auto errors = r.All(DiagKind::FileNotFound);
  ASSERT_EQ(errors.size(), 1u) << r.Messages();
  EXPECT_EQ(errors[0]->loc.line, 3u);
  ASSERT_EQ(errors[0]->notes.size(), 1u);
  EXPECT_NE(errors[0]->notes[0].message.find("collision geometry 'hit'"), std::string::npos)
      << r.Messages();
}

}  // namespace
}  // namespace mdlc::testing
