// loadable_output_test.cc - `mdlc convert` writes what the target's own
// reader loads (issue 58):
//   - MJCF: a mesh MuJoCo cannot read (COLLADA, glTF, PLY) is written by
//     --copy-assets as an OBJ of the triangles mdlc read, visual and
//     collision kept apart; without --copy-assets each such file gets one
//     -Wlossy warning;
//   - plain URDF (--plain): one root link, free bodies on floating joints,
//     capsules, ellipsoids and Drake's joints approximated with -Wlossy;
//   - a URDF root link that the plant floats gets a note in MJCF output, and
//     --fixed-base (Options::model.fixed_base) welds it to the world instead.
// The corpus conversions loaded by MuJoCo and urdfdom (tests/convert/
// CMakeLists.txt) check the same on real robots.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <variant>

#include "mdlc/convert.h"
#include "mdlc/kinematics.h"
#include "mdlc/mdlc.h"
#include "mdlc/meshes.h"

namespace mdlc {
namespace {
namespace fs = std::filesystem;

/// A folder of the test's own, removed after it.
class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / fmt::format("mdlc_loadable_{}", ::getpid())) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

std::string Messages(const Result& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics()) out += r.FormatText(d);
  return out;
}

/// The compile's diagnostics, then a conversion's of its Result.
std::string Messages(const Result& r, const ConvertOutput& converted) {
  std::string out = Messages(r);
  for (const Diagnostic& d : converted.diagnostics) out += r.FormatText(d);
  return out;
}

std::vector<const Diagnostic*> Find(const std::vector<Diagnostic>& diagnostics, DiagKind kind,
                                    std::string_view text) {
  std::vector<const Diagnostic*> out;
  for (const Diagnostic& d : diagnostics) {
    if (d.kind == kind && d.message.find(text) != std::string::npos) out.push_back(&d);
  }
  return out;
}

