#include "ir/assets/package_map.h"

#include <fmt/format.h>

#include <cstdlib>

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "ir/assets/package_manifest.h"
#include "ir/count_text.h"
#include "ir/load_report.h"

namespace mdlc::assets {
namespace fs = std::filesystem;

const PackageMap& NoPackages() {
  static const PackageMap empty;
  return empty;
}

bool PackageMap::Add(const std::string& name, const std::string& path, DiagnosticEngine& diags,
                     Loc loc) {
  std::error_code ec;
  const std::string normal = fs::weakly_canonical(path, ec).string();
  auto it = packages_.find(name);
  if (it != packages_.end()) {
    if (it->second.path == normal) return true;
    diags.Report(DiagKind::DuplicateName, loc,
                 fmt::format("package '{}' is already defined at '{}'; cannot also be '{}'", name,
                             it->second.path, normal));
    return false;
  }
  if (!fs::is_directory(normal, ec)) {
    diags.Report(DiagKind::FileNotFound, loc,
                 fmt::format("package '{}': '{}' is not a directory", name, path));
    return false;
  }
  packages_.emplace(name, Package{normal, std::nullopt, loc});
  return true;
}

namespace {
// `s` without XML's white space (space, tab, newline, carriage return)
// around it, as the format readers trim text.
std::string_view TrimXmlSpace(std::string_view s) {
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

// The package a package.xml names: its <package> root's <name>, trimmed;
// nullopt when the root is not <package> or the name is empty.
std::optional<std::string> ManifestPackageName(const PackageManifest& manifest) {
  if (manifest.root != "package") return std::nullopt;
  std::string text(TrimXmlSpace(manifest.name ? *manifest.name : std::string()));
  if (text.empty()) return std::nullopt;
  return text;
}
}  // namespace

void PackageMap::AddFromManifest(const ManifestFile& manifest, SourceManager& sources,
                                 DiagnosticEngine& diags) {
  // package.xml is read strictly (COMMON-014)
  // read by this compile, within its own limits (only the walk is shared)
  LoadError error;
  auto file = sources.LoadFile(manifest.path, {}, &error);
  if (!file) {
    ReportLoadError(diags, {}, error, fmt::format("cannot read '{}'", manifest.path));
    return;
  }
  const std::optional<PackageManifest> read = ReadPackageManifest(*file, sources, diags);
  if (!read) return;
  const std::optional<std::string> named = ManifestPackageName(*read);
  if (!named) {
    diags.Report(DiagKind::MissingElement, read->root_at,
                 "package.xml must be a <package> with a non-empty <name>");
    return;
  }
  const std::string& text = *named;
  const Loc name_at = read->name_at;
  std::optional<std::string> deprecated = read->deprecated;
  const std::string& normal = manifest.dir;
  auto it = packages_.find(text);
  if (it != packages_.end()) {
    if (it->second.path != normal) {
      // the first one found wins (COMMON-013)
      auto diag = diags.Report(
          DiagKind::RenamedDuplicate, name_at,
          fmt::format("package '{}' found again at '{}'; keeping the first, at '{}'", text,
                      normal, it->second.path));
      if (it->second.defined_at.valid()) diag.Note(it->second.defined_at, "first defined here");
      it->second.shadowed.push_back(normal);
    }
    return;
  }
  packages_.emplace(text, Package{normal, std::move(deprecated), name_at});
}

void PackageMap::PopulateFromFolder(const std::string& root, SourceManager& sources,
                                    DiagnosticEngine& diags) {
  PopulateFromScan(ScanFolder(root), sources, diags);
}

void PackageMap::PopulateFromScan(const FolderScan& scan, SourceManager& sources,
                                  DiagnosticEngine& diags) {
  if (!scan.is_directory) {
    diags.Report(DiagKind::FileNotFound, {},
                 fmt::format("package path '{}' is not a directory", scan.root));
    return;
  }
  searched_.push_back(scan.root);
  for (const ManifestFile& manifest : scan.manifests) AddFromManifest(manifest, sources, diags);
}

void PackageMap::PopulateFromPathList(std::string_view paths, SourceManager& sources,
                                      DiagnosticEngine& diags) {
  for (const std::string& root : SplitPathList(paths)) PopulateFromFolder(root, sources, diags);
}

void PackageMap::PopulateFromAmentPrefixes(std::string_view prefixes) {
  for (const std::string& prefix : SplitPathList(prefixes)) {
    // a prefix without an index holds no ROS packages (an install prefix may
    // hold anything): skipped quietly, as ROS 2's own lookup does
    const fs::path index = fs::path(prefix) / "share/ament_index/resource_index/packages";
    std::error_code ec;
    fs::directory_iterator entries(index, ec);
    if (ec) continue;
    searched_.push_back(fmt::format("{} (ament index)", prefix));
    for (const fs::directory_entry& entry : entries) {
      const std::string name = entry.path().filename().string();
      if (packages_.contains(name)) continue;  // an earlier source wins
      const fs::path share = fs::path(prefix) / "share" / name;
      if (!fs::is_directory(share, ec)) continue;  // registered, not installed
      packages_.emplace(name, Package{fs::weakly_canonical(share, ec).string(), std::nullopt, {}});
    }
  }
}

const PackageMap::Package* PackageMap::Find(std::string_view name) const {
  auto it = packages_.find(name);
  return it == packages_.end() ? nullptr : &it->second;
}

std::optional<std::string> PackageMap::ShadowedCopyHolding(std::string_view uri) const {
  for (std::string_view scheme : {"package://", "model://"}) {
    if (!uri.starts_with(scheme)) continue;
    const std::string_view rest = uri.substr(scheme.size());
    const size_t slash = rest.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    const Package* package = Find(rest.substr(0, slash));
    if (!package) return std::nullopt;
    for (const std::string& copy : package->shadowed) {
      std::error_code ec;
      const fs::path file = fs::path(copy) / rest.substr(slash + 1);
      if (fs::exists(file, ec)) return file.lexically_normal().string();
    }
  }
  return std::nullopt;
}

namespace {
// The folder `base_dir` names, absolute and canonical: a file named
// "model.sdf" has base_dir "", "./model.sdf" ".", and each must look in the
// same folders above it as its absolute path does.
fs::path CanonicalDir(const std::string& base_dir) {
  std::error_code ec;
  fs::path dir = fs::absolute(base_dir.empty() ? fs::path(".") : fs::path(base_dir), ec);
  if (ec) return {};
  fs::path canonical = fs::weakly_canonical(dir, ec);
  return ec ? dir.lexically_normal() : canonical;
}

// `model://NAME` where NAME is no package: Gazebo's convention is a model
// folder NAME (holding model.config) on its model paths. mdlc looks in the
// folders SDF_PATH, GZ_SIM_RESOURCE_PATH and GAZEBO_MODEL_PATH list, then in
// the two folders above the referring file's (the layout of model collections,
// where models sit side by side).
std::optional<fs::path> GazeboModelFolder(std::string_view name, const std::string& base_dir) {
  std::vector<fs::path> roots;
  for (const char* var : {"SDF_PATH", "GZ_SIM_RESOURCE_PATH", "GAZEBO_MODEL_PATH"}) {
    if (const char* value = std::getenv(var)) {
      std::string_view list(value);
      while (!list.empty()) {
        const size_t colon = list.find(':');
        if (colon != 0) roots.emplace_back(std::string(list.substr(0, colon)));
        if (colon == std::string_view::npos) break;
        list.remove_prefix(colon + 1);
      }
    }
  }
  std::error_code ec;
  fs::path up = CanonicalDir(base_dir);
  for (int i = 0; i < 2 && up.has_parent_path() && up != up.parent_path(); ++i) {
    up = up.parent_path();
    roots.push_back(up);
  }
  for (const fs::path& root : roots) {
    const fs::path candidate = root / std::string(name);
    if (fs::is_directory(candidate, ec) && fs::exists(candidate / "model.config", ec)) {
      return candidate;
    }
  }
  return std::nullopt;
}

// The nearest folder above `base_dir` whose package.xml names `name`. Drake
// does not look upward for packages (nor does mdlc: COMMON-011), but a model
// that names its own package is the common case of a package left off the
// command line, so the error says which folder to give. Read quietly with
// its own sources: this is a hint, and the walk stops at the first match.
std::optional<fs::path> EnclosingPackageNamed(std::string_view name, const std::string& base_dir) {
  constexpr int kMaxLevels = 64;  // a bound on the walk, far above real trees
  std::error_code ec;
  fs::path dir = CanonicalDir(base_dir);
  if (dir.empty()) return std::nullopt;
  for (int level = 0; level < kMaxLevels; ++level) {
    const fs::path manifest = dir / "package.xml";
    if (fs::is_regular_file(manifest, ec)) {
      SourceManager sources;
      DiagnosticEngine quiet;
      if (auto file = sources.LoadFile(manifest.string())) {
        if (auto read = ReadPackageManifest(*file, sources, quiet)) {
          if (ManifestPackageName(*read) == name) return dir;
        }
      }
    }
    if (!dir.has_parent_path() || dir == dir.parent_path()) break;
    dir = dir.parent_path();
  }
  return std::nullopt;
}
}  // namespace

std::optional<std::string> UriToPath(std::string_view uri, const std::string& base_dir,
                                     const PackageMap& packages, Loc loc,
                                     DiagnosticEngine& diags) {
  std::string path;
  const size_t scheme_end = uri.find("://");
  if (scheme_end == std::string_view::npos) {
    fs::path p(uri);
    path = p.is_absolute() ? p.string() : (fs::path(base_dir) / p).string();
  } else {
    const std::string_view scheme = uri.substr(0, scheme_end);
    std::string_view rest = uri.substr(scheme_end + 3);
    if (scheme == "file") {
      // file:///abs is absolute; a relative file://x (sloppy, but written)
      // is taken relative to the referring file, like a bare path
      fs::path p(rest);
      path = p.is_absolute() ? p.string() : (fs::path(base_dir) / p).string();
    } else if (scheme == "package" || scheme == "model") {
      if (scheme == "package" && rest.starts_with('/') && rest.size() > 1 && rest[1] != '/') {
        // package:///NAME/path: an empty authority before the package name,
        // common in older URDFs; read as package://NAME/path
        rest.remove_prefix(1);
        diags.Report(DiagKind::MalformedUri, loc,
                     fmt::format("'{}' has an empty authority (three slashes after 'package:'); "
                                 "read as 'package://{}'",
                                 uri, rest));
      }
      const size_t slash = rest.find('/');
      const std::string_view name = rest.substr(0, slash);
      const PackageMap::Package* package = packages.Find(name);
      std::optional<fs::path> gazebo_model;
      if (!package && scheme == "model") gazebo_model = GazeboModelFolder(name, base_dir);
      if (gazebo_model) {
        path = (*gazebo_model / (slash == std::string_view::npos ? "" : rest.substr(slash + 1))).string();
      } else if (!package) {
        auto diag = diags.Report(
            DiagKind::FileNotFound, loc,
            fmt::format("unknown package '{}' in '{}'", name, uri));
        if (packages.searched().empty() && packages.size() == 0) {
          diag.Note(loc, "no packages are known: give --package-path DIR, --package NAME=DIR "
                         "or set ROS_PACKAGE_PATH or AMENT_PREFIX_PATH");
        } else {
          diag.Note(loc, fmt::format("{} known; searched {}", ir::CountOf(packages.size(), "package"),
                                     packages.searched().empty()
                                         ? std::string("no folders")
                                         : fmt::format("'{}'", fmt::join(packages.searched(), "', '"))));
        }
        if (auto enclosing = EnclosingPackageNamed(name, base_dir)) {
          std::error_code ec;
          const std::string folder = fs::proximate(*enclosing, ec).string();
          diag.Note(loc, fmt::format("the package.xml in '{}', a folder above this file, names "
                                     "package '{}': give --package-path {}",
                                     folder, name, folder));
        }
        return std::nullopt;
      }
      if (package) {
        if (package->deprecated) {
          diags.Report(DiagKind::UnsupportedValue, loc,
                       fmt::format("package '{}' is deprecated: {}", name, *package->deprecated));
        }
        path = (fs::path(package->path) / (slash == std::string_view::npos ? "" : rest.substr(slash + 1))).string();
      }
    } else {
      diags.Report(DiagKind::BadValue, loc,
                   fmt::format("unsupported scheme '{}://' in '{}'; use package://, model://, "
                               "file:// or a path",
                               scheme, uri));
      return std::nullopt;
    }
  }
  return path;
}

std::optional<std::string> ResolveUri(std::string_view uri, const std::string& base_dir,
                                      const PackageMap& packages, Loc loc,
                                      DiagnosticEngine& diags) {
  std::optional<std::string> path = UriToPath(uri, base_dir, packages, loc, diags);
  if (!path) return std::nullopt;
  std::error_code ec;
  if (!fs::exists(*path, ec)) {
    diags.Report(DiagKind::FileNotFound, loc,
                 fmt::format("'{}' resolves to '{}', which does not exist", uri, *path));
    return std::nullopt;
  }
  return fs::path(*path).lexically_normal().string();
}

}  // namespace mdlc::assets
