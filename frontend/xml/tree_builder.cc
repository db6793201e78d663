#include "frontend/xml/tree_builder.h"

#include <libxml/parser.h>
#include <libxml/SAX2.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "frontend/xml/trim.h"
#include "frontend/xml/xml_document.h"

namespace mdlc::xml {
namespace {

TreeBuilder& BuilderOf(void* ctx) {
  return *static_cast<TreeBuilder*>(static_cast<xmlParserCtxtPtr>(ctx)->_private);
}

std::string_view View(const unsigned char* s) { return reinterpret_cast<const char*>(s); }

// Entity lookups, the last guard against expansion. After a fatal error
// libxml2 stops calling the handlers, OnEntityDeclaration among them, yet
// still records an internal entity's declaration for itself and expands
// references to it in attribute values; a lookup that knows only XML's five
// predefined entities leaves every declared one undefined, whatever was
// recorded.
xmlEntityPtr PredefinedEntityOnly(void*, const xmlChar* name) {
  return xmlGetPredefinedEntity(name);
}
xmlEntityPtr NoParameterEntity(void*, const xmlChar*) { return nullptr; }

// XML's four blank characters only. Indentation is most of the text of a
// deeply nested document, so runs of spaces are passed eight at a time.
bool IsBlank(std::string_view text) {
  constexpr uint64_t kEightSpaces = 0x2020202020202020ull;
  const char* p = text.data();
  const char* const end = p + text.size();
  while (p < end) {
    uint64_t word;
    if (end - p >= 8 && (std::memcpy(&word, p, 8), word == kEightSpaces)) {
      p += 8;
      continue;
    }
    if (!IsXmlSpace(*p)) return false;
    ++p;
  }
  return true;
}

// Whether every byte of `text` is ASCII, eight at a time.
bool IsAscii(std::string_view text) {
  constexpr uint64_t kHighBits = 0x8080808080808080ull;
  const char* p = text.data();
  const char* const end = p + text.size();
  for (uint64_t word; end - p >= 8; p += 8) {
    std::memcpy(&word, p, 8);
    if (word & kHighBits) return false;
  }
  for (; p < end; ++p) {
    if (static_cast<unsigned char>(*p) >= 0x80) return false;
  }
  return true;
}

// Every node type initializes each member where it is declared, so `new T`
// sets them one store at a time. `new T()` would zero the whole node first,
// which the compiler does with a string instruction slow to start, once for
// every element of the document.
template <typename T>
T* Make(BlockCarver& arena) {
  return new (arena.Allocate(sizeof(T), alignof(T))) T;
}

}  // namespace

void* BlockCarver::Refill(size_t bytes, size_t alignment) {
  bytes = std::max<size_t>(bytes, 1);
  // a large piece gets its own allocation, so the current block's rest
  // stays in use; otherwise that rest (a few bytes, as a rule) is left
  if (bytes > kBlockSize / 4) return arena_.allocate(bytes, alignment);
  cursor_ = static_cast<char*>(arena_.allocate(kBlockSize, alignof(std::max_align_t)));
  end_ = cursor_ + kBlockSize;
  return Allocate(bytes, alignment);
}

TreeBuilder::TreeBuilder(FileId file, const SourceManager& sources,
                         std::pmr::memory_resource& arena, DiagnosticEngine& diags)
    : file_(file),
      arena_(arena),
      diags_(diags),
      limits_(sources.limits()),
      locator_(sources.Contents(file)) {}

void TreeBuilder::Install(_xmlSAXHandler& sax) {
  // no libxml2 DOM at all: with these unset it makes no document, DTD or
  // entity reference nodes
  sax.startDocument = nullptr;
  sax.endDocument = nullptr;
  sax.internalSubset = nullptr;
  sax.externalSubset = nullptr;
  sax.reference = nullptr;  // unknown references are errors, or skipped
  sax.startElementNs = OnStartElement;
  sax.endElementNs = OnEndElement;
  sax.characters = OnCharacters;
  sax.ignorableWhitespace = OnCharacters;  // blanks are judged by FlushText
  sax.cdataBlock = OnCdata;
  sax.comment = OnComment;
  sax.processingInstruction = OnProcessingInstruction;
  sax.entityDecl = OnEntityDeclaration;
  sax.getEntity = PredefinedEntityOnly;
  sax.getParameterEntity = NoParameterEntity;
}

// ---- callbacks ----------------------------------------------------------------

void TreeBuilder::OnStartElement(void* ctx, const unsigned char* local,
                                 const unsigned char* prefix, const unsigned char*,
                                 int namespace_count, const unsigned char** namespaces,
                                 int attribute_count, int defaulted_count,
                                 const unsigned char** attributes) {
  // attributes a DTD would default come last; like libxml2's own DOM
  // (without XML_PARSE_DTDATTR), mdlc ignores them
  TreeBuilder& self = BuilderOf(ctx);
  if (!self.keep_namespace_declarations_) namespace_count = 0;
  self.StartElement(ctx, local, prefix, namespace_count, namespaces,
                    attribute_count - defaulted_count, attributes);
}

void TreeBuilder::OnEndElement(void* ctx, const unsigned char*, const unsigned char*,
                               const unsigned char*) {
  BuilderOf(ctx).EndElement();
}

void TreeBuilder::OnCharacters(void* ctx, const unsigned char* text, int length) {
  TreeBuilder& self = BuilderOf(ctx);
  if (self.open_.empty()) return;
  const std::string_view chunk(reinterpret_cast<const char*>(text), static_cast<size_t>(length));
  if (self.pending_blank_ && !IsBlank(chunk)) self.pending_blank_ = false;
  if (!self.pending_marks_ && !chunk.empty() && (IsXmlSpace(chunk[0]) || !IsAscii(chunk))) {
    self.pending_marks_ = true;
  }
  self.pending_text_.append(chunk);
}

void TreeBuilder::OnCdata(void* ctx, const unsigned char* text, int length) {
  TreeBuilder& self = BuilderOf(ctx);
  if (self.open_.empty()) return;
  self.FlushText(false);
  self.AddContent(detail::ContentKind::kCdata,
                  self.Copy({reinterpret_cast<const char*>(text), static_cast<size_t>(length)}));
}

void TreeBuilder::OnComment(void* ctx, const unsigned char* text) {
  TreeBuilder& self = BuilderOf(ctx);
  if (self.open_.empty()) {
    // comments outside the root belong to no element; a writer keeps them
    if (self.keep_namespace_declarations_) {
      self.outside_comments_.emplace_back(self.Copy(View(text)), self.root_ != nullptr);
    }
    return;
  }
  self.FlushText(false);
  self.AddContent(detail::ContentKind::kComment, self.Copy(View(text)));
}

void TreeBuilder::OnProcessingInstruction(void* ctx, const unsigned char*, const unsigned char*) {
  TreeBuilder& self = BuilderOf(ctx);
  if (self.open_.empty()) return;
  // a child nobody reads, which still decides whether nearby blanks stay
  self.FlushText(false);
  self.NoteOtherChild();
}

// The parser's own guard, behind Parse's scan: an entity declaration the
// scan missed is never recorded, so no reference can expand; the parse
// stops at once and Parse reports it.
void TreeBuilder::OnEntityDeclaration(void* ctx, const unsigned char*, int, const unsigned char*,
                                      const unsigned char*, unsigned char*) {
  BuilderOf(ctx).declared_entity_ = true;
  xmlStopParser(static_cast<xmlParserCtxtPtr>(ctx));
}

// ---- building -----------------------------------------------------------------

void TreeBuilder::StartElement(void* parser, const unsigned char* local,
                               const unsigned char* prefix, int namespace_count,
                               const unsigned char** namespaces, int attribute_count,
                               const unsigned char** attributes) {
  if (!open_.empty()) {
    FlushText(false);
    NoteOtherChild();
  }
  auto* element = Make<detail::ElementNode>(arena_);
  element->name = QualifiedName(prefix, local);
  element_counts_.Add(element->name);
  if (attribute_count + namespace_count > 0) {
    const int total = attribute_count + namespace_count;
    auto* nodes = static_cast<detail::AttributeNode*>(arena_.Allocate(
        sizeof(detail::AttributeNode) * total, alignof(detail::AttributeNode)));
    // namespace declarations, when kept, come first, as attributes named
    // as written ("xmlns:xacro", "xmlns"); libxml2 gives a (prefix, URI)
    // pair for each
    for (int i = 0; i < namespace_count; ++i) {
      const unsigned char* ns_prefix = namespaces[2 * i];
      auto* node = new (nodes + i) detail::AttributeNode;
      node->name = ns_prefix ? Copy(fmt::format("xmlns:{}", View(ns_prefix))) : Copy("xmlns");
      node->value = Copy(namespaces[2 * i + 1] ? View(namespaces[2 * i + 1]) : "");
      element->attribute_name_bits |= XmlElement::NameBit(node->name);
    }
    // libxml2 gives five pointers per attribute: local name, prefix, URI,
    // and the value's start and end (not NUL-terminated)
    for (int i = 0; i < attribute_count; ++i) {
      const unsigned char** a = attributes + 5 * i;
      auto* node = new (nodes + namespace_count + i) detail::AttributeNode;
      node->name = QualifiedName(a[1], a[0]);
      node->value = CopyValue(
          {reinterpret_cast<const char*>(a[3]), static_cast<size_t>(a[4] - a[3])});
      element->attribute_name_bits |= XmlElement::NameBit(node->name);
    }
    element->attributes = nodes;
    element->attribute_count = static_cast<uint32_t>(total);
  }
  if (!locator_.Place(*element)) {
    // a guard: the scan lost its way, so fall back on libxml2's line
    element->line = static_cast<uint32_t>(
        std::max(xmlSAX2GetLineNumber(static_cast<xmlParserCtxtPtr>(parser)), 1));
  }

  const uint64_t depth = open_.size() + 1;  // the root is 1 deep
  if (++elements_ > limits_.elements || depth > limits_.depth) {
    const Loc at{file_, element->line, element->column};
    diags_.Report(DiagKind::LimitExceeded, at,
                  elements_ > limits_.elements
                      ? fmt::format("the document has more than {} elements, the elements limit "
                                    "(raise it with --limit elements=N)",
                                    limits_.elements)
                      : fmt::format("element nested {} deep, over the depth limit of {} "
                                    "(raise it with --limit depth=N)",
                                    depth, limits_.depth));
    over_limit_ = true;
    xmlStopParser(static_cast<xmlParserCtxtPtr>(parser));
    return;
  }

  if (open_.empty()) {
    root_ = element;
  } else {
    Open& parent = open_.back();
    detail::LinkElementChild(parent.element, parent.last_child, parent.unplaced_content, element,
                             XmlElement::NameBit(element->name));
  }
  open_.push_back(Open{element});
}

void TreeBuilder::EndElement() {
  if (open_.empty()) return;
  FlushText(true);
  open_.pop_back();
}

void TreeBuilder::FlushText(bool at_end_tag) {
  if (pending_text_.empty()) return;
  Open& open = open_.back();
  const bool keep = keep_blank_text_ || !pending_blank_ || open.first_is_text || open.last_is_text ||
                    open.blanks_matter || (at_end_tag && !open.has_children);
  if (keep) {
    if (pending_marks_) open.blanks_matter = true;
    AddContent(detail::ContentKind::kText, Copy(pending_text_));
  }
  pending_text_.clear();
  pending_blank_ = true;
  pending_marks_ = false;
}

void TreeBuilder::AddContent(detail::ContentKind kind, std::string_view text) {
  Open& open = open_.back();
  auto* node = Make<detail::ContentNode>(arena_);
  node->kind = kind;
  node->text = text;
  if (open.last_content) {
    open.last_content->next = node;
  } else {
    open.element->content = node;
  }
  open.last_content = node;
  if (!open.unplaced_content) open.unplaced_content = node;
  if (kind != detail::ContentKind::kText) {
    NoteOtherChild();
    return;
  }
  if (!open.has_children) open.first_is_text = true;
  open.has_children = true;
  open.last_is_text = true;
}

void TreeBuilder::NoteOtherChild() {
  Open& open = open_.back();
  open.has_children = true;
  open.last_is_text = false;
}

std::string_view TreeBuilder::QualifiedName(const unsigned char* prefix,
                                            const unsigned char* local) {
  // libxml2 interns names in its dictionary, which the document keeps
  if (!prefix) return View(local);
  auto [it, inserted] = joined_names_.try_emplace({prefix, local});
  if (inserted) {
    it->second = Copy(fmt::format("{}:{}", View(prefix), View(local)));
  }
  return it->second;
}

std::string_view TreeBuilder::Copy(std::string_view text) {
  auto* out = static_cast<char*>(arena_.Allocate(text.size() + 1, 1));
  std::memcpy(out, text.data(), text.size());
  out[text.size()] = '\0';
  return {out, text.size()};
}

std::string_view TreeBuilder::CopyValue(std::string_view value) {
  std::string_view copy = Copy(value);
  if (value.find('&') == std::string_view::npos) return copy;
  // decode in place: the result is never longer
  char* out = const_cast<char*>(copy.data());
  size_t n = 0;
  for (size_t i = 0; i < copy.size();) {
    if (copy.compare(i, 5, "&#38;") == 0) {
      out[n++] = '&';
      i += 5;
    } else {
      out[n++] = copy[i++];
    }
  }
  out[n] = '\0';
  return {out, n};
}

}  // namespace mdlc::xml
