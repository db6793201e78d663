// writer.cc - see writer.h: picks the writer for the target format.
#include "backend/writers/writer.h"

#include <fmt/format.h>

namespace mdlc::writers {

std::optional<std::string> Write(const backend::CompiledModel& model, const ir::Module& module,
                                 const WriteOptions& options, DiagnosticEngine& diags) {
  const size_t errors_before = diags.error_count();
  if (options.fuse_fixed && options.to != Format::Mjcf) {
    diags.Report(DiagKind::UnsupportedValue, Loc{},
                 fmt::format("--fuse-fixed applies to MJCF output; the {} writer keeps every "
                             "body",
                             FormatName(options.to)));
  }
  if (options.plain && options.to != Format::Urdf) {
    diags.Report(DiagKind::UnsupportedValue, Loc{},
                 fmt::format("--plain applies to URDF output; the {} writer has one dialect",
                             FormatName(options.to)));
  }
  std::optional<std::string> text;
  switch (options.to) {
    case Format::Urdf:
      text = WriteUrdf(model, module, options, diags);
      break;
    case Format::Sdf:
      text = WriteSdf(model, module, options, diags);
      break;
    case Format::Mjcf:
      text = WriteMjcf(model, module, options, diags);
      break;
    default:
      diags.Report(DiagKind::NotImplemented, Loc{},
                   fmt::format("mdlc cannot write {}; it writes urdf, sdf and mjcf",
                               FormatName(options.to)));
      return std::nullopt;
  }
  if (diags.error_count() != errors_before) return std::nullopt;
  return text;
}

}  // namespace mdlc::writers
