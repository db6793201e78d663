// What the writers make of deep nesting (issue 16). A kinematic chain
// 10,000 links long: MJCF nests each body in its parent, and the writer
// walks the tree in a loop (10,000 recursive calls overflowed the stack)
// and indents at most 32 levels (indenting each level made the file grow
// as the square of the chain: 610 MB for these 10,000 links, 14 MB now).
// Models nested 1,000 deep: SDFormat nests each model in its parent, and
// the writer holds a model as its parent and its own name (the full scoped
// names it held cost the square of the depth: 30 s and 3.8 GB for the
// benchmark's 10,000 levels, 0.6 s and 163 MB now).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "tests/unit/compile_test_util.h"
#include "tests/unit/writers/written.h"

namespace mdlc {
namespace {

using testing::CompiledText;
using testing::Count;
using testing::Written;

std::string ChainUrdf(int n) {
  std::string out = "<robot name='chain'>\n  <link name='l0'/>\n";
  for (int i = 1; i < n; ++i) {
    out += fmt::format(
        "  <link name='l{0}'><inertial><mass value='1'/>"
        "<inertia ixx='1' iyy='1' izz='1' ixy='0' ixz='0' iyz='0'/></inertial></link>\n"
        "  <joint name='j{0}' type='continuous'><parent link='l{1}'/><child link='l{0}'/>"
        "<origin xyz='0 0 0.1'/><axis xyz='0 0 1'/></joint>\n",
        i, i - 1);
  }
  return out + "</robot>\n";
}

TEST(DeepNesting, A10000LinkChainWritesAsNestedMjcfAndReadsBack) {
  constexpr int kLinks = 10000;
  CompiledText chain("chain.urdf", ChainUrdf(kLinks));
  ASSERT_TRUE(chain.ok()) << chain.Messages();
  DiagnosticEngine diags;
  const std::string text = Written(chain, Format::Mjcf, diags);
  // nothing lost; the one note says the root link floats (issue 58)
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].kind, DiagKind::FreeBase);
  // every line indented 32 levels at most: the size grows with the chain
  size_t widest = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    widest = std::max(widest, line.find_first_not_of(' '));
  }
  EXPECT_EQ(widest, 2u * 32);
  EXPECT_LT(text.size(), size_t{400} * kLinks);

  CompiledText reread("chain.xml", text);
  ASSERT_TRUE(reread.ok()) << reread.Messages();
  const nlohmann::json bodies = reread.Json()["bodies"];
  EXPECT_EQ(bodies.size(), chain.Json()["bodies"].size());
  // the last link sits 0.1 m above the one before it, 9,999 times over
  EXPECT_NEAR(bodies.back()["X_WB"]["p"][2].get<double>(), 0.1 * (kLinks - 1), 1e-9);
}

// model m{i} holds link l and model m{i+1}, a revolute joint between the
// two links; ten frames and one more joint name links far below
std::string NestedSdf(int depth) {
  std::string out = "<sdf version='1.9'>\n";
  std::string path;  // "m1::m2::...", the scope below the top model
  for (int i = 0; i < depth; ++i) {
    out += fmt::format(
        "<model name='m{0}'><pose>0 0 0.1 0 0 0</pose>"
        "<link name='l'><inertial><mass>1</mass></inertial></link>\n",
        i);
    if (i + 1 < depth) {
      out += fmt::format(
          "<joint name='j' type='revolute'><parent>l</parent><child>m{0}::l</child>"
          "<axis><xyz>0 0 1</xyz></axis></joint>\n",
          i + 1);
    }
  }
  for (int i = depth - 1; i >= 0; --i) out += "</model>\n";
  return out + "</sdf>\n";
}

TEST(DeepNesting, Models1000DeepWriteAsNestedSdformatAndReadBack) {
  constexpr int kDepth = 1000;
  CompiledText nested("nested.sdf", NestedSdf(kDepth));
  ASSERT_TRUE(nested.ok()) << nested.Messages();
  DiagnosticEngine diags;
  const std::string text = Written(nested, Format::Sdf, diags);
  EXPECT_TRUE(diags.diagnostics().empty());
  // a model a level, each naming its own link and its child model's
  EXPECT_EQ(Count(text, "<model "), size_t{kDepth});
  // linear: local names, and indentation capped at 32 levels
  EXPECT_LT(text.size(), size_t{2500} * kDepth);

  CompiledText reread("nested.sdf", text);
  ASSERT_TRUE(reread.ok()) << reread.Messages();
  const nlohmann::json before = nested.Json(), after = reread.Json();
  EXPECT_EQ(after["model_instances"], before["model_instances"]);
  ASSERT_EQ(after["bodies"].size(), before["bodies"].size());
  for (size_t b = 0; b < before["bodies"].size(); ++b) {
    EXPECT_EQ(after["bodies"][b]["name"], before["bodies"][b]["name"]);
    EXPECT_EQ(after["bodies"][b]["model_instance"], before["bodies"][b]["model_instance"]);
  }
  // the innermost link sits 0.1 m above its parent's, 1,000 levels down
  EXPECT_NEAR(after["bodies"].back()["X_WB"]["p"][2].get<double>(), 0.1 * kDepth, 1e-9);
  EXPECT_EQ(after["joints"].size(), before["joints"].size());
}

// Models nested 30,000 deep, each level's link floating: the writer opens
// and closes the levels in a loop (recursing per level overflowed the stack
// at 20,000), and places each floating link's joint in its own model
// without walking up to the world (which made the levels cost N^2).
TEST(DeepNesting, FloatingModels30000DeepWriteAsNestedSdformat) {
  constexpr int kDepth = 30000;
  std::string text = "<sdf version='1.9'>\n";
  for (int i = 0; i < kDepth; ++i) {
    text += fmt::format("<model name='m{}'><link name='l'><inertial><mass>1</mass>"
                        "</inertial></link>\n",
                        i);
  }
  for (int i = 0; i < kDepth; ++i) text += "</model>\n";
  Limits limits;
  limits.model_depth = kDepth;  // past the default, which bounds what outputs print
  CompiledText nested("floating.sdf", text + "</sdf>\n", limits);
  ASSERT_TRUE(nested.ok()) << nested.Messages();
  DiagnosticEngine diags;
  const std::string written = Written(nested, Format::Sdf, diags);
  EXPECT_TRUE(diags.diagnostics().empty());
  EXPECT_EQ(Count(written, "<model "), size_t{kDepth});
  EXPECT_EQ(Count(written, "</model>"), size_t{kDepth});
  EXPECT_LT(written.size(), size_t{2500} * kDepth);
}

}  // namespace
}  // namespace mdlc
