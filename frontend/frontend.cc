#include "frontend/frontend.h"

#include <fmt/format.h>

#include "ir/load_report.h"

namespace mdlc::frontend {

std::optional<ModelId> ReadModelFile(const std::string& path, FrontendContext& ctx,
                                     std::optional<Format> format) {
  if (!format) format = FormatFromPath(path);
  if (!format) {
    ctx.diags.Report(DiagKind::UnknownFormat, {},
                     fmt::format("'{}': unknown file extension; expected .urdf, .sdf, .xml "
                                 "(MJCF) or .dmd.yaml, or a format named ({})",
                                 path, kFormatNames));
    return std::nullopt;
  }
  LoadError error;
  auto file = ctx.sources.LoadFile(path, {}, &error);
  if (!file) {
    ReportLoadError(ctx.diags, {}, error, fmt::format("cannot read '{}'", path));
    return std::nullopt;
  }
  return ReadModel(*file, *format, ctx);
}

std::shared_ptr<const xml::XmlDocument> ParseXml(FileId file, FrontendContext& ctx) {
  if (ctx.documents) return ctx.documents->Parse(file, ctx.sources, ctx.diags);
  return xml::XmlDocument::Parse(file, ctx.sources, ctx.diags);
}

std::optional<ModelId> ReadModel(FileId file, Format format, FrontendContext& ctx) {
  switch (format) {
    case Format::Urdf: return ReadUrdf(file, ctx);
    case Format::Sdf: return ReadSdf(file, ctx);
    case Format::Mjcf: return ReadMjcf(file, ctx);
    case Format::Directives: return ReadDirectives(file, ctx);
  }
  return std::nullopt;
}

}  // namespace mdlc::frontend
