// The writers' collision filters (COMMON-051/052/054, EXT-040). URDF and
// SDFormat: one group per declaration of the compiled scene (a joint's pair,
// a welded composite, a group ignoring itself) and two for a group that
// ignores another, so a composite of N links is written in N members, not
// N(N-1)/2 groups (issue 16). MJCF: no <exclude> within a welded composite.
// Read back, the written filters are exactly the original pairs; the world,
// which no group can name, and SDFormat pairs across top-level models are
// reported.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backend/writers/filter_declarations.h"
#include "backend/writers/writer.h"
#include "tests/unit/compile_test_util.h"
#include "tests/unit/writers/written.h"

namespace mdlc {
namespace {

using testing::CompiledText;
using testing::Count;
using testing::Written;

constexpr const char* kBox =
    "<collision><geometry><box size='0.1 0.1 0.1'/></geometry></collision>";

/// `n` links welded in a chain, all in one group that ignores itself, and a
/// hand on a revolute joint whose group ignores the first link's.
std::string WeldedGroupUrdf(int n) {
  std::string out = "<robot name='r' xmlns:drake='http://drake.mit.edu'>\n";
  for (int i = 0; i < n; ++i) {
    out += fmt::format("  <link name='l{}'>{}</link>\n", i, kBox);
    if (i > 0) {
      out += fmt::format(
          "  <joint name='w{0}' type='fixed'><parent link='l{1}'/><child link='l{0}'/></joint>\n",
          i, i - 1);
    }
  }
  out += fmt::format("  <link name='hand'>{}</link>\n", kBox);
  out += fmt::format(
      "  <joint name='wrist' type='revolute'><parent link='l{}'/><child link='hand'/>"
      "<axis xyz='0 0 1'/><limit effort='0' lower='-1' upper='1' velocity='1'/></joint>\n",
      n - 1);
  out += "  <drake:collision_filter_group name='all'>\n";
  for (int i = 0; i < n; ++i) out += fmt::format("    <drake:member link='l{}'/>\n", i);
  out += "    <drake:ignored_collision_filter_group name='all'/>\n";
  out += "  </drake:collision_filter_group>\n";
  out += "  <drake:collision_filter_group name='base'><drake:member link='l0'/>"
         "<drake:ignored_collision_filter_group name='tool'/></drake:collision_filter_group>\n";
  out += "  <drake:collision_filter_group name='tool'><drake:member link='hand'/>"
         "</drake:collision_filter_group>\n";
  return out + "</robot>\n";
}

TEST(WrittenFilterGroups, AWeldedGroupIsOneGroupAndReadsBackTheSamePairs) {
  constexpr int kLinks = 300;  // 44,850 pairs within the composite
  CompiledText original("welded.urdf", WeldedGroupUrdf(kLinks));
  ASSERT_TRUE(original.ok()) << original.Messages();
  const nlohmann::json filters = original.Json()["collision_filters"];
  ASSERT_EQ(filters.size(), size_t{kLinks * (kLinks - 1) / 2 + 2});  // and wrist, base-tool
  for (Format to : {Format::Urdf, Format::Sdf}) {
    SCOPED_TRACE(FormatName(to));
    DiagnosticEngine diags;
    const std::string text = Written(original, to, diags);
    for (const Diagnostic& d : diags.diagnostics()) ADD_FAILURE() << d.message;
    // the wrist's pair, the composite and base-tool (two groups); the weld
    // pairs lie within the composite, and group 'all' is the composite again
    EXPECT_EQ(Count(text, "<drake:collision_filter_group "), 4u);
    EXPECT_EQ(Count(text, "<drake:member"), size_t{2 + kLinks + 2});
    CompiledText reread(to == Format::Urdf ? "reread.urdf" : "reread.sdf", text);
    ASSERT_TRUE(reread.ok()) << reread.Messages();
    EXPECT_EQ(reread.Json()["collision_filters"], filters);
  }
}

TEST(WrittenFilterGroups, MjcfExcludesNoPairWithinAWeldedComposite) {
  constexpr int kLinks = 300;
  CompiledText original("welded.urdf", WeldedGroupUrdf(kLinks));
  ASSERT_TRUE(original.ok()) << original.Messages();
  DiagnosticEngine diags;
  const std::string text = Written(original, Format::Mjcf, diags);
  for (const Diagnostic& d : diags.diagnostics()) {  // MJCF joints hold no velocity limits
    EXPECT_EQ(d.message.find("collision"), std::string::npos) << d.message;
  }
  // the composite is bodies nested without joints: MuJoCo and mdlc's reader
  // filter it; the wrist's pair and base-tool are written
  EXPECT_EQ(Count(text, "<exclude "), 2u) << text.substr(text.find("<contact>"));
  CompiledText reread("reread.xml", text);
  ASSERT_TRUE(reread.ok()) << reread.Messages();
  EXPECT_EQ(reread.Json()["collision_filters"], original.Json()["collision_filters"]);
}

/// Two top-level models of two welded links each, welded to each other by
/// a world joint.
constexpr const char* kTwoModelWorld = R"(<sdf version='1.10'>
  <world name='w'>
    <model name='m1'>
      <link name='a'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision></link>
      <link name='b'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision></link>
      <joint name='ab' type='fixed'><parent>a</parent><child>b</child></joint>
    </model>
    <model name='m2'>
      <link name='c'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision></link>
      <link name='d'><collision name='c'><geometry><box><size>1 1 1</size></box></geometry></collision></link>
      <joint name='cd' type='fixed'><parent>c</parent><child>d</child></joint>
    </model>
    <joint name='bridge' type='fixed'><parent>m1::b</parent><child>m2::c</child></joint>
  </world>
</sdf>
)";

TEST(WrittenFilterGroups, SdformatSplitsACompositeAtTopLevelModels) {
  CompiledText original("world.sdf", kTwoModelWorld);
  ASSERT_TRUE(original.ok()) << original.Messages();
  // one composite of the four links: six pairs
  const nlohmann::json filters = original.Json()["collision_filters"];
  ASSERT_EQ(filters.size(), 6u);
  DiagnosticEngine diags;
  const std::string text = Written(original, Format::Sdf, diags);
  // each model keeps its half of the composite; the pairs across them are
  // reported once (the bridge's pair lies within the composite)
  std::vector<std::string> lossy;
  for (const Diagnostic& d : diags.diagnostics()) {
    ASSERT_EQ(d.kind, DiagKind::Lossy) << d.message;
    EXPECT_TRUE(d.loc.valid()) << d.message;
    lossy.push_back(d.message);
  }
  EXPECT_EQ(lossy, (std::vector<std::string>{
                       "the collision filter of link 'a' between different top-level models "
                       "('m1', 'm2') is dropped: a collision filter group holds the links of "
                       "one model; it is kept within each model"}));
  EXPECT_EQ(Count(text, "<drake:collision_filter_group "), 2u);
  // the world joint welds the models again, so the composite comes back whole
  CompiledText reread("reread.sdf", text);
  ASSERT_TRUE(reread.ok()) << reread.Messages();
  EXPECT_EQ(reread.Json()["collision_filters"], filters);
}

BodyId B(uint32_t index) { return BodyId(index); }

TEST(FilterDeclarations, TheWorldIsLeftOutAndReportedOncePerBody) {
  const BodyId world = B(0);
  backend::CollisionFilters filters(
      {{world, B(1)}, {B(2), B(3)}, {B(5), B(6)}},           // the last within a set
      {{world, B(1), B(4)}, {B(5), B(6)}, {B(6), B(5)}},  // the last declared twice
      {{{world, B(7)}, {B(8), B(9)}},
       {{B(7)}, {B(7)}},      // a body never with itself: no pair
       {{world}, {B(1), world}}});  // only pairs with the world
  std::vector<size_t> reported;
  const std::vector<writers::FilterDeclaration> out = writers::DeclarationsWithoutWorld(
      filters, [&](BodyId b) { reported.push_back(b.index()); });
  EXPECT_EQ(reported, (std::vector<size_t>{1, 4, 8, 9}));
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].members, (std::vector<BodyId>{B(2), B(3)}));
  EXPECT_TRUE(out[0].ignores_itself());
  EXPECT_EQ(out[1].members, (std::vector<BodyId>{B(1), B(4)}));
  EXPECT_EQ(out[2].members, (std::vector<BodyId>{B(5), B(6)}));
  EXPECT_EQ(out[3].members, (std::vector<BodyId>{B(7)}));
  EXPECT_EQ(out[3].ignored, (std::vector<BodyId>{B(8), B(9)}));
}

}  // namespace
}  // namespace mdlc
