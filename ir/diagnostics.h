// diagnostics.h - the diagnostic engine: errors, warnings and notes with
// source locations, a policy (-Werror, -W<group>), and pluggable consumers.
//
// Emitting never throws. A frontend or pass that reports an error keeps going
// where it can, so one run reports as many independent problems as possible;
// the pass manager stops at the next pass boundary once an error exists.
//
//   diags.Report(DiagKind::UnknownReference, loc, "joint 'j' names unknown link 'x'")
//       .Note(link_loc, "did you mean 'y'?");
//
// The diagnostic is delivered when the returned InFlightDiagnostic goes out
// of scope, after any notes were attached.
#pragma once

#include <functional>
#include <string>
#include <span>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "ir/location.h"

namespace mdlc {

class SourceManager;

enum class Severity { Note, Warning, Error };

enum class DiagKind {
#define DIAG(id, severity, group, name) id,
#include "ir/diagnostic_kinds.def"
#undef DIAG
};

struct DiagKindInfo {
  Severity default_severity;
  std::string_view group;
  std::string_view name;
};
const DiagKindInfo& InfoFor(DiagKind kind);
/// Every kind's facts, in DiagKind order: the one walk of diagnostic_kinds.def
/// that the option checker and `--list-warnings` read their groups from.
std::span<const DiagKindInfo> AllDiagKindInfo();
std::string_view SeverityName(Severity s);

struct DiagnosticNote {
  Loc loc;
  std::string message;
};

struct Diagnostic {
  DiagKind kind;
  Severity severity;
  Loc loc;
  std::string message;
  std::vector<DiagnosticNote> notes;
};

class DiagnosticEngine;

/// A diagnostic being built; delivered to the engine on destruction.
class InFlightDiagnostic {
 public:
  InFlightDiagnostic(DiagnosticEngine* engine, Diagnostic diag)
      : engine_(engine), diag_(std::move(diag)) {}
  InFlightDiagnostic(InFlightDiagnostic&& other) noexcept
      : engine_(other.engine_), diag_(std::move(other.diag_)) {
    other.engine_ = nullptr;
  }
  InFlightDiagnostic(const InFlightDiagnostic&) = delete;
  ~InFlightDiagnostic();

  InFlightDiagnostic& Note(Loc loc, std::string message) & {
    diag_.notes.push_back({loc, std::move(message)});
    return *this;
  }
  InFlightDiagnostic&& Note(Loc loc, std::string message) && {
    diag_.notes.push_back({loc, std::move(message)});
    return std::move(*this);
  }

 private:
  DiagnosticEngine* engine_;
  Diagnostic diag_;
};

/// What the user asked for on the command line (-Werror, -Wno-x, ...).
struct DiagnosticPolicy {
  bool warnings_as_errors = false;                 // -Werror / --strict
  std::unordered_set<std::string> disabled_groups;  // -Wno-<group>
  std::unordered_set<std::string> error_groups;     // -Werror=<group>
  size_t max_errors = 0;                            // 0 = unlimited
};

class DiagnosticEngine {
 public:
  using Consumer = std::function<void(const Diagnostic&)>;

  DiagnosticEngine() = default;
  explicit DiagnosticEngine(DiagnosticPolicy policy) : policy_(std::move(policy)) {}

  // Cold: the compiler moves every path that reports out of the hot code,
  // so a reader's per-element code stays small in the instruction cache.
  [[gnu::cold]] InFlightDiagnostic Report(DiagKind kind, Loc loc, std::string message) {
    return InFlightDiagnostic(this, Diagnostic{kind, InfoFor(kind).default_severity, loc,
                                               std::move(message), {}});
  }

  /// Replaces the consumer (default: keep diagnostics in `diagnostics()`).
  void SetConsumer(Consumer consumer) { consumer_ = std::move(consumer); }
  DiagnosticPolicy& policy() { return policy_; }

  size_t error_count() const { return error_count_; }
  size_t warning_count() const { return warning_count_; }
  bool has_errors() const { return error_count_ > 0; }
  /// Everything delivered so far when no consumer is set.
  const std::vector<Diagnostic>& diagnostics() const { return stored_; }
  std::vector<Diagnostic> TakeDiagnostics() { return std::exchange(stored_, {}); }

 private:
  friend class InFlightDiagnostic;
  void Deliver(Diagnostic diag);

  DiagnosticPolicy policy_;
  Consumer consumer_;
  std::vector<Diagnostic> stored_;
  size_t error_count_ = 0;
  size_t warning_count_ = 0;
  bool flood_reported_ = false;
};

/// Clang-style text: "file:line:col: error: message [-Wgroup]", the source
/// line with a caret, then notes and "in file included from" lines.
std::string FormatDiagnosticText(const Diagnostic& diag, const SourceManager& sources,
                                 bool color = false);
/// One JSON object on one line: severity, kind, group, message, file, line,
/// column, notes, include chain.
std::string FormatDiagnosticJson(const Diagnostic& diag, const SourceManager& sources);

}  // namespace mdlc
