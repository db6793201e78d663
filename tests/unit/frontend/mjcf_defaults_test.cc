// mjcf_defaults_test.cc - default class chains (MJCF-011, MJCF-012): what an
// element inherits from classes nested deeper than the layers a lookup
// walks before it asks the far layers (DefaultLayer::kShortWalk), and that
// an answer the far layers remember is the same from every class below.
// MuJoCo's own reading of such a chain is checked by the oracle model
// tests/models/mjcf/oracle/defaults_deep_chain.xml.
#include "frontend/mjcf/mjcf_defaults.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::frontend::mjcf {
namespace {

constexpr int kDepth = 30;  // classes c0 (outermost) .. c29, well past the short walk
static_assert(kDepth > 3 * DefaultLayer::kShortWalk);

// `<default>` with classes c0..c{kDepth-1} nested in each other; class k
// holds `<geom>` with the attributes `geom(k)` gives (main: k = -1), and
// `<joint>` only where `joint(k)` gives some.
template <typename GeomAttributes, typename JointAttributes>
std::string NestedDefaults(GeomAttributes geom, JointAttributes joint) {
  auto kinds = [&](int k) {
    std::string out = fmt::format("<geom {}/>", geom(k));
    if (std::string j = joint(k); !j.empty()) out += fmt::format("<joint {}/>", j);
    return out;
  };
  std::string xml = "<default>" + kinds(-1);
  for (int k = 0; k < kDepth; ++k) xml += fmt::format("<default class='c{}'>{}", k, kinds(k));
  for (int k = 0; k < kDepth; ++k) xml += "</default>";
  return xml + "</default>";
}

class DeepDefaults : public ::testing::Test {
 protected:
  void Read(const std::string& xml) {
    doc_ = xml::XmlDocument::Parse(sources_.AddBuffer("defaults.xml", xml), sources_, diags_);
    ASSERT_NE(doc_, nullptr);
    defaults_.Read(doc_->Root(), diags_);
    ASSERT_FALSE(diags_.has_errors());
  }
  const DefaultLayer* Geoms(int k) const {
    return defaults_.Layers(defaults_.IndexOf(fmt::format("c{}", k)), "geom");
  }

  SourceManager sources_;
  DiagnosticEngine diags_;
  std::unique_ptr<xml::XmlDocument> doc_;
  DefaultClasses defaults_;
};

// MJCF-012: the nearest class that writes an attribute gives it, at any
// depth, and its level counts the layers up to it.
TEST_F(DeepDefaults, Mjcf012NearestWriterAtAnyDepth) {
  Read(NestedDefaults(
      [](int k) {
        if (k == -1) return std::string("contype='7' density='100'");
        if (k == 4) return std::string("density='104'");
        return fmt::format("rgba='0 0 0 {}'", k);
      },
      [](int) { return std::string(); }));
  // asked first from the deepest class, then from classes whose walk ends
  // on layers the first answer left remembered, then again
  for (int k : {29, 15, 21, 9, 8, 7, 0, 29}) {
    SCOPED_TRACE(k);
    const DefaultLayer* layers = Geoms(k);
    ASSERT_NE(layers, nullptr);
    const Inherited contype = layers->Find("contype");
    EXPECT_EQ(contype.attribute.value, "7");
    EXPECT_EQ(contype.level, k + 1);  // c_k .. c0, then main
    const Inherited density = layers->Find("density");
    EXPECT_EQ(density.attribute.value, k >= 4 ? "104" : "100");
    EXPECT_EQ(density.level, k >= 4 ? k - 4 : k + 1);
    EXPECT_EQ(layers->Find("rgba").attribute.value, fmt::format("0 0 0 {}", k));
    EXPECT_FALSE(layers->Find("margin").attribute.present());
  }
}

// MJCF-012: an element's own attribute wins over its class's; a class
// without a default of the element's kind is skipped.
TEST_F(DeepDefaults, Mjcf012ElementLevelsSkipClassesWithoutTheKind) {
  Read(NestedDefaults([](int) { return std::string("rgba='1 1 1 1'"); },
                      [](int k) {
                        if (k == -1) return std::string("damping='0.5' axis='0 0 1'");
                        if (k == 27) return std::string("axis='1 0 0'");
                        return std::string();
                      }));
  auto xml = xml::XmlDocument::Parse(
      sources_.AddBuffer("joint.xml", "<joint class='c29' range='0 1'/>"), sources_, diags_);
  ASSERT_NE(xml, nullptr);
  const Element joint(xml->Root(), "joint", defaults_.IndexOf("c29"), defaults_);
  EXPECT_EQ(joint.Get("range").value, "0 1");
  EXPECT_EQ(joint.Get("axis").value, "1 0 0");  // c27's, the nearest joint default
  EXPECT_EQ(joint.Get("damping").value, "0.5");  // main's
  // the layers of a kind: c27's joint, then main's, nothing else
  ASSERT_NE(joint.Layers(), nullptr);
  EXPECT_EQ(joint.Layers()->Find("axis").level, 0);
  EXPECT_EQ(joint.Layers()->Find("damping").level, 1);
  EXPECT_FALSE(joint.Layers()->Find("range").attribute.present());
  ASSERT_NE(joint.Layers()->parent(), nullptr);
  EXPECT_EQ(joint.Layers()->parent()->parent(), nullptr);
  // no class writes a <site>: no layers; an unknown class reads main's
  EXPECT_EQ(defaults_.Layers(defaults_.IndexOf("c29"), "site"), nullptr);
  EXPECT_EQ(defaults_.IndexOf("no_such_class"), defaults_.IndexOf("main"));
  EXPECT_FALSE(defaults_.Has("no_such_class"));
}

// MJCF-011: geom@size is overwritten value by value, from main down to the
// class; the far layers' part is the same whichever class asks first.
TEST_F(DeepDefaults, Mjcf011LayeredNumbersOverwriteValueByValue) {
  Read(NestedDefaults(
      [](int k) {
        if (k == -1) return std::string("size='1 2 3'");
        if (k == 4) return std::string("size='4'");
        if (k == 20) return std::string("size='5 6'");
        return std::string("rgba='0 0 0 1'");
      },
      [](int) { return std::string(); }));
  for (int k : {29, 12, 3, 25, 20, 4}) {
    SCOPED_TRACE(k);
    const LayeredPrefix& size = Geoms(k)->Layered("size", 3);
    EXPECT_TRUE(size.ok);
    EXPECT_EQ(size.written, 3u);
    const std::vector<double> expected = k >= 20 ? std::vector<double>{5, 6, 3}
                                         : k >= 4 ? std::vector<double>{4, 2, 3}
                                                  : std::vector<double>{1, 2, 3};
    EXPECT_EQ(size.values, expected);
  }
  // a list no layer writes leaves nothing written
  EXPECT_EQ(Geoms(29)->Layered("friction", 3).written, 0u);
}

// A bad list in a far layer marks every class below it, and no class above.
TEST_F(DeepDefaults, LayeredNumbersRememberABadLayer) {
  Read(NestedDefaults(
      [](int k) { return k == 10 ? std::string("size='0.1 x'") : std::string("size='1'"); },
      [](int) { return std::string(); }));
  EXPECT_FALSE(Geoms(29)->Layered("size", 3).ok);
  EXPECT_FALSE(Geoms(10)->Layered("size", 3).ok);
  EXPECT_TRUE(Geoms(9)->Layered("size", 3).ok);
}

}  // namespace
}  // namespace mdlc::frontend::mjcf
