// asset_paths.cc - see asset_paths.h.
#include "backend/writers/asset_paths.h"

#include <fmt/format.h>

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
  fs::path relative = file.lexically_relative(output_dir_);
  return (relative.empty() ? file : relative).generic_string();
}

std::optional<fs::path> AssetPaths::Copy(const fs::path& file, Loc loc) {
  if (auto it = copies_.find(file); it != copies_.end()) return it->second;
  auto bytes = ReadAll(file);
  if (!bytes) {
    diags_.Report(DiagKind::FileNotFound, loc,
                  fmt::format("cannot read '{}' to copy it", file.generic_string()));
    return std::nullopt;
  }
  std::error_code ec;
  const fs::path dir = fs::weakly_canonical(fs::absolute(*options_.copy_assets_dir, ec), ec);
  auto& by_content = copies_by_content_[*bytes];
  if (by_content.empty()) {
    fs::create_directories(dir, ec);
    by_content = dir / fmt::format("{}-{:016x}{}", file.stem().string(), ContentHash(*bytes),
                                   file.extension().string());
    std::ofstream out(by_content, std::ios::binary);
    out << *bytes;
    if (!out) {
      diags_.Report(DiagKind::FileNotFound, loc,
                    fmt::format("cannot write the copy '{}'", by_content.generic_string()));
      by_content.clear();
      return std::nullopt;
    }
  }
  copies_[file] = by_content;
  return by_content;
}

}  // namespace mdlc::writers