size_t Count(const std::string& text, std::string_view what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::string Mesh(std::string_view name) {
  return (fs::path(MDLC_TEST_MODELS) / "meshes" / name).string();
}

/// Each triangle as its three corners, starting at the smallest (so the
/// winding is kept), the list sorted: the same surface, however a reader
/// numbers the vertices.
std::vector<std::array<double, 9>> Surface(const MeshTriangles& m) {
  std::vector<std::array<double, 9>> out;
  for (const Eigen::Vector3i& t : m.triangles) {
    std::array<std::array<double, 3>, 3> c;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& v = m.vertices[t[k]];
      c[k] = {v.x(), v.y(), v.z()};
    }
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back({c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

const char* const kInertial =
    R"(<inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>)";

/// A one-link URDF whose visuals are the test meshes MuJoCo cannot read and
/// whose collision is one it can.
std::string MeshesUrdf() {
  return fmt::format(R"(<robot name="meshes">
  <link name="base">
    {0}
    <visual name="dae"><geometry><mesh filename="{1}"/></geometry></visual>
    <visual name="gltf"><geometry><mesh filename="{2}"/></geometry></visual>
    <visual name="ply"><geometry><mesh filename="{3}" scale="2 2 2"/></geometry></visual>
    <collision name="hit"><geometry><mesh filename="{4}"/></geometry></collision>
  </link>
</robot>
)",
                     kInertial, Mesh("box.dae"), Mesh("box.gltf"), Mesh("box.ply"),
                     Mesh("box.obj"));
}

Result CompileText(const std::string& text, const fs::path& file, Options options = {}) {
  Result r = Compile(Input::Text(text, file.string()), options);
  EXPECT_TRUE(r.ok()) << Messages(r);
  return r;
}

// BEYOND-001: a COLLADA, glTF or PLY mesh becomes an OBJ copy MuJoCo reads,
// holding the triangles mdlc read (so the converted model reads back with
// the same shapes); the OBJ collision mesh is copied as it is, and the
// visual and collision geoms stay apart.
TEST(MjcfMeshes, CopyAssetsWritesMeshesMujocoCannotReadAsObj) {
  TempDir dir;
  Result source = CompileText(MeshesUrdf(), dir.path() / "meshes.urdf");
  ConvertOptions convert;
  convert.to = Format::Mjcf;
  convert.output = (dir.path() / "meshes.xml").string();
  convert.copy_assets_dir = (dir.path() / "assets").string();
  const ConvertOutput converted = mdlc::Convert(source, convert);
  const std::optional<std::string>& text = converted.text;
  ASSERT_TRUE(text) << Messages(source, converted);
  EXPECT_TRUE(Find(converted.diagnostics, DiagKind::Lossy, "mesh").empty())
      << Messages(source, converted);
  for (const char* ext : {".dae", ".gltf", ".ply"}) {
    EXPECT_EQ(Count(*text, ext), 0u) << ext << "\n" << *text;
  }
  EXPECT_EQ(Count(*text, ".obj\""), 4u) << *text;  // three converted, one copied
  std::set<std::string> files;
  for (const auto& e : fs::directory_iterator(dir.path() / "assets")) {
    files.insert(e.path().extension().string());
  }
  EXPECT_EQ(files, std::set<std::string>{".obj"});
  // the visuals and the collision stay apart
  EXPECT_EQ(Count(*text, "contype=\"0\""), 3u) << *text;

  std::ofstream(convert.output) << *text;
  Result back = Compile(Input::File(convert.output));
  ASSERT_TRUE(back.ok()) << Messages(back);
  // each geometry's mesh, read back from its copy, has the triangles mdlc
  // read from the original, at the same scale
  std::map<std::string, std::pair<std::string, Eigen::Vector3d>> original;  // name -> file, scale
  for (const auto& g : source.scene_graph().geometries) {
    const auto& m = std::get<ir::Mesh>(g.shape);
    original[g.name] = {m.resolved, m.scale};
  }
  size_t compared = 0;
  for (const auto& g : back.scene_graph().geometries) {
    const auto& m = std::get<ir::Mesh>(g.shape);
    SCOPED_TRACE(g.name);
    ASSERT_TRUE(original.count(g.name));
    const auto& [file, scale] = original[g.name];
    EXPECT_EQ(m.scale, scale);
    const std::vector<MeshTriangles> a = mdlc::ReadMeshes(source, {file});
    const std::vector<MeshTriangles> b = mdlc::ReadMeshes(back, {m.resolved});
    ASSERT_TRUE(a[0].ok() && b[0].ok()) << a[0].error << b[0].error;
    SCOPED_TRACE(file + " -> " + m.resolved);
    EXPECT_EQ(Surface(a[0]), Surface(b[0]));
    ++compared;
  }
  EXPECT_EQ(compared, 4u);
}

// Without --copy-assets the file is named as it is: one warning per file
// MuJoCo cannot read, saying how to get one it reads.
TEST(MjcfMeshes, WithoutCopyAssetsEachUnreadableMeshIsWarnedOnce) {
  TempDir dir;
  const std::string urdf = std::regex_replace(
      MeshesUrdf(), std::regex("<collision"),
      fmt::format(R"(<visual name="dae_again"><geometry><mesh filename="{}"/></geometry></visual>
    <collision)",
                  Mesh("box.dae")));
  Result source = CompileText(urdf, dir.path() / "meshes.urdf");
  ConvertOptions convert;
  convert.to = Format::Mjcf;
  convert.output = (dir.path() / "meshes.xml").string();
  const ConvertOutput converted = mdlc::Convert(source, convert);
  ASSERT_TRUE(converted.text) << Messages(source, converted);
  const auto warned =
      Find(converted.diagnostics, DiagKind::Lossy, "MuJoCo reads STL, OBJ and MSH meshes only");
  ASSERT_EQ(warned.size(), 3u) << Messages(source, converted);  // dae (twice named), gltf, ply
  EXPECT_NE(warned[0]->message.find("box.dae"), std::string::npos) << warned[0]->message;
  EXPECT_NE(warned[0]->message.find("--copy-assets writes an OBJ of it that MuJoCo reads"),
            std::string::npos)
      << warned[0]->message;
  EXPECT_NE(source.FormatText(*warned[0]).find("meshes.urdf:4:"), std::string::npos)
      << source.FormatText(*warned[0]);
}

// Plain URDF: urdfdom reads one tree of its own elements. Two free bodies
// hang from a world link by floating joints; a capsule and an ellipsoid
// become the cylinder and sphere that bound them, a ball joint a fixed
// joint, each with a -Wlossy warning. Drake reads it back with the same
// free bodies.
TEST(PlainUrdf, OneRootLinkAndNoDrakeShapesOrJoints) {
  TempDir dir;
  // SDFormat spells the inertial its own way
  const std::string inertial =
      "<inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz>"
      "<ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>";
  const std::string model = fmt::format(R"(<sdf version="1.9">
  <world name="w">
    <model name="a">
      <link name="a_body">{0}
        <collision name="pill"><geometry><capsule><radius>0.1</radius><length>0.4</length></capsule></geometry></collision>
      </link>
      <link name="a_head"><pose>0 0 1 0 0 0</pose>{0}</link>
      <joint name="neck" type="ball"><parent>a_body</parent><child>a_head</child></joint>
    </model>
    <model name="b">
      <link name="b_body">{0}
        <visual name="egg"><geometry><ellipsoid><radii>0.1 0.2 0.3</radii></ellipsoid></geometry></visual>
      </link>
    </model>
  </world>
</sdf>
)",
                                        inertial);
  Result source = CompileText(model, dir.path() / "scene.sdf");
  ConvertOptions convert;
  convert.to = Format::Urdf;
  convert.plain = true;
  convert.output = (dir.path() / "scene.urdf").string();
  const ConvertOutput converted = mdlc::Convert(source, convert);
  const std::optional<std::string>& text = converted.text;
  ASSERT_TRUE(text) << Messages(source, converted);
  EXPECT_EQ(Count(*text, "drake:capsule"), 0u) << *text;
  EXPECT_EQ(Count(*text, "drake:ellipsoid"), 0u) << *text;
  EXPECT_EQ(Count(*text, "drake:joint"), 0u) << *text;
  EXPECT_EQ(Count(*text, "type=\"floating\""), 2u) << *text;
  // one root: every link but "world" is some joint's child
  std::set<std::string> links, children;
  const std::regex link_re("<link name=\"([^\"]*)\""), child_re("<child link=\"([^\"]*)\"");
  for (std::sregex_iterator it(text->begin(), text->end(), link_re), end; it != end; ++it) {
    links.insert((*it)[1]);
  }
  for (std::sregex_iterator it(text->begin(), text->end(), child_re), end; it != end; ++it) {
    children.insert((*it)[1]);
  }
  std::vector<std::string> roots;
  for (const std::string& l : links) {
    if (!children.count(l)) roots.push_back(l);
  }
  EXPECT_EQ(roots, std::vector<std::string>{"world"}) << *text;
  const std::vector<Diagnostic>& lossy = converted.diagnostics;
  EXPECT_EQ(Find(lossy, DiagKind::Lossy, "capsule 'pill' is written as the cylinder").size(), 1u)
      << Messages(source, converted);
  EXPECT_EQ(Find(lossy, DiagKind::Lossy, "ellipsoid 'egg' is written as the sphere").size(), 1u)
      << Messages(source, converted);
  EXPECT_EQ(Find(lossy, DiagKind::Lossy, "ball joint 'neck' has no plain URDF type").size(), 1u)
      << Messages(source, converted);
  EXPECT_NE(text->find("<cylinder radius=\"0.1\" length=\"0.6000000000000001\""),
            std::string::npos)
      << *text;  // 0.4 + 2 * 0.1
  EXPECT_NE(text->find("<sphere radius=\"0.3\""), std::string::npos) << *text;

  std::ofstream(convert.output) << *text;
  Result back = Compile(Input::File(convert.output));
  ASSERT_TRUE(back.ok()) << Messages(back);
  // both bodies still float (7 + 7 positions); the neck is welded
  EXPECT_EQ(back.plant().num_positions, 14);
  EXPECT_EQ(source.plant().num_positions, 17);  // and the ball joint's roll, pitch, yaw

  // without --plain: Drake's dialect, as before
  convert.plain = false;
  const ConvertOutput converted_drake = mdlc::Convert(source, convert);
  const std::optional<std::string>& drake = converted_drake.text;
  ASSERT_TRUE(drake);
  EXPECT_EQ(Count(*drake, "<drake:capsule"), 1u);
  EXPECT_EQ(Count(*drake, "<drake:joint"), 1u);
}

const char* const kArm = R"(<robot name="arm">
  <link name="base">
    <inertial><mass value="4"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="1"/>
  </joint>
  <link name="upper">
    <inertial><origin xyz="0 0 0.2"/><mass value="1"/>
      <inertia ixx="0.02" iyy="0.02" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
</robot>
)";

