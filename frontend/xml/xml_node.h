// xml_node.h - the nodes of mdlc's own XML tree.
//
// libxml2 tokenizes and checks the document; mdlc builds the tree itself
// from libxml2's SAX events (tree_builder.h), because libxml2's DOM costs
// more than the reading of it: a node, an attribute node, a text node and a
// string per attribute, with names measured and compared anew at every
// lookup. These nodes hold exactly what the readers ask for, with names and
// values as sized views and every position already found, in one arena per
// document (XmlDocument owns it). XmlElement is the only way readers see them.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>

namespace mdlc::xml {

/// Whether x and y hold the same Word at `offset` (unaligned loads).
template <typename Word>
inline bool SameWordAt(const char* x, const char* y, size_t offset) {
  Word u, v;
  std::memcpy(&u, x + offset, sizeof(Word));
  std::memcpy(&v, y + offset, sizeof(Word));
  return u == v;
}

/// Name equality for lookups by name. Names are short (`link`, `inertial`,
/// `drake:proximity_properties`), and a lookup mostly meets names that
/// differ, so the length is compared first and then the bytes as at most
/// two overlapping machine words, inline: a call to memcmp for every name
/// of the same length cost more than the comparison itself.
/// Names longer than 16 bytes are rare and go to memcmp.
inline bool SameName(std::string_view a, std::string_view b) {
  const size_t n = a.size();
  if (n != b.size()) return false;
  const char* x = a.data();
  const char* y = b.data();
  // Two loads of a word of w bytes, [0, w) and [n - w, n), cover every byte
  // once or twice when w <= n <= 2w.
  if (n >= 8) {
    if (n > 16) return std::memcmp(x, y, n) == 0;
    return SameWordAt<uint64_t>(x, y, 0) && SameWordAt<uint64_t>(x, y, n - 8);
  }
  if (n >= 4) return SameWordAt<uint32_t>(x, y, 0) && SameWordAt<uint32_t>(x, y, n - 4);
  if (n == 0) return true;
  // 1 to 3 bytes: the first, the middle and the last (some are the same byte)
  return x[0] == y[0] && x[n / 2] == y[n / 2] && x[n - 1] == y[n - 1];
}

}  // namespace mdlc::xml

namespace mdlc::xml::detail {


struct AttributeNode {
  std::string_view name;   // qualified, as written ("drake:acceleration")
  std::string_view value;  // references decoded; NUL-terminated
  uint32_t line = 0;       // of the name; 0 when the scan could not place it
  uint32_t column = 0;
};

// Text, CDATA and comments directly inside an element, in document order.
enum class ContentKind : uint8_t { kText, kCdata, kComment };
struct ElementNode;
struct ContentNode {
  ContentKind kind = ContentKind::kText;
  std::string_view text;  // NUL-terminated
  ContentNode* next = nullptr;
  // the element child this node comes before; null when it follows them
  // all. Element children and content are kept in two lists (readers ask
  // for one or the other); this puts them back in document order.
  const ElementNode* before = nullptr;
};

struct ElementNode {
  std::string_view name;  // qualified, as written
  ElementNode* parent = nullptr;
  ElementNode* first_child = nullptr;  // element children only
  ElementNode* next_sibling = nullptr;
  AttributeNode* attributes = nullptr;  // attribute_count of them, in document order
  ContentNode* content = nullptr;
  uint32_t attribute_count = 0;
  uint32_t line = 0;  // of the start tag's '<'
  uint32_t column = 0;
  // the file the element is written in, when it is not the document's own
  // (a document a macro stage built from several files); its attributes
  // are written there too
  uint32_t file = UINT32_MAX;
  // XmlElement::NameBit of every attribute name, or'ed
  uint64_t attribute_name_bits = 0;
  // the same for the names of the element children
  uint64_t child_name_bits = 0;
};

/// Appends `child` to `parent`'s element children (`last_child` is the last
/// so far), and places the content added since the previous element child
/// (`unplaced`) before it. Both tree builders link elements so.
inline void LinkElementChild(ElementNode* parent, ElementNode*& last_child,
                             ContentNode*& unplaced, ElementNode* child, uint64_t child_bit) {
  child->parent = parent;
  parent->child_name_bits |= child_bit;
  if (last_child) {
    last_child->next_sibling = child;
  } else {
    parent->first_child = child;
  }
  last_child = child;
  for (ContentNode* c = unplaced; c; c = c->next) c->before = child;
  unplaced = nullptr;
}

}  // namespace mdlc::xml::detail
