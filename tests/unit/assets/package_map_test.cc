// PackageMap and URI resolution (COMMON-010..014).
#include "ir/assets/package_map.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace mdlc::assets {
namespace {
namespace fs = std::filesystem;

class PackageMapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("mdlc_pkg_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  void Write(const fs::path& rel, const std::string& text) {
    fs::create_directories((root_ / rel).parent_path());
    std::ofstream(root_ / rel) << text;
  }
  void Package(const fs::path& dir, const std::string& name, const std::string& extra = "") {
    Write(dir / "package.xml", "<package><name>" + name + "</name>" + extra + "</package>");
  }
  std::string Canonical(const fs::path& rel) { return fs::weakly_canonical(root_ / rel).string(); }
  // paths are compared canonical: the temporary folder may be reached
  // through a symbolic link
  static std::optional<std::string> Canon(const std::optional<std::string>& path) {
    if (!path) return std::nullopt;
    return fs::weakly_canonical(*path).string();
  }

  fs::path root_;
  SourceManager sources_;
  DiagnosticEngine diags_;
};

TEST_F(PackageMapTest, NameComesFromPackageXmlAndNestedPackagesAreFound) {  // COMMON-012
  Package("dir_a", "alpha");
  Package("dir_a/inner", "alpha_inner");
  Package("set/dir_b", "beta");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  EXPECT_EQ(map.size(), 3u);
  ASSERT_TRUE(map.Find("alpha"));
  EXPECT_EQ(map.Find("alpha")->path, Canonical("dir_a"));
  EXPECT_TRUE(map.Find("alpha_inner"));
  EXPECT_TRUE(map.Find("beta"));
  EXPECT_FALSE(map.Find("dir_a"));
  EXPECT_EQ(diags_.diagnostics().size(), 0u);
}

TEST_F(PackageMapTest, IgnoreMarkersSkipTheirSubtree) {  // COMMON-012
  Package("kept", "kept");
  Package("skipped/pkg", "skipped");
  Write("skipped/COLCON_IGNORE", "");
  Package("also/pkg", "also");
  Write("also/CATKIN_IGNORE", "");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  EXPECT_TRUE(map.Find("kept"));
  EXPECT_FALSE(map.Find("skipped"));
  EXPECT_FALSE(map.Find("also"));
}

TEST_F(PackageMapTest, FirstFoundWinsWithAWarning) {  // COMMON-013
  Package("a", "same");
  Package("b", "same");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  EXPECT_EQ(map.Find("same")->path, Canonical("a"));
  EXPECT_EQ(diags_.warning_count(), 1u);
  EXPECT_EQ(diags_.error_count(), 0u);
}

TEST_F(PackageMapTest, ConflictingExplicitDefinitionIsAnError) {  // COMMON-013
  fs::create_directories(root_ / "x");
  fs::create_directories(root_ / "y");
  PackageMap map;
  EXPECT_TRUE(map.Add("p", (root_ / "x").string(), diags_));
  EXPECT_TRUE(map.Add("p", (root_ / "x").string(), diags_));
  EXPECT_FALSE(map.Add("p", (root_ / "y").string(), diags_));
  EXPECT_EQ(diags_.error_count(), 1u);
}

TEST_F(PackageMapTest, MalformedOrNamelessManifestIsAnError) {  // COMMON-014
  Write("bad/package.xml", "<package><name>oops</package>");
  Write("nameless/package.xml", "<package><version>1</version></package>");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  EXPECT_EQ(map.size(), 0u);
  // libxml2 may say more than once what is wrong with the malformed one
  EXPECT_GE(diags_.error_count(), 2u);
  bool nameless_reported = false;
  for (const auto& d : diags_.diagnostics()) {
    nameless_reported |= d.message.find("non-empty <name>") != std::string::npos;
  }
  EXPECT_TRUE(nameless_reported);
}

TEST_F(PackageMapTest, DeprecatedPackagesWarnOnUse) {  // COMMON-014
  Package("old", "old", "<export><deprecated>use new</deprecated></export>");
  Write("old/mesh.obj", "");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  auto path = ResolveUri("package://old/mesh.obj", "/", map, {}, diags_);
  ASSERT_TRUE(path);
  EXPECT_EQ(diags_.warning_count(), 1u);
  EXPECT_NE(diags_.diagnostics()[0].message.find("deprecated"), std::string::npos);
}

