#include "frontend/xml/xml_document.h"

#include <libxml/parser.h>
#include <libxml/SAX2.h>
#include <libxml/xmlerror.h>

#include <fmt/format.h>

#include <algorithm>

#include "frontend/xml/memory_stream.h"
#include "frontend/xml/start_tags.h"
#include "frontend/xml/tree_builder.h"
#include "frontend/xml/xml_declaration.h"
#include "ir/assets/xml_guard.h"

namespace mdlc::xml {
namespace {

struct ErrorSink {
  DiagnosticEngine* diags;
  FileId file;
  int reported = 0;
};

void OnXmlError(void* user, xmlErrorPtr error) {
  auto* sink = static_cast<ErrorSink*>(user);
  assets::ReportXmlError(*error, sink->file, sink->reported, *sink->diags);
}

// What libxml2's parse left: whether the text was well formed, where the
// parser stopped (line 0 when it could not even be made) and its name
// dictionary, which the tree's names point into (null on failure).
struct ParseOutcome {
  bool well_formed = false;
  Loc stopped_at;
  xmlDictPtr names = nullptr;
};

// libxml2's parse of `text` into `builder`'s tree; `version`, when set, is
// a declared version libxml2 would refuse, read as "1.0" instead.
ParseOutcome ParseInto(TreeBuilder& builder, std::string_view text,
                       const std::optional<DeclaredVersion>& version, const char* path,
                       ErrorSink& sink) {
  xmlSetStructuredErrorFunc(&sink, OnXmlError);
  const int options = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                      XML_PARSE_NOWARNING | XML_PARSE_NOERROR;
  ParseOutcome outcome;
  if (xmlParserCtxtPtr parser = xmlNewParserCtxt()) {
    TreeBuilder::Install(*parser->sax);
    parser->_private = &builder;
    // read through callbacks, not xmlCtxtReadMemory, which copies the whole
    // buffer first: the parser then holds a few kilobytes of it at a time.
    // With no startDocument handler libxml2 makes no document, except a
    // stand-in it may make to hold a DTD's declarations: freed unread.
    MemoryStream stream{text};
    std::string mended;  // the declaration, with a version libxml2 reads
    if (version) {
      const size_t value_end = version->offset + version->value.size();
      mended = std::string(text.substr(0, version->offset)) + "1.0";
      stream = MemoryStream{mended, text.substr(value_end)};
    }
    xmlFreeDoc(xmlCtxtReadIO(parser, MemoryStream::Read, nullptr, &stream, path, nullptr, options));
    outcome.well_formed = parser->wellFormed != 0;
    outcome.stopped_at =
        Loc{sink.file, static_cast<uint32_t>(std::max(xmlSAX2GetLineNumber(parser), 1)),
            static_cast<uint32_t>(std::max(xmlSAX2GetColumnNumber(parser), 1))};
    if (outcome.well_formed && parser->dict && xmlDictReference(parser->dict) == 0) {
      outcome.names = parser->dict;
    }
    xmlFreeParserCtxt(parser);
  }
  xmlSetStructuredErrorFunc(nullptr, nullptr);
  xmlResetLastError();
  return outcome;
}

}  // namespace

XmlDocument::~XmlDocument() {
  if (names_) xmlDictFree(names_);
}

std::unique_ptr<XmlDocument> XmlDocument::Parse(FileId file, const SourceManager& sources,
                                                DiagnosticEngine& diags,
                                                const ParseOptions& options) {
  assets::InstallXmlSecurityHooks();
  std::string_view text = sources.Contents(file);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    diags.Report(DiagKind::EmptyFile, Loc{file, 1, 1}, assets::kEmptyXmlFile);
    return nullptr;
  }
  // refuse entity declarations before libxml2 ever sees them
  std::optional<size_t> entity_decl;
  const size_t first_tag = NextStartTag(text, 0, &entity_decl);
  if (entity_decl) {
    diags.Report(DiagKind::EntityDeclaration, sources.LocForOffset(file, *entity_decl),
                 assets::kEntityDeclarationRefused);
    return nullptr;
  }
  if (first_tag == std::string_view::npos) {
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "malformed XML: no root element");
    return nullptr;
  }

  const std::optional<DeclaredVersion> version = UnsupportedXmlVersion(text);
  if (version) {
    diags.Report(DiagKind::XmlWarning, sources.LocForOffset(file, version->offset),
                 fmt::format("the XML declaration names version '{}'; read as XML 1.0",
                             version->value));
  }

  std::unique_ptr<XmlDocument> document(new XmlDocument());
  document->file_ = file;
  document->sources_ = &sources;
  TreeBuilder builder(file, sources, document->arena_, diags);
  builder.set_keep_blank_text(options.keep_blank_text);
  builder.set_keep_namespace_declarations(options.keep_namespace_declarations);
  ErrorSink sink{&diags, file};
  const ParseOutcome outcome = ParseInto(builder, text, version, sources.Path(file).c_str(), sink);
  document->names_ = outcome.names;
  if (outcome.stopped_at.line == 0) {
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "the XML parser ran out of memory");
    return nullptr;
  }
  if (builder.declared_entity()) {
    diags.Report(DiagKind::EntityDeclaration, outcome.stopped_at,
                 assets::kEntityDeclarationRefused);
    return nullptr;
  }
  if (builder.over_limit()) return nullptr;  // reported where the limit was passed
  if (!outcome.well_formed || sink.reported > 0 || !builder.root() || !outcome.names) {
    if (sink.reported == 0) {
      diags.Report(DiagKind::XmlSyntax, outcome.stopped_at, "malformed XML");
    }
    return nullptr;
  }
  document->root_ = builder.root();
  document->element_counts_ = builder.TakeElementCounts();
  document->outside_comments_ = builder.TakeOutsideComments();
  return document;
}

