// package_scan.h - the package.xml files under package-path folders, found
// by walking the folders once (COMMON-012).
//
// A compile fills its PackageMap from a scan. Walking a big folder tree is
// most of the cost of a package path (a stat per folder and per ignore
// marker), so `mdlc check`, which compiles many files with the same package
// path, walks it once (PackageScan) and shares the result, read-only, with
// every compile; each compile still reads the manifests into its own
// sources and reports into its own diagnostics, so what it says (and the
// "searched" notes of an unknown package) is exactly what a walk of its own
// would have given.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace mdlc::assets {

/// A package.xml a walk found. Each compile reads it itself, within its
/// own input limits.
struct ManifestFile {
  std::string path;
  std::string dir;  // the package's folder, canonical
};

/// What walking one package-path folder found.
struct FolderScan {
  std::string root;
  bool is_directory = false;
  /// The root's own package.xml first, then the sub-folders' in sorted path
  /// order (so "the first one found" is deterministic); folders holding
  /// COLCON_IGNORE, AMENT_IGNORE or CATKIN_IGNORE are skipped.
  std::vector<ManifestFile> manifests;
};

/// Walks `root` for package.xml files. Touches only the
/// filesystem; safe to call from any thread.
FolderScan ScanFolder(const std::string& root);

/// The package-path folders of a run, walked once. Immutable once built, so
/// any number of threads may read it at once.
class PackageScan {
 public:
  /// Walks each of `roots`, in order.
  explicit PackageScan(std::vector<std::string> roots);

  const std::vector<std::string>& roots() const { return roots_; }
  const std::vector<FolderScan>& folders() const { return folders_; }

 private:
  std::vector<std::string> roots_;
  std::vector<FolderScan> folders_;
};

/// The entries of a colon-separated folder list (ROS_PACKAGE_PATH), empty
/// ones left out.
std::vector<std::string> SplitPathList(std::string_view paths);

}  // namespace mdlc::assets
