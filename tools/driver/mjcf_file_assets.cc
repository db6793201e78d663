// mjcf_file_assets.cc - see mjcf_file_assets.h.
#include "tools/driver/mjcf_file_assets.h"

#include <filesystem>
#include <map>
#include <set>

#include "frontend/xml/xml_document.h"

namespace mdlc::tools {
namespace {
namespace fs = std::filesystem;

/// Where MuJoCo looks for asset files, as a <compiler> element sets it
/// (relative to the main file's folder; the specific folders win over
/// assetdir, MJCF-006).
struct AssetFolders {
  std::string meshdir, texturedir, assetdir;
  std::string For(std::string_view kind) const {
    const std::string& specific = kind == "texture" ? texturedir : meshdir;
    return specific.empty() ? assetdir : specific;
  }
};

/// The file an included file was included into, all the way up: MuJoCo
/// resolves every file name against the main file's folder.
FileId MainFile(const SourceManager& sources, FileId file) {
  for (Loc from = sources.IncludedFrom(file); from.valid(); from = sources.IncludedFrom(file)) {
    file = from.file;
  }
  return file;
}

// the attributes of each asset element that name a file (a cube texture
// may name one per face)
const std::map<std::string_view, std::vector<std::string_view>> kFileAttributes = {
    {"texture",
     {"file", "fileright", "fileleft", "fileup", "filedown", "filefront", "fileback"}},
    {"hfield", {"file"}},
    {"skin", {"file"}},
};

}  // namespace

std::vector<MjcfFileAsset> MjcfFileAssets(const SourceManager& sources) {
  struct Parsed {
    FileId file;
    std::unique_ptr<xml::XmlDocument> doc;
  };
  std::vector<Parsed> documents;
  std::set<std::string> seen_paths;  // a file included twice is listed once
  for (size_t f = 0; f < sources.FileCount(); ++f) {
    const FileId id{static_cast<uint32_t>(f)};
    if (sources.IsExpansion(id) || !seen_paths.insert(sources.Path(id)).second) continue;
    if (sources.Contents(id).find("<mujoco") == std::string_view::npos) continue;
    DiagnosticEngine unreported;  // the compile reported what is wrong with the file
    auto doc = xml::XmlDocument::Parse(id, sources, unreported);
    if (doc && doc->Root() && doc->Root().Name() == "mujoco") documents.push_back({id, std::move(doc)});
  }
  // the <compiler> settings of each main file, from any file of its model
  std::map<uint32_t, AssetFolders> folders;
  for (const Parsed& p : documents) {
    AssetFolders& f = folders[MainFile(sources, p.file).value];
    for (auto e = p.doc->Root().FirstChild(); e; e = e.NextSibling()) {
      if (e.Name() != "compiler") continue;
      if (auto a = e.Attribute("meshdir"); a.present()) f.meshdir = a.value;
      if (auto a = e.Attribute("texturedir"); a.present()) f.texturedir = a.value;
      if (auto a = e.Attribute("assetdir"); a.present()) f.assetdir = a.value;
    }
  }
  std::vector<MjcfFileAsset> assets;
  for (const Parsed& p : documents) {
    const FileId main = MainFile(sources, p.file);
    const fs::path base = fs::path(sources.Path(main)).parent_path();
    for (auto asset = p.doc->Root().FirstChild(); asset; asset = asset.NextSibling()) {
      if (asset.Name() != "asset") continue;
      for (auto e = asset.FirstChild(); e; e = e.NextSibling()) {
        const auto attributes = kFileAttributes.find(e.Name());
        if (attributes == kFileAttributes.end()) continue;
        for (std::string_view name : attributes->second) {
          const xml::XmlAttribute file = e.Attribute(name);
          if (!file.present() || file.value.empty()) continue;
          const fs::path written(file.value);
          const fs::path resolved =
              written.is_absolute() ? written
                                    : base / folders[main.value].For(e.Name()) / written;
          assets.push_back({std::string(e.Name()), std::string(file.value),
                            resolved.lexically_normal().string(), file.loc});
        }
      }
    }
  }
  return assets;
}

}  // namespace mdlc::tools
