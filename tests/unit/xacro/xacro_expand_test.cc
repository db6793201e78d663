// The xacro stage (frontend/xacro/): what mdlc adds to ros/xacro's
// behaviour, which tests/xacro/ checks against ros/xacro's own output:
// locations through expansion, limits, and the deliberate differences.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "ir/assets/package_map.h"
#include "frontend/xacro/macro_params.h"
#include "frontend/xacro/xacro.h"
#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::xacro {
namespace {

namespace fs = std::filesystem;

// A folder of files for one test, an expansion of its top file, and the
// diagnostics it reported.
class XacroFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("mdlc_xacro_{}_{}", ::getpid(),
                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Write(const std::string& name, std::string_view text) {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
  }
  std::unique_ptr<Expansion> Expand(const std::string& name, XacroOptions options = {}) {
    return ExpandFile((dir_ / name).string(), options, sources_, diags_);
  }
  // every diagnostic as text, as `mdlc compile` prints it
  std::string Printed() const {
    std::string out;
    for (const Diagnostic& d : diags_.diagnostics()) out += FormatDiagnosticText(d, sources_);
    return out;
  }
  const Diagnostic* First(DiagKind kind) const {
    for (const Diagnostic& d : diags_.diagnostics()) {
      if (d.kind == kind) return &d;
    }
    return nullptr;
  }

  fs::path dir_;
  SourceManager sources_;
  DiagnosticEngine diags_;
};

constexpr std::string_view kLegMacro = R"X(<?xml version="1.0"?>
<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="leg" params="side">
    <link name="${side}_leg"/>
  </xacro:macro>
  <link name="base"/>
  <xacro:leg side="left"/>
</robot>
)X";

// XACRO: text a macro expands is placed where it is written (the body,
// line 4), in an expansion whose call site is line 7.
TEST_F(XacroFiles, ExpandedElementsArePlacedInTheMacroBodyAndRememberTheCall) {
  Write("r.urdf.xacro", kLegMacro);
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  auto doc = ToXmlDocument(*expansion, sources_);
  ASSERT_TRUE(doc);
  xml::XmlElement leg = doc->Root().FirstChild().NextSibling();
  ASSERT_TRUE(leg);
  EXPECT_EQ(leg.Attribute("name").value, "left_leg");
  const Loc at = leg.GetLoc();
  EXPECT_EQ(at.line, 4u);
  EXPECT_EQ(at.column, 5u);
  ASSERT_TRUE(sources_.IsExpansion(at.file));
  EXPECT_EQ(sources_.SpellingFile(at.file), expansion->file);
  EXPECT_EQ(sources_.ExpandedAt(at.file).line, 7u);
  EXPECT_EQ(sources_.ExpansionNote(at.file), "in expansion of macro 'leg'");
  // an attribute is placed in its element's file
  EXPECT_EQ(leg.Attribute("name").loc.file, at.file);
  EXPECT_EQ(leg.Attribute("name").loc.column, 11u);
  // a diagnostic there prints the body line, then the call as a note
  Diagnostic d{DiagKind::UnknownReference, Severity::Error, at, "something about the leg", {}};
  const std::string printed = FormatDiagnosticText(d, sources_);
  EXPECT_NE(printed.find("r.urdf.xacro:4:5: error: something about the leg"), std::string::npos)
      << printed;
  EXPECT_NE(printed.find("r.urdf.xacro:7:3: note: in expansion of macro 'leg'"), std::string::npos)
      << printed;
  const std::string json = FormatDiagnosticJson(d, sources_);
  EXPECT_NE(json.find(R"("expanded_from":[{"message":"in expansion of macro 'leg'")"),
            std::string::npos)
      << json;
}

// Nested calls: one note per call, innermost first.
TEST_F(XacroFiles, NestedMacroCallsGiveOneNotePerCallInnermostFirst) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="inner" params="">
    <link name="${undefined_name}"/>
  </xacro:macro>
  <xacro:macro name="outer" params="">
    <xacro:inner/>
  </xacro:macro>
  <xacro:outer/>
</robot>
)X");
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const std::string printed = Printed();
  const size_t error = printed.find("r.urdf.xacro:3:11: error: in '${undefined_name}'");
  const size_t inner = printed.find("r.urdf.xacro:6:5: note: in expansion of macro 'inner'");
  const size_t outer = printed.find("r.urdf.xacro:8:3: note: in expansion of macro 'outer'");
  ASSERT_NE(error, std::string::npos) << printed;
  ASSERT_NE(inner, std::string::npos) << printed;
  ASSERT_NE(outer, std::string::npos) << printed;
  EXPECT_LT(error, inner);
  EXPECT_LT(inner, outer);
}

