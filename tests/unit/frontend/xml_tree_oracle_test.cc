// mdlc's XML tree against libxml2's own DOM (COMMON-004): mdlc builds its
// tree from libxml2's SAX events (frontend/xml/tree_builder.h), so every
// document the readers see must hold what libxml2's DOM, parsed as mdlc once
// parsed it (XML_PARSE_NOBLANKS), holds: the same elements, attributes in
// order with the same decoded values, the same text and the same comments;
// and mdlc's exact places for elements and attributes must be where the
// text writes them. Compared on hand-made edge cases and on every XML file of the test models,
// diagnostics inputs, fuzz regressions and examples.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "frontend/xml/xml_document.h"
#include "tests/corpus/shared_corpus.h"
#include "tests/unit/files_under.h"

namespace mdlc::xml {
namespace {

std::string Str(const xmlChar* s) { return s ? reinterpret_cast<const char*>(s) : ""; }

std::string QualifiedName(const xmlNs* ns, const xmlChar* name) {
  return ns && ns->prefix ? Str(ns->prefix) + ":" + Str(name) : Str(name);
}

// what the readers can ask of one element, from libxml2's DOM
struct Expected {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::string text;
  std::vector<std::string> comments;
  std::vector<xmlNode*> children;
};

Expected FromDom(xmlNode* node) {
  Expected e;
  e.name = QualifiedName(node->ns, node->name);
  for (xmlAttr* a = node->properties; a; a = a->next) {
    xmlChar* value = xmlNodeListGetString(node->doc, a->children, 1);
    e.attributes.emplace_back(QualifiedName(a->ns, a->name), Str(value));
    xmlFree(value);
  }
  for (xmlNode* c = node->children; c; c = c->next) {
    if (c->type == XML_ELEMENT_NODE) e.children.push_back(c);
    if (c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) e.text += Str(c->content);
    if (c->type == XML_COMMENT_NODE) e.comments.push_back(Str(c->content));
  }
  return e;
}

// The offset in `text` of a 1-based line and byte column; npos when the
// text has no such place.
size_t OffsetOf(const std::vector<size_t>& line_starts, const std::string& text, Loc loc) {
  if (loc.line == 0 || loc.line > line_starts.size() || loc.column == 0) return std::string::npos;
  const size_t offset = line_starts[loc.line - 1] + loc.column - 1;
  return offset < text.size() ? offset : std::string::npos;
}

// Where mdlc places an element and its attributes (frontend/xml/start_tags.h)
// is where they are written: the element at the '<' of its start tag, on a
// line no later than the one libxml2 records for it; each attribute at its
// name, which an '=' follows.
void CheckLocations(xmlNode* node, XmlElement element, const std::string& text,
                    const std::vector<size_t>& line_starts, const std::string& at) {
  const Loc loc = element.GetLoc();
  const size_t offset = OffsetOf(line_starts, text, loc);
  ASSERT_NE(offset, std::string::npos) << at;
  EXPECT_EQ(text.compare(offset, element.Name().size() + 1, "<" + std::string(element.Name())), 0)
      << at << ": placed at " << loc.line << ":" << loc.column;
  EXPECT_LE(loc.line, static_cast<uint32_t>(xmlGetLineNo(node))) << at;
  element.ForEachAttributeName([&](std::string_view name) {
    const Loc a = element.Attribute(name).loc;
    const size_t o = OffsetOf(line_starts, text, a);
    ASSERT_NE(o, std::string::npos) << at << " @" << name;
    EXPECT_GT(o, offset) << at << " @" << name;
    EXPECT_EQ(text.compare(o, name.size(), name), 0) << at << " @" << name << " placed at "
                                                     << a.line << ":" << a.column;
    const size_t eq = text.find_first_not_of(" \t\r\n", o + name.size());
    EXPECT_TRUE(eq != std::string::npos && text[eq] == '=') << at << " @" << name;
  });
}

// Compares the two trees element by element, and the elements' places in
// `text`; returns how many it compared.
int CompareTrees(xmlNode* dom, XmlElement mine, const std::string& text, const std::string& where) {
  std::vector<size_t> line_starts{0};
  for (size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i + 1)) {
    line_starts.push_back(i + 1);
  }
  int compared = 0;
  std::vector<std::pair<xmlNode*, XmlElement>> stack{{dom, mine}};
  while (!stack.empty()) {
    xmlNode* const node = stack.back().first;
    const XmlElement element = stack.back().second;
    stack.pop_back();
    ++compared;
    const Expected e = FromDom(node);
    const std::string at = where + " <" + e.name + "> line " + std::to_string(xmlGetLineNo(node));
    EXPECT_EQ(element.Name(), e.name) << at;
    std::vector<std::pair<std::string, std::string>> attributes;
    element.ForEachAttributeName([&](std::string_view name) {
      attributes.emplace_back(std::string(name), std::string(element.Attribute(name).value));
    });
    EXPECT_EQ(attributes, e.attributes) << at;
    EXPECT_EQ(element.Text(), e.text) << at;
    std::string storage;
    EXPECT_EQ(element.TextView(storage), e.text) << at;
    EXPECT_EQ(element.Comments(), e.comments) << at;
    CheckLocations(node, element, text, line_starts, at);
    std::vector<XmlElement> children;
    for (XmlElement c = element.FirstChild(); c; c = c.NextSibling()) {
      EXPECT_EQ(c.Parent().raw(), element.raw()) << at;
      children.push_back(c);
    }
    EXPECT_EQ(children.size(), e.children.size()) << at;
    if (children.size() != e.children.size()) continue;
    for (size_t i = children.size(); i-- > 0;) stack.emplace_back(e.children[i], children[i]);
  }
  return compared;
}

// libxml2's DOM as mdlc's reader used to build it; null when libxml2 refuses
// the text.
xmlDocPtr ParseDom(const std::string& text) {
  const int options = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                      XML_PARSE_NOWARNING | XML_PARSE_NOERROR | XML_PARSE_NOBLANKS;
  return xmlReadMemory(text.data(), static_cast<int>(text.size()), "oracle.xml", nullptr, options);
}

// Compares one document; returns the elements compared (0 when skipped).
int CompareDocument(const std::string& text, const std::string& where) {
  SourceManager sources;
  DiagnosticEngine diags;
  const FileId file = sources.AddBuffer(where, text);
  std::unique_ptr<XmlDocument> mine = XmlDocument::Parse(file, sources, diags);
  if (text.find("<!ENTITY") != std::string::npos) {
    // never given to libxml2's DOM, which may spend seconds on an entity bomb
    EXPECT_FALSE(mine) << where << ": mdlc refuses entity declarations";
    return 0;
  }
  xmlDocPtr dom = ParseDom(text);
  int compared = 0;
  if (!dom) {
    EXPECT_FALSE(mine) << where << ": libxml2 refuses it, so must mdlc";
  } else {
    EXPECT_TRUE(mine) << where << ": libxml2 accepts it, so must mdlc";
    if (mine) compared = CompareTrees(xmlDocGetRootElement(dom), mine->Root(), text, where);
  }
  xmlFreeDoc(dom);
  return compared;
}

TEST(XmlTreeOracleTest, EdgeCasesMatchLibxml2sDom) {
  const char* documents[] = {
      // blanks: indentation dropped, whole-blank content kept, blanks next to text kept
      "<r>\n  <a>  </a>\n  <b>x</b>\n  <!-- c -->\n  <c> <!--k--> y </c>\n  <d>t <e/> </d>\n</r>",
      "<r><a>\n</a><b><!--only--></b><c> <?pi x?> </c><d><![CDATA[ ]]>  </d></r>",
      "<r>  text first <a/>  <b/>  </r>",
      // text that starts with a blank marks its element: every later blank is kept
      // (a commented-out block's stray "-->" in a real xacro expansion)
      "<r><a/>\n  --&gt;\n\n  <b/>\n  <c/>\n  <d><e/>\n  <f/></d>\n</r>",
      // text that starts with another character does not, unless it leaves ASCII
      "<r><a/>&gt;\n\n  <b/>\n  <c/>\n</r>",
      "<r><a/>x y\n  <b/>\n  <c/>\n</r>",
      "<r><a/>\xC3\xA9t\xC3\xA9\n  <b/>\n  <c/>\n</r>",
      "<r><a/>x \xC3\xA9\n  <b/>\n  <c/>\n</r>",
      // references in text and attributes, decoded; whitespace in values normalized
      "<r a='x &amp; y &#38; z &lt;&#x41;&gt;' b='&quot;q&apos;' c=\"t\tn\nr\r\n.\">"
      "a &amp;&#38;amp; b<![CDATA[&amp;]]>&#x263A;</r>",
      "<r v='&amp;#38;'/>",
      // namespaces: declared, undeclared, default; declarations are not attributes
      "<r xmlns='urn:d' xmlns:drake='urn:x' a='1' drake:b='2'><drake:k drake:c='3'/>"
      "<q:k xmlns:q='urn:q' q:d='4'/><u:k u:e='5'/></r>",
      // attributes a DTD defaults are not the element's
      "<!DOCTYPE r [<!ATTLIST r d CDATA 'dflt'> <!ELEMENT r ANY>]><r e='1'><!-- x --></r>",
      // comments and PIs outside the root; an external DTD never read
      "<?xml version='1.0'?><!-- before --><!DOCTYPE r SYSTEM 'none.dtd'><r/><!-- after -->",
      // places: CRLF line ends, attributes on lines of their own, a value
      // holding a newline, '>' and '/', several tags on one line, no final newline
      "<r\r\n  a='1'\r\n\tb=\"2\"><c\n/><d e='x\ny' f='>' g=\"/\"/><e h='1'/><e h='2'/>\r\n</r>",
      "<r><a b='1'\n\n\n c='2'\n/>\n\n<d/></r>",
      // "<!--->" opens a comment and does not close it: what follows, up to
      // the next "-->", is the comment's
      "<r><!--->\n<a/>\n--><b/>\n<?p?><c/></r>",
      // unclosed, and a duplicate attribute: refused by both
      "<r><a>",
      "<r a='1' a='2'/>",
  };
  int compared = 0;
  for (const char* d : documents) compared += CompareDocument(d, d);
  // long text and long blank runs, past libxml2's 300-byte chunks
  std::string long_text = "<r><a>" + std::string(5000, 'x') + " &amp; " + std::string(700, 'y') +
                          "</a><b>" + std::string(1000, ' ') + "</b>" + std::string(50, '\n') +
                          "<c/></r>";
  compared += CompareDocument(long_text, "long text");
  // the scans read 16 bytes at a time: put tags, newlines, comments and
  // values holding newlines at every offset within those blocks
  std::string shifted = "<r>";
  for (int blanks = 0; blanks < 40; ++blanks) {
    for (int newlines = 0; newlines < 4; ++newlines) {
      shifted += std::string(blanks, ' ') + std::string(newlines, '\n');
      shifted += "<a k='" + std::string(blanks % 20, 'v') + std::string(newlines, '\n') + "w'" +
                 std::string(newlines, '\n') + " m='1'>" + std::string(blanks % 7, '\n');
      if (newlines == 2) shifted += "<!--" + std::string(blanks, '\n') + "<x>-->";
      shifted += "<b/></a>";
    }
  }
  shifted += "</r>";
  compared += CompareDocument(shifted, "tags at every offset of a block");
  EXPECT_GE(compared, 20);
}

// Compares every XML file under `roots`; returns {files, elements}.
std::pair<int, int> CompareFilesUnder(const std::vector<std::filesystem::path>& roots) {
  int files = 0;
  int elements = 0;
  testing::ForEachFileUnder(
      roots, {".urdf", ".sdf", ".xml", ".world", ".config", ".xacro"},
      [&](const std::string& path, const std::string& text) {
        if (text.find_first_not_of(" \t\r\n") == std::string::npos) return;
        ++files;
        elements += CompareDocument(text, path);
      });
  return {files, elements};
}

TEST(XmlTreeOracleTest, EveryTestModelMatchesLibxml2sDom) {
  const std::filesystem::path tests = std::filesystem::path(MDLC_TEST_MODELS).parent_path();
  auto [files, elements] = CompareFilesUnder(
      {tests / "models", tests / "diag", tests / "fuzz", std::filesystem::path(MDLC_EXAMPLES_DIR)});
  EXPECT_GE(files, 100);
  EXPECT_GE(elements, 1000);
}

TEST(XmlTreeOracleTest, EveryCorpusFileMatchesLibxml2sDom) {
  const std::filesystem::path corpus = corpus_test::Corpus();
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << "no corpus beside the project";
  auto [files, elements] = CompareFilesUnder({corpus});
  EXPECT_GE(files, 300);
  EXPECT_GE(elements, 10000);
}

}  // namespace
}  // namespace mdlc::xml
