// unknown_element.h - the warning for a child element a format does not
// define, with the closest one it does define when the tag looks like a
// misspelling (<inertail> in <link>: did you mean <inertial>?).
#pragma once

#include <initializer_list>
#include <string_view>

#include "frontend/xml/xml_document.h"
#include "ir/diagnostics.h"

namespace mdlc::frontend {

/// "unknown element <tag> in <parent> is ignored" at `child`, and a note
/// naming the closest of `known` (the children `parent` may have), if any is
/// close enough to be a typo.
void ReportUnknownElement(DiagnosticEngine& diags, const xml::XmlElement& child,
                          std::string_view parent, std::initializer_list<std::string_view> known);

}  // namespace mdlc::frontend
