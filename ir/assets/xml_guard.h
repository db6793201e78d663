// xml_guard.h - what every libxml2 parse in mdlc shares: the hooks that keep
// a document from reaching outside itself, the words for what is refused,
// and libxml2's errors as diagnostics. It sits in the lowest layer that reads
// XML (package.xml, here), so the format readers' hardened parse
// (frontend/xml) and the package manifest reader use one copy.
#pragma once

#include <libxml/xmlerror.h>

#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::assets {

/// Initialises libxml2 once and refuses every external load (DTDs,
/// external entities), for every parse in the process.
void InstallXmlSecurityHooks();

/// An entity declaration is refused before libxml2 expands anything.
inline constexpr const char* kEntityDeclarationRefused =
    "entity declarations are not allowed in robot model files; "
    "mdlc never expands or fetches entities";
/// A file of blanks only.
inline constexpr const char* kEmptyXmlFile =
    "the file is empty; an XML model needs a root element";

/// Reports libxml2's `error` in `file` as a "malformed XML" error; namespace
/// complaints and warnings are not errors, and only the first 20 are shown
/// (`reported` counts them).
void ReportXmlError(const xmlError& error, FileId file, int& reported, DiagnosticEngine& diags);

}  // namespace mdlc::assets
