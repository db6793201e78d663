// package_scan.cc - see package_scan.h.
#include "ir/assets/package_scan.h"

#include <algorithm>
#include <filesystem>
#include <system_error>


namespace mdlc::assets {
namespace fs = std::filesystem;
namespace {

bool IsIgnored(const fs::path& dir) {
  std::error_code e;
  return fs::exists(dir / "COLCON_IGNORE", e) || fs::exists(dir / "AMENT_IGNORE", e) ||
         fs::exists(dir / "CATKIN_IGNORE", e);
}

ManifestFile Manifest(const fs::path& manifest) {
  std::error_code ec;
  return {manifest.string(), fs::weakly_canonical(manifest.parent_path(), ec).string()};
}

}  // namespace

FolderScan ScanFolder(const std::string& root) {
  FolderScan scan;
  scan.root = root;
  std::error_code ec;
  scan.is_directory = fs::is_directory(root, ec);
  if (!scan.is_directory || IsIgnored(root)) return scan;
  if (fs::exists(fs::path(root) / "package.xml", ec)) {
    scan.manifests.push_back(Manifest(fs::path(root) / "package.xml"));
  }
  // the recursive iterator keeps its own stack: no recursion per folder level
  std::vector<fs::path> dirs;
  for (fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec),
       end;
       it != end; it.increment(ec)) {
    if (ec) break;
    if (!it->is_directory(ec) || it->is_symlink(ec)) continue;
    if (IsIgnored(it->path())) {
      it.disable_recursion_pending();
      continue;
    }
    dirs.push_back(it->path());
  }
  std::sort(dirs.begin(), dirs.end());
  for (const fs::path& dir : dirs) {
    if (fs::exists(dir / "package.xml", ec)) scan.manifests.push_back(Manifest(dir / "package.xml"));
  }
  return scan;
}

PackageScan::PackageScan(std::vector<std::string> roots) : roots_(std::move(roots)) {
  folders_.reserve(roots_.size());
  for (const std::string& root : roots_) folders_.push_back(ScanFolder(root));
}

std::vector<std::string> SplitPathList(std::string_view paths) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= paths.size()) {
    size_t end = paths.find(':', start);
    if (end == std::string_view::npos) end = paths.size();
    if (end > start) out.emplace_back(paths.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

}  // namespace mdlc::assets
