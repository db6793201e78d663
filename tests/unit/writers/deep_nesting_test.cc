// What the writers make of a kinematic chain 10,000 links long (issue 16).
// MJCF nests each body in its parent: the writer walks the tree in a loop
// (10,000 recursive calls overflowed the stack), and indents at most 32
// levels (indenting each level made the file grow as the square of the
// chain: 610 MB for these 10,000 links, 14 MB now).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "backend/writers/writer.h"
#include "tests/unit/compile_test_util.h"

namespace mdlc {
namespace {

using testing::CompiledText;

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
  writers::WriteOptions options;
  options.to = Format::Mjcf;
  const std::optional<std::string> text =
      writers::Write(chain.model(), chain.module(), options, diags);
  ASSERT_TRUE(text.has_value());
  EXPECT_TRUE(diags.diagnostics().empty());
  // every line indented 32 levels at most: the size grows with the chain
  size_t widest = 0;
  std::istringstream lines(*text);
  for (std::string line; std::getline(lines, line);) {
    widest = std::max(widest, line.find_first_not_of(' '));
  }
  EXPECT_EQ(widest, 2u * 32);
  EXPECT_LT(text->size(), size_t{400} * kLinks);

  CompiledText reread("chain.xml", *text);
  ASSERT_TRUE(reread.ok()) << reread.Messages();
  const nlohmann::json bodies = reread.Json()["bodies"];
  EXPECT_EQ(bodies.size(), chain.Json()["bodies"].size());
  // the last link sits 0.1 m above the one before it, 9,999 times over
  EXPECT_NEAR(bodies.back()["X_WB"]["p"][2].get<double>(), 0.1 * (kLinks - 1), 1e-9);
}

}  // namespace
}  // namespace mdlc
