// assets.cc - see assets.h.
#include "assets.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <variant>

#include "backend/json_writer.h"
#include "ir/count_text.h"
#include "mdlc/ir.h"
#include "tools/driver/mjcf_file_assets.h"

namespace mdlc::tools {
namespace {
namespace fs = std::filesystem;

struct Asset {
  std::string kind;  // model, config (model.config), mesh, texture, hfield, skin
  std::string uri;   // as written
  std::string resolved;
  Loc loc;  // where it is first named
  int uses = 0;
  std::string problem;  // the diagnostic that reported it, if any
};

std::string Extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::optional<uintmax_t> Size(const std::string& path) {
  std::error_code ec;
  const uintmax_t size = fs::file_size(path, ec);
  if (ec) return std::nullopt;
  return size;
}

std::vector<Asset> Collect(const Result& result) {
  std::vector<Asset> assets;
  const SourceManager& sources = result.sources();
  std::set<std::string> model_files;  // a file included many times is read once
  for (size_t f = 0; f < sources.FileCount(); ++f) {
    const FileId id{static_cast<uint32_t>(f)};
    const std::string& path = sources.Path(id);
    // package.xml files are how packages were found, not part of the model
    if (sources.IsExpansion(id) || fs::path(path).filename() == "package.xml" ||
        !model_files.insert(path).second) {
      continue;
    }
    const bool config = fs::path(path).filename() == "model.config";  // a Gazebo model folder's
    assets.push_back({config ? "config" : "model", path, path, sources.IncludedFrom(id), 1, {}});
  }
  // (kind, file) -> asset: one entry per file, however many URIs name it
  std::map<std::pair<std::string, std::string>, size_t> index;
  auto add = [&](const std::string& kind, const std::string& uri, const std::string& resolved,
                 Loc loc) {
    const std::string& file = resolved.empty() ? uri : resolved;
    auto [it, inserted] = index.try_emplace({kind, file}, assets.size());
    if (inserted) assets.push_back({kind, uri, resolved, loc, 0, {}});
    Asset& a = assets[it->second];
    ++a.uses;
    if (a.resolved.empty()) a.resolved = resolved;
  };
  const ir::Module& m = IrModule(result);
  for (const ir::Geometry& g : m.geometries) {
    if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape)) {
      add("mesh", mesh->uri, mesh->resolved, mesh->uri_loc.valid() ? mesh->uri_loc : g.loc);
    }
  }
  for (const ir::Material& material : m.materials) {
    if (!material.texture.empty()) add("texture", material.texture, material.texture, material.loc);
  }
  // what MJCF names and mdlc does not read: textures, height fields, skins
  for (const MjcfFileAsset& a : MjcfFileAssets(sources)) add(a.kind, a.uri, a.resolved, a.loc);
  // what reported a file missing: a diagnostic where its URI is written
  for (Asset& a : assets) {
    if (a.kind == "model" || a.kind == "config") continue;
    for (const Diagnostic& d : result.diagnostics()) {
      if (d.loc == a.loc && (d.kind == DiagKind::FileNotFound || d.kind == DiagKind::MissingAsset ||
                             d.kind == DiagKind::MalformedUri || d.severity == Severity::Error)) {
        a.problem = d.message;
        break;
      }
    }
    if (a.problem.empty() && (a.resolved.empty() || !fs::exists(a.resolved))) {
      a.problem = "not found";
    }
  }
  return assets;
}

}  // namespace

AssetReport ListAssets(const Result& result, bool json) {
  const std::vector<Asset> assets = Collect(result);
  AssetReport report;
  for (const Asset& a : assets) report.all_found = report.all_found && a.problem.empty();
  if (json) {
    backend::JsonWriter w(1);
    w.BeginArray();
    for (const Asset& a : assets) {
      w.BeginObject(backend::JsonWriter::Layout::Compact);
      w.Key("kind").String(a.kind);
      w.Key("uri").String(a.uri);
      if (a.problem.empty()) {
        w.Key("path").String(a.resolved);
        w.Key("format").String(Extension(a.resolved));
        if (auto size = Size(a.resolved)) w.Key("bytes").Int(static_cast<int64_t>(*size));
      } else {
        w.Key("error").String(a.problem);
      }
      if (a.kind != "model" && a.kind != "config") w.Key("uses").Int(a.uses);
      w.EndObject();
    }
    w.EndArray();
    report.text = w.Take() + "\n";
    return report;
  }
  for (const Asset& a : assets) {
    if (!a.problem.empty()) {
      report.text += fmt::format("{:<8} {}: {}\n", a.kind, a.uri, a.problem);
      continue;
    }
    const auto size = Size(a.resolved);
    report.text += fmt::format("{:<8} {}{} [{}, {}]{}\n", a.kind, a.uri,
                               a.uri == a.resolved ? "" : " -> " + a.resolved,
                               Extension(a.resolved),
                               size ? ir::CountOf(*size, "byte") : "size unknown",
                               a.uses > 1 ? fmt::format(", used {} times", a.uses) : "");
  }
  return report;
}

}  // namespace mdlc::tools
