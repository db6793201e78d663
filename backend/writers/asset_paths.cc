// asset_paths.cc - see asset_paths.h.
#include "backend/writers/asset_paths.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <system_error>


namespace mdlc::writers {
namespace fs = std::filesystem;

namespace {
std::optional<std::string> ReadAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// 64-bit FNV-1a: names a copy by its content, so equal files share one copy
uint64_t ContentHash(const std::string& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}
}  // namespace

void AssetPaths::ReportInlineMeshLeftOut(const std::string& geometry, const ir::Mesh& mesh,
                                         std::string_view target, const std::string& why,
                                         Loc loc) {
  if (!inline_left_out_.emplace(loc.file.value, loc.line, loc.column, geometry).second) return;
  if (why.empty()) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("geometry '{}' is left out: its mesh '{}' is written in the "
                              "model file (vertex and face lists), and {} names mesh files "
                              "only; --copy-assets writes an OBJ of it",
                              geometry, mesh.uri, target));
    return;
  }
  diags_.Report(DiagKind::Lossy, loc,
                fmt::format("geometry '{}' is left out: its mesh '{}' is written in the model "
                            "file (vertex and face lists), and mdlc cannot write it as OBJ ({})",
                            geometry, mesh.uri, why));
}

AssetPaths::AssetPaths(const WriteOptions& options, DiagnosticEngine& diags)
    : options_(options), diags_(diags) {
  std::error_code ec;
  const fs::path out = options.output.empty() ? fs::path(".") : options.output.parent_path();
  output_dir_ = fs::weakly_canonical(fs::absolute(out.empty() ? fs::path(".") : out, ec), ec);
}

std::optional<std::string> AssetPaths::Name(const std::string& uri, const std::string& resolved,
                                            Loc loc) {
  if (options_.keep_package_uris && uri.starts_with("package://")) return uri;
  if (resolved.empty()) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("'{}' did not resolve to a file; it is written as the source "
                              "wrote it",
                              uri));
    return uri;
  }
  std::error_code ec;
  fs::path file = fs::weakly_canonical(fs::absolute(resolved, ec), ec);
  if (options_.copy_assets_dir) {
    auto copy = Copy(file, loc);
    if (!copy) return std::nullopt;
    file = *copy;
  }
  return Relative(file);
}

std::string AssetPaths::Relative(const fs::path& file) const {
  fs::path relative = file.lexically_relative(output_dir_);
  return (relative.empty() ? file : relative).generic_string();
}

std::optional<std::string> AssetPaths::NameMesh(const std::string& uri,
                                                const std::string& resolved, Loc loc,
                                                const MeshTarget& target) {
  if (resolved.empty()) return Name(uri, resolved, loc);
  std::error_code ec;
  const fs::path file = fs::weakly_canonical(fs::absolute(resolved, ec), ec);
  // asked once per file: a target's verdict may read the file's header
  auto [verdict, first] = target_verdicts_.try_emplace(file);
  if (first) verdict->second = target.why_not(file);
  const std::string& why = verdict->second;
  if (why.empty()) return Name(uri, resolved, loc);
  const bool kept_uri = options_.keep_package_uris && uri.starts_with("package://");
  if (options_.copy_assets_dir && !kept_uri && options_.meshes) {
    if (auto obj = ObjCopy(file, loc)) return Relative(*obj);
    return Name(uri, resolved, loc);  // UnconvertibleMesh() says why
  }
  if (unreadable_reported_.insert(file).second) {
    diags_.Report(DiagKind::Lossy, loc,
                  fmt::format("mesh '{}' is named as it is, but {}; {}--copy-assets writes "
                              "an OBJ of it that {} reads",
                              uri, why, kept_uri ? "without --keep-package-uris, " : "",
                              target.reader));
  }
  return Name(uri, resolved, loc);
}

std::optional<std::string> AssetPaths::UnconvertibleMesh(const std::string& resolved) const {
  if (resolved.empty()) return std::nullopt;
  std::error_code ec;
  auto it = unconvertible_.find(fs::weakly_canonical(fs::absolute(resolved, ec), ec));
  if (it == unconvertible_.end()) return std::nullopt;
  return it->second;
}

std::optional<std::string> AssetPaths::NameInlineMesh(const ir::Mesh& mesh, Loc loc,
                                                      std::string* why) {
  why->clear();
  if (!options_.copy_assets_dir || !options_.meshes || !mesh.inline_data) return std::nullopt;
  auto [it, first] = inline_copies_.try_emplace(mesh.resolved);
  InlineCopy& copy = it->second;
  if (first) {
    const ObjOrError obj =
        options_.meshes->ObjForInline(*mesh.inline_data, fmt::format("mesh '{}'", mesh.uri));
    if (!obj.ok()) {
      copy.why = obj.error;
    } else if (auto file = WriteCopy(obj.obj, fs::path(mesh.uri.empty() ? "mesh" : mesh.uri),
                                     ".obj", loc)) {
      copy.name = Relative(*file);
    } else {
      copy.why = "the copy cannot be written (reported)";
    }
  }
  *why = copy.why;
  return copy.name;
}

std::optional<fs::path> AssetPaths::ObjCopy(const fs::path& file, Loc loc) {
  if (auto it = obj_copies_.find(file); it != obj_copies_.end()) return it->second;
  if (unconvertible_.count(file)) return std::nullopt;
  // the triangles the compile read (its limits, its up-axis handling)
  const ObjOrError obj = options_.meshes->ObjFor(file);
  if (!obj.ok()) {
    unconvertible_[file] = obj.error;
    return std::nullopt;
  }
  auto copy = WriteCopy(obj.obj, file, ".obj", loc);
  if (copy) obj_copies_[file] = *copy;
  return copy;
}

std::optional<fs::path> AssetPaths::Copy(const fs::path& file, Loc loc) {
  if (auto it = copies_.find(file); it != copies_.end()) return it->second;
  auto bytes = ReadAll(file);
  if (!bytes) {
    diags_.Report(DiagKind::FileNotFound, loc,
                  fmt::format("cannot read '{}' to copy it", file.generic_string()));
    return std::nullopt;
  }
  auto copy = WriteCopy(*bytes, file, file.extension().string(), loc);
  if (copy) copies_[file] = *copy;
  return copy;
}

std::optional<fs::path> AssetPaths::WriteCopy(const std::string& bytes,
                                              const fs::path& named_after,
                                              const std::string& extension, Loc loc) {
  std::error_code ec;
  const fs::path dir = fs::weakly_canonical(fs::absolute(*options_.copy_assets_dir, ec), ec);
  auto& by_content = copies_by_content_[bytes];
  if (by_content.empty()) {
    fs::create_directories(dir, ec);
    by_content = dir / fmt::format("{}-{:016x}{}", named_after.stem().string(),
                                   ContentHash(bytes), extension);
    errno = 0;
    std::ofstream out(by_content, std::ios::binary);
    out << bytes;
    out.flush();
    if (!out) {
      // the system's reason (no such directory, permission denied, disk full)
      diags_.Report(DiagKind::FileNotFound, loc,
                    fmt::format("cannot write the copy '{}': {}", by_content.generic_string(),
                                errno ? std::strerror(errno) : "the file cannot be written"));
      by_content.clear();
      return std::nullopt;
    }
  }
  return by_content;
}

}  // namespace mdlc::writers
