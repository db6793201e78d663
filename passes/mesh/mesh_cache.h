// mesh_cache.h - every mesh file read at most once per compile.
//
// Keyed by the resolved path: however many geometries (or fitted
// primitives) name a file, and at whatever scale, it is read once; the
// unscaled mesh is shared. Prefetch() reads many files in parallel before
// the passes ask for them one by one. Get() is thread-safe.
//
// One cache lives in each PassContext (passes/pass.h); load-meshes fills it
// and the passes after it (fit-to-mesh, mass-from-geometry,
// inertia-from-collisions) read from it.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/mesh_loader.h"
#include "passes/mesh/triangle_mesh.h"

namespace mdlc::mesh {

class MeshCache {
 public:
  using Loader = std::function<MeshOrError(const std::string& path)>;

  /// A cache that reads files within `limits`, where `reading` says
  /// (mesh_loader.h), oriented as `axes` says (mesh_axes.h). The reader
  /// program is looked for once, here.
  explicit MeshCache(const Limits& limits = {},
                     MeshReading reading = MeshReading::kChildProcess,
                     const MeshAxes& axes = {});
  /// A cache with another loader (tests).
  explicit MeshCache(Loader loader) : loader_(std::move(loader)) {}
  MeshCache(const MeshCache&) = delete;
  MeshCache& operator=(const MeshCache&) = delete;

  /// The mesh at `path`, reading it on first use.
  MeshOrError Get(const std::string& path);
  /// Reads every path not read yet, on up to hardware_concurrency threads
  /// when there are several.
  void Prefetch(const std::vector<std::string>& paths);
  /// Files actually read so far.
  size_t files_read() const { return files_read_.load(); }
  /// The reader program files are read with; empty: in this process.
  const std::string& reader() const { return reader_; }
  /// Why files are read in this process though a reader program was asked
  /// for (worth telling the user: the protection is off); else empty.
  const std::string& reader_missing() const { return reader_missing_; }

 private:
  struct Entry {
    std::once_flag once;
    MeshOrError result;
  };
  std::shared_ptr<Entry> EntryFor(const std::string& path);

  Loader loader_;
  std::string reader_;
  std::string reader_missing_;
  std::mutex mutex_;  // guards entries_ (not the loading itself)
  std::unordered_map<std::string, std::shared_ptr<Entry>> entries_;
  std::atomic<size_t> files_read_{0};
};

}  // namespace mdlc::mesh
