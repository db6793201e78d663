// reader_pool.h - reads mesh files in mesh reader worker processes that
// each read many files (issues 16 and 57), so that a crash, hang or leak
// inside assimp becomes an error about one file instead of taking down the
// compiler or the program embedding it, at the cost of a process per
// reading thread rather than per file.
//
// A worker (reader/mdlc_mesh_reader.cc) takes request frames and answers
// with reply frames (worker_frames.h). A worker that crashes, fails, sends
// a malformed reply or does not answer within the mesh-seconds limit is
// ended; the mesh it was reading gets an error saying which of these
// happened, and the next mesh gets a fresh worker. A worker found dead
// between meshes costs nothing but its replacement: a request that could
// not be delivered is sent again, to a fresh worker.
//
// A worker serves a bounded number of files, then is replaced, so that
// whatever assimp leaks stays bounded in a long-lived pool (the fuzzer's).
#pragma once

#include <sys/types.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ir/limits.h"
#include "passes/mesh/io/triangle_mesh.h"

namespace mdlc::mesh {

class WorkerProcess;

class MeshReaderPool {
 public:
  /// Files a worker reads before it is replaced.
  static constexpr size_t kFilesPerWorker = 1000;

  /// Workers run `program --serve`; none is started before the first read.
  explicit MeshReaderPool(std::string program);
  /// Ends the idle workers.
  ~MeshReaderPool();
  MeshReaderPool(const MeshReaderPool&) = delete;
  MeshReaderPool& operator=(const MeshReaderPool&) = delete;

  /// The mesh in `path`, read by a worker within `limits` and oriented as
  /// `axes` says. Thread-safe: each concurrent read has a worker of its own.
  MeshOrError Read(const std::string& path, const Limits& limits, const MeshAxes& axes = {});

  const std::string& program() const { return program_; }
  /// Workers started so far.
  size_t workers_started() const { return started_.load(); }
  /// The process ids of the workers waiting for a request (tests).
  std::vector<pid_t> IdleWorkers() const;

 private:
  std::unique_ptr<WorkerProcess> Checkout();
  void GiveBack(std::unique_ptr<WorkerProcess> worker);

  std::string program_;
  mutable std::mutex mutex_;  // guards idle_
  std::vector<std::unique_ptr<WorkerProcess>> idle_;
  std::atomic<size_t> started_{0};
};

/// The pool of workers of `program` that every compile in this process
/// shares, so that a program compiling many models (an embedder, a
/// benchmark, a Python session) starts its workers once; idle workers end
/// when this process does (their input closes). Never destroyed. A process
/// forked from one that had a pool gets a pool of its own.
std::shared_ptr<MeshReaderPool> SharedMeshReaderPool(const std::string& program);

/// The mesh in `path`, read by a worker of `reader` started for it alone.
MeshOrError LoadMeshInChild(const std::string& reader, const std::string& path,
                            const Limits& limits, const MeshAxes& axes = {});

}  // namespace mdlc::mesh