TEST_F(PackageMapTest, ResolvesEveryUriForm) {  // COMMON-010
  Package("pkg", "pkg");
  Write("pkg/meshes/a.obj", "");
  Write("models/b.obj", "");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  const std::string base = (root_ / "models").string();
  EXPECT_EQ(Canon(ResolveUri("package://pkg/meshes/a.obj", base, map, {}, diags_)),
            Canonical("pkg/meshes/a.obj"));
  EXPECT_EQ(Canon(ResolveUri("model://pkg/meshes/a.obj", base, map, {}, diags_)),
            Canonical("pkg/meshes/a.obj"));
  EXPECT_EQ(Canon(ResolveUri("b.obj", base, map, {}, diags_)), Canonical("models/b.obj"));
  EXPECT_EQ(Canon(ResolveUri("../models/b.obj", base, map, {}, diags_)), Canonical("models/b.obj"));
  EXPECT_EQ(Canon(ResolveUri("file://" + (root_ / "models/b.obj").string(), base, map, {}, diags_)),
            Canonical("models/b.obj"));
  EXPECT_EQ(Canon(ResolveUri((root_ / "models/b.obj").string(), "/elsewhere", map, {}, diags_)),
            Canonical("models/b.obj"));
  EXPECT_EQ(diags_.diagnostics().size(), 0u);
}

// package:///NAME/path (an empty authority, as Pinocchio-era URDFs write
// it) is read as package://NAME/path, with a warning that says so
TEST_F(PackageMapTest, PackageUriWithThreeSlashesIsReadAsTwoWithAWarning) {  // COMMON-010
  Package("pkg", "pkg");
  Write("pkg/meshes/a.obj", "");
  PackageMap map;
  map.PopulateFromFolder(root_.string(), sources_, diags_);
  const FileId file = sources_.AddBuffer("robot.urdf", "\n\n<mesh/>\n");
  const Loc at{file, 3, 1};
  EXPECT_EQ(Canon(ResolveUri("package:///pkg/meshes/a.obj", "/", map, at, diags_)),
            Canonical("pkg/meshes/a.obj"));
  ASSERT_EQ(diags_.diagnostics().size(), 1u);
  const Diagnostic& d = diags_.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::MalformedUri);
  EXPECT_EQ(d.severity, Severity::Warning);
  EXPECT_EQ(d.loc, at);
  EXPECT_NE(d.message.find("'package:///pkg/meshes/a.obj' has an empty authority"),
            std::string::npos)
      << d.message;
  EXPECT_NE(d.message.find("read as 'package://pkg/meshes/a.obj'"), std::string::npos)
      << d.message;
  EXPECT_EQ(InfoFor(d.kind).group, "uri");
  EXPECT_EQ(diags_.error_count(), 0u);
  // the tolerance is for package:// only; four slashes still name no package
  EXPECT_FALSE(ResolveUri("package:////pkg/meshes/a.obj", "/", map, at, diags_));
  EXPECT_FALSE(ResolveUri("model:///pkg/meshes/a.obj", "/", map, at, diags_));
  EXPECT_EQ(diags_.error_count(), 2u);
}

// PX4's x500_base: model.sdf in models/x500_base/ (with model.config) names
// model://x500_base/meshes/...; the folder is found however the referring
// file's path was spelled, relative to the working folder or not
TEST_F(PackageMapTest, GazeboModelFolderIsFoundHoweverTheFileIsNamed) {  // issue 55, SDF-031
  Write("models/x500_base/model.config", "<model><name>x500_base</name></model>");
  Write("models/x500_base/meshes/a.obj", "v 0 0 0\n");
  const fs::path cwd = fs::current_path();
  fs::current_path(root_ / "models" / "x500_base");
  PackageMap none;
  const std::string expected = Canonical("models/x500_base/meshes/a.obj");
  // the base folder of "model.sdf", "./model.sdf", "../x500_base/model.sdf" and its absolute path
  const std::vector<std::string> bases = {"", ".", "../x500_base",
                                          (root_ / "models/x500_base").string(),
                                          (root_ / "models//x500_base/").string()};
  for (const std::string& base : bases) {
    EXPECT_EQ(Canon(ResolveUri("model://x500_base/meshes/a.obj", base, none, {}, diags_)), expected)
        << "base '" << base << "'";
  }
  fs::current_path(cwd);
  EXPECT_EQ(diags_.diagnostics().size(), 0u);
}