TEST_F(XacroFiles, AnUndefinedPropertyIsLocatedWithDidYouMean) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="width" value="0.5"/>
  <link name="a"><visual><geometry><box size="${widht} 1 1"/></geometry></visual></link>
</robot>
)X");
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const Diagnostic* d = First(DiagKind::XacroError);
  ASSERT_TRUE(d) << Printed();
  EXPECT_EQ(d->loc.line, 3u);
  EXPECT_EQ(d->loc.column, 41u);
  EXPECT_NE(d->message.find("'widht'"), std::string::npos) << d->message;
  EXPECT_NE(d->message.find("did you mean 'width'?"), std::string::npos) << d->message;
}

TEST_F(XacroFiles, AnUnknownMacroAndAnUnknownArgGetDidYouMean) {
  Write("m.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="wheel" params=""><link name="w"/></xacro:macro>
  <xacro:wheal/>
</robot>
)X");
  EXPECT_FALSE(Expand("m.urdf.xacro"));
  EXPECT_NE(Printed().find("m.urdf.xacro:3:3: error: no macro named 'wheal' is defined; did you "
                           "mean 'wheel'?"),
            std::string::npos)
      << Printed();
  Write("a.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="prefix" default=""/>
  <link name="$(arg prefx)base"/>
</robot>
)X");
  EXPECT_FALSE(Expand("a.urdf.xacro"));
  EXPECT_NE(Printed().find("did you mean 'prefix'?"), std::string::npos) << Printed();
}

TEST_F(XacroFiles, ArgumentsWinOverDefaults) {
  Write("r.urdf.xacro", R"X(<robot name="$(arg name)" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="name" default="fallback"/>
  <xacro:arg name="size" default="2"/>
  <link name="l${2 * float('$(arg size)')}"/>
</robot>
)X");
  XacroOptions options;
  options.args = {{"name", "given"}};
  auto expansion = Expand("r.urdf.xacro", options);
  ASSERT_TRUE(expansion) << Printed();
  EXPECT_EQ(expansion->root->FindAttribute("name")->value, "given");
  EXPECT_EQ(expansion->root->FirstElementChild()->FindAttribute("name")->value, "l4.0");
}

TEST_F(XacroFiles, FindUsesThePackageMap) {
  Write("pkg/package.xml", "<package><name>demo</name></package>");
  Write("pkg/urdf/parts.xacro", R"X(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="from_package"/>
</robot>
)X");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="$(find demo)/urdf/parts.xacro"/>
</robot>
)X");
  assets::PackageMap packages;
  ASSERT_TRUE(packages.Add("demo", (dir_ / "pkg").string(), diags_));
  XacroOptions options;
  options.packages = &packages;
  auto expansion = Expand("r.urdf.xacro", options);
  ASSERT_TRUE(expansion) << Printed();
  EXPECT_EQ(expansion->root->FirstElementChild()->FindAttribute("name")->value, "from_package");
  ASSERT_EQ(expansion->dependencies.size(), 1u);
  EXPECT_EQ(fs::path(expansion->dependencies[0]).filename(), "parts.xacro");
}

// A file included again is not read again, yet each inclusion is its own
// place: an error in the second says it was included from the second include.
TEST_F(XacroFiles, EachInclusionOfAFileIsPlacedAtItsOwnInclude) {
  Write("part.xacro", R"X(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="${n}"/>
</robot>
)X");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="n" value="a"/>
  <xacro:include filename="part.xacro"/>
  <xacro:property name="n" remove="true"/>
  <xacro:include filename="part.xacro"/>
</robot>
)X");
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const Diagnostic* d = First(DiagKind::XacroError);
  ASSERT_TRUE(d) << Printed();
  EXPECT_EQ(fs::path(sources_.Path(d->loc.file)).filename(), "part.xacro");
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_EQ(sources_.IncludedFrom(d->loc.file).line, 5u);
  EXPECT_NE(Printed().find("in file included from " + (dir_ / "r.urdf.xacro").string() + ":5:"),
            std::string::npos)
      << Printed();
}

