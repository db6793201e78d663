#include "frontend/xml/xml_document.h"

#include <libxml/parser.h>
#include <libxml/SAX2.h>
#include <libxml/tree.h>
#include <libxml/xmlerror.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <mutex>
#include <vector>

#include "frontend/xml/dom_arena.h"

namespace mdlc::xml {
namespace {

// Each node's position is stored in its `_private` slot as line and column
// packed in one word (line in the high half); 0 means "unknown".
void SetLineColumn(void*& slot, Loc loc) {
  slot = reinterpret_cast<void*>((static_cast<uintptr_t>(loc.line) << 32) | loc.column);
}
std::optional<Loc> GetLineColumn(void* slot, FileId file) {
  auto v = reinterpret_cast<uintptr_t>(slot);
  if (v == 0) return std::nullopt;
  return Loc{file, static_cast<uint32_t>(v >> 32), static_cast<uint32_t>(v & 0xffffffffu)};
}

// Line and column of offsets met in increasing order, found by counting the
// newlines passed since the last one: one pass over the text in all, where a
// search of the line table per element and attribute cost a tenth of lowering
// a large model.
class LineTracker {
 public:
  LineTracker(std::string_view text, FileId file, const SourceManager& sources)
      : text_(text), file_(file), sources_(sources) {}

  Loc At(size_t offset) {
    if (offset < scanned_) return sources_.LocForOffset(file_, offset);  // a guard: callers go forward
    const char* data = text_.data();
    for (const char* p = data + scanned_; (p = static_cast<const char*>(
                                               std::memchr(p, '\n', offset - (p - data))));) {
      ++p;
      ++line_;
      line_start_ = static_cast<size_t>(p - data);
    }
    scanned_ = offset;
    return Loc{file_, line_, static_cast<uint32_t>(offset - line_start_ + 1)};
  }

