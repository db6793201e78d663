// mdlc's YAML tree (frontend/directives/yaml_tree.h) against yaml-cpp's own
// node graph, YAML::Load, which the directives reader used before it (DMD-001):
// the same kinds, tags, scalars, places and children, in the same order, on
// hand-made edge cases, on every YAML file of the project and, when present,
// of the corpus; and the same errors, at the same places, on broken YAML.
#include "frontend/directives/yaml_tree.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/corpus/shared_corpus.h"
#include "tests/unit/files_under.h"

namespace mdlc::frontend::yaml {
namespace {

// Compares one node and everything under it; counts the nodes compared.
// Aliases are followed, so a depth bound stops a node that holds itself.
int CompareNode(const Node& ours, const YAML::Node& theirs, const std::string& where, int depth) {
  if (depth > 300) return 0;
  const std::string at = where + " (line " + std::to_string(ours.line()) + ")";
  const YAML::Mark mark = theirs.Mark();
  if (mark.is_null()) {
    EXPECT_EQ(ours.line(), 0u) << at;
  } else {
    EXPECT_EQ(ours.line(), static_cast<uint32_t>(mark.line + 1)) << at;
    EXPECT_EQ(ours.column(), static_cast<uint32_t>(mark.column + 1)) << at;
  }
  int compared = 1;
  switch (theirs.Type()) {
    case YAML::NodeType::Undefined:
      ADD_FAILURE() << "yaml-cpp made an undefined node at " << at;
      return compared;
    case YAML::NodeType::Null:
      EXPECT_TRUE(ours.IsNull()) << at;
      EXPECT_EQ(ours.Tag(), theirs.Tag()) << at;
      return compared;
    case YAML::NodeType::Scalar:
      EXPECT_TRUE(ours.IsScalar()) << at;
      EXPECT_EQ(ours.Tag(), theirs.Tag()) << at;
      EXPECT_EQ(ours.Scalar(), theirs.Scalar()) << at;
      return compared;
    case YAML::NodeType::Sequence: {
      EXPECT_TRUE(ours.IsSequence()) << at;
      EXPECT_EQ(ours.Tag(), theirs.Tag()) << at;
      EXPECT_EQ(ours.size(), theirs.size()) << at;
      if (!ours.IsSequence() || ours.size() != theirs.size()) return compared;
      size_t i = 0;
      for (const Node item : ours.Items()) {
        compared += CompareNode(item, theirs[i], at + "[" + std::to_string(i) + "]", depth + 1);
        ++i;
      }
      return compared;
    }
    case YAML::NodeType::Map: {
      EXPECT_TRUE(ours.IsMap()) << at;
      EXPECT_EQ(ours.Tag(), theirs.Tag()) << at;
      EXPECT_EQ(ours.size(), theirs.size()) << at;
      if (!ours.IsMap() || ours.size() != theirs.size()) return compared;
      auto it = theirs.begin();
      for (const Entry entry : ours.Entries()) {
        const YAML::Node key = it->first;
        const YAML::Node value = it->second;
        compared += CompareNode(entry.first, key, at + " key", depth + 1);
        compared += CompareNode(entry.second, value,
                                at + "." + (key.IsScalar() ? key.Scalar() : "?"), depth + 1);
        ++it;
      }
      return compared;
    }
  }
  return compared;
}

// Loads `text` both ways; compares the trees, or the errors. Returns the
// nodes compared (0 when both rejected the text).
int CompareText(const std::string& text, const std::string& name) {
  std::unique_ptr<Document> ours;
  std::string our_error;
  try {
    ours = Document::Load(text);
  } catch (const YAML::Exception& e) {
    our_error = std::to_string(e.mark.line) + ":" + std::to_string(e.mark.column) + ": " + e.msg;
  }
  YAML::Node theirs;
  std::string their_error;
  try {
    theirs = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    their_error = std::to_string(e.mark.line) + ":" + std::to_string(e.mark.column) + ": " + e.msg;
  }
  EXPECT_EQ(our_error, their_error) << name;
  if (!ours || !their_error.empty()) return 0;
  return CompareNode(ours->root(), theirs, name, 0);
}

TEST(YamlTreeOracleTest, EdgeCasesMatchYamlCpp) {
  const char* texts[] = {
      "directives:\n- add_model:\n    name: a\n    file: package://x/a.urdf\n",
      // anchors, aliases and merge keys
      "base: &b {x: 1, y: 2}\nderived:\n  <<: *b\n  y: 3\n",
      "a: &a {p: 1}\nb: &b {q: 2}\nc:\n  <<: [*a, *b]\n  r: 3\n",
      "a: &x hello\nb: *x\nc: [*x, *x]\n",
      "s: &s [1, 2, {k: v}]\nt: [*s, *s]\n",
      // tags: written, quoted, plain, core schema
      "r: !Rpy {deg: [0, 0, 90]}\ns: !Deterministic {value: 1.5}\nq: 'quoted'\nd: \"double\"\n"
      "p: plain\nt: !!str 5\nu: !Uniform {min: 0, max: 1}\n",
      // nulls in every spelling, and empty values
      "a: ~\nb: null\nc:\nd: Null\ne: ''\nf: NULL\ng: [~, null]\nh: {x: ~}\n",
      "- \n- ~\n-\n",
      // empty documents
      "", "# only a comment\n", "---\n", "---\n...\n", "  \n\n",
      // only the first document is read
      "a: 1\n---\nb: 2\n",
      // block scalars
      "a: |\n  line1\n  line2\nb: >\n  folded\n  text\nc: |-\n  kept\n",
      // a key written twice stays twice, in order
      "a: 1\na: 2\nb: 3\n",
      // a key that is not a scalar
      "? [a, b]\n: c\n? {k: v}\n: d\n",
      // nested and flow collections
      "- - 1\n  - 2\n- [3, [4, 5]]\n- {a: [6, {b: 7}]}\n",
      // text outside ASCII, escapes, special numbers
      "name: \"\\u00e9t\\u00e9\"\nother: \xC3\xA9t\xC3\xA9\nn: [.inf, -.inf, .nan, 1e3, 0x1F]\n",
      // Windows line ends and a byte-order mark
      "a: 1\r\nb:\r\n  - 2\r\n  - c\r\n", "\xEF\xBB\xBF" "a: 1\n",
      // text yaml-cpp forgives: read as it reads it
      "key: 'unterminated\n", "- a\nb: c\n",
      // comments everywhere
      "# head\na: 1 # tail\n# between\nb: # before value\n  - 2\n",
  };
  int compared = 0;
  for (const char* text : texts) compared += CompareText(text, std::string("text: ") + text);

  std::string deep;  // deep, but under yaml-cpp's depth guard
  for (int i = 0; i < 200; ++i) deep += "[";
  for (int i = 0; i < 200; ++i) deep += "]";
  compared += CompareText(deep, "200 nested lists");
  std::string wide = "items:\n";
  for (int i = 0; i < 2000; ++i) wide += "- {name: item_" + std::to_string(i) + ", v: [1, 2]}\n";
  compared += CompareText(wide, "2000 items");
  compared += CompareText("long: " + std::string(20000, 'x') + "\n", "a long scalar");
  EXPECT_GE(compared, 10000);
}

TEST(YamlTreeOracleTest, BrokenYamlFailsAsInYamlCpp) {
  std::string too_deep;  // past yaml-cpp's depth guard
  for (int i = 0; i < 5000; ++i) too_deep += "[";
  const std::string texts[] = {
      "a: [1, 2\n", "a: *missing\n", "a:\n  - b\n c: d\n", "{a: 1", "a: b: c\n", "&a &b x\n",
      too_deep,
  };
  for (const std::string& text : texts) {
    EXPECT_THROW(Document::Load(text), YAML::Exception) << text.substr(0, 40);
    EXPECT_EQ(CompareText(text, "broken: " + text.substr(0, 40)), 0);
  }
}

// Compares every YAML file under `roots`; returns {files, nodes}.
std::pair<int, int> CompareFilesUnder(const std::vector<std::filesystem::path>& roots) {
  int files = 0;
  int nodes = 0;
  testing::ForEachFileUnder(roots, {".yaml", ".yml"},
                            [&](const std::string& path, const std::string& text) {
                              ++files;
                              nodes += CompareText(text, path);
                            });
  return {files, nodes};
}

TEST(YamlTreeOracleTest, EveryProjectYamlFileMatchesYamlCpp) {
  const std::filesystem::path tests = std::filesystem::path(MDLC_TEST_MODELS).parent_path();
  auto [files, nodes] = CompareFilesUnder({tests, std::filesystem::path(MDLC_EXAMPLES_DIR)});
  EXPECT_GE(files, 15);
  EXPECT_GE(nodes, 200);
}

TEST(YamlTreeOracleTest, EveryCorpusYamlFileMatchesYamlCpp) {
  const std::filesystem::path corpus = corpus_test::Corpus();
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << "no corpus beside the project";
  auto [files, nodes] = CompareFilesUnder({corpus});
  EXPECT_GE(files, 20);
  EXPECT_GE(nodes, 500);
}

}  // namespace
}  // namespace mdlc::frontend::yaml