std::unique_ptr<XmlDocument> XmlDocument::SameTextAs(std::shared_ptr<const XmlDocument> original,
                                                     FileId file) {
  std::unique_ptr<XmlDocument> doc(new XmlDocument());
  doc->root_ = original->root_;
  doc->file_ = file;
  doc->sources_ = original->sources_;
  doc->element_counts_ = original->element_counts_;
  doc->original_ = std::move(original);
  return doc;
}

XmlElement XmlDocument::Root() const { return XmlElement(this, root_); }

// ---- XmlElement ---------------------------------------------------------------

Loc XmlElement::GetLoc() const {
  const FileId file = node_->file == UINT32_MAX ? doc_->file() : FileId{node_->file};
  return Loc{file, node_->line, node_->column};
}

XmlElement XmlElement::Child(std::string_view name) const {
  if (!(node_->child_name_bits & NameBit(name))) return {};
  for (const detail::ElementNode* c = node_->first_child; c; c = c->next_sibling) {
    if (SameName(c->name, name)) return XmlElement(doc_, c);
  }
  return {};
}

XmlAttribute XmlElement::Attribute(std::string_view name) const {
  for (uint32_t i = 0; i < node_->attribute_count; ++i) {
    const detail::AttributeNode& a = node_->attributes[i];
    if (!SameName(a.name, name)) continue;
    // an attribute the scan could not place is reported at its element
    const Loc element = GetLoc();
    return XmlAttribute{a.name, a.value,
                        a.line ? Loc{element.file, a.line, a.column} : element};
  }
  return {};
}

std::string XmlElement::Text() const {
  std::string out;
  for (const detail::ContentNode* c = node_->content; c; c = c->next) {
    if (c->kind != detail::ContentKind::kComment) out += c->text;
  }
  return out;
}

std::string_view XmlElement::TextView(std::string& storage) const {
  const detail::ContentNode* text = nullptr;
  for (const detail::ContentNode* c = node_->content; c; c = c->next) {
    if (c->kind == detail::ContentKind::kComment) continue;
    if (text) {  // more than one piece: joined
      storage = Text();
      return storage;
    }
    text = c;
  }
  return text ? text->text : std::string_view();
}

std::vector<std::string> XmlElement::Comments() const {
  std::vector<std::string> out;
  for (const detail::ContentNode* c = node_->content; c; c = c->next) {
    if (c->kind == detail::ContentKind::kComment) out.emplace_back(c->text);
  }
  return out;
}

}  // namespace mdlc::xml
