// ReadPackageManifest: package.xml read with libxml2, hardened, below the
// format readers (COMMON-014).
#include "ir/assets/package_manifest.h"

#include <gtest/gtest.h>

#include <string>

namespace mdlc::assets {
namespace {

class PackageManifestTest : public ::testing::Test {
 protected:
  std::optional<PackageManifest> Read(std::string text) {
    file_ = sources_.AddBuffer("package.xml", std::move(text));
    return ReadPackageManifest(file_, sources_, diags_);
  }
  SourceManager sources_;
  DiagnosticEngine diags_;
  FileId file_;
};

TEST_F(PackageManifestTest, NameDeprecationAndPlacesAreRead) {
  auto read = Read(
      "<?xml version=\"1.0\"?>\n"
      "<package format=\"3\">\n"
      "  <description>a > b</description>\n"
      "  <name> arm<![CDATA[_x]]> </name>\n"
      "  <export><deprecated>use &amp; enjoy</deprecated></export>\n"
      "</package>\n");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->root, "package");
  EXPECT_EQ(read->root_at, (Loc{file_, 2, 1}));
  EXPECT_EQ(read->name, " arm_x ");  // trimmed by its reader, the package map
  EXPECT_EQ(read->name_at, (Loc{file_, 4, 3}));
  EXPECT_EQ(read->deprecated, "use & enjoy");
  EXPECT_EQ(diags_.diagnostics().size(), 0u);
}

TEST_F(PackageManifestTest, OnlyTheRootsOwnNameCounts) {
  auto read = Read("<package><export><name>inner</name></export></package>");
  ASSERT_TRUE(read);
  EXPECT_FALSE(read->name);
  EXPECT_FALSE(read->deprecated);
}

TEST_F(PackageManifestTest, EntityDeclarationsAreRefusedUnexpanded) {
  EXPECT_FALSE(Read("<!DOCTYPE package [<!ENTITY n \"secret\">]>\n"
                    "<package><name>&n;</name></package>"));
  ASSERT_EQ(diags_.error_count(), 1u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::EntityDeclaration);
}

TEST_F(PackageManifestTest, ExternalReferencesAreNotFetched) {
  // an external DTD is neither loaded nor a reason to refuse the manifest
  auto read = Read("<!DOCTYPE package SYSTEM \"http://example.com/p.dtd\">\n"
                   "<package><name>p</name></package>");
  ASSERT_TRUE(read);
  EXPECT_EQ(read->name, "p");
}

TEST_F(PackageManifestTest, MalformedAndEmptyAreErrors) {
  EXPECT_FALSE(Read("<package><name>oops</package>"));
  ASSERT_GE(diags_.error_count(), 1u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::XmlSyntax);
  EXPECT_EQ(diags_.diagnostics()[0].message.rfind("malformed XML", 0), 0u);
  EXPECT_FALSE(Read("  \n"));
  EXPECT_EQ(diags_.diagnostics().back().kind, DiagKind::EmptyFile);
}

}  // namespace
}  // namespace mdlc::assets
