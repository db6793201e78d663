#include "frontend/frontend.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace mdlc::frontend {

std::string_view FormatName(Format format) {
  switch (format) {
    case Format::Urdf: return "URDF";
    case Format::Sdf: return "SDFormat";
    case Format::Mjcf: return "MJCF";
    case Format::Directives: return "Model Directives";
  }
  return "?";
}

std::optional<Format> FormatFromPath(std::string_view path) {
  std::string lower(path);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  auto ends_with = [&](std::string_view suffix) { return std::string_view(lower).ends_with(suffix); };
  if (ends_with(".urdf")) return Format::Urdf;
  if (ends_with(".sdf")) return Format::Sdf;
  if (ends_with(".xml")) return Format::Mjcf;
  if (ends_with(".dmd.yaml")) return Format::Directives;
  return std::nullopt;
}

std::optional<ModelId> ReadModelFile(const std::string& path, FrontendContext& ctx) {
  auto format = FormatFromPath(path);
  if (!format) {
    ctx.diags.Report(DiagKind::UnknownFormat, {},
                     fmt::format("'{}': unknown file extension; expected .urdf, .sdf, .xml "
                                 "(MJCF) or .dmd.yaml",
                                 path));
    return std::nullopt;
  }
  std::string error;
  auto file = ctx.sources.LoadFile(path, {}, &error);
  if (!file) {
    ctx.diags.Report(DiagKind::FileNotFound, {}, fmt::format("cannot read '{}': {}", path, error));
    return std::nullopt;
  }
  return ReadModel(*file, *format, ctx);
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
