// xacro_tree.h - the tree a xacro expansion works on.
//
// Expansion rewrites the document in place the way xacro defines it:
// macro calls are replaced by their bodies, properties and macros vanish,
// comments before them go too, and text is evaluated. That needs a tree
// whose nodes can be cloned, moved and spliced, with text, comments and
// elements in document order - unlike the readers' XmlDocument, which is
// built once and read. Every node keeps the Loc where its text is written;
// a node cloned out of a macro body is placed in an expansion file id
// (SourceManager::AddExpansion), so diagnostics can trace it to the call.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "ir/location.h"

namespace mdlc::xacro {

struct Attribute {
  std::string name;   // qualified, as written
  std::string value;
  Loc loc;
};

class Node {
 public:
  enum class Kind : uint8_t { kElement, kText, kComment, kCdata };

  Kind kind = Kind::kElement;
  std::string name;  // element: qualified name; otherwise empty
  std::string text;  // text, comment or CDATA content
  std::vector<Attribute> attributes;
  Loc loc;

  Node* parent() const { return parent_; }
  Node* first_child() const { return first_; }
  Node* last_child() const { return last_; }
  Node* next() const { return next_; }
  Node* previous() const { return previous_; }
  bool is_element() const { return kind == Kind::kElement; }

  const Attribute* FindAttribute(std::string_view attribute) const;
  Attribute* FindAttribute(std::string_view attribute);
  /// Sets or adds (at the end) an attribute.
  void SetAttribute(std::string_view attribute, std::string value, Loc loc);
  void RemoveAttribute(std::string_view attribute);
  /// The first element child, and the next element sibling.
  Node* FirstElementChild() const;
  Node* NextElementSibling() const;

 private:
  friend class Tree;
  Node* parent_ = nullptr;
  Node* first_ = nullptr;
  Node* last_ = nullptr;
  Node* next_ = nullptr;
  Node* previous_ = nullptr;
};

/// Owns every node made during one expansion; nodes are unlinked, never
/// freed, until the tree goes.
class Tree {
 public:
  Node* Make(Node::Kind kind);
  /// A deep copy, unlinked; `relocate` (may be null) maps each copied Loc.
  template <typename Relocate>
  Node* Clone(const Node& node, Relocate&& relocate);
  Node* Clone(const Node& node) {
    return Clone(node, [](Loc loc) { return loc; });
  }

  void AppendChild(Node* parent, Node* child);
  /// Inserts `node` (unlinked first if linked) before `before` in its parent.
  void InsertBefore(Node* before, Node* node);
  void Unlink(Node* node);
  /// Replaces `node` by `by`'s children (`content_only`) or by `by` itself;
  /// a null `by` removes `node`. `by` may be `node` itself (content only).
  void Replace(Node* node, Node* by, bool content_only);
  size_t size() const { return size_; }

 private:
  // nodes are carved from blocks: an expansion makes tens of thousands,
  // and one allocation each was a tenth of its time
  static constexpr size_t kBlockNodes = 256;
  std::vector<std::unique_ptr<Node[]>> blocks_;
  size_t size_ = 0;
};

template <typename Relocate>
Node* Tree::Clone(const Node& node, Relocate&& relocate) {
  Node* copy = Make(node.kind);
  copy->name = node.name;
  copy->text = node.text;
  copy->attributes = node.attributes;
  copy->loc = relocate(node.loc);
  for (Attribute& a : copy->attributes) a.loc = relocate(a.loc);
  for (const Node* c = node.first_child(); c; c = c->next()) {
    AppendChild(copy, Clone(*c, relocate));
  }
  return copy;
}

}  // namespace mdlc::xacro
