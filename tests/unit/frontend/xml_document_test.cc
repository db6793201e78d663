// XmlDocument: exact element and attribute locations recovered from the
// buffer, and the security rules (COMMON-004, COMMON-008).
#include "frontend/xml/xml_document.h"

#include <gtest/gtest.h>

namespace mdlc::xml {
namespace {

class XmlDocumentTest : public ::testing::Test {
 protected:
  std::unique_ptr<XmlDocument> Parse(std::string text) {
    file_ = sources_.AddBuffer("test.xml", std::move(text));
    return XmlDocument::Parse(file_, sources_, diags_);
  }
  SourceManager sources_;
  DiagnosticEngine diags_;
  FileId file_;
};

// SameName compares by machine words; every length and every position of a
// differing byte must give the answer string equality gives.
TEST(XmlSameName, AgreesWithStringEqualityAtEveryLengthAndPosition) {
  for (size_t n = 0; n <= 40; ++n) {
    std::string a(n, 'a');
    for (size_t i = 0; i < n; ++i) a[i] = static_cast<char>('a' + i % 26);
    // equal contents at different addresses, and a differing length
    const std::string same = a;
    EXPECT_TRUE(SameName(a, same)) << n;
    EXPECT_FALSE(SameName(a, a + "x")) << n;
    for (size_t i = 0; i < n; ++i) {
      std::string b = a;
      b[i] = '#';
      EXPECT_FALSE(SameName(a, b)) << "length " << n << ", byte " << i;
      EXPECT_FALSE(SameName(b, a)) << "length " << n << ", byte " << i;
    }
  }
  // views into one buffer compare by their own bytes, not their neighbours'
  const std::string buffer = "xlinkylinkz";
  EXPECT_TRUE(SameName(std::string_view(buffer).substr(1, 4), std::string_view(buffer).substr(6, 4)));
  EXPECT_FALSE(SameName(std::string_view(buffer).substr(0, 5), std::string_view(buffer).substr(5, 5)));
}

TEST_F(XmlDocumentTest, ElementsAndAttributesHaveExactColumns) {
  auto doc = Parse("<robot name='r'>\n  <link\n      name=\"a\"/>  <link name='b'/>\n</robot>\n");
  ASSERT_TRUE(doc);
  XmlElement robot = doc->Root();
  EXPECT_EQ(robot.GetLoc(), (Loc{file_, 1, 1}));
  EXPECT_EQ(robot.Attribute("name").loc, (Loc{file_, 1, 8}));
  XmlElement a = robot.FirstChild();
  // a multi-line start tag: the element is where '<' is, the attribute where its name is
  EXPECT_EQ(a.GetLoc(), (Loc{file_, 2, 3}));
  EXPECT_EQ(a.Attribute("name").loc, (Loc{file_, 3, 7}));
  EXPECT_EQ(a.Attribute("name").value, "a");
  XmlElement b = a.NextSibling();
  EXPECT_EQ(b.GetLoc(), (Loc{file_, 3, 19}));
  EXPECT_EQ(b.Attribute("name").loc, (Loc{file_, 3, 25}));
  EXPECT_FALSE(b.NextSibling());
}

TEST_F(XmlDocumentTest, MarkupInCommentsAndCdataDoesNotShiftLocations) {
  auto doc = Parse(
      "<robot name='r'><!-- <link name='fake'> -->\n"
      "<![CDATA[ <joint> ]]><?pi <link?>\n"
      "  <link name='real'/></robot>");
  ASSERT_TRUE(doc);
  XmlElement link = doc->Root().FirstChild();
  EXPECT_EQ(link.Name(), "link");
  EXPECT_EQ(link.GetLoc(), (Loc{file_, 3, 3}));
  EXPECT_EQ(link.Attribute("name").value, "real");
}

TEST_F(XmlDocumentTest, PrefixedNamesWorkWithOrWithoutNamespaceDeclaration) {
  auto declared = Parse(
      "<robot xmlns:drake='http://drake.mit.edu' name='r'>"
      "<drake:joint name='j' drake:x='1'/></robot>");
  ASSERT_TRUE(declared);
  EXPECT_EQ(declared->Root().FirstChild().Name(), "drake:joint");
  EXPECT_TRUE(declared->Root().FirstChild().Attribute("drake:x").present());
  auto undeclared = Parse("<robot name='r'><drake:joint name='j' drake:x='1'/></robot>");
  ASSERT_TRUE(undeclared);
  EXPECT_EQ(undeclared->Root().FirstChild().Name(), "drake:joint");
  EXPECT_TRUE(undeclared->Root().FirstChild().Attribute("drake:x").present());
  EXPECT_EQ(diags_.error_count(), 0u);
}

// The name bits may give false alarms (two names on one bit) but never
// miss: every attribute present has its bit set, prefixed, one-character
// and namespaced names included, so a clear bit safely means absent.
TEST_F(XmlDocumentTest, AttributeNameBitsNeverMissAPresentAttribute) {
  auto doc = Parse(
      "<r xmlns:d='http://drake.mit.edu' xmlns:q='urn:q'>"
      "<e a='1' ab='2' d:x='3' q:y='4' pos='5' quat='6' contype='7' conaffinity='8'/>"
      "<f/></r>");
  ASSERT_TRUE(doc);
  const XmlElement e = doc->Root().FirstChild();
  const uint64_t bits = e.AttributeNameBits();
  const char* present[] = {"a", "ab", "d:x", "q:y", "pos", "quat", "contype", "conaffinity"};
  for (const char* name : present) {
    ASSERT_TRUE(e.Attribute(name).present()) << name;
    EXPECT_NE(bits & XmlElement::NameBit(name), 0u) << name;
  }
  // a name whose bit is clear is absent, whatever the other names are
  const char* probes[] = {"b", "zz", "size", "rgba", "d:y", "euler", "xyaxes", "name", "class"};
  int rejected = 0;
  for (const char* name : probes) {
    EXPECT_FALSE(e.Attribute(name).present()) << name;
    if (!(bits & XmlElement::NameBit(name))) ++rejected;
  }
  EXPECT_GE(rejected, 5) << "the bits should rule out most absent names";
  EXPECT_EQ(e.NextSibling().AttributeNameBits(), 0u);
}

// Child() answers an absent name from the children's name bits without a
// walk; names that share a bit with a present child still need the walk and
// must come back absent, and only direct children count.
TEST_F(XmlDocumentTest, ChildFindsTheFirstOfItsNameAndNothingElse) {
  auto doc = Parse(
      "<r xmlns:d='http://drake.mit.edu'>"
      "<model><pose n='1'/><link n='a'/><link n='b'/><d:joint/><x/>"
      "<nested><static/></nested></model><empty/></r>");
  ASSERT_TRUE(doc);
  const XmlElement model = doc->Root().FirstChild();
  for (const char* name : {"pose", "link", "d:joint", "x", "nested"}) {
    const XmlElement c = model.Child(name);
    ASSERT_TRUE(c) << name;
    EXPECT_EQ(c.Name(), name);
  }
  EXPECT_EQ(model.Child("link").Attribute("n").value, "a");
  // "position" and "po" share "pose"'s bit, "linker" "link"'s: the walk says no
  EXPECT_EQ(XmlElement::NameBit("position"), XmlElement::NameBit("pose"));
  for (const char* name : {"position", "po", "linker", "static", "joint", "d:joints", "", "y"}) {
    EXPECT_FALSE(model.Child(name)) << name;
  }
  EXPECT_TRUE(model.Child("nested").Child("static"));
  EXPECT_FALSE(model.NextSibling().Child("link"));  // no children at all
}

TEST_F(XmlDocumentTest, MalformedXmlReportsLineAndColumn) {  // COMMON-004
  EXPECT_FALSE(Parse("<robot name='r'>\n  <link>\n</robot>\n"));
  ASSERT_GE(diags_.diagnostics().size(), 1u);
  const Diagnostic& d = diags_.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::XmlSyntax);
  EXPECT_EQ(d.loc.line, 3u);
  EXPECT_GT(d.loc.column, 0u);
  EXPECT_NE(d.message.find("malformed XML"), std::string::npos);
}

// pybullet's minitaur files declare version "0.0", which libxml2 alone
// refuses and urdfdom, MuJoCo and Drake read: a warning, and the document
TEST_F(XmlDocumentTest, AnUnknownXmlVersionIsAWarning) {  // issue 55, COMMON-004
  const std::pair<std::string, uint32_t> declarations[] = {
      {"<?xml version=\"0.0\" ?>", 16},
      {"<?xml version='2.0' encoding='utf-8'?>", 16},
      {"\xEF\xBB\xBF<?xml  version = \"1\"?>", 22},  // a byte-order mark first (columns count bytes)
      {"<?xml version=\"1.0abc\"?>", 16}};
  for (const auto& [declaration, column] : declarations) {
    diags_ = DiagnosticEngine();
    auto doc = Parse(declaration + "\n<robot name='r'>\n  <link name='a'/>\n</robot>\n");
    ASSERT_TRUE(doc) << declaration;
    EXPECT_EQ(diags_.error_count(), 0u) << declaration;
    ASSERT_EQ(diags_.diagnostics().size(), 1u) << declaration;
    const Diagnostic& d = diags_.diagnostics()[0];
    EXPECT_EQ(d.kind, DiagKind::XmlWarning);
    EXPECT_EQ(d.severity, Severity::Warning);
    EXPECT_EQ(d.loc, (Loc{file_, 1, column})) << declaration;
    EXPECT_NE(d.message.find("read as XML 1.0"), std::string::npos) << d.message;
    // the document is read whole, every element where it is written
    EXPECT_EQ(doc->Root().Attribute("name").value, "r");
    EXPECT_EQ(doc->Root().FirstChild().GetLoc(), (Loc{file_, 3, 3}));
  }
  // versions libxml2 reads pass in silence
  for (const char* declaration : {"<?xml version=\"1.0\"?>", "<?xml version=\"1.1\"?>"}) {
    diags_ = DiagnosticEngine();
    EXPECT_TRUE(Parse(std::string(declaration) + "<r/>")) << declaration;
    EXPECT_TRUE(diags_.diagnostics().empty()) << declaration;
  }
  // a document still has to be well formed after its declaration
  diags_ = DiagnosticEngine();
  EXPECT_FALSE(Parse("<?xml version=\"0.0\"?>\n<robot>\n"));
  EXPECT_TRUE(diags_.has_errors());
}

TEST_F(XmlDocumentTest, EmptyAndWhitespaceOnlyFilesAreErrors) {  // COMMON-004
  EXPECT_FALSE(Parse(""));
  EXPECT_FALSE(Parse("  \n\t\n"));
  EXPECT_EQ(diags_.error_count(), 2u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::EmptyFile);
}

TEST_F(XmlDocumentTest, EntityDeclarationsAreRefusedBeforeParsing) {  // COMMON-008
  EXPECT_FALSE(Parse("<!DOCTYPE r [\n <!ENTITY x SYSTEM 'file:///etc/passwd'>\n]>\n<r>&x;</r>"));
  ASSERT_EQ(diags_.diagnostics().size(), 1u);
  EXPECT_EQ(diags_.diagnostics()[0].kind, DiagKind::EntityDeclaration);
  EXPECT_EQ(diags_.diagnostics()[0].loc, (Loc{file_, 2, 2}));
}

TEST_F(XmlDocumentTest, ExternalDtdIsNeverLoaded) {  // COMMON-008
  // a DOCTYPE naming an external DTD parses, without reading it
  auto doc = Parse("<!DOCTYPE robot SYSTEM 'file:///definitely/not/here.dtd'>\n<robot name='r'/>");
  ASSERT_TRUE(doc);
  EXPECT_EQ(doc->Root().Name(), "robot");
  EXPECT_EQ(diags_.error_count(), 0u);
}

TEST_F(XmlDocumentTest, TextContentConcatenatesTextAndCdata) {
  auto doc = Parse("<t>a<![CDATA[b]]>c<!-- no -->d</t>");
  ASSERT_TRUE(doc);
  EXPECT_EQ(doc->Root().Text(), "abcd");
}

TEST_F(XmlDocumentTest, TextViewIsTheTextWithOrWithoutACopy) {
  auto doc = Parse("<t><one> 1 2 </one><mixed>a<![CDATA[b]]>c</mixed><none/></t>");
  ASSERT_TRUE(doc);
  std::string storage;
  EXPECT_EQ(doc->Root().Child("one").TextView(storage), " 1 2 ");
  EXPECT_TRUE(storage.empty());  // one text node: viewed in place
  EXPECT_EQ(doc->Root().Child("mixed").TextView(storage), "abc");
  EXPECT_EQ(doc->Root().Child("none").TextView(storage), "");
}

// Attribute locations pair attributes in order, past namespace declarations
// (which are not attributes); Child compares prefixed names in place; the
// document counts its elements.
TEST_F(XmlDocumentTest, PrefixedAttributesAndChildrenAfterDeclarations) {
  auto doc = Parse(
      "<r a='1' xmlns:drake='urn:x' drake:b='2' c='3'>"
      "<drake:k n='p'/><k n='q'/></r>");
  ASSERT_TRUE(doc);
  XmlElement r = doc->Root();
  EXPECT_EQ(r.Attribute("a").loc, (Loc{file_, 1, 4}));
  EXPECT_EQ(r.Attribute("drake:b").loc, (Loc{file_, 1, 30}));
  EXPECT_EQ(r.Attribute("c").loc, (Loc{file_, 1, 42}));
  EXPECT_EQ(r.Child("drake:k").Attribute("n").value, "p");
  EXPECT_EQ(r.Child("k").Attribute("n").value, "q");
  EXPECT_FALSE(r.Child("drake"));
  EXPECT_FALSE(r.Child("drake:"));
  EXPECT_EQ(doc->CountOf("r"), 1u);
  EXPECT_EQ(doc->CountOf("drake:k"), 1u);
  EXPECT_EQ(doc->CountOf("k"), 1u);
}

// The elements limit stops libxml2's parse at the first element over it, so
// the rest of a document over the limit is never read: here, a syntax
// error after that element is never reached (issue 16: limits).
TEST_F(XmlDocumentTest, AnElementOverTheLimitStopsTheParseThere) {
  Limits limits;
  limits.elements = 3;
  sources_.set_limits(limits);
  EXPECT_FALSE(Parse("<r>\n <a/>\n <b/>\n <c/>\n <d/>\n <broken>\n</r>"));
  ASSERT_EQ(diags_.diagnostics().size(), 1u);
  const Diagnostic& d = diags_.diagnostics()[0];
  EXPECT_EQ(d.kind, DiagKind::LimitExceeded);
  EXPECT_EQ(d.loc, (Loc{file_, 4, 2}));  // <c>, the fourth element
}

// An attribute value written across lines or with references reads as
// libxml2 decodes it; its location stays at its name.
TEST_F(XmlDocumentTest, AttributeValuesAreDecodedAndNormalized) {
  auto doc = Parse("<r a='x &amp; y&#38;z &lt;&#x41;'\n   b=\"1\n2\t3\"/>");
  ASSERT_TRUE(doc);
  EXPECT_EQ(doc->Root().Attribute("a").value, "x & y&z <A");
  EXPECT_EQ(doc->Root().Attribute("b").value, "1 2 3");
  EXPECT_EQ(doc->Root().Attribute("b").loc, (Loc{file_, 2, 4}));
}

}  // namespace
}  // namespace mdlc::xml
