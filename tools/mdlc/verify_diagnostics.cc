#include "verify_diagnostics.h"

#include <fmt/format.h>

#include <regex>

namespace mdlc::tools {
namespace {

struct Expectation {
  Severity severity;
  FileId file;
  uint32_t line;
  std::string text;
  Loc where;  // the comment itself
  bool matched = false;
};

std::vector<Expectation> CollectExpectations(const SourceManager& sources) {
  static const std::regex pattern(
      R"(expected-(error|warning|note)(@([+-]?)(\d+))?\s*\{\{(.*?)\}\})");
  std::vector<Expectation> out;
  for (size_t f = 0; f < sources.FileCount(); ++f) {
    FileId file{static_cast<uint32_t>(f)};
    // an expansion shows its file's text again; its comments are that file's
    if (sources.IsExpansion(file)) continue;
    std::string_view text = sources.Contents(file);
    // only lines that mention "expected-" are worth a regex
    size_t pos = 0;
    while ((pos = text.find("expected-", pos)) != std::string_view::npos) {
      const Loc at = sources.LocForOffset(file, pos);
      std::string line(sources.LineText(file, at.line));
      for (auto it = std::sregex_iterator(line.begin(), line.end(), pattern);
           it != std::sregex_iterator(); ++it) {
        const auto& m = *it;
        Expectation e;
        e.severity = m[1] == "error" ? Severity::Error
                     : m[1] == "warning" ? Severity::Warning
                                         : Severity::Note;
        e.file = file;
        e.line = at.line;
        if (m[2].matched) {
          const int n = std::stoi(m[4]);
          if (m[3] == "+") e.line = at.line + n;
          else if (m[3] == "-") e.line = at.line - n;
          else e.line = static_cast<uint32_t>(n);
        }
        e.text = m[5];
        e.where = Loc{file, at.line, static_cast<uint32_t>(m.position(0) + 1)};
        out.push_back(std::move(e));
      }
      // skip the rest of this line
      const size_t eol = text.find('\n', pos);
      pos = eol == std::string_view::npos ? text.size() : eol + 1;
    }
  }
  return out;
}

std::string Describe(const SourceManager& sources, Loc loc) {
  if (!loc.valid()) return "<no location>";
  return fmt::format("{}:{}", sources.Path(loc.file), loc.line);
}

bool Matches(Expectation& e, Severity severity, Loc loc, const std::string& message,
             const SourceManager& sources) {
  // text a macro expansion placed is expected where it is written
  if (e.matched || e.severity != severity || !loc.valid() ||
      e.file != sources.SpellingFile(loc.file) || e.line != loc.line) {
    return false;
  }
  if (message.find(e.text) == std::string::npos) return false;
  e.matched = true;
  return true;
}

}  // namespace

std::vector<std::string> VerifyDiagnostics(const std::vector<Diagnostic>& diagnostics,
                                           const SourceManager& sources) {
  std::vector<Expectation> expectations = CollectExpectations(sources);
  std::vector<std::string> problems;
  auto match = [&](Severity severity, Loc loc, const std::string& message) {
    for (auto& e : expectations) {
      if (Matches(e, severity, loc, message, sources)) return true;
    }
    return false;
  };
  for (const Diagnostic& d : diagnostics) {
    if (!match(d.severity, d.loc, d.message)) {
      problems.push_back(fmt::format("{}: unexpected {}: {}", Describe(sources, d.loc),
                                     SeverityName(d.severity), d.message));
    }
    for (const auto& note : d.notes) {
      match(Severity::Note, note.loc, note.message);  // notes are checked only when expected
    }
    // the macro calls that placed the text, as the printed notes say them
    for (FileId file = d.loc.file; file.valid() && sources.IsExpansion(file);) {
      const Loc at = sources.ExpandedAt(file);
      match(Severity::Note, at, sources.ExpansionNote(file));
      file = at.file;
    }
  }
  for (const auto& e : expectations) {
    if (!e.matched) {
      problems.push_back(fmt::format("{}: expected {} on line {} was not produced: {}",
                                     Describe(sources, e.where), SeverityName(e.severity), e.line,
                                     e.text));
    }
  }
  return problems;
}

}  // namespace mdlc::tools
