#include "ir/diagnostics.h"

#include <array>
#include <utility>

namespace mdlc {

namespace {
constexpr std::array kKindInfo = {
#define DIAG(id, severity, group, name) DiagKindInfo{Severity::severity, group, name},
#include "ir/diagnostic_kinds.def"
#undef DIAG
};
}  // namespace

const DiagKindInfo& InfoFor(DiagKind kind) { return kKindInfo[static_cast<size_t>(kind)]; }
std::span<const DiagKindInfo> AllDiagKindInfo() { return kKindInfo; }

std::string_view SeverityName(Severity s) {
  switch (s) {
    case Severity::Note: return "note";
    case Severity::Warning: return "warning";
    case Severity::Error: return "error";
  }
  return "error";
}

InFlightDiagnostic::~InFlightDiagnostic() {
  if (engine_) engine_->Deliver(std::move(diag_));
}

void DiagnosticEngine::Deliver(Diagnostic diag) {
  const std::string group(InfoFor(diag.kind).group);
  // apply the policy: warnings and notes can be silenced, only warnings promoted
  if (diag.severity != Severity::Error && policy_.disabled_groups.count(group)) return;
  if (diag.severity == Severity::Warning) {
    if (policy_.warnings_as_errors || policy_.error_groups.count(group)) {
      diag.severity = Severity::Error;
    }
  }
  if (diag.severity == Severity::Error) {
    if (policy_.max_errors && error_count_ >= policy_.max_errors) {
      // past the limit: count, but deliver only one "too many errors"
      ++error_count_;
      if (flood_reported_) return;
      flood_reported_ = true;
      diag = Diagnostic{DiagKind::TooManyErrors, Severity::Error, {},
                        "too many errors emitted, stopping now", {}};
    } else {
      ++error_count_;
    }
  } else if (diag.severity == Severity::Warning) {
    ++warning_count_;
  }
  if (consumer_) {
    consumer_(diag);
  } else {
    stored_.push_back(std::move(diag));
  }
}

}  // namespace mdlc
