// drake_spellings.h - Drake's drake: elements in both of their spellings,
// for tests run once per format. URDF writes a child's value or name in an
// attribute (<drake:mu_dynamic value='0.5'/>), SDFormat in the child's text
// (<drake:mu_dynamic>0.5</drake:mu_dynamic>); the frontends share
// everything else (frontend/drake_child_reader.h, frontend/drake_proximity.h),
// so what an element lowers to, what it rejects and what it says are checked
// once for both: geometry properties in
// frontend/drake_geometry_spellings_test.cc, model elements and joints in
// frontend/drake_model_spellings_test.cc. What only one format has is
// tested beside that format's other tests (urdf_*_test.cc, sdf_*_test.cc).
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "ir/format.h"
#include "passes/pass_manager.h"
#include "tests/unit/sdf_test_util.h"
#include "tests/unit/test_values.h"
#include "tests/unit/urdf_test_util.h"

// a namespace of its own: the unit tests are compiled in batches of files
// (MDLC_UNITY_BUILD), and the plain names of these helpers (Model, Broken)
// are taken in other files
namespace mdlc::drake_spellings {
namespace {

using testing::Find;
using testing::kInf;
using testing::Number;
using testing::Numbers;

constexpr double kPi = std::numbers::pi;

// ------------------------------------------------------------ the spellings

/// `tag` holding the number(s) `value`: URDF's @value, SDFormat's text.
std::string DrakeValue(std::string_view tag, std::string_view value, Format format) {
  return format == Format::Urdf ? fmt::format("<{} value='{}'/>", tag, value)
                                : fmt::format("<{0}>{1}</{0}>", tag, value);
}
/// `tag` naming `name` (a link, frame, group or renderer): URDF's attribute
/// `attr`, SDFormat's text.
std::string DrakeName(std::string_view tag, std::string_view name, Format format,
                      std::string_view attr = "name") {
  return format == Format::Urdf ? fmt::format("<{} {}='{}'/>", tag, attr, name)
                                : fmt::format("<{0}>{1}</{0}>", tag, name);
}
/// What an unwritten value or name is reported as: a missing attribute
/// (URDF), or an element missing its text (SDFormat).
DiagKind MissingKind(Format format) {
  return format == Format::Urdf ? DiagKind::MissingAttribute : DiagKind::MissingElement;
}

/// Model `m`: links a..e, a revolute joint 'rev' a->b, a prismatic joint
/// 'pri' b->c and a frame 'fa' on a, then `body`, which starts on line 8 of
/// the file in both formats (tests check the lines that diagnostics and
/// references point at). The SDFormat text is what SdfFileText wraps (two
/// lines before it).
std::string Model(std::string_view body, Format format) {
  if (format == Format::Urdf) {
    return fmt::format(R"(<?xml version='1.0'?>
<robot name='m'
       xmlns:drake='http://drake.mit.edu'>
  <link name='a'/><link name='b'/><link name='c'/><link name='d'/><link name='e'/>
  <joint name='rev' type='revolute'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/></joint>
  <joint name='pri' type='prismatic'><parent link='b'/><child link='c'/><axis xyz='1 0 0'/></joint>
  <frame name='fa' link='a' xyz='0 0 1'/>
{}
</robot>)",
                       body);
  }
  return fmt::format(R"(<model name='m'>
  <link name='a'/><link name='b'/><link name='c'/><link name='d'/><link name='e'/>
  <joint name='rev' type='revolute'><parent>a</parent><child>b</child><axis><xyz>0 0 1</xyz></axis></joint>
  <joint name='pri' type='prismatic'><parent>b</parent><child>c</child><axis><xyz>1 0 0</xyz></axis></joint>
  <frame name='fa' attached_to='a'><pose>0 0 1 0 0 0</pose></frame>
{}
</model>)",
                     body);
}

/// Model `m` with one link `a` holding `link_children`.
std::string OneLink(std::string_view link_children, Format format) {
  return format == Format::Urdf
             ? fmt::format("<robot name='m'><link name='a'>{}</link></robot>", link_children)
             : testing::SdfLink(link_children);
}
std::string_view UnitBox(Format format) {
  return format == Format::Urdf ? "<box size='1 1 1'/>" : "<box><size>1 1 1</size></box>";
}
/// One collision box `c` with `children` beside its geometry.
std::string BoxCollision(std::string_view children, Format format) {
  return OneLink(fmt::format("<collision name='c'><geometry>{}</geometry>{}</collision>",
                             UnitBox(format), children),
                 format);
}
/// One visual box `v` with `children` beside its geometry.
std::string BoxVisual(std::string_view children, Format format) {
  return OneLink(
      fmt::format("<visual name='v'><geometry>{}</geometry>{}</visual>", UnitBox(format), children),
      format);
}
/// The collision box with <drake:proximity_properties> holding `children`.
std::string ProximityOf(std::string_view children, Format format) {
  return BoxCollision(
      fmt::format("<drake:proximity_properties>{}</drake:proximity_properties>", children), format);
}

