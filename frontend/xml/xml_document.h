// xml_document.h - an XML document as mdlc reads it, with exact source locations.
//
// libxml2 parses and checks the text; mdlc keeps its own compact tree of
// what the readers use (xml_node.h, built by tree_builder.h), with every
// element and attribute placed at its line and column in the text
// (start_tags.h). Readers see it through XmlElement views.
//
// Security: documents are parsed with no network access, no DTD loading and
// no entity substitution, and any document that declares entities is
// rejected before libxml2 sees it (no billion-laughs, no external entities).
// Deep documents are allowed (XML_PARSE_HUGE); nothing here recurses per
// nesting level.
#pragma once

#include <cstdint>
#include <memory>
#include <memory_resource>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/xml/element_counts.h"
#include "frontend/xml/xml_node.h"
#include "ir/diagnostics.h"
#include "ir/location.h"
#include "ir/source_manager.h"

struct _xmlDict;

namespace mdlc::xml {

class XmlDocument;
class XmlDocumentBuilder;

/// How a document is read. The model readers take the defaults; a macro
/// stage that writes the document back out needs every node.
struct ParseOptions {
  /// Keep whitespace-only text between elements too, which the readers'
  /// default drops (libxml2's NOBLANKS rules, see tree_builder.h).
  bool keep_blank_text = false;
  /// Keep namespace declarations as attributes named as written
  /// ("xmlns:xacro"), first in their element's list; the readers' default
  /// has none (libxml2 reports declarations apart from attributes).
  bool keep_namespace_declarations = false;
};

/// A text, CDATA or comment node, as XmlElement::ForEachNode visits it.
struct XmlContent {
  detail::ContentKind kind;
  std::string_view text;
};

/// A view of one attribute: its value and location.
struct XmlAttribute {
  std::string_view name;   // qualified ("drake:acceleration")
  std::string_view value;  // as written (entities never expanded)
  Loc loc;                 // at the attribute's name
  bool present() const { return loc.valid(); }
};

/// A non-owning view of one element node.
class XmlElement {
 public:
  XmlElement() = default;
  XmlElement(const XmlDocument* doc, const detail::ElementNode* node) : doc_(doc), node_(node) {}

  explicit operator bool() const { return node_ != nullptr; }
  /// Qualified name as written: "link", "drake:joint".
  std::string_view Name() const { return node_->name; }
  Loc GetLoc() const;

  /// First child element, next sibling element (null element at the end).
  XmlElement FirstChild() const { return XmlElement(doc_, node_->first_child); }
  XmlElement NextSibling() const { return XmlElement(doc_, node_->next_sibling); }
  /// First child element named `name`. A name no child has is answered
  /// from the children's name summary, without walking them: a model of
  /// 10,000 links asked for its <pose> or <static> steps over none of them.
  XmlElement Child(std::string_view name) const;
  XmlElement Parent() const { return XmlElement(doc_, node_->parent); }
  /// Asks the cache for the memory holding this element's subtree, ahead of
  /// reading it. The tree is built in document order into one arena, so an
  /// element's descendants follow it (2 KB hold a link's subtree). Measured
  /// where it is used, and only there: an SDFormat model's links and joints,
  /// which it took from 93 to 83 ms in the 10,000-link chain's frontend;
  /// URDF's and MJCF's walks, and a world's one-link models, gained nothing
  /// from it and do without.
  void PrefetchSubtree() const {
    constexpr size_t kBytes = 2048;  // a typical link's subtree; 1 and 4 KB measured alike
    const char* at = reinterpret_cast<const char*>(node_);
    for (size_t offset = 0; offset < kBytes; offset += 64) __builtin_prefetch(at + offset);
  }

