// diag_printers.cc - text and JSON renderings of a Diagnostic.
#include <fmt/format.h>

#include <string>

#include "ir/diagnostics.h"
#include "ir/location_text.h"
#include "ir/source_manager.h"

namespace mdlc {

std::string LocationText(Loc loc, const SourceManager& sources) {
  if (!loc.valid()) return "mdlc";
  std::string out = sources.Path(loc.file);
  if (loc.line) out += fmt::format(":{}", loc.line);
  if (loc.line && loc.column) out += fmt::format(":{}", loc.column);
  return out;
}

namespace {

// the source line and a caret under the column (tabs kept so the caret lines up)
void AppendSnippet(std::string& out, Loc loc, const SourceManager& sources) {
  if (!loc.valid() || loc.line == 0) return;
  std::string_view text = sources.LineText(loc.file, loc.line);
  if (text.empty()) return;
  constexpr size_t kMaxShown = 200;
  std::string_view shown = text.substr(0, kMaxShown);
  out += fmt::format("{}\n", shown);
  if (loc.column == 0 || loc.column > shown.size() + 1) return;
  std::string pad;
  for (size_t i = 0; i + 1 < loc.column; ++i) pad += (shown[i] == '\t') ? '\t' : ' ';
  out += pad + "^\n";
}

void AppendIncludeChain(std::string& out, Loc loc, const SourceManager& sources) {
  if (!loc.valid()) return;
  for (Loc from = sources.IncludedFrom(loc.file); from.valid();
       from = sources.IncludedFrom(from.file)) {
    out += fmt::format("in file included from {}:\n", LocationText(from, sources));
  }
}

// Where expanded text came from, innermost expansion first: a note at each
// call site (which may itself be expanded text) naming the expansion.
void AppendExpansionNotes(std::string& out, Loc loc, const SourceManager& sources) {
  constexpr int kMaxShown = 64;  // a runaway recursion is cut by its limit anyway
  int shown = 0;
  for (FileId file = loc.file; file.valid() && sources.IsExpansion(file) && shown < kMaxShown;
       ++shown) {
    const Loc at = sources.ExpandedAt(file);
    out += fmt::format("{}: note: {}\n", LocationText(at, sources), sources.ExpansionNote(file));
    AppendSnippet(out, at, sources);
    file = at.file;
  }
}

void AppendJsonString(std::string& out, std::string_view s) {
  out += '"';
  for (unsigned char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (c < 0x20) {
          out += fmt::format("\\u{:04x}", c);
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  out += '"';
}

void AppendJsonLoc(std::string& out, Loc loc, const SourceManager& sources) {
  out += "\"file\":";
  if (loc.valid()) {
    AppendJsonString(out, sources.Path(loc.file));
  } else {
    out += "null";
  }
  out += fmt::format(",\"line\":{},\"column\":{}", loc.line, loc.column);
}

}  // namespace

std::string FormatDiagnosticText(const Diagnostic& diag, const SourceManager& sources,
                                 bool color) {
  const auto& info = InfoFor(diag.kind);
  std::string out;
  AppendIncludeChain(out, diag.loc, sources);
  const char* sev_color = diag.severity == Severity::Error     ? "\033[1;31m"
                          : diag.severity == Severity::Warning ? "\033[1;35m"
                                                               : "\033[1;36m";
  // the group that -W selects: on every warning and note, and on an error
  // that a warning became (-Werror)
  std::string flag;
  if (diag.severity != Severity::Error || info.default_severity != Severity::Error) {
    flag = fmt::format(" [-W{}]", info.group);
  }
  if (color) {
    out += fmt::format("\033[1m{}: {}{}:\033[0m\033[1m {}{}\033[0m\n", LocationText(diag.loc, sources),
                       sev_color, SeverityName(diag.severity), diag.message, flag);
  } else {
    out += fmt::format("{}: {}: {}{}\n", LocationText(diag.loc, sources),
                       SeverityName(diag.severity), diag.message, flag);
  }
  AppendSnippet(out, diag.loc, sources);
  AppendExpansionNotes(out, diag.loc, sources);
  for (const auto& note : diag.notes) {
    out += fmt::format("{}: note: {}\n", LocationText(note.loc, sources), note.message);
    AppendSnippet(out, note.loc, sources);
  }
  return out;
}

std::string FormatDiagnosticJson(const Diagnostic& diag, const SourceManager& sources) {
  const auto& info = InfoFor(diag.kind);
  std::string out = "{\"severity\":";
  AppendJsonString(out, SeverityName(diag.severity));
  out += ",\"kind\":";
  AppendJsonString(out, info.name);
  out += ",\"group\":";
  AppendJsonString(out, info.group);
  out += ",\"message\":";
  AppendJsonString(out, diag.message);
  out += ',';
  AppendJsonLoc(out, diag.loc, sources);
  out += ",\"notes\":[";
  for (size_t i = 0; i < diag.notes.size(); ++i) {
    if (i) out += ',';
    out += "{\"message\":";
    AppendJsonString(out, diag.notes[i].message);
    out += ',';
    AppendJsonLoc(out, diag.notes[i].loc, sources);
    out += '}';
  }
  out += "],\"expanded_from\":[";
  bool first = true;
  for (FileId file = diag.loc.file; file.valid() && sources.IsExpansion(file);) {
    const Loc at = sources.ExpandedAt(file);
    if (!first) out += ',';
    first = false;
    out += "{\"message\":";
    AppendJsonString(out, sources.ExpansionNote(file));
    out += ',';
    AppendJsonLoc(out, at, sources);
    out += '}';
    file = at.file;
  }
  out += "],\"included_from\":[";
  first = true;
  if (diag.loc.valid()) {
    for (Loc from = sources.IncludedFrom(diag.loc.file); from.valid();
         from = sources.IncludedFrom(from.file)) {
      if (!first) out += ',';
      first = false;
      out += '{';
      AppendJsonLoc(out, from, sources);
      out += '}';
    }
  }
  out += "]}";
  return out;
}

}  // namespace mdlc
