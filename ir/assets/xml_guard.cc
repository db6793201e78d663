// xml_guard.cc - see xml_guard.h.
#include "ir/assets/xml_guard.h"

#include <libxml/parser.h>

#include <mutex>
#include <string>

namespace mdlc::assets {
namespace {
xmlParserInputPtr RefuseExternalEntity(const char*, const char*, xmlParserCtxtPtr) {
  return nullptr;
}
}  // namespace

void InstallXmlSecurityHooks() {
  static std::once_flag once;
  std::call_once(once, [] {
    xmlInitParser();
    xmlSetExternalEntityLoader(RefuseExternalEntity);
  });
}

void ReportXmlError(const xmlError& error, FileId file, int& reported, DiagnosticEngine& diags) {
  // namespace complaints (an undeclared "drake:" prefix) are not errors for
  // robot formats: names keep their prefix as written
  if (error.domain == XML_FROM_NAMESPACE) return;
  if (error.level == XML_ERR_WARNING) return;
  if (++reported > 20) return;
  std::string message = error.message ? error.message : "unknown XML error";
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  const Loc loc{file, static_cast<uint32_t>(error.line > 0 ? error.line : 0),
                static_cast<uint32_t>(error.int2 > 0 ? error.int2 : 0)};
  diags.Report(DiagKind::XmlSyntax, loc, "malformed XML: " + message);
}

}  // namespace mdlc::assets