TEST_F(XacroFiles, AnIncludeCycleIsAnErrorAtTheInclude) {
  Write("a.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="b.xacro"/>
</robot>
)X");
  Write("b.xacro", R"X(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="a.xacro"/>
</robot>
)X");
  EXPECT_FALSE(Expand("a.xacro"));
  const Diagnostic* d = First(DiagKind::XacroError);
  ASSERT_TRUE(d) << Printed();
  EXPECT_EQ(fs::path(sources_.Path(d->loc.file)).filename(), "b.xacro");
  EXPECT_EQ(d->loc.line, 2u);
  EXPECT_NE(d->message.find("includes itself"), std::string::npos) << d->message;
  // the include chain is printed too
  EXPECT_NE(Printed().find("in file included from"), std::string::npos) << Printed();
}

TEST_F(XacroFiles, AMacroThatNeverStopsCallingItselfMeetsTheMacroDepthLimit) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="forever" params="n">
    <xacro:forever n="${n + 1}"/>
  </xacro:macro>
  <xacro:forever n="0"/>
</robot>
)X");
  Limits limits;
  limits.macro_depth = 50;
  sources_.set_limits(limits);
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const Diagnostic* d = First(DiagKind::LimitExceeded);
  ASSERT_TRUE(d) << Printed();
  EXPECT_EQ(d->loc.line, 3u);
  EXPECT_NE(d->message.find("--limit macro-depth=N"), std::string::npos) << d->message;
}

TEST_F(XacroFiles, AMacroThatDoublesItsOutputMeetsTheExpansionNodesLimit) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="twice" params="n">
    <xacro:if value="${n > 0}">
      <xacro:twice n="${n - 1}"/>
      <xacro:twice n="${n - 1}"/>
    </xacro:if>
    <link name="l"/>
  </xacro:macro>
  <xacro:twice n="40"/>
</robot>
)X");
  Limits limits;
  limits.expansion_nodes = 20'000;
  sources_.set_limits(limits);
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const Diagnostic* d = First(DiagKind::LimitExceeded);
  ASSERT_TRUE(d) << Printed();
  EXPECT_NE(d->message.find("--limit expansion-nodes=N"), std::string::npos) << d->message;
}

TEST_F(XacroFiles, SourceNestedTooDeepIsALimitError) {
  std::string text = "<robot name=\"r\">";
  for (int i = 0; i < 1200; ++i) text += "<a>";
  for (int i = 0; i < 1200; ++i) text += "</a>";
  text += "</robot>";
  Write("deep.urdf.xacro", text);
  EXPECT_FALSE(Expand("deep.urdf.xacro"));
  ASSERT_TRUE(First(DiagKind::LimitExceeded)) << Printed();
}

TEST_F(XacroFiles, AnEntityDeclarationIsRefused) {
  Write("e.urdf.xacro", R"X(<?xml version="1.0"?>
<!DOCTYPE robot [<!ENTITY x "xxxxxxxx">]>
<robot name="&x;"/>
)X");
  EXPECT_FALSE(Expand("e.urdf.xacro"));
  EXPECT_TRUE(First(DiagKind::EntityDeclaration)) << Printed();
}

TEST_F(XacroFiles, FatalIsALocatedErrorAndWarningALocatedWarning) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <w v="${xacro.warning('check', 3)}"/>
  <f v="${xacro.fatal('stop here')}"/>
</robot>
)X");
  EXPECT_FALSE(Expand("r.urdf.xacro"));
  const Diagnostic* warning = First(DiagKind::XacroWarning);
  ASSERT_TRUE(warning) << Printed();
  EXPECT_EQ(warning->loc.line, 2u);
  EXPECT_EQ(warning->message, "check 3");
  const Diagnostic* error = First(DiagKind::XacroError);
  ASSERT_TRUE(error) << Printed();
  EXPECT_EQ(error->loc.line, 3u);
  EXPECT_EQ(error->message, "stop here");
}

// Deliberate difference: xacro prints xacro.error's message and goes on;
// mdlc reports a located error, so the expansion goes on (later errors are
// reported too) but the compile fails.
TEST_F(XacroFiles, ErrorIsALocatedErrorAndTheExpansionGoesOn) {
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <a v="${xacro.error('first')}"/>
  <b v="${xacro.error('second')}"/>
</robot>
)X");
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion);
  ASSERT_EQ(diags_.error_count(), 2u) << Printed();
  EXPECT_EQ(diags_.diagnostics()[0].message, "first");
  EXPECT_EQ(diags_.diagnostics()[0].loc.line, 2u);
  EXPECT_EQ(diags_.diagnostics()[1].loc.line, 3u);
}

