#include "sax_floor.h"

#include <libxml/parser.h>
#include <libxml/SAX2.h>

#include "frontend/xml/memory_stream.h"

namespace mdlc::bench {
namespace {

// the handler slots frontend/xml/tree_builder.cc sets, each doing nothing
void IgnoreStart(void*, const xmlChar*, const xmlChar*, const xmlChar*, int, const xmlChar**,
                 int, int, const xmlChar**) {}
void IgnoreEnd(void*, const xmlChar*, const xmlChar*, const xmlChar*) {}
void IgnoreCharacters(void*, const xmlChar*, int) {}
void IgnoreComment(void*, const xmlChar*) {}
void IgnoreProcessingInstruction(void*, const xmlChar*, const xmlChar*) {}
void IgnoreEntityDeclaration(void*, const xmlChar*, int, const xmlChar*, const xmlChar*,
                             xmlChar*) {}
xmlEntityPtr NoEntity(void*, const xmlChar* name) { return xmlGetPredefinedEntity(name); }
xmlEntityPtr NoParameterEntity(void*, const xmlChar*) { return nullptr; }

}  // namespace

bool ParseWithEmptySaxHandlers(std::string_view text) {
  xmlParserCtxtPtr parser = xmlNewParserCtxt();
  if (!parser) return false;
  xmlSAXHandler& sax = *parser->sax;
  sax.startDocument = nullptr;
  sax.endDocument = nullptr;
  sax.internalSubset = nullptr;
  sax.externalSubset = nullptr;
  sax.reference = nullptr;
  sax.startElementNs = IgnoreStart;
  sax.endElementNs = IgnoreEnd;
  sax.characters = IgnoreCharacters;
  sax.ignorableWhitespace = IgnoreCharacters;
  sax.cdataBlock = IgnoreCharacters;
  sax.comment = IgnoreComment;
  sax.processingInstruction = IgnoreProcessingInstruction;
  sax.entityDecl = IgnoreEntityDeclaration;
  sax.getEntity = NoEntity;
  sax.getParameterEntity = NoParameterEntity;
  // mdlc's reader's options (xml_document.cc)
  const int options = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                      XML_PARSE_NOWARNING | XML_PARSE_NOERROR;
  // read as XmlDocument::Parse reads
  xml::MemoryStream stream{text};
  xmlFreeDoc(
      xmlCtxtReadIO(parser, xml::MemoryStream::Read, nullptr, &stream, "bench.xml", nullptr, options));
  const bool well_formed = parser->wellFormed != 0;
  xmlFreeParserCtxt(parser);
  return well_formed;
}

void TimeEmptySaxParse(benchmark::State& state, std::string_view text) {
  for (auto _ : state) {
    if (!ParseWithEmptySaxHandlers(text)) state.SkipWithError("libxml2 rejected the model");
  }
}

}  // namespace mdlc::bench
