// mesh_cache.h - every mesh file read at most once per compile, and not at
// all when the derived cache already knows what the compile takes from it.
//
// Keyed by the resolved path: however many geometries (or fitted
// primitives) name a file, and at whatever scale, it is read once; the
// unscaled mesh is shared. Thread-safe.
//
// Two questions can be asked of a file:
//  - Status(): whether it is a mesh, and the facts a compile reports and
//    keys derived data by (MeshFacts). With a DerivedMeshCache these come
//    from the cache when it has them for the file's content and the
//    reading settings (limits, up-axis handling), so a warm compile hashes
//    the file and reads no mesh (issue 57); else the file is read.
//  - Get(): the triangles themselves, read on first use.
// Survey() and Prefetch() ask many files in parallel, one reader worker
// per thread (reader_pool.h).
//
// One cache lives in each PassContext (passes/pass.h); load-meshes surveys
// the files the compile needs, and the passes after it (fit-to-mesh,
// mass-from-geometry, inertia-from-collisions) take derived data through
// cached_properties.h, which reads the mesh only on a miss.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/derived_cache.h"
#include "passes/mesh/mesh_loader.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

class MeshReaderPool;

/// What a compile takes from a mesh file besides its triangles.
struct MeshFacts {
  UpAxis declared_up = UpAxis::kNone;
  bool turned_to_z_up = false;
  uint64_t vertices = 0;
  uint64_t triangles = 0;
};

/// A mesh file's facts, or why it is not a mesh.
struct MeshStatus {
  std::optional<MeshFacts> facts;
  std::string error;        // set when `facts` is not
  bool over_limit = false;  // the error is an input limit (ir/limits.h)
  bool ok() const { return facts.has_value(); }
};

class MeshCache {
 public:
  using Loader = std::function<MeshOrError(const std::string& path)>;

  /// A cache that reads files within `limits`, where `reading` says
  /// (mesh_loader.h), oriented as `axes` says (mesh_axes.h), and keeps what
  /// it learns in `derived` (none: every compile reads its meshes). The
  /// reader program is looked for once, here.
  explicit MeshCache(const Limits& limits = {},
                     MeshReading reading = MeshReading::kChildProcess,
                     const MeshAxes& axes = {},
                     std::shared_ptr<DerivedMeshCache> derived = nullptr);
  /// A cache with another loader (tests); `settings` names what the loader
  /// does, for the derived cache's keys.
  explicit MeshCache(Loader loader, std::shared_ptr<DerivedMeshCache> derived = nullptr,
                     std::string settings = "test-loader");
  ~MeshCache();
  MeshCache(const MeshCache&) = delete;
  MeshCache& operator=(const MeshCache&) = delete;

  /// The mesh at `path`, reading it on first use. A file of points without
  /// triangles gives their convex hull (point_cloud.h).
  MeshOrError Get(const std::string& path);
  /// Keeps `mesh` under `key`, a name no file has (an MJCF inline mesh):
  /// Get() and Status() answer from it and nothing is read, hashed or
  /// stored in the derived cache for it. A key already asked for keeps what
  /// it had.
  void Provide(const std::string& key, MeshOrError mesh);
  /// Whether `path` is a mesh and its facts; from the derived cache when it
  /// has them, else by reading the file (Get).
  MeshStatus Status(const std::string& path);
  /// Status() of every path: the derived cache asked for all of them on up
  /// to hardware_concurrency threads, then the files it does not know read
  /// on as many threads as their size is worth (a thread per 2 MB, up to
  /// hardware_concurrency: each thread starts a worker).
  void Survey(const std::vector<std::string>& paths);
  /// Get() of every path, on up to hardware_concurrency threads.
  void Prefetch(const std::vector<std::string>& paths);

  /// The digest of the file's content (computed once per file); nullopt
  /// when it cannot be read.
  std::optional<ContentDigest> Digest(const std::string& path);
  /// Where derived data is kept; null when nowhere.
  DerivedMeshCache* derived() const { return derived_.get(); }

  /// Files parsed as meshes, files hashed, and files whose facts came from
  /// the derived cache, so far (`--time-passes`).
  size_t files_read() const { return files_read_.load(); }
  size_t files_hashed() const { return files_hashed_.load(); }
  size_t facts_from_cache() const { return facts_from_cache_.load(); }
  /// The reader program files are read with; empty: in this process.
  const std::string& reader() const { return reader_; }
  /// Why files are read in this process though a reader program was asked
  /// for (worth telling the user: the protection is off); else empty.
  const std::string& reader_missing() const { return reader_missing_; }
  /// Reader worker processes started since this cache was made (by the
  /// process's shared pool, reader_pool.h: idle workers of earlier compiles
  /// are reused).
  size_t workers_started() const;

 private:
  struct Entry {
    std::once_flag read_once, status_once, digest_once, lookup_once;
    MeshOrError mesh;
    MeshStatus status;
    std::optional<ContentDigest> digest;
    std::optional<std::string> facts_key;   // where the facts are kept
    std::optional<MeshFacts> cached_facts;  // what the derived cache had
  };
  std::shared_ptr<Entry> EntryFor(const std::string& path);
  /// Asks the derived cache for the file's facts, once.
  Entry& LookUp(const std::string& path);
  MeshStatus FindStatus(const std::string& path);
  /// Runs `work` on each of `todo` (no repeats), on up to `threads` threads.
  static void ForEachInParallel(const std::vector<std::string>& todo, size_t threads,
                                const std::function<void(const std::string&)>& work);

  Loader loader_;
  std::string settings_;  // what changes a read's result besides the bytes
  std::shared_ptr<DerivedMeshCache> derived_;
  std::shared_ptr<MeshReaderPool> pool_;
  size_t workers_before_ = 0;
  std::string reader_;
  std::string reader_missing_;
  std::mutex mutex_;  // guards entries_ (not the loading itself)
  std::unordered_map<std::string, std::shared_ptr<Entry>> entries_;
  std::atomic<size_t> files_read_{0}, files_hashed_{0}, facts_from_cache_{0};
};

}  // namespace mdlc::mesh
