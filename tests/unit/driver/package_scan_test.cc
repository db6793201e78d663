// Package folders walked once and shared by many compiles (Options::
// package_scan, as `mdlc check` does, issue 15): every compile must resolve
// the same packages and say the same things, "searched" notes included, as
// a compile that walks the folders itself (COMMON-012..014).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "ir/assets/package_scan.h"
#include "mdlc/ir.h"
#include "mdlc/mdlc.h"

namespace mdlc {
namespace {
namespace fs = std::filesystem;

class PackageScanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("mdlc_scan_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_);
    // packages to find, one found twice, one behind an ignore marker, and a
    // model naming meshes in them
    Package("pkgs/arm", "arm");
    Package("pkgs/arm_copy", "arm");  // warned about, with a note
    Package("pkgs/ignored/hidden", "hidden");
    Write("pkgs/ignored/COLCON_IGNORE", "");
    Package("more/gripper", "gripper");
    Write("pkgs/arm/meshes/link.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    Write("more/gripper/finger.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
    Write("robot.urdf", R"(<robot name="r">
  <link name="a"><visual><geometry><mesh filename="package://arm/meshes/link.obj"/></geometry></visual></link>
  <link name="b"><visual><geometry><mesh filename="package://gripper/finger.obj"/></geometry></visual></link>
  <link name="c"><visual><geometry><mesh filename="package://hidden/x.obj"/></geometry></visual></link>
  <joint name="j1" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="j2" type="fixed"><parent link="a"/><child link="c"/></joint>
</robot>
)");
    options_.packages.paths = {(root_ / "pkgs").string(), (root_ / "more").string()};
  }
  void TearDown() override { fs::remove_all(root_); }

  void Write(const fs::path& rel, const std::string& text) {
    fs::create_directories((root_ / rel).parent_path());
    std::ofstream(root_ / rel) << text;
  }
  void Package(const fs::path& dir, const std::string& name) {
    Write(dir / "package.xml", "<package>\n  <name>" + name + "</name>\n</package>\n");
  }

  /// What a compile said (each diagnostic with its notes, as printed) and
  /// where each mesh URI resolved to.
  std::string Outcome(const Options& options) const {
    const Result r = Compile(Input::File((root_ / "robot.urdf").string()), options);
    std::string out;
    for (const Diagnostic& d : r.diagnostics()) out += r.FormatText(d);
    for (const ir::Geometry& g : mdlc::IrModule(r).geometries) {
      if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape)) {
        out += mesh->uri + " -> " + mesh->resolved + "\n";
      }
    }
    return out;
  }

  fs::path root_;
  Options options_;
};

TEST_F(PackageScanTest, ASharedScanResolvesAndReportsLikeAWalkPerCompile) {
  const std::string walked = Outcome(options_);
  // the outcome has all the parts this test is about
  EXPECT_NE(walked.find("package://arm/meshes/link.obj -> " + (root_ / "pkgs/arm").string()),
            std::string::npos) << walked;
  EXPECT_NE(walked.find("package 'arm' found again"), std::string::npos) << walked;
  EXPECT_NE(walked.find("note: first defined here"), std::string::npos) << walked;
  EXPECT_NE(walked.find("unknown package 'hidden'"), std::string::npos) << walked;
  EXPECT_NE(walked.find("searched '" + (root_ / "pkgs").string() + "', '" +
                        (root_ / "more").string() + "'"),
            std::string::npos)
      << walked;

  Options shared = options_;
  shared.packages.scan = ScanPackages(options_);
  EXPECT_EQ(Outcome(shared), walked);
  EXPECT_EQ(Outcome(shared), walked);  // the scan is not used up
}

TEST_F(PackageScanTest, BrokenManifestsAndMissingFoldersAreReportedTheSame) {  // COMMON-014
  Write("pkgs/broken/package.xml", "<package><name></name></package>");
  options_.packages.paths.push_back((root_ / "not_a_folder").string());
  const std::string walked = Outcome(options_);
  EXPECT_NE(walked.find("package.xml must be a <package>"), std::string::npos) << walked;
  EXPECT_NE(walked.find("is not a directory"), std::string::npos) << walked;
  Options shared = options_;
  shared.packages.scan = ScanPackages(options_);
  EXPECT_EQ(Outcome(shared), walked);
}

TEST_F(PackageScanTest, ThreadsShareOneScan) {
  const std::string walked = Outcome(options_);
  Options shared = options_;
  shared.packages.scan = ScanPackages(options_);
  std::vector<std::string> outcomes(4);
  std::vector<std::thread> threads;
  for (std::string& outcome : outcomes) {
    threads.emplace_back([&] { outcome = Outcome(shared); });
  }
  for (std::thread& t : threads) t.join();
  for (const std::string& outcome : outcomes) EXPECT_EQ(outcome, walked);
}

TEST_F(PackageScanTest, TheFoldersAreNotWalkedAgain) {
  Options shared = options_;
  shared.packages.scan = ScanPackages(options_);
  // a package made after the scan is not seen by compiles that use it...
  Package("pkgs/ignored_no_more", "hidden");
  Write("pkgs/ignored_no_more/x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(Outcome(shared).find("unknown package 'hidden'"), std::string::npos);
  // ...but by a compile that walks the folders itself
  EXPECT_EQ(Outcome(options_).find("unknown package 'hidden'"), std::string::npos);
}

TEST_F(PackageScanTest, AScanOfOtherFoldersIsNotUsed) {
  Options other = options_;
  other.packages.paths.pop_back();
  Options mismatched = options_;
  mismatched.packages.scan = ScanPackages(other);
  EXPECT_EQ(Outcome(mismatched), Outcome(options_));
}

TEST_F(PackageScanTest, RosPackagePathIsPartOfTheScan) {
  Options ros;
  ros.packages.use_ros_package_path = true;
  const std::string list = ":" + (root_ / "pkgs").string() + "::" + (root_ / "more").string();
  ASSERT_EQ(::setenv("ROS_PACKAGE_PATH", list.c_str(), 1), 0);
  const auto scan = ScanPackages(ros);
  const std::vector<std::string> expected = {(root_ / "pkgs").string(),
                                             (root_ / "more").string()};
  EXPECT_EQ(scan->roots(), expected);
  const std::string walked = Outcome(ros);
  ros.packages.scan = scan;
  EXPECT_EQ(Outcome(ros), walked);
  ::unsetenv("ROS_PACKAGE_PATH");
}

TEST_F(PackageScanTest, AmentPrefixPathIsReadWithTheRosEnvironment) {
  // 'hidden' installed in a ROS 2 prefix, as colcon lays it out
  Write("install/share/ament_index/resource_index/packages/hidden", "");
  Write("install/share/hidden/x.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ASSERT_EQ(::setenv("AMENT_PREFIX_PATH", (root_ / "install").string().c_str(), 1), 0);
  const std::string resolved =
      "package://hidden/x.obj -> " + (root_ / "install/share/hidden/x.obj").string();
  // a library reads the environment only when asked
  EXPECT_EQ(Outcome(options_).find(resolved), std::string::npos);
  Options ros = options_;
  ros.packages.use_ros_package_path = true;
  const std::string walked = Outcome(ros);
  EXPECT_NE(walked.find(resolved), std::string::npos) << walked;
  EXPECT_EQ(walked.find("unknown package"), std::string::npos) << walked;
  // the index is read per compile, alongside a shared scan
  ros.packages.scan = ScanPackages(ros);
  EXPECT_EQ(Outcome(ros), walked);
  ::unsetenv("AMENT_PREFIX_PATH");
}

}  // namespace
}  // namespace mdlc
