#include "ir/load_report.h"

#include <fmt/format.h>

namespace mdlc {

void ReportLoadError(DiagnosticEngine& diags, Loc at, const LoadError& error,
                     std::string_view cannot_read) {
  if (error.over_limit) {
    diags.Report(DiagKind::LimitExceeded, at, error.message);
    return;
  }
  diags.Report(DiagKind::FileNotFound, at,
               error.message.empty() ? std::string(cannot_read)
                                     : fmt::format("{}: {}", cannot_read, error.message));
}

}  // namespace mdlc