 private:
  std::string_view text_;
  FileId file_;
  const SourceManager& sources_;
  size_t scanned_ = 0;     // newlines before here are counted
  uint32_t line_ = 1;      // the line `scanned_` is on
  size_t line_start_ = 0;  // that line's first offset
};

// No document may pull in anything from outside: refuse every external load.
xmlParserInputPtr RefuseExternalEntity(const char*, const char*, xmlParserCtxtPtr) { return nullptr; }

// The parser's own guard, behind the scan in Parse: an entity declaration
// the scan missed is never recorded, so no reference can expand; the parse
// stops at once and Parse reports it.
void RefuseEntityDeclaration(void* context, const xmlChar*, int, const xmlChar*, const xmlChar*,
                             xmlChar*) {
  auto* parser = static_cast<xmlParserCtxtPtr>(context);
  *static_cast<bool*>(parser->_private) = true;
  xmlStopParser(parser);
}

void InstallSecurityHooks() {
  static std::once_flag once;
  std::call_once(once, [] {
    DomArena::Install();
    xmlInitParser();
    xmlSetExternalEntityLoader(RefuseExternalEntity);
  });
}

struct ErrorSink {
  DiagnosticEngine* diags;
  FileId file;
  int reported = 0;
};

void OnXmlError(void* user, xmlErrorPtr error) {
  auto* sink = static_cast<ErrorSink*>(user);
  // namespace complaints (an undeclared "drake:" prefix) are not errors for
  // robot formats: names keep their prefix as written
  if (error->domain == XML_FROM_NAMESPACE) return;
  if (error->level == XML_ERR_WARNING) return;
  if (++sink->reported > 20) return;
  std::string message = error->message ? error->message : "unknown XML error";
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  Loc loc{sink->file, static_cast<uint32_t>(error->line > 0 ? error->line : 0),
          static_cast<uint32_t>(error->int2 > 0 ? error->int2 : 0)};
  sink->diags->Report(DiagKind::XmlSyntax, loc, "Failed to parse XML: " + message);
}

// XML name characters (ASCII letters, digits, _ : - . and any non-ASCII byte),
// as a table: this runs for every byte of every start tag
constexpr auto kNameChar = [] {
  std::array<bool, 256> table{};
  for (int c = 0; c < 256; ++c) {
    table[c] = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               c == '_' || c == ':' || c == '-' || c == '.' || c >= 0x80;
  }
  return table;
}();
bool IsNameChar(char c) { return kNameChar[static_cast<unsigned char>(c)]; }

// `text`, NUL-terminated, equals `s`; compared without measuring `text`
// first (attribute lookups run this for every attribute they pass over, so
// most calls end at the first character)
bool CStringEquals(const char* text, std::string_view s) {
  for (char c : s) {
    if (*text++ != c) return false;  // text's NUL mismatches: names hold none
  }
  return *text == '\0';
}

// prefix:name == qualified, without building a string
bool QualifiedNameEquals(const xmlChar* prefix, const xmlChar* name, std::string_view qualified) {
  const char* local = reinterpret_cast<const char*>(name);
  if (!prefix) return CStringEquals(local, qualified);
  size_t i = 0;
  for (const char* p = reinterpret_cast<const char*>(prefix); *p; ++p, ++i) {
    if (i >= qualified.size() || qualified[i] != *p) return false;
  }
  if (i >= qualified.size() || qualified[i] != ':') return false;
  return CStringEquals(local, qualified.substr(i + 1));
}

// Scans markup from `pos`, skipping comments, PIs, CDATA, DOCTYPE and end
// tags, and returns the offset of the next start tag's '<' (npos at the end).
// Reports entity declarations found in a DOCTYPE.
size_t NextStartTag(std::string_view text, size_t pos, std::optional<size_t>* entity_decl) {
  while (true) {
    pos = text.find('<', pos);
    if (pos == std::string_view::npos || pos + 1 >= text.size()) return std::string_view::npos;
    std::string_view rest = text.substr(pos);
    auto skip_past = [&](std::string_view terminator) {
      size_t end = text.find(terminator, pos);
      return end == std::string_view::npos ? text.size() : end + terminator.size();
    };
    if (rest.starts_with("<!--")) {
      pos = skip_past("-->");
    } else if (rest.starts_with("<![CDATA[")) {
      pos = skip_past("]]>");
    } else if (rest.starts_with("<?")) {
      pos = skip_past("?>");
    } else if (rest.starts_with("<!")) {
      // DOCTYPE (with an optional [internal subset]) or another declaration;
      // a quoted ']' or '>' can end the DOCTYPE early here, so a declaration
      // met on its own is checked too
      if (rest.starts_with("<!ENTITY") && entity_decl && !*entity_decl) *entity_decl = pos;
      size_t i = pos + 2;
      int depth = 0;
      for (; i < text.size(); ++i) {
        char c = text[i];
        if (c == '[') ++depth;
        else if (c == ']') --depth;
        else if (c == '>' && depth <= 0) break;
        else if (c == '<' && text.substr(i).starts_with("<!ENTITY") && entity_decl && !*entity_decl)
          *entity_decl = i;
      }
      pos = i + 1;
    } else if (rest[1] == '/') {
      pos = skip_past(">");
    } else {
      return pos;
    }
  }
}

// The source buffer, handed to libxml2 a piece at a time.
struct MemoryStream {
  std::string_view rest;
  static int Read(void* context, char* out, int size) {
    auto* self = static_cast<MemoryStream*>(context);
    const size_t n = std::min(self->rest.size(), static_cast<size_t>(std::max(size, 0)));
    std::memcpy(out, self->rest.data(), n);
    self->rest.remove_prefix(n);
    return static_cast<int>(n);
  }
};

// libxml2's parse of `text`, made while a DomArena scope is active. Leaves
// nothing libxml2 keeps beyond the parse (its thread's last error) pointing
// into the arena. `stopped_at` is where the parser stopped; line 0 when the
// parser could not even be made.
xmlDocPtr ReadInArena(std::string_view text, const char* path, ErrorSink& sink,
                      bool& declared_entity, Loc& stopped_at) {
  xmlSetStructuredErrorFunc(&sink, OnXmlError);
  // NOBLANKS and COMPACT: no nodes for indentation, small text inline; mdlc
  // only reads the tree, and locations come from the buffer itself
  const int options = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                      XML_PARSE_NOWARNING | XML_PARSE_NOERROR | XML_PARSE_NOBLANKS |
                      XML_PARSE_COMPACT;
  xmlDocPtr doc = nullptr;
  if (xmlParserCtxtPtr parser = xmlNewParserCtxt()) {
    parser->_private = &declared_entity;
    parser->sax->entityDecl = RefuseEntityDeclaration;
    // read through callbacks, not xmlCtxtReadMemory, which copies the whole
    // buffer first: the parser then holds a few kilobytes of it at a time
    MemoryStream stream{text};
    doc = xmlCtxtReadIO(parser, MemoryStream::Read, nullptr, &stream, path, nullptr, options);
    stopped_at = Loc{sink.file, static_cast<uint32_t>(std::max(xmlSAX2GetLineNumber(parser), 1)),
                     static_cast<uint32_t>(std::max(xmlSAX2GetColumnNumber(parser), 1))};
    xmlFreeParserCtxt(parser);
  }
  xmlSetStructuredErrorFunc(nullptr, nullptr);
  xmlResetLastError();
  return doc;
}

}  // namespace

// The document lives in arena_: it goes with the arena, never through
// xmlFreeDoc (which would visit every node only to free nothing).
XmlDocument::~XmlDocument() = default;

std::unique_ptr<XmlDocument> XmlDocument::Parse(FileId file, const SourceManager& sources,
                                                DiagnosticEngine& diags) {
  InstallSecurityHooks();
  std::string_view text = sources.Contents(file);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    diags.Report(DiagKind::EmptyFile, Loc{file, 1, 1}, "Failed to parse XML: the file is empty");
    return nullptr;
  }
  // refuse entity declarations before libxml2 ever sees them
  std::optional<size_t> entity_decl;
  const size_t first_tag = NextStartTag(text, 0, &entity_decl);
  if (entity_decl) {
    diags.Report(DiagKind::EntityDeclaration, sources.LocForOffset(file, *entity_decl),
                 "entity declarations are not allowed in robot model files; "
                 "mdlc never expands or fetches entities");
    return nullptr;
  }
  if (first_tag == std::string_view::npos) {
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "Failed to parse XML: no root element");
    return nullptr;
  }

  auto arena = std::make_unique<DomArena>();
  xmlDocPtr doc = nullptr;
  bool declared_entity = false;
  ErrorSink sink{&diags, file};
  Loc stopped_at;
  {
    // every allocation libxml2 makes in here is the arena's
    DomArena::Scope scope(*arena);
    doc = ReadInArena(text, sources.Path(file).c_str(), sink, declared_entity, stopped_at);
  }
  if (!doc && !declared_entity && sink.reported == 0 && stopped_at.line == 0) {
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "Failed to parse XML: out of memory");
    return nullptr;
  }
  if (declared_entity) {
    diags.Report(DiagKind::EntityDeclaration, stopped_at,
                 "entity declarations are not allowed in robot model files; "
                 "mdlc never expands or fetches entities");
    return nullptr;
  }
  if (!doc || sink.reported > 0) {
    if (sink.reported == 0) {
      diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "Failed to parse XML");
    }
    return nullptr;
  }
  std::unique_ptr<XmlDocument> result(new XmlDocument());
  result->arena_ = std::move(arena);
  result->doc_ = doc;
  result->file_ = file;
  result->sources_ = &sources;
  if (!result->AssignLocations(diags)) return nullptr;
  return result;
}

