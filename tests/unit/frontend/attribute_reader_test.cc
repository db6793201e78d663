// Number syntax and typed attribute reads (COMMON-007).
#include "frontend/xml/attribute_reader.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mdlc::xml {
namespace {

TEST(ParseDoubleTest, AcceptsCDoublesAndNonFiniteSpellings) {
  EXPECT_EQ(ParseDouble("1.5"), 1.5);
  EXPECT_EQ(ParseDouble("  -2e-3 "), -2e-3);
  EXPECT_EQ(ParseDouble("+4"), 4.0);
  EXPECT_EQ(ParseDouble(".5"), 0.5);
  EXPECT_TRUE(std::isnan(*ParseDouble("nan")));
  EXPECT_TRUE(std::isinf(*ParseDouble("inf")));
  EXPECT_EQ(*ParseDouble("-inf"), -INFINITY);
  EXPECT_TRUE(std::isinf(*ParseDouble("1e999")));
}

TEST(ParseDoubleTest, RejectsGarbage) {
  EXPECT_FALSE(ParseDouble(""));
  EXPECT_FALSE(ParseDouble("1.0kg"));
  EXPECT_FALSE(ParseDouble("one"));
  EXPECT_FALSE(ParseDouble("1 2"));
  EXPECT_FALSE(ParseDouble("0x"));
}

TEST(ParseDoubleListTest, SplitsOnAnyWhitespace) {
  auto v = ParseDoubleList(" 1\t2\n3  ");
  ASSERT_TRUE(v);
  EXPECT_EQ(*v, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(ParseDoubleList("")->size(), 0u);
  EXPECT_FALSE(ParseDoubleList("1 x 3"));
}

// Lists are read in one pass, each number where it stands; every token must
// still read exactly as ParseDouble reads it alone (COMMON-007).
TEST(ParseDoubleListTest, ReadsEachTokenAsParseDoubleDoes) {
  for (const char* token : {"1.5", "+4", ".5", "-2e-3", "1e999", "-1e999", "1e-400", "inf",
                            "-inf", "1.0kg", "1e", "0x1p3", "--1", "+", "1,2", "nan"}) {
    const std::string list = std::string("0 ") + token + "\t7";
    const auto alone = ParseDouble(token);
    const auto listed = ParseDoubleList(list);
    ASSERT_EQ(alone.has_value(), listed.has_value()) << token;
    if (!alone) continue;
    ASSERT_EQ(listed->size(), 3u) << token;
    EXPECT_EQ((*listed)[0], 0.0);
    EXPECT_EQ((*listed)[2], 7.0);
    if (std::isnan(*alone)) {
      EXPECT_TRUE(std::isnan((*listed)[1])) << token;
    } else {
      EXPECT_EQ((*listed)[1], *alone) << token;
    }
  }
  double out[2];
  EXPECT_EQ(ParseDoublesInto("1 2 3", out, 2), 3u);  // counts past the capacity
  EXPECT_EQ(out[1], 2.0);
  EXPECT_FALSE(ParseDoublesInto("1 +", out, 2));
}

class AttributeReaderTest : public ::testing::Test {
 protected:
  XmlElement Root(std::string text) {
    FileId f = sources_.AddBuffer("t.xml", std::move(text));
    doc_ = XmlDocument::Parse(f, sources_, diags_);
    return doc_->Root();
  }
  SourceManager sources_;
  DiagnosticEngine diags_;
  std::unique_ptr<XmlDocument> doc_;
};

TEST_F(AttributeReaderTest, ReportsEachProblemAtItsAttribute) {
  XmlElement e = Root("<e a='1 2 3' b='1 2' c='1 nan 3' d='true' f='maybe'/>");
  AttributeReader r(diags_);
  EXPECT_EQ(*r.Vector3(e, "a"), Eigen::Vector3d(1, 2, 3));
  EXPECT_FALSE(r.Vector3(e, "b"));
  EXPECT_FALSE(r.Vector3(e, "c"));
  EXPECT_TRUE(r.Vector3(e, "c", Need::Optional, Finite::NotRequired));
  EXPECT_EQ(r.Bool(e, "d"), true);
  EXPECT_FALSE(r.Bool(e, "f"));
  EXPECT_FALSE(r.Double(e, "missing"));
  EXPECT_FALSE(r.Double(e, "missing", Need::Required));
  ASSERT_EQ(diags_.diagnostics().size(), 4u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::BadValue);
  EXPECT_EQ(diags_.diagnostics()[0].loc.column, 14u);  // at b
  EXPECT_EQ(diags_.diagnostics()[1].kind, DiagKind::NonFinite);
  EXPECT_EQ(diags_.diagnostics()[2].kind, DiagKind::BadValue);
  EXPECT_EQ(diags_.diagnostics()[3].kind, DiagKind::MissingAttribute);
  EXPECT_EQ(diags_.diagnostics()[3].loc.column, 1u);  // at the element
}

TEST_F(AttributeReaderTest, WarnsAboutUnknownAttributes) {
  XmlElement e = Root("<joint name='j' tpye='x' xmlns:drake='http://drake.mit.edu'/>");
  AttributeReader r(diags_);
  r.WarnUnknownAttributes(e, {"name", "type"});
  ASSERT_EQ(diags_.diagnostics().size(), 1u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::UnknownAttribute);
  EXPECT_NE(diags_.diagnostics()[0].message.find("'tpye'"), std::string::npos);
}

}  // namespace
}  // namespace mdlc::xml
