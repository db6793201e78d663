// diagnostic_claims_test.cc - the strict-diagnostics check the unit-test
// fixtures run: what it lets pass and what it fails, and that it fails once.
#include "tests/unit/diagnostic_claims.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mdlc::testing {
namespace {

std::vector<Diagnostic> One(DiagKind kind, std::string message) {
  return {Diagnostic{kind, InfoFor(kind).default_severity, Loc{}, std::move(message), {}}};
}

TEST(DiagnosticClaims, AnUnclaimedDiagnosticFailsWithItsKindAndMessage) {
  EXPECT_NONFATAL_FAILURE(
      {
        DiagnosticClaims claims;
        claims.Check(One(DiagKind::BadValue, "mass 'x' is not a number"));
      },
      "[bad-value] mass 'x' is not a number");
}

TEST(DiagnosticClaims, AClaimCoversItsKindAndText) {
  DiagnosticClaims claims;
  claims.Expect(DiagKind::BadValue, "not a number");
  claims.Check(One(DiagKind::BadValue, "mass 'x' is not a number"));  // no failure
  EXPECT_NONFATAL_FAILURE(
      {
        DiagnosticClaims other_kind;
        other_kind.Found(DiagKind::NonFinite, "not a number");
        other_kind.Check(One(DiagKind::BadValue, "mass 'x' is not a number"));
      },
      "[bad-value] mass 'x' is not a number");
}

TEST(DiagnosticClaims, AnExpectedDiagnosticThatIsNotEmittedFails) {
  EXPECT_NONFATAL_FAILURE(
      {
        DiagnosticClaims claims;
        claims.Expect(DiagKind::BadValue, "not a number");
        claims.Check({});
      },
      "expected a [bad-value] diagnostic containing 'not a number'; none was emitted");
}

TEST(DiagnosticClaims, WhatAQueryFoundIsClaimedWithoutBeingRequired) {
  DiagnosticClaims claims;
  claims.Found(DiagKind::BadValue, "not a number");
  claims.Check({});  // no failure
  claims.Check(One(DiagKind::BadValue, "mass 'x' is not a number"));  // no failure
}

TEST(DiagnosticClaims, ExpectErrorCoversErrorsOfAnyKindOnly) {
  DiagnosticClaims claims;
  claims.ExpectError("'x'");
  claims.Check(One(DiagKind::NonFinite, "mass 'x' must be finite"));  // no failure
  EXPECT_NONFATAL_FAILURE(
      {
        DiagnosticClaims warning;
        warning.ExpectError("'x'");
        warning.Found(DiagKind::UnknownElement, "");
        warning.Check(One(DiagKind::UnknownElement, "element 'x' is unknown"));
      },
      "expected an error containing ''x''; none was emitted");
}

TEST(DiagnosticClaims, EachProblemIsReportedOnce) {
  // checked mid-test and again at the end: one failure, not two
  EXPECT_NONFATAL_FAILURE(
      {
        DiagnosticClaims claims;
        const auto diags = One(DiagKind::BadValue, "mass 'x' is not a number");
        claims.Check(diags);
        claims.Check(diags);
      },
      "not a number");
}

}  // namespace
}  // namespace mdlc::testing
