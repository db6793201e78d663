// derived_cache.h - derived mesh data (convex hulls' and meshes' mass
// properties) kept on disk between compiles (issue 16).
//
// An entry is keyed by what it was derived from: the bytes of the mesh file,
// the processing options (scale, inertia mode, what was computed) and the
// cache format version, so an edited file, other options or a new mdlc never
// see a stale entry. Entries are written to a temporary file and renamed
// into place, so readers see whole entries or none; an entry that is
// truncated or corrupt (its checksum or key does not match) is ignored and
// recomputed. Any number of threads and processes may share a directory.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mdlc::mesh {

/// A file's content, condensed: two independent 64-bit hashes and its size.
/// A key (DerivedMeshCache::Key) adds the options to it.
struct ContentDigest {
  uint64_t a = 0, b = 0, size = 0;
};

class DerivedMeshCache {
 public:
  /// Entries live in `dir` (made when first written).
  explicit DerivedMeshCache(std::string dir) : dir_(std::move(dir)) {}

  /// Where the command line keeps the cache: $MDLC_CACHE_DIR, else
  /// $XDG_CACHE_HOME/mdlc, else $HOME/.cache/mdlc; empty when none is set.
  static std::string DefaultDirectory();

  /// The key of data derived from the file at `path` with `options` (any
  /// text that names the processing); nullopt when the file cannot be read.
  static std::optional<std::string> Key(const std::string& path, std::string_view options);
  /// The same from the file's digest, for a file digested once and keyed
  /// many times.
  static std::string Key(const ContentDigest& content, std::string_view options);
  /// The digest of the file at `path`; nullopt when it cannot be read.
  static std::optional<ContentDigest> Digest(const std::string& path);

  /// The values stored under `key`, or nullopt (a miss) when there are none
  /// or the entry is damaged.
  std::optional<std::vector<double>> Load(const std::string& key);
  /// Stores `values` under `key`; a failure to write only costs a later miss.
  void Store(const std::string& key, const std::vector<double>& values);

  const std::string& directory() const { return dir_; }
  size_t hits() const { return hits_.load(); }
  size_t misses() const { return misses_.load(); }

 private:
  std::string dir_;
  std::atomic<size_t> hits_{0}, misses_{0};
};

}  // namespace mdlc::mesh
