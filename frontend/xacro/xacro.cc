#include "frontend/xacro/xacro.h"

#include <fmt/format.h>

#include "frontend/xacro/expander.h"

namespace mdlc::xacro {

bool IsXacroPath(std::string_view path) { return path.ends_with(".xacro"); }

std::unique_ptr<Expansion> ExpandBuffer(FileId file, const XacroOptions& options,
                                        SourceManager& sources, DiagnosticEngine& diags) {
  Expander expander(options, sources, diags);
  return expander.Run(file);
}

std::unique_ptr<Expansion> ExpandFile(const std::string& path, const XacroOptions& options,
                                      SourceManager& sources, DiagnosticEngine& diags) {
  LoadError error;
  std::optional<FileId> file = sources.LoadFile(path, {}, &error);
  if (!file) {
    diags.Report(error.over_limit ? DiagKind::LimitExceeded : DiagKind::FileNotFound, Loc{},
                 fmt::format("cannot read '{}': {}", path, error.message));
    return nullptr;
  }
  return ExpandBuffer(*file, options, sources, diags);
}

}  // namespace mdlc::xacro
