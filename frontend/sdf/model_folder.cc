// model_folder.cc - see model_folder.h.
#include "frontend/sdf/model_folder.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>

#include "frontend/xml/trim.h"
#include "ir/load_report.h"

namespace mdlc::frontend::sdf {
namespace fs = std::filesystem;

std::optional<std::string> ModelFileInFolder(const std::string& dir, Loc loc,
                                             FrontendContext& ctx) {
  const std::string config = dir + "/model.config";
  std::error_code ec;
  if (!fs::exists(config, ec)) {
    ctx.diags.Report(
        DiagKind::FileNotFound, loc,
        fmt::format("'{}' is a folder without a model.config naming its model file", dir));
    return std::nullopt;
  }
  LoadError error;
  auto file = ctx.sources.LoadFile(config, loc, &error);
  if (!file) {
    ReportLoadError(ctx.diags, loc, error, fmt::format("cannot read '{}'", config));
    return std::nullopt;
  }
  std::shared_ptr<const xml::XmlDocument> doc = ParseXml(*file, ctx);
  if (!doc) return std::nullopt;
  std::string best;
  int best_version = -1;
  for (auto e = doc->Root().FirstChild(); e; e = e.NextSibling()) {
    if (e.Name() != "sdf") continue;
    int version = 0;
    if (auto v = e.Attribute("version"); v.present()) {
      // "1.9" -> 109 (an unreadable version ranks lowest)
      std::string_view t = v.value;
      size_t dot = t.find('.');
      if (dot != std::string_view::npos) {
        version = std::atoi(std::string(t.substr(0, dot)).c_str()) * 100 +
                  std::atoi(std::string(t.substr(dot + 1)).c_str());
      }
    }
    if (version > 111) continue;  // newer than mdlc reads
    const std::string text = e.Text();
    const std::string_view trimmed = xml::Trim(text);
    if (trimmed.empty()) continue;
    if (version > best_version) {
      best_version = version;
      best = std::string(trimmed);
    }
  }
  if (best.empty()) {
    ctx.diags.Report(DiagKind::MissingElement, doc->Root().GetLoc(),
                     "model.config names no <sdf> model file");
    return std::nullopt;
  }
  return dir + "/" + best;
}

}  // namespace mdlc::frontend::sdf
