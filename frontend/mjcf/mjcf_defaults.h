// mjcf_defaults.h - <default> classes (MJCF-011, MJCF-012): what an element
// inherits from its class.
//
// MuJoCo copies a parent class into each nested class before reading the
// nested class's own elements, so an element inherits, per attribute, what
// the nearest class in its chain writes. mdlc keeps the classes as written
// and links each class's default of one kind (its <geom>, its <joint>) to
// the nearest enclosing class's default of the same kind: an element's
// defaults are that chain of layers, nearest first. A lookup walks a few
// layers; past those it asks the far layer, which works its answer out once
// and keeps it, so an element of a class nested N deep costs no N-step walk
// (a chain of 4,000 classes used by 4,000 geoms stays linear).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <absl/container/flat_hash_map.h>

#include "ir/diagnostics.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::frontend::mjcf {

struct MjcfDocument;

/// An attribute as an element sees it after defaults: written on the element
/// itself, or inherited from a default class (then `loc` is where the
/// default class element wrote it, so diagnostics point at the real text).
using Attribute = xml::XmlAttribute;

/// An attribute and the layer that gives it: 0 for the layer asked, 1 for
/// the next one up, ... Absent (`!attribute.present()`) when none gives it.
struct Inherited {
  Attribute attribute;
  int level = 0;
};

/// A list of numbers that each layer overwrites value by value, root class
/// first (geom@size): the first `written` values are what the layers leave.
struct LayeredPrefix {
  std::vector<double> values;
  size_t written = 0;
  bool ok = true;  // false: a layer's text is not a list of at most n numbers
};

/// One class's default element of one kind (`<geom>` in `<default
/// class="x">`), linked to the nearest enclosing class's default of the same
/// kind. Classes in between that have none of that kind are skipped.
class DefaultLayer {
 public:
  /// Layers an answer walks before it asks the far layer to remember it:
  /// real models nest a few classes, and their lookups never allocate.
  static constexpr int kShortWalk = 8;

  DefaultLayer(xml::XmlElement e, const DefaultLayer* parent)
      : e_(e),
        parent_(parent),
        chain_names_(e.AttributeNameBits() | (parent ? parent->chain_names_ : 0)) {}

  const xml::XmlElement& xml() const { return e_; }
  const DefaultLayer* parent() const { return parent_; }
  /// The nearest layer from this one up that writes `name` (level 0: this).
  Inherited Find(std::string_view name) const;
  /// `name` read as up to `n` numbers by every layer from the root down to
  /// this one, each overwriting the values it gives; remembered per layer.
  const LayeredPrefix& Layered(std::string_view name, size_t n) const;

 private:
  Inherited FindRemembered(std::string_view name, uint64_t bit) const;

  xml::XmlElement e_;
  const DefaultLayer* parent_;
  // XmlElement::AttributeNameBits of this layer and every layer above: a
  // clear bit proves a name absent from the rest of the chain
  uint64_t chain_names_;
  // answers worked out for lookups that reached this layer past a short walk
  mutable absl::flat_hash_map<std::string, Inherited> found_;
  mutable absl::flat_hash_map<std::pair<std::string, size_t>, LayeredPrefix> layered_;
};

/// The default-class tree: classes by name, each with its default element
/// per kind ("geom", "joint", "motor", ...) and its parent class.
class DefaultClasses {
 public:
  /// Reads one top-level <default> tree (nested classes by a work list);
  /// `document` expands includes inside it when given.
  void Read(const xml::XmlElement& default_element, DiagnosticEngine& diags,
            const MjcfDocument* document = nullptr);
  /// True for a class some <default> names, and for "main".
  bool Has(std::string_view class_name) const;
  /// The class's index for Layers: "main" (0) for a name no class has.
  int IndexOf(std::string_view class_name) const;
  /// The default layers an element of `kind` in class `class_index` inherits,
  /// nearest first; nullptr when neither the class nor an ancestor has a
  /// default of that kind. Worked out once per (class, kind).
  const DefaultLayer* Layers(int class_index, std::string_view kind) const;

 private:
  struct ClassNode {
    std::string name;
    int parent = -1;  // index into classes_, -1 for the root ("main")
    absl::flat_hash_map<std::string, xml::XmlElement> kinds;  // "geom" -> <geom ...>
    // kind -> the layers of that kind this class's elements inherit
    mutable absl::flat_hash_map<std::string, const DefaultLayer*> layers;
  };
  std::vector<ClassNode> classes_;
  absl::flat_hash_map<std::string, int> by_name_;
  mutable std::deque<DefaultLayer> layers_;  // stable addresses
};

/// An element with the default class it uses resolved once: `Get` returns
/// the element's own attribute, else the nearest class layer's. MuJoCo
/// applies a class to elements of the same kind; actuator shortcuts (motor,
/// position, ...) read their own kind.
class Element {
 public:
  /// An element of a kind no default class applies to (compiler, option,
  /// body, inertial, frame, freejoint).
  Element(xml::XmlElement e, std::string_view kind) : e_(e), kind_(kind) {}
  Element(xml::XmlElement e, std::string_view kind, int class_index,
          const DefaultClasses& defaults)
      : e_(e), kind_(kind), class_index_(class_index), defaults_(&defaults) {}

  const xml::XmlElement& xml() const { return e_; }
  Loc loc() const { return e_.GetLoc(); }
  std::string_view kind() const { return kind_; }
  Attribute Get(std::string_view name) const;
  /// The attribute as the element itself writes it (not a default).
  Attribute Own(std::string_view name) const;
  /// True if the element itself writes the attribute (not a default).
  bool HasOwn(std::string_view name) const { return Own(name).present(); }
  /// The class's default layers of this element's kind, nearest first
  /// (nullptr: none), looked up on first use: elements read a dozen
  /// attributes each, most absent, and many write all they use.
  const DefaultLayer* Layers() const;

 private:
  xml::XmlElement e_;
  std::string_view kind_;
  int class_index_ = 0;
  const DefaultClasses* defaults_ = nullptr;
  mutable const DefaultLayer* layers_ = nullptr;
  mutable bool layers_known_ = false;
  // XmlElement::AttributeNameBits of the element, read on the first lookup
  mutable uint64_t own_names_ = 0;
  mutable bool own_names_known_ = false;
};

}  // namespace mdlc::frontend::mjcf
