// What the xacro stage asks of the XML layer: documents read with every
// node in order (blanks, namespace declarations, comments outside the root)
// and documents built by a program.
#include <gtest/gtest.h>

#include "frontend/xml/document_builder.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::xml {
namespace {

// each child of `e` as "<name>", "text", "<!--c-->" in document order
std::vector<std::string> NodesOf(const XmlElement& e) {
  std::vector<std::string> out;
  e.ForEachNode([&](const XmlElement& child) { out.push_back("<" + std::string(child.Name()) + ">"); },
                [&](const XmlContent& c) {
                  out.push_back(c.kind == detail::ContentKind::kComment
                                    ? "<!--" + std::string(c.text) + "-->"
                                    : std::string(c.text));
                });
  return out;
}

TEST(XmlDocumentNodeOrder, ChildrenAndContentAreVisitedInDocumentOrder) {
  SourceManager sources;
  DiagnosticEngine diags;
  const FileId file = sources.AddBuffer(
      "a.xml", "<r>t1<a/><!--c1-->t2<b/><!--c2--><c/>t3</r>");
  auto doc = XmlDocument::Parse(file, sources, diags);
  ASSERT_TRUE(doc);
  EXPECT_EQ(NodesOf(doc->Root()),
            (std::vector<std::string>{"t1", "<a>", "<!--c1-->", "t2", "<b>", "<!--c2-->", "<c>",
                                      "t3"}));
}

TEST(XmlDocumentNodeOrder, BlanksAreKeptOnlyWhenAsked) {
  SourceManager sources;
  DiagnosticEngine diags;
  const FileId file = sources.AddBuffer("a.xml", "<r>\n  <a/>\n\n  <b/>\n</r>");
  auto readers = XmlDocument::Parse(file, sources, diags);
  ASSERT_TRUE(readers);
  EXPECT_EQ(NodesOf(readers->Root()), (std::vector<std::string>{"<a>", "<b>"}));
  ParseOptions options;
  options.keep_blank_text = true;
  auto all = XmlDocument::Parse(file, sources, diags, options);
  ASSERT_TRUE(all);
  EXPECT_EQ(NodesOf(all->Root()),
            (std::vector<std::string>{"\n  ", "<a>", "\n\n  ", "<b>", "\n"}));
}

TEST(XmlDocumentNodeOrder, NamespaceDeclarationsAndOutsideCommentsWhenAsked) {
  SourceManager sources;
  DiagnosticEngine diags;
  const FileId file = sources.AddBuffer(
      "a.xml", "<!--before--><r xmlns:x=\"u\" a=\"1\" xmlns=\"d\"><x:e/></r><!--after-->");
  auto plain = XmlDocument::Parse(file, sources, diags);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain->Root().Attribute("xmlns:x").present());
  EXPECT_TRUE(plain->outside_comments().empty());
  ParseOptions options;
  options.keep_namespace_declarations = true;
  auto doc = XmlDocument::Parse(file, sources, diags, options);
  ASSERT_TRUE(doc);
  const XmlAttribute x = doc->Root().Attribute("xmlns:x");
  ASSERT_TRUE(x.present());
  EXPECT_EQ(x.value, "u");
  EXPECT_EQ(x.loc.column, 17u);  // placed where it is written
  EXPECT_EQ(doc->Root().Attribute("xmlns").value, "d");
  EXPECT_EQ(doc->Root().Attribute("a").value, "1");
  ASSERT_EQ(doc->outside_comments().size(), 2u);
  EXPECT_EQ(doc->outside_comments()[0], (std::pair<std::string_view, bool>{"before", false}));
  EXPECT_EQ(doc->outside_comments()[1], (std::pair<std::string_view, bool>{"after", true}));
  EXPECT_TRUE(diags.diagnostics().empty());
}

TEST(XmlDocumentBuilder, BuildsADocumentPlacedInSeveralFiles) {
  SourceManager sources;
  const FileId top = sources.AddBuffer("top.xml", "");
  const FileId part = sources.AddBuffer("part.xml", "");
  XmlDocumentBuilder builder(top, sources);
  const AttributeSpec robot[] = {{"name", "r", Loc{top, 1, 8}}};
  builder.StartElement("robot", Loc{top, 1, 1}, robot);
  const AttributeSpec link[] = {{"name", "a", Loc{part, 3, 9}}, {"type", "x", Loc{part, 3, 18}}};
  builder.StartElement("link", Loc{part, 3, 3}, link);
  builder.EndElement();
  builder.AddContent(detail::ContentKind::kComment, "note");
  builder.StartElement("link", Loc{top, 5, 3}, {});
  builder.EndElement();
  builder.EndElement();
  auto doc = builder.Finish();
  ASSERT_TRUE(doc);
  EXPECT_EQ(doc->file(), top);
  EXPECT_EQ(doc->CountOf("link"), 2u);
  const XmlElement first = doc->Root().Child("link");
  ASSERT_TRUE(first);
  EXPECT_EQ(first.GetLoc(), (Loc{part, 3, 3}));
  EXPECT_EQ(first.Attribute("type").loc, (Loc{part, 3, 18}));
  EXPECT_EQ(first.NextSibling().GetLoc(), (Loc{top, 5, 3}));
  EXPECT_EQ(doc->Root().Attribute("name").loc, (Loc{top, 1, 8}));
  EXPECT_EQ(NodesOf(doc->Root()), (std::vector<std::string>{"<link>", "<!--note-->", "<link>"}));
}

TEST(XmlDocumentBuilder, NothingBuiltIsNoDocument) {
  SourceManager sources;
  XmlDocumentBuilder builder(sources.AddBuffer("x.xml", ""), sources);
  EXPECT_FALSE(builder.Finish());
}

}  // namespace
}  // namespace mdlc::xml
