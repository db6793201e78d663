// Tests for the SourceManager: buffers, offsets to line:column, line text.
#include "ir/source_manager.h"

#include <gtest/gtest.h>

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

TEST(SourceManagerTest, RecordsIncludeSite) {
  SourceManager sm;
  FileId parent = sm.AddBuffer("parent.sdf", "<sdf/>");
  FileId child = sm.AddBuffer("child.sdf", "<sdf/>", Loc{parent, 1, 2});
  EXPECT_EQ(sm.IncludedFrom(child), (Loc{parent, 1, 2}));
  EXPECT_FALSE(sm.IncludedFrom(parent).valid());
}

}  // namespace
}  // namespace mdlc
