// verify_diagnostics.h - `--verify-diagnostics`: checks the diagnostics a
// compile produced against expectations written in the input files
// themselves, as MLIR's -verify-diagnostics does:
//
//   <!-- expected-error@+1 {{unknown link 'x'}} -->
//   <joint name="j" ...>
//
// `expected-error`, `expected-warning` or `expected-note`, optionally with
// `@+N`, `@-N` (relative line) or `@N` (absolute line); without it the
// comment's own line. The text in {{ }} must occur in the message. Every
// expectation must be met and every error and warning expected.
#pragma once

#include <string>
#include <vector>

#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::tools {

/// Returns the problems found (empty when everything matched).
std::vector<std::string> VerifyDiagnostics(const std::vector<Diagnostic>& diagnostics,
                                           const SourceManager& sources);

}  // namespace mdlc::tools
