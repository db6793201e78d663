// The compile's XML document cache (frontend/xml/document_cache.h, issue 16):
// a file loaded again with the same text reuses the first load's tree, placed
// in the new load's buffer, so diagnostics still name the load (and its
// include site) they come from; changed text, and text whose parse reported
// anything, is parsed again.
#include "frontend/xml/document_cache.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tools/driver/compiler.h"

namespace mdlc {
namespace {

constexpr const char* kRobot =
    "<robot name=\"r\">\n  <link name=\"base\"><inertial><mass value=\"1\"/>"
    "<inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial></link>\n"
    "</robot>\n";

TEST(DocumentCacheTest, TheSameTextLoadedAgainSharesTheTreeInItsOwnBuffer) {
  SourceManager sources;
  DiagnosticEngine diags;
  xml::DocumentCache cache;
  const FileId first = sources.AddBuffer("robot.urdf", kRobot);
  const FileId second = sources.AddBuffer("robot.urdf", kRobot);
  const FileId third = sources.AddBuffer("robot.urdf", kRobot);
  auto a = cache.Parse(first, sources, diags);
  auto b = cache.Parse(second, sources, diags);
  auto c = cache.Parse(third, sources, diags);
  ASSERT_TRUE(a && b && c);
  // the first load's tree is not kept (a file loaded once keeps nothing);
  // the second's is, and the third shares it
  EXPECT_EQ(cache.reused(), 1u);
  EXPECT_NE(a->Root().raw(), b->Root().raw());
  EXPECT_EQ(b->Root().raw(), c->Root().raw());
  EXPECT_EQ(c->file(), third);
  const xml::XmlElement link = c->Root().FirstChild();
  EXPECT_EQ(link.GetLoc(), (Loc{third, 2, 3}));
  EXPECT_EQ(link.Attribute("name").loc.file, third);
  EXPECT_EQ(b->Root().FirstChild().GetLoc(), (Loc{second, 2, 3}));
  // the copy keeps the tree alive on its own
  b.reset();
  EXPECT_EQ(c->Root().FirstChild().Attribute("name").value, "base");
  EXPECT_TRUE(diags.diagnostics().empty());
}

TEST(DocumentCacheTest, ChangedTextIsParsedAgain) {
  SourceManager sources;
  DiagnosticEngine diags;
  xml::DocumentCache cache;
  for (int i = 0; i < 2; ++i) cache.Parse(sources.AddBuffer("robot.urdf", kRobot), sources, diags);
  auto b = cache.Parse(sources.AddBuffer("robot.urdf", "<robot name=\"other\"/>"), sources, diags);
  ASSERT_TRUE(b);
  EXPECT_EQ(cache.reused(), 0u);
  EXPECT_EQ(b->Root().Attribute("name").value, "other");
}

TEST(DocumentCacheTest, ABrokenFileReportsAtEveryLoad) {
  SourceManager sources;
  DiagnosticEngine diags;
  xml::DocumentCache cache;
  constexpr const char* kBroken = "<robot name=\"r\">\n<link>\n</robot>\n";
  EXPECT_FALSE(cache.Parse(sources.AddBuffer("broken.urdf", kBroken), sources, diags));
  const size_t errors = diags.error_count();
  ASSERT_GT(errors, 0u);
  for (int load = 2; load <= 3; ++load) {
    const FileId again = sources.AddBuffer("broken.urdf", kBroken);
    EXPECT_FALSE(cache.Parse(again, sources, diags));
    EXPECT_EQ(diags.error_count(), load * errors);
    EXPECT_EQ(diags.diagnostics().back().loc.file, again);
  }
  EXPECT_EQ(cache.reused(), 0u);
}

// DMD-002: a scene adding one robot three times. The robot's unknown
// attribute is reported once per instance, each time in the buffer of that
// load, whose include site is that instance's `file:` line.
TEST(DocumentCacheTest, EachInstanceOfAReusedFileReportsAtItsOwnDirective) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("mdlc_doc_cache_{}", ::getpid());
  fs::create_directories(dir);
  std::ofstream(dir / "arm.urdf")
      << "<robot name=\"arm\" colour=\"red\">\n  <link name=\"base\"/>\n</robot>\n";
  std::string scene = "directives:\n";
  for (int i = 0; i < 3; ++i) {
    scene += fmt::format("- add_model:\n    name: arm_{}\n    file: file://{}\n", i,
                         (dir / "arm.urdf").string());
  }
  std::ofstream(dir / "scene.dmd.yaml") << scene;

  Compilation c;
  c.options.inputs = {Input::File((dir / "scene.dmd.yaml").string())};
  EXPECT_TRUE(c.RunFrontends());
  std::vector<uint32_t> include_lines;
  std::vector<FileId> files;
  for (const Diagnostic& d : c.diags.diagnostics()) {
    if (d.message.find("colour") == std::string::npos) continue;
    EXPECT_EQ(d.loc.line, 1u);
    files.push_back(d.loc.file);
    include_lines.push_back(c.sources.IncludedFrom(d.loc.file).line);
  }
  fs::remove_all(dir);
  ASSERT_EQ(files.size(), 3u) << "one warning per instance";
  EXPECT_NE(files[0], files[1]);
  EXPECT_NE(files[1], files[2]);
  EXPECT_EQ(include_lines, (std::vector<uint32_t>{4, 7, 10}));
  // each instance was read in full from the shared tree
  EXPECT_EQ(c.module.bodies.size() - 1, 3u);  // beside the world body
}

}  // namespace
}  // namespace mdlc
