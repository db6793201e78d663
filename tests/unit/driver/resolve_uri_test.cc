// mdlc::ResolveUri: a URI no model names (a texture, a controller's
// configuration) resolves with the packages a compile would use, exactly as
// a mesh reference does (COMMON-010, COMMON-011; Drake's
// PackageMap::ResolveUrl).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "mdlc/mdlc.h"

namespace mdlc {
namespace {
namespace fs = std::filesystem;

class ResolveUriTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("mdlc_resolve_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_);
    Write("ws/arm/package.xml", "<package><name>arm</name></package>");
    Write("ws/arm/config/gains.yaml", "kp: 1\n");
    Write("old/package.xml",
          "<package><name>old</name><export><deprecated>use arm</deprecated></export></package>");
    Write("old/texture.png", "");
  }
  void TearDown() override { fs::remove_all(root_); }
  void Write(const fs::path& rel, const std::string& text) {
    fs::create_directories((root_ / rel).parent_path());
    std::ofstream(root_ / rel) << text;
  }
  static std::string Canonical(const std::string& path) {
    return fs::weakly_canonical(path).string();
  }

  fs::path root_;
};

TEST_F(ResolveUriTest, PackageModelFileAndRelativeForms) {
  Options options;
  options.packages.paths = {(root_ / "ws").string()};
  const std::string gains = Canonical((root_ / "ws/arm/config/gains.yaml").string());
  for (const std::string& uri : {std::string("package://arm/config/gains.yaml"),
                                std::string("model://arm/config/gains.yaml"),
                                "file://" + (root_ / "ws/arm/config/gains.yaml").string()}) {
    const UriResolution r = ResolveUri(uri, options);
    ASSERT_TRUE(r.ok()) << uri;
    EXPECT_EQ(Canonical(*r.path), gains) << uri;
    EXPECT_TRUE(r.messages.empty()) << uri;
  }
  const UriResolution relative = ResolveUri("config/../config/gains.yaml", {},
                                            (root_ / "ws/arm").string());
  ASSERT_TRUE(relative.ok());
  EXPECT_EQ(*relative.path, (root_ / "ws/arm/config/gains.yaml").string());  // lexically normal
  Options by_name;
  by_name.packages.definitions = {{"arm", (root_ / "ws/arm").string()}};
  EXPECT_EQ(Canonical(*ResolveUri("package://arm/config/gains.yaml", by_name).path), gains);
}

TEST_F(ResolveUriTest, WhatNamesNoFileSaysWhy) {
  Options options;
  options.packages.paths = {(root_ / "ws").string()};
  const UriResolution unknown = ResolveUri("package://gripper/a.obj", options);
  EXPECT_FALSE(unknown.ok());
  ASSERT_EQ(unknown.messages.size(), 1u);
  EXPECT_NE(unknown.messages[0].find("error: unknown package 'gripper'"), std::string::npos)
      << unknown.messages[0];
  EXPECT_NE(unknown.messages[0].find("note: 1 package known; searched '" +
                                     (root_ / "ws").string() + "'"),
            std::string::npos)
      << unknown.messages[0];
  const UriResolution missing = ResolveUri("package://arm/config/none.yaml", options);
  EXPECT_FALSE(missing.ok());
  ASSERT_EQ(missing.messages.size(), 1u);
  EXPECT_NE(missing.messages[0].find("which does not exist"), std::string::npos);
  const UriResolution scheme = ResolveUri("https://example.com/a.obj", options);
  EXPECT_FALSE(scheme.ok());
  ASSERT_EQ(scheme.messages.size(), 1u);
  EXPECT_NE(scheme.messages[0].find("unsupported scheme 'https://'"), std::string::npos);
}

TEST_F(ResolveUriTest, ADeprecatedPackageResolvesWithItsWarning) {  // COMMON-014
  Options options;
  options.packages.paths = {(root_ / "old").string()};
  const UriResolution r = ResolveUri("package://old/texture.png", options);
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r.messages.size(), 1u);
  EXPECT_NE(r.messages[0].find("warning: package 'old' is deprecated: use arm"), std::string::npos)
      << r.messages[0];
}

}  // namespace
}  // namespace mdlc