// URDF-017: Drake floats a URDF root link that no joint holds; MuJoCo's own
// URDF import would fix it. The MJCF's free joint is said in a note at the
// root link, naming --fixed-base.
TEST(FixedBase, UrdfRootFloatingInMjcfGetsANote) {
  TempDir dir;
  Result source = CompileText(kArm, dir.path() / "arm.urdf");
  EXPECT_EQ(source.plant().num_positions, 8);  // 7 floating + the shoulder
  ConvertOptions convert;
  convert.to = Format::Mjcf;
  convert.output = (dir.path() / "arm.xml").string();
  const ConvertOutput converted = mdlc::Convert(source, convert);
  const std::optional<std::string>& text = converted.text;
  ASSERT_TRUE(text);
  EXPECT_EQ(Count(*text, "<freejoint"), 1u) << *text;
  const auto notes = Find(converted.diagnostics, DiagKind::FreeBase, "root link 'base'");
  ASSERT_EQ(notes.size(), 1u) << Messages(source, converted);
  EXPECT_NE(notes[0]->message.find("--fixed-base welds it"), std::string::npos)
      << notes[0]->message;
  EXPECT_NE(source.FormatText(*notes[0]).find("arm.urdf:2:3: note:"), std::string::npos)
      << source.FormatText(*notes[0]);
  // URDF and SDFormat readers float it as Drake does: no note there
  convert.to = Format::Sdf;
  convert.output = (dir.path() / "arm.sdf").string();
  Result again = CompileText(kArm, dir.path() / "arm.urdf");
  const ConvertOutput converted_again = mdlc::Convert(again, convert);
  ASSERT_TRUE(converted_again.text);
  EXPECT_TRUE(Find(converted_again.diagnostics, DiagKind::FreeBase, "").empty())
      << Messages(again, converted_again);
}

