// location_text.h - a source location as diagnostics print it:
// "file:line:col" ("file:line" without a column, "file" without a line,
// "mdlc" for no location). The text renderer (diag_printers.cc) and the
// command line's count of repeated warnings say places the same way.
#pragma once

#include <string>

#include "ir/source_manager.h"

namespace mdlc {

std::string LocationText(Loc loc, const SourceManager& sources);

}  // namespace mdlc