bool XmlDocument::AssignLocations(DiagnosticEngine& diags) {
  std::string_view text = sources_->Contents(file_);
  const Limits& limits = sources_->limits();
  uint64_t elements = 0;
  uint64_t depth = 1;  // of `node`, the root element being 1 deep
  size_t pos = 0;
  LineTracker lines(text, file_, *sources_);
  // iterative pre-order walk over element nodes: document order
  xmlNode* node = xmlDocGetRootElement(doc_);
  while (node) {
    if (node->type == XML_ELEMENT_NODE) {
      pos = NextStartTag(text, pos, nullptr);
      if (pos == std::string_view::npos) break;  // defensive: keep unknown offsets
      SetLineColumn(node->_private, lines.At(pos));
      if (++elements > limits.elements || depth > limits.depth) {
        const bool too_many = elements > limits.elements;
        diags.Report(DiagKind::LimitExceeded, lines.At(pos),
                     too_many ? fmt::format("the document has more than {} elements, the elements "
                                            "limit (raise it with --limit elements=N)",
                                            limits.elements)
                              : fmt::format("element nested {} deep, over the depth limit of {} "
                                            "(raise it with --limit depth=N)",
                                            depth, limits.depth));
        return false;
      }
      // the start tag: "<name attr='v' ...>". libxml2 keeps the attributes
      // in the order written, so the next unplaced one is almost always the
      // one met next; the list is searched only when it is not (xmlns
      // declarations are not attributes)
      xmlAttr* next_unplaced = node->properties;
      size_t i = pos + 1;
      while (i < text.size() && IsNameChar(text[i])) ++i;
      while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size() || text[i] == '>' || text[i] == '/') break;
        const size_t name_start = i;
        while (i < text.size() && IsNameChar(text[i])) ++i;
        std::string_view attr_name = text.substr(name_start, i - name_start);
        while (i < text.size() && text[i] != '"' && text[i] != '\'') ++i;
        if (i >= text.size()) break;
        const char quote = text[i];
        const size_t close = text.find(quote, i + 1);
        i = close == std::string_view::npos ? text.size() : close + 1;
        auto matches = [&](xmlAttr* a) {
          return !a->_private &&
                 QualifiedNameEquals(a->ns ? a->ns->prefix : nullptr, a->name, attr_name);
        };
        xmlAttr* found = next_unplaced && matches(next_unplaced) ? next_unplaced : nullptr;
        for (xmlAttr* a = node->properties; !found && a; a = a->next) {
          if (matches(a)) found = a;
        }
        if (found) {
          SetLineColumn(found->_private, lines.At(name_start));
          if (found == next_unplaced) next_unplaced = found->next;
        }
      }
      pos = i;
      if (node->children) {
        node = node->children;
        ++depth;
        continue;
      }
    } else if (node->type != XML_ENTITY_REF_NODE && node->children &&
               node->type != XML_ATTRIBUTE_NODE) {
      node = node->children;
      ++depth;
      continue;
    }
    // climb until a sibling exists
    while (node && !node->next) {
      node = node->parent;
      --depth;
      if (node && node->type == XML_DOCUMENT_NODE) node = nullptr;
    }
    if (node) node = node->next;
  }
  element_count_ = elements;
  return true;
}