// --fixed-base welds the root link to the world where it is: the MJCF has no
// free joint, no note, and the arm's mass matrix is the shoulder's alone.
TEST(FixedBase, WeldsEachFreeRootToTheWorld) {
  TempDir dir;
  Options options;
  options.model.fixed_base = true;
  Result source = CompileText(kArm, dir.path() / "arm.urdf", options);
  ASSERT_EQ(source.plant().num_positions, 1);
  bool welded = false;
  for (const auto& j : source.plant().joints) {
    welded |= j.type == ir::JointType::Weld && j.parent.index() == 0;
  }
  EXPECT_TRUE(welded);
  Result floating = CompileText(kArm, dir.path() / "arm.urdf");
  const Eigen::MatrixXd M = mdlc::MassMatrix(source, mdlc::DefaultPositions(source));
  const Eigen::MatrixXd M_free = mdlc::MassMatrix(floating, mdlc::DefaultPositions(floating));
  ASSERT_EQ(M.rows(), 1);
  // the shoulder's entry is the same as in the floating arm's matrix
  EXPECT_NEAR(M(0, 0), M_free(6, 6), 1e-12);

  ConvertOptions convert;
  convert.to = Format::Mjcf;
  convert.output = (dir.path() / "arm.xml").string();
  const ConvertOutput converted = mdlc::Convert(source, convert);
  const std::optional<std::string>& text = converted.text;
  ASSERT_TRUE(text);
  EXPECT_EQ(Count(*text, "<freejoint"), 0u) << *text;
  EXPECT_TRUE(Find(converted.diagnostics, DiagKind::FreeBase, "").empty())
      << Messages(source, converted);
  // a body with a pose of its own (SDFormat) is welded where it is
  const std::string sdf = R"(<sdf version="1.9"><model name="m">
  <link name="box"><pose>1 2 3 0 0 0.5</pose>
    <inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
  </link></model></sdf>
)";
  Result box = CompileText(sdf, dir.path() / "box.sdf", options);
  ASSERT_EQ(box.plant().num_positions, 0);
  const auto X_WB = mdlc::BodyPoses(box, mdlc::DefaultPositions(box));
  EXPECT_TRUE(X_WB.back().p.isApprox(Eigen::Vector3d(1, 2, 3), 1e-15)) << X_WB.back().p;
}

}  // namespace
}  // namespace mdlc