// xacro's deprecated bare names still work, with a warning naming the new one.
TEST_F(XacroFiles, DeprecatedBareNamesWarnOncePerName) {
  Write("units.yaml", "a: 1\n");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <a v="${sorted([2, 1])}" w="${sorted([3])}" y="${load_yaml('units.yaml')['a']}"/>
</robot>
)X");
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  Node* a = expansion->root->FirstElementChild();
  EXPECT_EQ(a->FindAttribute("v")->value, "[1, 2]");
  EXPECT_EQ(a->FindAttribute("y")->value, "1");
  size_t warnings = 0;
  for (const Diagnostic& d : diags_.diagnostics()) {
    if (d.kind != DiagKind::XacroWarning) continue;
    ++warnings;
    EXPECT_EQ(d.loc.line, 2u);
  }
  EXPECT_EQ(warnings, 2u) << Printed();
  EXPECT_NE(Printed().find("use python.sorted"), std::string::npos) << Printed();
  EXPECT_NE(Printed().find("use xacro.load_yaml"), std::string::npos) << Printed();
}

// Deliberate difference: ros/xacro 2 cannot say $(dirname) (it has no file
// name to give) and fails; mdlc gives the folder of the file being read, as
// ROS 1's xacro does. An included file gets its own folder.
TEST_F(XacroFiles, DirnameIsTheFolderOfTheFileBeingRead) {
  Write("sub/part.xacro", R"X(<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <inner dir="$(dirname)"/>
</robot>
)X");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <outer dir="$(dirname)"/>
  <xacro:include filename="sub/part.xacro"/>
</robot>
)X");
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  Node* outer = expansion->root->FirstElementChild();
  Node* inner = outer->NextElementSibling();
  EXPECT_EQ(fs::path(outer->FindAttribute("dir")->value), fs::absolute(dir_).lexically_normal());
  EXPECT_EQ(fs::path(inner->FindAttribute("dir")->value),
            fs::absolute(dir_ / "sub").lexically_normal());
}

// Deliberate difference: the unit tags later xacro releases read (ros/xacro
// 2.0.10 knows !degrees and !radians only).
TEST_F(XacroFiles, YamlUnitTagsOfLaterXacroReleasesAreRead) {
  Write("units.yaml", "a: !millimeters 250\nb: !inches 2\nc: !degrees 90\n");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:property name="u" value="${xacro.load_yaml('units.yaml')}"/>
  <v a="${u.a}" b="${u['b']}" c="${u.c}"/>
</robot>
)X");
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  Node* v = expansion->root->FirstElementChild();
  EXPECT_EQ(v->FindAttribute("a")->value, "0.25");
  EXPECT_EQ(v->FindAttribute("b")->value, "0.0508");
  EXPECT_EQ(v->FindAttribute("c")->value, "1.5707963267948966");
}

TEST_F(XacroFiles, WrittenXmlCarriesTheBannerAndTheExpandedTree) {
  Write("r.urdf.xacro", kLegMacro);
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  const std::string xml = WriteXml(*expansion, "r.urdf.xacro");
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\" ?>\n", 0), 0u);
  EXPECT_NE(xml.find("autogenerated by xacro from r.urdf.xacro"), std::string::npos);
  EXPECT_NE(xml.find("<link name=\"left_leg\"/>"), std::string::npos) << xml;
  EXPECT_EQ(xml.find("xacro:"), std::string::npos) << xml;
  // and it reads back as XML
  SourceManager again;
  DiagnosticEngine diags;
  auto doc = xml::XmlDocument::Parse(again.AddBuffer("out.urdf", xml), again, diags);
  ASSERT_TRUE(doc);
  EXPECT_EQ(doc->Root().Name(), "robot");
}

TEST(XacroPath, XacroFilesAreNamedByTheirLastExtension) {
  EXPECT_TRUE(IsXacroPath("robot.urdf.xacro"));
  EXPECT_TRUE(IsXacroPath("robot.xacro"));
  EXPECT_TRUE(IsXacroPath("dir.xacro/robot.sdf.xacro"));
  EXPECT_FALSE(IsXacroPath("robot.urdf"));
  EXPECT_FALSE(IsXacroPath("robot.xacro.urdf"));
}

}  // namespace
}  // namespace mdlc::xacro

