// Tests for the diagnostic engine, its policy (COMMON-001, COMMON-002) and
// its text and JSON renderings.
#include "ir/diagnostics.h"

#include <gtest/gtest.h>

#include "ir/source_manager.h"

namespace mdlc {
namespace {

TEST(DiagnosticsTest, CountsBySeverityAndKeepsNotes) {
  DiagnosticEngine diags;
  SourceManager sm;
  FileId f = sm.AddBuffer("m.urdf", "<robot>\n  <joint name='j'/>\n</robot>\n");
  diags.Report(DiagKind::UnknownReference, Loc{f, 2, 3}, "joint 'j' names unknown link 'x'")
      .Note(Loc{f, 1, 1}, "the model is here");
  diags.Report(DiagKind::UnknownElement, Loc{f, 1, 1}, "unknown element <foo>");
  EXPECT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.warning_count(), 1u);
  ASSERT_EQ(diags.diagnostics().size(), 2u);
  EXPECT_EQ(diags.diagnostics()[0].notes.size(), 1u);
}

TEST(DiagnosticsTest, StrictModePromotesWarnings) {  // COMMON-002
  DiagnosticPolicy policy;
  policy.warnings_as_errors = true;
  DiagnosticEngine diags(policy);
  diags.Report(DiagKind::UnknownElement, {}, "unknown element");
  EXPECT_EQ(diags.error_count(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].severity, Severity::Error);
}

TEST(DiagnosticsTest, GroupsCanBeSilencedOrPromoted) {
  DiagnosticPolicy policy;
  policy.disabled_groups.insert("unknown");
  policy.error_groups.insert("unsupported");
  DiagnosticEngine diags(policy);
  diags.Report(DiagKind::UnknownAttribute, {}, "silenced");
  diags.Report(DiagKind::UnsupportedElement, {}, "promoted");
  EXPECT_EQ(diags.warning_count(), 0u);
  EXPECT_EQ(diags.error_count(), 1u);
  ASSERT_EQ(diags.diagnostics().size(), 1u);
  EXPECT_EQ(diags.diagnostics()[0].message, "promoted");
}

TEST(DiagnosticsTest, ErrorsAreNeverSilenced) {
  DiagnosticPolicy policy;
  policy.disabled_groups.insert("names");
  DiagnosticEngine diags(policy);
  diags.Report(DiagKind::UnknownReference, {}, "still an error");
  EXPECT_EQ(diags.error_count(), 1u);
}

TEST(DiagnosticsTest, MaxErrorsStopsTheFlood) {
  DiagnosticPolicy policy;
  policy.max_errors = 2;
  DiagnosticEngine diags(policy);
  for (int i = 0; i < 10; ++i) diags.Report(DiagKind::BadValue, {}, "bad");
  ASSERT_EQ(diags.diagnostics().size(), 3u);
  EXPECT_EQ(diags.diagnostics()[2].kind, DiagKind::TooManyErrors);
}

TEST(DiagnosticsTest, TextFormatHasLocationSourceLineAndCaret) {
  SourceManager sm;
  FileId f = sm.AddBuffer("m.urdf", "<robot>\n  <joint name='j'/>\n</robot>\n");
  Diagnostic d{DiagKind::UnknownReference, Severity::Error, Loc{f, 2, 3}, "bad joint", {}};
  d.notes.push_back({Loc{f, 1, 1}, "robot here"});
  EXPECT_EQ(FormatDiagnosticText(d, sm),
            "m.urdf:2:3: error: bad joint\n"
            "  <joint name='j'/>\n"
            "  ^\n"
            "m.urdf:1:1: note: robot here\n"
            "<robot>\n"
            "^\n");
}

TEST(DiagnosticsTest, TextFormatNamesWarningGroup) {
  SourceManager sm;
  FileId f = sm.AddBuffer("m.urdf", "<robot/>\n");
  Diagnostic d{DiagKind::UnknownElement, Severity::Warning, Loc{f, 1, 1}, "unknown", {}};
  EXPECT_EQ(FormatDiagnosticText(d, sm), "m.urdf:1:1: warning: unknown [-Wunknown]\n<robot/>\n^\n");
}

TEST(DiagnosticsTest, TextFormatShowsIncludeChain) {
  SourceManager sm;
  FileId parent = sm.AddBuffer("top.sdf", "<sdf>\n<include/>\n</sdf>\n");
  FileId child = sm.AddBuffer("part.sdf", "<sdf/>\n", Loc{parent, 2, 1});
  Diagnostic d{DiagKind::BadValue, Severity::Error, Loc{child, 1, 1}, "bad", {}};
  EXPECT_EQ(FormatDiagnosticText(d, sm).substr(0, 40), "in file included from top.sdf:2:1:\npart.");
}

TEST(DiagnosticsTest, JsonFormatIsOneEscapedObject) {
  SourceManager sm;
  FileId f = sm.AddBuffer("dir/m \"x\".urdf", "<robot/>\n");
  Diagnostic d{DiagKind::BadValue, Severity::Error, Loc{f, 1, 2}, "tab\there", {}};
  EXPECT_EQ(FormatDiagnosticJson(d, sm),
            R"({"severity":"error","kind":"bad-value","group":"schema","message":"tab\there",)"
            R"("file":"dir/m \"x\".urdf","line":1,"column":2,"notes":[],"expanded_from":[],"included_from":[]})");
}

}  // namespace
}  // namespace mdlc
