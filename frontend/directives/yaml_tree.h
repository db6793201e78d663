// yaml_tree.h - a YAML document as the directives reader reads it.
//
// yaml-cpp scans, parses and checks the text; mdlc keeps its own compact tree
// of what it produces, built from yaml-cpp's parse events (yaml_tree.cc),
// because yaml-cpp's own node graph costs more than the parse: every node is
// reference-counted, held in a set, and every access to a map entry makes
// and drops three counted handles. Here every node, string and child list
// lives in one arena per document, and a Node is a plain pointer.
//
// An alias (`*name`) is the node its anchor names, shared, never copied, as
// in yaml-cpp: aliases cannot make the tree grow beyond the text.
#pragma once

#include <cstdint>
#include <memory>
#include <memory_resource>
#include <string_view>

namespace mdlc::frontend::yaml {

namespace detail {
enum class NodeKind : uint8_t { kNull, kScalar, kSequence, kMap };
struct NodeData {
  NodeKind kind = NodeKind::kNull;
  uint32_t line = 0;  // 1-based; 0 when the parser gave no place
  uint32_t column = 0;
  std::string_view tag;     // as yaml-cpp reports it: "?" plain, "!" quoted, "!Rpy" written
  std::string_view scalar;  // a scalar's text
  // a sequence's items, or a map's keys and values interleaved
  const NodeData* const* children = nullptr;
  uint32_t child_count = 0;
};
}  // namespace detail

class Node;
struct Entry;

/// A node's children read `kStride` at a time, each step seen as a `Value`:
/// a sequence's items one by one (Node), a map's keys and values two by
/// two (Entry). Made by Node::Items() and Node::Entries().
template <typename Value, size_t kStride>
class ChildRange {
 public:
  class iterator {
   public:
    explicit iterator(const detail::NodeData* const* at) : at_(at) {}
    Value operator*() const;
    iterator& operator++() {
      at_ += kStride;
      return *this;
    }
    bool operator!=(const iterator& other) const { return at_ != other.at_; }

   private:
    const detail::NodeData* const* at_;
  };
  ChildRange(const detail::NodeData* const* begin, size_t steps) : begin_(begin), steps_(steps) {}
  iterator begin() const { return iterator(begin_); }
  iterator end() const { return iterator(begin_ + kStride * steps_); }

 private:
  const detail::NodeData* const* begin_;
  size_t steps_;
};

/// A view of one node; a default Node is undefined (an absent value).
class Node {
 public:
  Node() = default;
  explicit Node(const detail::NodeData* data) : data_(data) {}

  bool IsDefined() const { return data_ != nullptr; }
  bool IsNull() const { return data_ && data_->kind == detail::NodeKind::kNull; }
  bool IsScalar() const { return data_ && data_->kind == detail::NodeKind::kScalar; }
  bool IsSequence() const { return data_ && data_->kind == detail::NodeKind::kSequence; }
  bool IsMap() const { return data_ && data_->kind == detail::NodeKind::kMap; }

  /// A scalar's text; empty for any other node.
  std::string_view Scalar() const { return data_ ? data_->scalar : std::string_view(); }
  std::string_view Tag() const { return data_ ? data_->tag : std::string_view(); }
  /// Where the node starts (1-based); 0 when unknown or undefined.
  uint32_t line() const { return data_ ? data_->line : 0; }
  uint32_t column() const { return data_ ? data_->column : 0; }

  /// Items of a sequence, entries of a map; 0 for anything else.
  size_t size() const {
    if (IsSequence()) return data_->child_count;
    if (IsMap()) return data_->child_count / 2;
    return 0;
  }
  /// The i-th item of a sequence (i < size()).
  Node operator[](size_t i) const { return Node(data_->children[i]); }

  /// A sequence's items, in order: for (Node item : node.Items()).
  ChildRange<Node, 1> Items() const {
    return {IsSequence() ? data_->children : nullptr, IsSequence() ? size() : 0};
  }
  /// A map's entries, in order (repeated keys included): for (Entry e : node.Entries()).
  ChildRange<Entry, 2> Entries() const {
    return {IsMap() ? data_->children : nullptr, IsMap() ? size() : 0};
  }

 private:
  const detail::NodeData* data_ = nullptr;
};

/// One key of a map and its value.
struct Entry {
  Node first;   // the key
  Node second;  // the value
};

template <>
inline Node ChildRange<Node, 1>::iterator::operator*() const {
  return Node(at_[0]);
}
template <>
inline Entry ChildRange<Entry, 2>::iterator::operator*() const {
  return Entry{Node(at_[0]), Node(at_[1])};
}

/// The first document of a YAML text, owning its nodes.
class Document {
 public:
  /// Parses `text` with yaml-cpp. Throws YAML::Exception (with its place)
  /// on malformed YAML, as YAML::Load does. A text without a document reads
  /// as a null root without a place.
  static std::unique_ptr<Document> Load(std::string_view text);

  Node root() const { return Node(root_); }

 private:
  friend class TreeBuilder;
  Document() = default;

  std::pmr::monotonic_buffer_resource arena_{16 * 1024};
  const detail::NodeData* root_ = nullptr;
};

}  // namespace mdlc::frontend::yaml
