// xml_document.h - a libxml2 DOM with exact source locations.
//
// libxml2 records only a line per node (and that line is where the start tag
// ends). XmlDocument recovers exact positions itself: after parsing, one
// linear scan of the buffer pairs each start tag, in document order, with its
// element node, and each attribute with its name, counting lines on the way.
// Line and column live in the nodes' `_private` slots, so lookups are O(1)
// with no side tables.
//
// Security: documents are parsed with no network access, no DTD loading and
// no entity substitution, and any document that declares entities is
// rejected before libxml2 sees it (no billion-laughs, no external entities).
// Deep documents are allowed (XML_PARSE_HUGE); nothing here recurses per
// nesting level.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ir/diagnostics.h"
#include "ir/location.h"
#include "ir/source_manager.h"

struct _xmlDoc;
struct _xmlNode;
struct _xmlAttr;

namespace mdlc::xml {

class XmlDocument;
class DomArena;

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
  XmlElement(const XmlDocument* doc, _xmlNode* node) : doc_(doc), node_(node) {}

  explicit operator bool() const { return node_ != nullptr; }
  /// Qualified name as written: "link", "drake:joint".
  std::string_view Name() const;
  Loc GetLoc() const;

  /// First child element, next sibling element (null element at the end).
  XmlElement FirstChild() const;
  XmlElement NextSibling() const;
  /// First child element named `name`.
  XmlElement Child(std::string_view name) const;
  XmlElement Parent() const;

  /// The attribute `name`; `present()` is false when absent.
  XmlAttribute Attribute(std::string_view name) const;
  /// A summary of which attribute names the element has, for callers that
  /// ask for many names most elements lack (MJCF reads a dozen per element):
  /// the bit NameBit(n) is set for every attribute n present, so a clear bit
  /// proves `n` absent without walking the attribute list.
  uint64_t AttributeNameBits() const;
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

  _xmlNode* raw() const { return node_; }

 private:
  friend class XmlDocument;
  XmlAttribute MakeAttribute(_xmlAttr* attr) const;
  std::string_view AttributeName(_xmlAttr* attr) const;
  _xmlAttr* FirstAttribute() const;
  static _xmlAttr* NextAttribute(_xmlAttr* attr);
  // the first two characters pick the bit: cheap, and they differ between
  // most names one element kind allows
  static uint64_t NameBitOf(char first, char second) {
    const unsigned h = static_cast<unsigned char>(first) * 7u + static_cast<unsigned char>(second);
    return uint64_t{1} << (h & 63u);
  }

  const XmlDocument* doc_ = nullptr;
  _xmlNode* node_ = nullptr;
};

struct PairHash {
  size_t operator()(const std::pair<const void*, const void*>& p) const {
    return std::hash<const void*>()(p.first) * 31 + std::hash<const void*>()(p.second);
  }
};

class XmlDocument {
 public:
  ~XmlDocument();
  XmlDocument(const XmlDocument&) = delete;
  XmlDocument& operator=(const XmlDocument&) = delete;

  /// Parses a buffer already in the SourceManager. Reports problems to
  /// `diags` and returns null when the document is unusable.
  static std::unique_ptr<XmlDocument> Parse(FileId file, const SourceManager& sources,
                                            DiagnosticEngine& diags);

  XmlElement Root() const;
  FileId file() const { return file_; }
  /// How many elements the document holds.
  uint64_t element_count() const { return element_count_; }
  const SourceManager& sources() const { return *sources_; }

  /// "prefix:name", stored for the document's lifetime (libxml2 keeps the
  /// two parts apart; views of the joined name must stay valid).
  std::string_view JoinedName(const unsigned char* prefix, const unsigned char* name) const;

 private:
  XmlDocument() = default;
  /// Records each element's and attribute's line and column, counting elements and
  /// nesting depth on the way; reports the first element over the elements
  /// or depth limit (sources.limits()) and returns false there.
  bool AssignLocations(DiagnosticEngine& diags);

  // the DOM's memory (dom_arena.h); doc_ lives in it
  std::unique_ptr<DomArena> arena_;
  _xmlDoc* doc_ = nullptr;
  // joined prefixed names by (prefix, name) pointers, which libxml2 interns;
  // unordered_map never moves its values, so views into them stay valid
  mutable std::unordered_map<std::pair<const void*, const void*>, std::string, PairHash>
      joined_names_;
  FileId file_;
  const SourceManager* sources_ = nullptr;
  uint64_t element_count_ = 0;
};

template <typename F>
void XmlElement::ForEachAttributeName(F&& f) const {
  for (_xmlAttr* a = FirstAttribute(); a; a = NextAttribute(a)) f(AttributeName(a));
}


}  // namespace mdlc::xml