/// One child of a drake: element: its tag and the value or name it writes,
/// spelled by Element; or, kAsIs, the child's whole text (the attributes both
/// formats share, as in <drake:tendon_constraint_joint name='j' a='1'/>).
struct Child {
  enum Kind { kValue, kName, kAsIs };
  std::string tag;  // for kAsIs, only what a Broken names the child by
  std::string text;
  Kind kind = kValue;
};
/// The element `tag` with `children`, one a line after its own.
std::string Element(std::string_view tag, const std::vector<Child>& children, Format format) {
  std::string out = fmt::format("<{}>", tag);
  for (const Child& c : children) {
    out += "\n    ";
    out += c.kind == Child::kValue  ? DrakeValue(c.tag, c.text, format)
           : c.kind == Child::kName ? DrakeName(c.tag, c.text, format)
                                    : c.text;
  }
  return out + fmt::format("\n  </{}>", tag);
}

/// One format's frontend on a text that Model or OneLink wrote, then, when
/// asked, the default passes. Strict about diagnostics, as the fixtures it
/// wraps are (diagnostic_claims.h).
class Lowering {
 public:
  explicit Lowering(Format format) {
    if (format == Format::Urdf) {
      urdf_.emplace();
    } else {
      sdf_.emplace();
    }
  }
  Lowering(const Lowering&) = delete;
  Lowering& operator=(const Lowering&) = delete;

  bool Read(const std::string& text) { return urdf_ ? urdf_->Read(text) : sdf_->Read(text); }
  /// The default pass pipeline, verifying after each pass.
  bool RunPasses() {
    passes::PassInstrumentation inst;
    inst.verify_each = true;
    passes::PassManager pm(inst);
    pm.AddDefaultPipeline();
    passes::PassContext ctx{module(), diags(), urdf_ ? urdf_->sources : sdf_->sources};
    return pm.Run(ctx);
  }

  ir::Module& module() { return urdf_ ? urdf_->module : sdf_->module; }
  DiagnosticEngine& diags() { return urdf_ ? urdf_->diags : sdf_->diags; }
  ModelId model() const { return urdf_ ? *urdf_->model : *sdf_->model; }
  const ir::Joint* Joint(std::string_view name) const {
    return urdf_ ? urdf_->Joint(name) : sdf_->Joint(name);
  }
  std::string Messages() const { return urdf_ ? urdf_->Messages() : sdf_->Messages(); }

  bool HasDiagnostic(DiagKind kind, std::string_view text) const {
    return claims().HasDiagnostic(kind, text);
  }
  void ExpectDiagnostic(DiagKind kind, std::string_view text) {
    claims().ExpectDiagnostic(kind, text);
  }
  /// The number of diagnostics of `kind`; counting them claims them all.
  size_t Count(DiagKind kind) {
    size_t n = 0;
    for (const auto& d : diags().diagnostics()) n += d.kind == kind;
    if (n) ExpectDiagnostic(kind, "");
    return n;
  }

 private:
  testing::ClaimsDiagnostics& claims() const {
    return urdf_ ? static_cast<testing::ClaimsDiagnostics&>(*urdf_) : *sdf_;
  }

  mutable std::optional<testing::Lowered> urdf_;
  mutable std::optional<testing::SdfFrontendResult> sdf_;
};

/// A change to one child of a valid element, and what the element must then
/// be rejected with.
struct Broken {
  std::string tag;                  // the child changed
  std::optional<std::string> text;  // what it writes instead; nullopt: it is left out
  DiagKind kind;
  std::string message;
};
/// `children` with the change `b`.
std::vector<Child> Apply(std::vector<Child> children, const Broken& b) {
  auto at = std::find_if(children.begin(), children.end(),
                         [&](const Child& c) { return c.tag == b.tag; });
  EXPECT_NE(at, children.end()) << b.tag;
  if (at == children.end()) return children;
  if (b.text) {
    at->text = *b.text;
  } else {
    children.erase(at);
  }
  return children;
}
/// The element `tag` with `children` changed by `b` is rejected, and adds
/// nothing to the module.
void ExpectRejected(Format format, std::string_view tag, const std::vector<Child>& children,
                    const Broken& b) {
  Lowering l(format);
  const std::string what = b.tag + " -> " + b.text.value_or("(left out)");
  EXPECT_FALSE(l.Read(Model(Element(tag, Apply(children, b), format), format))) << what;
  EXPECT_TRUE(l.HasDiagnostic(b.kind, b.message)) << what << "\n" << l.Messages();
  EXPECT_TRUE(l.module().force_elements.empty()) << what;
  EXPECT_TRUE(l.module().constraints.empty()) << what;
}

/// The format a test reads.
class DrakeSpellingTest : public ::testing::TestWithParam<Format> {
 protected:
  Format format() const { return GetParam(); }
};
std::string FormatParamName(const ::testing::TestParamInfo<Format>& info) {
  return info.param == Format::Urdf ? "Urdf" : "Sdf";
}
#define MDLC_BOTH_SPELLINGS(suite)                                                      \
  INSTANTIATE_TEST_SUITE_P(BothSpellings, suite,                                       \
                           ::testing::Values(Format::Urdf, Format::Sdf), FormatParamName)

}  // namespace
}  // namespace mdlc::drake_spellings
