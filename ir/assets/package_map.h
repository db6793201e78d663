// package_map.h - ROS-style packages and the URIs that name files in them
// (COMMON-010..015).
//
// A package is a directory holding a package.xml; its name is that file's
// <name> element, not the directory's. The map is filled explicitly (Add),
// by scanning folders (PopulateFromFolder, e.g. for --package-path), from
// ROS_PACKAGE_PATH, or from a ROS 2 install's ament index, and is then used
// to resolve `package://`, `model://`, `file://`, absolute and relative
// references. It is a plain value type that
// embedders fill programmatically as well.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/assets/package_scan.h"
#include "ir/diagnostics.h"
#include "ir/source_manager.h"

namespace mdlc::assets {

class PackageMap {
 public:
  struct Package {
    std::string path;                       // the package's directory
    std::optional<std::string> deprecated;  // message of a <deprecated> export
    Loc defined_at;                         // its package.xml, when scanned
    /// Other folders with a package.xml of the same name, found later and
    /// not used (COMMON-013): where a file missing from `path` may be.
    std::vector<std::string> shadowed;
  };

  /// Adds `name` at `path`. A different path for a known name is an error
  /// (COMMON-013); the same path again is fine. Returns false on error.
  bool Add(const std::string& name, const std::string& path, DiagnosticEngine& diags,
           Loc loc = {});

  /// Finds every package.xml under `root` (nested packages included;
  /// folders holding COLCON_IGNORE, AMENT_IGNORE or CATKIN_IGNORE skipped).
  /// A name found again at another path keeps the first and warns.
  void PopulateFromFolder(const std::string& root, SourceManager& sources,
                          DiagnosticEngine& diags);
  /// PopulateFromFolder for each entry of a colon-separated list.
  void PopulateFromPathList(std::string_view paths, SourceManager& sources,
                            DiagnosticEngine& diags);
  /// PopulateFromFolder from a walk made before (ScanFolder, or one of a
  /// PackageScan shared by many compiles): the same packages, diagnostics
  /// and "searched" folders, without walking the folder again.
  void PopulateFromScan(const FolderScan& scan, SourceManager& sources, DiagnosticEngine& diags);

  /// The packages a ROS 2 install registers: for each prefix of the
  /// colon-separated `prefixes` (AMENT_PREFIX_PATH), every NAME in its ament
  /// resource index (PREFIX/share/ament_index/resource_index/packages/NAME)
  /// is a package at PREFIX/share/NAME. An earlier prefix overlays a later
  /// one, as in ROS 2, and a package already known (given explicitly or
  /// found under a package path) keeps its folder; neither is a warning.
  void PopulateFromAmentPrefixes(std::string_view prefixes);

  const Package* Find(std::string_view name) const;
  /// For a `package://NAME/FILE` or `model://NAME/FILE` URI whose FILE is
  /// not in the package's folder: FILE in a shadowed copy that has it.
  std::optional<std::string> ShadowedCopyHolding(std::string_view uri) const;
  size_t size() const { return packages_.size(); }
  const std::map<std::string, Package, std::less<>>& packages() const { return packages_; }
  /// Folders scanned so far, for "searched in" notes.
  const std::vector<std::string>& searched() const { return searched_; }

 private:
  void AddFromManifest(const ManifestFile& manifest, SourceManager& sources,
                       DiagnosticEngine& diags);

  std::map<std::string, Package, std::less<>> packages_;
  std::vector<std::string> searched_;
};

/// The path a file reference written in a model names (COMMON-010):
/// `package://PKG/rel`, `model://PKG/rel`, `file:///abs`, an absolute path,
/// or a path relative to `base_dir` (the referring file's folder). Whether
/// the file exists is not checked. Reports an error at `loc` and returns
/// nullopt when the scheme is unsupported or the package unknown. The
/// non-standard `package:///PKG/rel` (an empty authority, as older URDFs
/// write it) is read as `package://PKG/rel`, with a warning.
/// The map of a compile that names no packages: only paths resolve. Every
/// context that may be given no map refers to this one instead.
const PackageMap& NoPackages();

std::optional<std::string> UriToPath(std::string_view uri, const std::string& base_dir,
                                     const PackageMap& packages, Loc loc,
                                     DiagnosticEngine& diags);

/// UriToPath, and the file must exist (COMMON-011): returns the path,
/// lexically normal, or reports an error at `loc` and returns nullopt.
std::optional<std::string> ResolveUri(std::string_view uri, const std::string& base_dir,
                                      const PackageMap& packages, Loc loc,
                                      DiagnosticEngine& diags);

}  // namespace mdlc::assets