XmlElement XmlDocument::Root() const { return XmlElement(this, xmlDocGetRootElement(doc_)); }

// ---- XmlElement ---------------------------------------------------------------

namespace {
xmlNode* SkipToElement(xmlNode* n) {
  while (n && n->type != XML_ELEMENT_NODE) n = n->next;
  return n;
}
}  // namespace

std::string_view XmlElement::Name() const {
  if (!(node_->ns && node_->ns->prefix)) return reinterpret_cast<const char*>(node_->name);
  return doc_->JoinedName(node_->ns->prefix, node_->name);
}

Loc XmlElement::GetLoc() const {
  if (auto loc = GetLineColumn(node_->_private, doc_->file())) return *loc;
  return Loc{doc_->file(), static_cast<uint32_t>(xmlGetLineNo(node_)), 0};
}

XmlElement XmlElement::FirstChild() const { return XmlElement(doc_, SkipToElement(node_->children)); }
XmlElement XmlElement::NextSibling() const { return XmlElement(doc_, SkipToElement(node_->next)); }

XmlElement XmlElement::Child(std::string_view name) const {
  // compared in place: no name is measured or joined on the way
  for (xmlNode* c = SkipToElement(node_->children); c; c = SkipToElement(c->next)) {
    if (QualifiedNameEquals(c->ns ? c->ns->prefix : nullptr, c->name, name)) {
      return XmlElement(doc_, c);
    }
  }
  return {};
}

