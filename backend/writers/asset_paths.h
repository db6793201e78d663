// asset_paths.h - how a written model names the files it uses (meshes,
// textures): by default a path relative to the output file's folder, so the
// written model loads from wherever it is written; with --copy-assets, copies
// of the files (one per distinct content) in a folder of the user's; with
// --keep-package-uris, package:// URIs as the source wrote them.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "backend/writers/writer.h"
#include "ir/diagnostics.h"

namespace mdlc::writers {

class AssetPaths {
 public:
  AssetPaths(const WriteOptions& options, DiagnosticEngine& diags);

  /// The text to write for a file that the source named `uri` and that
  /// resolved to `resolved` (empty when it did not resolve). nullopt after
  /// reporting a file that could not be copied.
  std::optional<std::string> Name(const std::string& uri, const std::string& resolved, Loc loc);

 private:
  std::optional<std::filesystem::path> Copy(const std::filesystem::path& file, Loc loc);

  const WriteOptions& options_;
  DiagnosticEngine& diags_;
  std::filesystem::path output_dir_;
  std::map<std::filesystem::path, std::filesystem::path> copies_;    // original -> copy
  std::map<std::string, std::filesystem::path> copies_by_content_;  // content -> copy
};

}  // namespace mdlc::writers
