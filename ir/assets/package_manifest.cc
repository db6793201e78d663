#include "ir/assets/package_manifest.h"
#include "ir/assets/xml_guard.h"

#include <libxml/parser.h>
#include <libxml/parserInternals.h>
#include <libxml/SAX2.h>
#include <libxml/xmlerror.h>

#include <algorithm>
#include <climits>
#include <string_view>

namespace mdlc::assets {
namespace {

// Entity lookups know XML's five predefined entities only, so nothing a
// document declares can expand, even where libxml2 records a declaration
// after a fatal error.
xmlEntityPtr PredefinedEntityOnly(void*, const xmlChar* name) {
  return xmlGetPredefinedEntity(name);
}
xmlEntityPtr NoParameterEntity(void*, const xmlChar*) { return nullptr; }

std::string_view View(const xmlChar* s) { return s ? reinterpret_cast<const char*>(s) : ""; }

// What the parse gathers: the manifest, and the state of the walk.
struct Reader {
  FileId file;
  const SourceManager* sources;
  DiagnosticEngine* diags;
  PackageManifest manifest;
  int depth = 0;               // of the element being read; the root is 1
  bool in_export = false;      // inside the root's first <export>
  bool export_seen = false;
  std::string* collecting = nullptr;  // the text being gathered, if any
  int collecting_depth = 0;
  bool declared_entity = false;
  int reported = 0;
};

Reader& ReaderOf(void* ctx) {
  return *static_cast<Reader*>(static_cast<xmlParserCtxtPtr>(ctx)->_private);
}

// Where the start tag libxml2 has just read begins. libxml2 calls the
// start-element handler with its input at the tag's end; no '<' can sit
// inside a tag (not even in an attribute value), so the last '<' before
// there is the tag's. Falls back to libxml2's line when the text does not
// show the expected name there (a guard: a re-encoded document).
Loc StartTagLoc(xmlParserCtxtPtr parser, const Reader& reader, std::string_view qualified) {
  const std::string_view text = reader.sources->Contents(reader.file);
  const long consumed = xmlByteConsumed(parser);
  if (consumed > 0 && !text.empty()) {
    const size_t from = std::min(static_cast<size_t>(consumed), text.size() - 1);
    const size_t open = text.rfind('<', from);
    if (open != std::string_view::npos && text.substr(open + 1).starts_with(qualified)) {
      return reader.sources->LocForOffset(reader.file, open);
    }
  }
  return Loc{reader.file, static_cast<uint32_t>(std::max(xmlSAX2GetLineNumber(parser), 1)), 0};
}

void OnStartElement(void* ctx, const xmlChar* local, const xmlChar* prefix, const xmlChar*, int,
                    const xmlChar**, int, int, const xmlChar**) {
  Reader& reader = ReaderOf(ctx);
  ++reader.depth;
  const std::string qualified =
      prefix ? std::string(View(prefix)) + ":" + std::string(View(local)) : std::string(View(local));
  auto* parser = static_cast<xmlParserCtxtPtr>(ctx);
  if (reader.depth == 1) {
    reader.manifest.root = qualified;
    reader.manifest.root_at = StartTagLoc(parser, reader, qualified);
  } else if (reader.depth == 2 && qualified == "name" && !reader.manifest.name) {
    reader.manifest.name.emplace();
    reader.manifest.name_at = StartTagLoc(parser, reader, qualified);
    reader.collecting = &*reader.manifest.name;
    reader.collecting_depth = 2;
  } else if (reader.depth == 2 && qualified == "export" && !reader.export_seen) {
    reader.export_seen = true;
    reader.in_export = true;
  } else if (reader.depth == 3 && reader.in_export && qualified == "deprecated" &&
             !reader.manifest.deprecated) {
    reader.manifest.deprecated.emplace();
    reader.collecting = &*reader.manifest.deprecated;
    reader.collecting_depth = 3;
  }
}

void OnEndElement(void* ctx, const xmlChar*, const xmlChar*, const xmlChar*) {
  Reader& reader = ReaderOf(ctx);
  if (reader.collecting && reader.depth == reader.collecting_depth) reader.collecting = nullptr;
  if (reader.depth == 2) reader.in_export = false;
  --reader.depth;
}

// An element's text is its own text and CDATA, not its children's (as the
// format readers' XmlElement::Text reads it).
void OnCharacters(void* ctx, const xmlChar* text, int length) {
  Reader& reader = ReaderOf(ctx);
  if (reader.collecting && reader.depth == reader.collecting_depth) {
    reader.collecting->append(reinterpret_cast<const char*>(text), static_cast<size_t>(length));
  }
}

// The parser's own guard, behind the scan in ReadPackageManifest: the
// declaration is never recorded and the parse stops at once.
void OnEntityDeclaration(void* ctx, const xmlChar*, int, const xmlChar*, const xmlChar*, xmlChar*) {
  ReaderOf(ctx).declared_entity = true;
  xmlStopParser(static_cast<xmlParserCtxtPtr>(ctx));
}

void OnXmlError(void* user, xmlErrorPtr error) {
  auto* reader = static_cast<Reader*>(user);
  ReportXmlError(*error, reader->file, reader->reported, *reader->diags);
}

void Install(xmlSAXHandler& sax) {
  // no libxml2 DOM, DTD or entity reference nodes: only these handlers run
  sax.startDocument = nullptr;
  sax.endDocument = nullptr;
  sax.internalSubset = nullptr;
  sax.externalSubset = nullptr;
  sax.reference = nullptr;
  sax.startElementNs = OnStartElement;
  sax.endElementNs = OnEndElement;
  sax.characters = OnCharacters;
  sax.ignorableWhitespace = OnCharacters;
  sax.cdataBlock = OnCharacters;
  sax.comment = nullptr;
  sax.processingInstruction = nullptr;
  sax.entityDecl = OnEntityDeclaration;
  sax.getEntity = PredefinedEntityOnly;
  sax.getParameterEntity = NoParameterEntity;
}

}  // namespace

std::optional<PackageManifest> ReadPackageManifest(FileId file, const SourceManager& sources,
                                                   DiagnosticEngine& diags) {
  InstallXmlSecurityHooks();
  const std::string_view text = sources.Contents(file);
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    diags.Report(DiagKind::EmptyFile, Loc{file, 1, 1}, kEmptyXmlFile);
    return std::nullopt;
  }
  // refused before libxml2 sees it. Stricter than the format readers' scan,
  // which skips comments: a package.xml has no reason to spell this at all.
  if (const size_t at = text.find("<!ENTITY"); at != std::string_view::npos) {
    diags.Report(DiagKind::EntityDeclaration, sources.LocForOffset(file, at), kEntityDeclarationRefused);
    return std::nullopt;
  }