  /// The attribute `name`; `present()` is false when absent.
  XmlAttribute Attribute(std::string_view name) const;
  /// A summary of which attribute names the element has, for callers that
  /// ask for many names most elements lack (MJCF reads a dozen per element):
  /// the bit NameBit(n) is set for every attribute n present, so a clear bit
  /// proves `n` absent without walking the attribute list.
  uint64_t AttributeNameBits() const { return node_->attribute_name_bits; }
  static uint64_t NameBit(std::string_view qualified_name) {
    return NameBitOf(qualified_name.empty() ? '\0' : qualified_name[0],
                     qualified_name.size() > 1 ? qualified_name[1] : '\0');
  }
  /// Every attribute's qualified name in document order, calling f(string_view).
  template <typename F>
  void ForEachAttributeName(F&& f) const;
  /// Concatenated text content of the element (entity references skipped).
  std::string Text() const;
  /// Text() without a copy when the text is one node, as it almost always
  /// is: a view of that node; else a view of `storage`, filled with Text().
  std::string_view TextView(std::string& storage) const;
  /// The text of each comment directly inside the element, in order.
  std::vector<std::string> Comments() const;
  /// Every child node in document order: on_element(XmlElement) for element
  /// children, on_content(XmlContent) for text, CDATA and comments.
  template <typename OnElement, typename OnContent>
  void ForEachNode(OnElement&& on_element, OnContent&& on_content) const;

  /// The element's identity, for comparisons and as a map key.
  const void* raw() const { return node_; }

 private:
  // the first two characters pick the bit: cheap, and they differ between
  // most names one element kind allows
  static uint64_t NameBitOf(char first, char second) {
    const unsigned h = static_cast<unsigned char>(first) * 7u + static_cast<unsigned char>(second);
    return uint64_t{1} << (h & 63u);
  }

  const XmlDocument* doc_ = nullptr;
  const detail::ElementNode* node_ = nullptr;
};

class XmlDocument {
 public:
  ~XmlDocument();
  XmlDocument(const XmlDocument&) = delete;
  XmlDocument& operator=(const XmlDocument&) = delete;

  /// Parses a buffer already in the SourceManager. Reports problems to
  /// `diags` and returns null when the document is unusable.
  static std::unique_ptr<XmlDocument> Parse(FileId file, const SourceManager& sources,
                                            DiagnosticEngine& diags,
                                            const ParseOptions& options = {});
  /// The tree of `original` read as `file`, a buffer holding the same text
  /// (the same file loaded again): nothing is parsed, and every element and
  /// attribute is placed in `file`, so diagnostics name the load they come
  /// from. The new document keeps `original` alive.
  static std::unique_ptr<XmlDocument> SameTextAs(std::shared_ptr<const XmlDocument> original,
                                                 FileId file);

  XmlElement Root() const;
  FileId file() const { return file_; }
  /// How many elements are named `name` ("link", "drake:joint").
  uint64_t CountOf(std::string_view name) const { return element_counts_.Of(name); }
  const SourceManager& sources() const { return *sources_; }
  /// Comments before (false) and after (true) the root element, in order;
  /// kept only when parsed with ParseOptions::keep_namespace_declarations.
  const std::vector<std::pair<std::string_view, bool>>& outside_comments() const {
    return outside_comments_;
  }

 private:
  friend class XmlDocumentBuilder;
  XmlDocument() = default;

  // every node, attribute and string of the tree; released at once
  std::pmr::monotonic_buffer_resource arena_{64 * 1024};
  detail::ElementNode* root_ = nullptr;
  // libxml2's name dictionary, which unprefixed names point into
  _xmlDict* names_ = nullptr;
  FileId file_;
  const SourceManager* sources_ = nullptr;
  ElementCounts element_counts_;
  std::vector<std::pair<std::string_view, bool>> outside_comments_;
  // the document whose arena holds the tree, for a SameTextAs copy
  std::shared_ptr<const XmlDocument> original_;
};

template <typename F>
void XmlElement::ForEachAttributeName(F&& f) const {
  for (uint32_t i = 0; i < node_->attribute_count; ++i) f(node_->attributes[i].name);
}

template <typename OnElement, typename OnContent>
void XmlElement::ForEachNode(OnElement&& on_element, OnContent&& on_content) const {
  const detail::ContentNode* content = node_->content;
  for (const detail::ElementNode* child = node_->first_child; child;
       child = child->next_sibling) {
    for (; content && content->before == child; content = content->next) {
      on_content(XmlContent{content->kind, content->text});
    }
    on_element(XmlElement(doc_, child));
  }
  for (; content; content = content->next) on_content(XmlContent{content->kind, content->text});
}

}  // namespace mdlc::xml
