#include "frontend/frontend.h"

#include <fmt/format.h>

#include <filesystem>

#include "frontend/sdf/model_folder.h"
#include "frontend/xacro/xacro.h"
#include "frontend/xml/start_tags.h"
#include "ir/load_report.h"

namespace mdlc::frontend {

std::optional<Format> XacroFormat(FileId file, const SourceManager& sources) {
  const std::string_view text = sources.Contents(file);
  const size_t start = xml::NextStartTag(text, 0, nullptr);
  if (start == std::string_view::npos) return std::nullopt;
  const size_t end = text.find_first_of(" \t\r\n/>", start + 1);
  const std::string_view root = text.substr(start + 1, end == std::string_view::npos ? end : end - start - 1);
  return FormatFromRootElement(root);
}

std::optional<ModelId> ReadModelFile(const std::string& given_path, FrontendContext& ctx,
                                     std::optional<Format> format) {
  std::string path = given_path;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    // a Gazebo model folder: its model.config names the file
    std::optional<std::string> model_file = sdf::ModelFileInFolder(path, {}, ctx);
    if (!model_file) return std::nullopt;
    path = *model_file;
    if (!format) format = FormatFromPath(path).value_or(Format::Sdf);
  }
  // a .xacro's format is its root element's, known once the file is read
  const bool xacro_by_name = !format && xacro::IsXacroPath(path);
  if (!format && !xacro_by_name) {
    format = FormatFromPath(path);
    if (!format) {
      ctx.diags.Report(DiagKind::UnknownFormat, {},
                       fmt::format("'{}': unknown file extension; expected .urdf, .sdf, "
                                   ".world, .xml (MJCF) or .dmd.yaml, or a format named ({})",
                                   path, kFormatNames));
      return std::nullopt;
    }
  }
  LoadError error;
  auto file = ctx.sources.LoadFile(path, {}, &error);
  if (!file) {
    ReportLoadError(ctx.diags, {}, error, fmt::format("cannot read '{}'", path));
    return std::nullopt;
  }
  if (xacro_by_name) {
    format = XacroFormat(*file, ctx.sources);
    if (!format) {
      ctx.diags.Report(DiagKind::UnknownFormat, Loc{*file, 1, 1},
                       fmt::format("'{}': the root element of a xacro file names its format, "
                                   "and this one is none of <robot> (URDF), <sdf> or <mujoco> "
                                   "(MJCF)",
                                   path));
      return std::nullopt;
    }
  }
  return ReadModel(*file, *format, ctx);
}

namespace {

std::shared_ptr<const xml::XmlDocument> ExpandXacro(FileId file, FrontendContext& ctx) {
  xacro::XacroOptions options;
  options.packages = &ctx.packages;
  // the arguments are the top-level file's; an included one takes its defaults
  if (!ctx.sources.IncludedFrom(file).valid()) options.args = ctx.options.xacro_args;
  std::unique_ptr<xacro::Expansion> expansion =
      xacro::ExpandBuffer(file, options, ctx.sources, ctx.diags);
  if (!expansion) return nullptr;
  return xacro::ToXmlDocument(*expansion, ctx.sources);
}

}  // namespace

std::shared_ptr<const xml::XmlDocument> ParseXml(FileId file, FrontendContext& ctx) {
  if (xacro::IsXacroPath(ctx.sources.Path(file))) return ExpandXacro(file, ctx);
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
