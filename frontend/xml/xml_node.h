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

/// Name equality for lookups by name, which mostly meet names that differ:
/// the length and the first and last bytes are compared inline, and memcmp
/// is called only when all three match (a lookup among <ixx>, <iyy>, ...
/// had called it for every sibling of the same length).
inline bool SameName(std::string_view a, std::string_view b) {
  const size_t n = a.size();
  if (n != b.size()) return false;
  if (n == 0) return true;
  return a[0] == b[0] && a[n - 1] == b[n - 1] && std::memcmp(a.data(), b.data(), n) == 0;
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
struct ContentNode {
  ContentKind kind = ContentKind::kText;
  std::string_view text;  // NUL-terminated
  ContentNode* next = nullptr;
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
  // XmlElement::NameBit of every attribute name, or'ed
  uint64_t attribute_name_bits = 0;
};

}  // namespace mdlc::xml::detail
