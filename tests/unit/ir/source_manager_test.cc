// Tests for the SourceManager: buffers, offsets to line:column, line text.
#include "ir/source_manager.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace mdlc {
namespace {

TEST(SourceManagerTest, MapsOffsetsToLineAndColumn) {
  SourceManager sm;
  FileId f = sm.AddBuffer("a.urdf", "ab\ncde\n\nf");
  EXPECT_EQ(sm.LocForOffset(f, 0), (Loc{f, 1, 1}));
  EXPECT_EQ(sm.LocForOffset(f, 1), (Loc{f, 1, 2}));
  EXPECT_EQ(sm.LocForOffset(f, 3), (Loc{f, 2, 1}));
  EXPECT_EQ(sm.LocForOffset(f, 5), (Loc{f, 2, 3}));
  EXPECT_EQ(sm.LocForOffset(f, 7), (Loc{f, 3, 1}));
  EXPECT_EQ(sm.LocForOffset(f, 8), (Loc{f, 4, 1}));
}

TEST(SourceManagerTest, ReturnsLineTextWithoutNewlineOrCarriageReturn) {
  SourceManager sm;
  FileId f = sm.AddBuffer("a", "first\r\nsecond\nthird");
  EXPECT_EQ(sm.LineText(f, 1), "first");
  EXPECT_EQ(sm.LineText(f, 2), "second");
  EXPECT_EQ(sm.LineText(f, 3), "third");
  EXPECT_EQ(sm.LineText(f, 4), "");
}

TEST(SourceManagerTest, MissingFileReportsError) {
  SourceManager sm;
  LoadError error;
  EXPECT_FALSE(sm.LoadFile("/nonexistent/definitely/not/here.urdf", {}, &error));
  EXPECT_FALSE(error.message.empty());
  EXPECT_FALSE(error.over_limit);
}

// Diagnostics print a file's path tidied (models/a//model.sdf,
// ./../assets.xml), unless tidying through a symbolic link would name
// another file.
TEST(SourceManagerTest, LoadedPathsAreTidied) {  // issue 55
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("mdlc_tidy_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "a" / "sub");
  fs::create_directories(root / "elsewhere" / "deep");
  std::ofstream(root / "a" / "m.sdf") << "<sdf/>";
  std::ofstream(root / "elsewhere" / "m.sdf") << "<other/>";
  fs::create_directory_symlink(root / "elsewhere" / "deep", root / "a" / "link");
  const std::string r = root.string();
  SourceManager sm;
  for (const std::string& written : {r + "/a//m.sdf", r + "/a/./m.sdf", r + "/a/sub/../m.sdf",
                                     r + "//a/m.sdf"}) {
    const auto f = sm.LoadFile(written);
    ASSERT_TRUE(f) << written;
    EXPECT_EQ(sm.Path(*f), r + "/a/m.sdf") << written;
    EXPECT_EQ(sm.Contents(*f), "<sdf/>");
  }
  // a/link/.. is elsewhere/, not a/: the path stays as written
  const std::string through_link = r + "/a/link/../m.sdf";
  const auto f = sm.LoadFile(through_link);
  ASSERT_TRUE(f);
  EXPECT_EQ(sm.Path(*f), through_link);
  EXPECT_EQ(sm.Contents(*f), "<other/>");
  fs::remove_all(root);
}

TEST(SourceManagerTest, RecordsIncludeSite) {
  SourceManager sm;
  FileId parent = sm.AddBuffer("parent.sdf", "<sdf/>");
  FileId child = sm.AddBuffer("child.sdf", "<sdf/>", Loc{parent, 1, 2});
  EXPECT_EQ(sm.IncludedFrom(child), (Loc{parent, 1, 2}));
  EXPECT_FALSE(sm.IncludedFrom(parent).valid());
}

}  // namespace
}  // namespace mdlc
