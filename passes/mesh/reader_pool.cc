// reader_pool.cc - see reader_pool.h.
#include "passes/mesh/reader_pool.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cstring>
#include <map>

#include "passes/mesh/io/mesh_wire.h"
#include "passes/mesh/io/worker_frames.h"
#include "passes/mesh/worker_process.h"

namespace mdlc::mesh {
namespace {

std::string SignalName(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGABRT: return "SIGABRT";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGKILL: return "SIGKILL";
    case SIGTERM: return "SIGTERM";
    case SIGPIPE: return "SIGPIPE";
    default: return ::strsignal(sig);
  }
}

MeshOrError Failed(std::string what) { return MeshOrError{nullptr, std::move(what)}; }

MeshOrError TimedOut(const std::string& path, const Limits& limits) {
  return {nullptr,
          fmt::format("the mesh reader did not finish reading '{}' within {} s (the "
                      "mesh-seconds limit; raise it with --limit mesh-seconds=N)",
                      path, limits.mesh_seconds),
          true};
}

/// What became of a worker that ended while reading `path`, having sent
/// `bytes` bytes of its reply.
MeshOrError EndedWhileReading(WorkerProcess& worker, const std::string& path,
                              const Limits& limits, WorkerProcess::Clock::time_point deadline,
                              size_t bytes) {
  int status = 0;
  switch (worker.WaitForExit(deadline, &status)) {
    case WorkerProcess::Exit::kTimedOut: return TimedOut(path, limits);
    case WorkerProcess::Exit::kLost:
      return Failed(fmt::format("lost the mesh reader while it read '{}': {}", path,
                                std::strerror(ECHILD)));
    case WorkerProcess::Exit::kExited: break;
  }
  if (WIFSIGNALED(status)) {
    return Failed(fmt::format("the mesh reader crashed (signal {}, {}) reading '{}'",
                              WTERMSIG(status), SignalName(WTERMSIG(status)), path));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return Failed(fmt::format("the mesh reader failed (exit status {}) reading '{}'",
                              WIFEXITED(status) ? WEXITSTATUS(status) : -1, path));
  }
  return Failed(fmt::format("the mesh reader sent a malformed reply reading '{}': {}", path,
                            bytes == 0 ? std::string("it ended without one")
                                       : fmt::format("it ended after {} bytes, inside it", bytes)));
}

}  // namespace

MeshReaderPool::MeshReaderPool(std::string program) : program_(std::move(program)) {}

MeshReaderPool::~MeshReaderPool() = default;

std::vector<pid_t> MeshReaderPool::IdleWorkers() const {
  std::lock_guard lock(mutex_);
  std::vector<pid_t> pids;
  for (const auto& w : idle_) pids.push_back(w->pid());
  return pids;
}

std::unique_ptr<WorkerProcess> MeshReaderPool::Checkout() {
  {
    std::lock_guard lock(mutex_);
    while (!idle_.empty()) {
      std::unique_ptr<WorkerProcess> w = std::move(idle_.back());
      idle_.pop_back();
      if (w->LooksAlive()) return w;
      // ended between meshes (killed, or gone with the machine's memory):
      // it held no request, so nothing is lost but the process
    }
  }
  ++started_;
  return std::make_unique<WorkerProcess>(std::vector<std::string>{program_, "--serve"});
}

void MeshReaderPool::GiveBack(std::unique_ptr<WorkerProcess> worker) {
  if (worker->served() >= kFilesPerWorker) return;  // replaced: see the header
  std::lock_guard lock(mutex_);
  idle_.push_back(std::move(worker));
}

MeshOrError MeshReaderPool::Read(const std::string& path, const Limits& limits,
                                 const MeshAxes& axes) {
  const std::string frame = EncodeRequestFrame(EncodeMeshRequest(path, limits, axes));
  const auto deadline =
      WorkerProcess::Clock::now() + std::chrono::seconds(limits.mesh_seconds);
  for (int attempt = 0;; ++attempt) {
    std::unique_ptr<WorkerProcess> worker = Checkout();
    if (!worker->started()) {
      return Failed(fmt::format("cannot run the mesh reader '{}' for '{}': {}", program_, path,
                                std::strerror(worker->start_error())));
    }
    const bool reused = worker->served() > 0;
    if (!worker->Send(frame) && reused && attempt == 0) {
      continue;  // it died just after it was found alive; the file is not why
    }
    // a fresh worker that took no request tells why when it is waited for
    std::string reply;
    size_t bytes = 0;
    switch (worker->Receive(deadline, &reply, &bytes)) {
      case WorkerProcess::Outcome::kTimedOut: return TimedOut(path, limits);
      case WorkerProcess::Outcome::kFailed:
        return Failed(fmt::format("lost the mesh reader while it read '{}': {}", path,
                                  std::strerror(errno)));
      case WorkerProcess::Outcome::kEnded:
        return EndedWhileReading(*worker, path, limits, deadline, bytes);
      case WorkerProcess::Outcome::kOverlong:
        return Failed(fmt::format(
            "the mesh reader sent a malformed reply reading '{}': more than one reply", path));
      case WorkerProcess::Outcome::kReply: break;
    }
    std::string problem;
    std::optional<MeshOrError> result = DecodeMeshReply(reply, &problem);
    if (!result) {
      return Failed(fmt::format("the mesh reader sent a malformed reply reading '{}': {}", path,
                                problem));
    }
    GiveBack(std::move(worker));
    return std::move(*result);
  }
}

std::shared_ptr<MeshReaderPool> SharedMeshReaderPool(const std::string& program) {
  static std::mutex mutex;
  // leaked on purpose: no destructor runs at exit while another thread may
  // still read, and the workers end with the process anyway
  static auto* pools = new std::map<std::string, std::shared_ptr<MeshReaderPool>>;
  static pid_t owner = ::getpid();
  std::lock_guard lock(mutex);
  if (::getpid() != owner) {
    // a forked child: its parent's workers answer its parent; leave them be
    pools = new std::map<std::string, std::shared_ptr<MeshReaderPool>>;
    owner = ::getpid();
  }
  std::shared_ptr<MeshReaderPool>& pool = (*pools)[program];
  if (!pool) pool = std::make_shared<MeshReaderPool>(program);
  return pool;
}

MeshOrError LoadMeshInChild(const std::string& reader, const std::string& path,
                            const Limits& limits, const MeshAxes& axes) {
  MeshReaderPool pool(reader);
  return pool.Read(path, limits, axes);
}

}  // namespace mdlc::mesh