XmlElement XmlElement::Parent() const {
  xmlNode* p = node_->parent;
  return XmlElement(doc_, p && p->type == XML_ELEMENT_NODE ? p : nullptr);
}

_xmlAttr* XmlElement::FirstAttribute() const { return node_->properties; }
_xmlAttr* XmlElement::NextAttribute(_xmlAttr* attr) { return attr->next; }

XmlAttribute XmlElement::MakeAttribute(_xmlAttr* a) const {
  XmlAttribute out;
  out.name = AttributeName(a);
  if (a->children && a->children->content && !a->children->next) {
    out.value = reinterpret_cast<const char*>(a->children->content);
  } else if (a->children) {
    // values with entity references: only the literal text segments
    out.value = reinterpret_cast<const char*>(a->children->content ? a->children->content
                                                                   : BAD_CAST "");
  }
  if (auto loc = GetLineColumn(a->_private, doc_->file())) {
    out.loc = *loc;
  } else {
    out.loc = GetLoc();
  }
  return out;
}

XmlAttribute XmlElement::Attribute(std::string_view name) const {
  if (name.empty()) return {};
  for (xmlAttr* a = node_->properties; a; a = a->next) {
    const xmlChar* prefix = a->ns ? a->ns->prefix : nullptr;
    // most attributes passed over differ in the first character
    if (static_cast<char>(prefix ? prefix[0] : a->name[0]) != name[0]) continue;
    if (QualifiedNameEquals(prefix, a->name, name)) return MakeAttribute(a);
  }
  return {};
}

uint64_t XmlElement::AttributeNameBits() const {
  uint64_t bits = 0;
  for (xmlAttr* a = node_->properties; a; a = a->next) {
    const xmlChar* prefix = a->ns ? a->ns->prefix : nullptr;
    if (prefix) {
      bits |= NameBitOf(static_cast<char>(prefix[0]), prefix[1] ? static_cast<char>(prefix[1]) : ':');
    } else {
      bits |= NameBitOf(static_cast<char>(a->name[0]), static_cast<char>(a->name[0] ? a->name[1] : 0));
    }
  }
  return bits;
}

std::string_view XmlElement::AttributeName(_xmlAttr* a) const {
  if (!(a->ns && a->ns->prefix)) return reinterpret_cast<const char*>(a->name);
  return doc_->JoinedName(a->ns->prefix, a->name);
}

std::string_view XmlDocument::JoinedName(const unsigned char* prefix,
                                         const unsigned char* name) const {
  auto [it, inserted] = joined_names_.try_emplace({prefix, name});
  if (inserted) {
    it->second = std::string(reinterpret_cast<const char*>(prefix)) + ':' +
                 reinterpret_cast<const char*>(name);
  }
  return it->second;
}

std::string XmlElement::Text() const {
  std::string out;
  for (xmlNode* c = node_->children; c; c = c->next) {
    if ((c->type == XML_TEXT_NODE || c->type == XML_CDATA_SECTION_NODE) && c->content) {
      out += reinterpret_cast<const char*>(c->content);
    }
  }
  return out;
}

std::string_view XmlElement::TextView(std::string& storage) const {
  xmlNode* only = node_->children;
  if (!only) return {};
  if (!only->next && (only->type == XML_TEXT_NODE || only->type == XML_CDATA_SECTION_NODE) &&
      only->content) {
    return reinterpret_cast<const char*>(only->content);
  }
  storage = Text();
  return storage;
}

std::vector<std::string> XmlElement::Comments() const {
  std::vector<std::string> out;
  for (xmlNode* c = node_->children; c; c = c->next) {
    if (c->type == XML_COMMENT_NODE && c->content) {
      out.emplace_back(reinterpret_cast<const char*>(c->content));
    }
  }
  return out;
}

}  // namespace mdlc::xml
