// diagnostic_claims.h - strict diagnostics for the unit-test fixtures.
//
// A test claims each diagnostic it expects, by kind and a substring of the
// message; the fixture then fails the test for every diagnostic that no claim
// covers, so a change that starts emitting a new warning is noticed instead
// of passing silently. A test of a clean model claims nothing and so asserts
// that the model lowers without a single diagnostic.
//
//   r.ExpectDiagnostic(DiagKind::UnsupportedElement, "drake:foo");  // must be emitted
//   r.ExpectError("drake:foo");  // an error of any kind, for tests that check only that
//   EXPECT_TRUE(r.HasDiagnostic(DiagKind::X, "text"));  // found: claimed too
//   r.ExpectNoOtherDiagnostics();  // optional: check now, not at the end
//
// The fixtures check at destruction, i.e. at the end of the test body, so
// every test that uses one is strict. Queries that find diagnostics
// (HasDiagnostic, Find, Count) claim what they found: a test that looked at a
// diagnostic has stated it expects it. Reading diags.diagnostics() directly
// claims nothing.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/diagnostics.h"

namespace mdlc::testing {

class DiagnosticClaims {
 public:
  /// Claims every diagnostic of `kind` whose message contains `text`; fails
  /// at the next check when none does.
  void Expect(DiagKind kind, std::string_view text) {
    claims_.push_back({kind, std::nullopt, std::string(text), /*required=*/true});
  }
  /// Claims every error (of any kind) whose message contains `text`; fails at
  /// the next check when none does.
  void ExpectError(std::string_view text) {
    claims_.push_back({std::nullopt, Severity::Error, std::string(text), /*required=*/true});
  }
  /// Claims what a query found; nothing is required of it.
  void Found(DiagKind kind, std::string_view text) {
    claims_.push_back({kind, std::nullopt, std::string(text), /*required=*/false});
  }

  /// Fails once for every diagnostic not checked before that no claim covers,
  /// and for every required claim that covers nothing.
  void Check(const std::vector<Diagnostic>& diags) {
    std::string unclaimed;
    for (size_t i = checked_; i < diags.size(); ++i) {
      const Diagnostic& d = diags[i];
      bool claimed = false;
      for (const auto& c : claims_) claimed = claimed || Covers(c, d);
      if (!claimed) {
        unclaimed += "  " + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) +
                     ": [" + std::string(InfoFor(d.kind).name) + "] " + d.message + "\n";
      }
    }
    checked_ = diags.size();
    if (!unclaimed.empty()) {
      ADD_FAILURE() << "diagnostics the test did not expect (claim them with "
                       "ExpectDiagnostic(kind, text)):\n"
                    << unclaimed;
    }
    for (auto& c : claims_) {
      if (!c.required || c.reported) continue;
      bool matched = false;
      for (const auto& d : diags) matched = matched || Covers(c, d);
      if (!matched) {
        c.reported = true;
        const std::string what =
            c.kind ? "a [" + std::string(InfoFor(*c.kind).name) + "] diagnostic" : "an error";
        ADD_FAILURE() << "expected " << what << " containing '" << c.text << "'; none was emitted";
      }
    }
  }

  /// The check the fixtures run at destruction; left out when the test has
  /// already stopped on a fatal failure or was skipped (its claims after that
  /// point never ran).
  void CheckAtEnd(const std::vector<Diagnostic>& diags) {
    if (::testing::Test::HasFatalFailure() || ::testing::Test::IsSkipped()) return;
    Check(diags);
  }

 private:
  struct Claim {
    std::optional<DiagKind> kind;  // none: any kind of `severity`
    std::optional<Severity> severity;
    std::string text;
    bool required;
    bool reported = false;
  };
  static bool Covers(const Claim& c, const Diagnostic& d) {
    return (!c.kind || *c.kind == d.kind) && (!c.severity || *c.severity == d.severity) &&
           d.message.find(c.text) != std::string::npos;
  }

  std::vector<Claim> claims_;
  size_t checked_ = 0;  // diagnostics before this index were checked already
};

/// The claim methods every fixture offers, over the diagnostics of one
/// engine (which the fixture owns). A fixture calls CheckClaimsAtEnd() in its
/// destructor, while that engine still exists.
class ClaimsDiagnostics {
 public:
  /// Whether a diagnostic of `kind` holds `text`; those found are claimed.
  bool HasDiagnostic(DiagKind kind, std::string_view text) const {
    for (const auto& d : diags_->diagnostics()) {
      if (d.kind == kind && d.message.find(text) != std::string::npos) {
        claims_.Found(kind, text);
        return true;
      }
    }
    return false;
  }
  /// Claims the diagnostics of `kind` holding `text`; at least one must come.
  void ExpectDiagnostic(DiagKind kind, std::string_view text) { claims_.Expect(kind, text); }
  /// Claims the errors (any kind) holding `text`; at least one must come.
  void ExpectError(std::string_view text) { claims_.ExpectError(text); }
  /// Fails for every diagnostic so far that no claim covers.
  void ExpectNoOtherDiagnostics() const { claims_.Check(diags_->diagnostics()); }

 protected:
  explicit ClaimsDiagnostics(const DiagnosticEngine& diags) : diags_(&diags) {}
  void CheckClaimsAtEnd() { claims_.CheckAtEnd(diags_->diagnostics()); }

  mutable DiagnosticClaims claims_;

 private:
  const DiagnosticEngine* diags_;
};

}  // namespace mdlc::testing
