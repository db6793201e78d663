// load_report.h - reporting a file SourceManager::LoadFile did not read.
#pragma once

#include <string_view>

#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc {

/// Reports `error` at `at`: a file over an input limit as limit-exceeded
/// with the limit's own message; an unreadable one as file-not-found,
/// `cannot_read` (e.g. "cannot read the included file 'x'") then its cause.
void ReportLoadError(DiagnosticEngine& diags, Loc at, const LoadError& error,
                     std::string_view cannot_read);

}  // namespace mdlc