TEST_F(PackageMapTest, UnresolvableUrisAreErrors) {  // COMMON-010, COMMON-011
  PackageMap map;
  EXPECT_FALSE(ResolveUri("http://example.com/a.obj", "/", map, {}, diags_));
  EXPECT_FALSE(ResolveUri("package://nowhere/a.obj", "/", map, {}, diags_));
  EXPECT_FALSE(ResolveUri("missing.obj", root_.string(), map, {}, diags_));
  ASSERT_EQ(diags_.error_count(), 3u);
  EXPECT_NE(diags_.diagnostics()[0].message.find("unsupported scheme"), std::string::npos);
  EXPECT_NE(diags_.diagnostics()[1].message.find("unknown package 'nowhere'"), std::string::npos);
  EXPECT_EQ(diags_.diagnostics()[1].notes.size(), 1u);  // says where it looked
  EXPECT_NE(diags_.diagnostics()[2].message.find("does not exist"), std::string::npos);
}

TEST_F(PackageMapTest, UnknownPackageNamedAboveTheFileSaysWhichFolderToGive) {  // COMMON-011
  // the package is still unknown (Drake does not look upward either); the
  // note names the folder whose package.xml, above the referring file,
  // names it
  Package("ws/own", "own");
  Package("ws/own/robots", "inner");  // a nearer package.xml of another name
  Write("ws/own/robots/urdf/robot.urdf", "<robot name='r'/>");
  PackageMap map;
  const std::string base = (root_ / "ws/own/robots/urdf").string();
  EXPECT_FALSE(ResolveUri("package://own/meshes/a.obj", base, map, {}, diags_));
  ASSERT_EQ(diags_.error_count(), 1u);
  const Diagnostic& d = diags_.diagnostics()[0];
  ASSERT_EQ(d.notes.size(), 2u);
  EXPECT_NE(d.notes[1].message.find("names package 'own': give --package-path "),
            std::string::npos)
      << d.notes[1].message;
  const std::string named = d.notes[1].message.substr(d.notes[1].message.rfind(' ') + 1);
  EXPECT_EQ(fs::weakly_canonical(named).string(), Canonical("ws/own"));
  // a package no folder above names gets no such note
  EXPECT_FALSE(ResolveUri("package://elsewhere/a.obj", base, map, {}, diags_));
  ASSERT_EQ(diags_.error_count(), 2u);
  EXPECT_EQ(diags_.diagnostics()[1].notes.size(), 1u);
}

// A ROS 2 install: PREFIX/share/ament_index/resource_index/packages/NAME
// registers the package at PREFIX/share/NAME.
TEST_F(PackageMapTest, AmentIndexNamesTheInstalledPackages) {  // COMMON-012
  auto install = [&](const std::string& prefix, const std::string& name, bool share = true) {
    Write(fs::path(prefix) / "share/ament_index/resource_index/packages" / name, "");
    if (share) fs::create_directories(root_ / prefix / "share" / name / "urdf");
  };
  install("overlay", "robot_description");
  install("underlay", "robot_description");  // overlaid by the first prefix
  install("underlay", "gripper_description");
  install("underlay", "registered_only", /*share=*/false);
  install("underlay", "given");
  fs::create_directories(root_ / "plain/share");  // a prefix holding no index
  Package("given_elsewhere", "given");

  PackageMap map;
  map.PopulateFromFolder((root_ / "given_elsewhere").string(), sources_, diags_);
  map.PopulateFromAmentPrefixes(fmt::format("{}::{}:{}:{}", (root_ / "overlay").string(),
                                            (root_ / "plain").string(),
                                            (root_ / "missing").string(),
                                            (root_ / "underlay").string()));
  EXPECT_EQ(diags_.diagnostics().size(), 0u);  // overlays are normal in ROS 2
  ASSERT_TRUE(map.Find("robot_description"));
  EXPECT_EQ(map.Find("robot_description")->path, Canonical("overlay/share/robot_description"));
  ASSERT_TRUE(map.Find("gripper_description"));
  EXPECT_EQ(map.Find("gripper_description")->path,
            Canonical("underlay/share/gripper_description"));
  EXPECT_FALSE(map.Find("registered_only"));
  ASSERT_TRUE(map.Find("given"));  // what a package path found comes first
  EXPECT_EQ(map.Find("given")->path, Canonical("given_elsewhere"));
  EXPECT_EQ(map.size(), 3u);
  // the prefixes with an index are named in "searched" notes
  const std::vector<std::string> searched = {(root_ / "given_elsewhere").string(),
                                             (root_ / "overlay").string() + " (ament index)",
                                             (root_ / "underlay").string() + " (ament index)"};
  EXPECT_EQ(map.searched(), searched);
  const auto mesh = ResolveUri("package://gripper_description/urdf", "/", map, {}, diags_);
  ASSERT_TRUE(mesh);
  EXPECT_EQ(Canon(mesh), Canonical("underlay/share/gripper_description/urdf"));
}

}  // namespace
}  // namespace mdlc::assets