namespace mdlc::xacro {
namespace {

std::string Params(std::string_view text) {
  std::string out;
  while (!text.empty()) {
    const MacroParam p = NextMacroParam(text);
    if (p.name.empty()) break;
    out += p.name;
    if (p.has_default) {
      out += ":=";
      if (p.forward) out += "^";
      out += p.default_text ? "[" + *p.default_text + "]" : "-";
    }
    out += " ";
  }
  return out;
}

// The grammar ros/xacro reads `params` with (a regular expression there);
// every expected value is what that expression gives.
TEST(XacroMacroParams, ReadAsXacroReadsThem) {
  EXPECT_EQ(Params("a b  c"), "a b c ");
  EXPECT_EQ(Params("a:=1 b=2 c := 3"), "a:=[1] b:=[2] c:=[3] ");
  EXPECT_EQ(Params("*origin **content name"), "*origin **content name ");
  EXPECT_EQ(Params("x:=^ y:=^|0.5 z:=^|${a b}"), "x:=^- y:=^[0.5] z:=^[${a b}] ");
  // a blank after := belongs to it: the default is what follows
  EXPECT_EQ(Params("d:= e:=''"), "d:=[e:=''] ");
  EXPECT_EQ(Params("d:="), "d:=- ");
  EXPECT_EQ(Params("f:='a b' g:=\"c d\" h:=x'y z'w"), "f:=['a b'] g:=[\"c d\"] h:=[x'y z'w] ");
  // $(...) is one default only when a blank follows its ')'; else blanks cut it
  EXPECT_EQ(Params("p:=$(find pkg)/x.yaml q:=${1 + 2}"), "p:=[$(find] pkg)/x.yaml q:=[${1 + 2}] ");
  EXPECT_EQ(Params("p:=$(find pkg) q"), "p:=[$(find pkg)] q ");
  EXPECT_EQ(Params("r:=${a}${b} s"), "r:=[${a}${b}] s ");
}

// The inputs that hung and overflowed the stack in a regular expression
// matcher (tests/fuzz/regressions/xacro/) read in one pass.
TEST(XacroMacroParams, UnbalancedQuotesAndLongDefaultsReadInOnePass) {
  EXPECT_EQ(Params("a:='unclosed b"), "a:='unclosed b ");
  const std::string quotes(100'000, '\'');
  std::string_view rest_of_quotes = quotes;
  NextMacroParam(rest_of_quotes);  // a name of quotes: read in one pass, whatever it gives
  EXPECT_EQ(Params("k:='$(find p)/y1e308   q:='x'"), "k:=['$(find p)/y1e308   q:='x'] ");
  const std::string long_default = "a:='" + std::string(200'000, 'x') + "' b";
  std::string_view rest = long_default;
  const MacroParam p = NextMacroParam(rest);
  EXPECT_EQ(p.name, "a");
  ASSERT_TRUE(p.default_text);
  EXPECT_EQ(p.default_text->size(), 200'002u);
  EXPECT_EQ(rest, "b");
}

TEST_F(XacroFiles, IncludePatternsMatchAsGlobDoes) {
  Write("parts/a1.xacro", "<robot><link name=\"a1\"/></robot>");
  Write("parts/a2.xacro", "<robot><link name=\"a2\"/></robot>");
  Write("parts/b.xacro", "<robot><link name=\"b\"/></robot>");
  Write("r.urdf.xacro", R"X(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:include filename="parts/a[0-9].xacro"/>
  <xacro:include filename="parts/[!a]*.xacro"/>
  <xacro:include filename="[z-a]/x.xacro"/>
</robot>
)X");
  auto expansion = Expand("r.urdf.xacro");
  ASSERT_TRUE(expansion) << Printed();
  std::string names;
  for (Node* n = expansion->root->FirstElementChild(); n; n = n->NextElementSibling()) {
    names += n->FindAttribute("name")->value + " ";
  }
  EXPECT_EQ(names, "a1 a2 b ");
  // the reversed range matches nothing, with a warning
  ASSERT_TRUE(First(DiagKind::XacroWarning)) << Printed();
  EXPECT_EQ(First(DiagKind::XacroWarning)->loc.line, 4u);
}

}  // namespace
}  // namespace mdlc::xacro