  if (text.size() > static_cast<size_t>(INT_MAX)) {  // libxml2 takes an int length
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "malformed XML: the file is too large");
    return std::nullopt;
  }

  Reader reader{file, &sources, &diags};
  xmlParserCtxtPtr parser = xmlNewParserCtxt();
  if (!parser) {
    diags.Report(DiagKind::XmlSyntax, Loc{file, 1, 1}, "the XML parser ran out of memory");
    return std::nullopt;
  }
  Install(*parser->sax);
  parser->_private = &reader;
  // no XML_PARSE_NOENT (no substitution), no XML_PARSE_DTDLOAD, no network;
  // no XML_PARSE_HUGE either: a package.xml is small, libxml2's limits hold
  const int options = XML_PARSE_NONET | XML_PARSE_BIG_LINES | XML_PARSE_NOWARNING |
                      XML_PARSE_NOERROR;
  xmlSetStructuredErrorFunc(&reader, OnXmlError);
  xmlFreeDoc(xmlCtxtReadMemory(parser, text.data(), static_cast<int>(text.size()),
                               sources.Path(file).c_str(), nullptr, options));
  const bool well_formed = parser->wellFormed != 0;
  const Loc stopped_at{file, static_cast<uint32_t>(std::max(xmlSAX2GetLineNumber(parser), 1)),
                       static_cast<uint32_t>(std::max(xmlSAX2GetColumnNumber(parser), 1))};
  xmlFreeParserCtxt(parser);
  xmlSetStructuredErrorFunc(nullptr, nullptr);
  xmlResetLastError();

  if (reader.declared_entity) {
    diags.Report(DiagKind::EntityDeclaration, stopped_at, kEntityDeclarationRefused);
    return std::nullopt;
  }
  if (!well_formed || reader.reported > 0 || reader.manifest.root.empty()) {
    if (reader.reported == 0) diags.Report(DiagKind::XmlSyntax, stopped_at, "malformed XML");
    return std::nullopt;
  }
  return std::move(reader.manifest);
}

}  // namespace mdlc::assets
