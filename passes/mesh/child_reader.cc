#include "passes/mesh/child_reader.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "passes/mesh/mesh_wire.h"

extern char** environ;

namespace mdlc::mesh {
namespace {

using Clock = std::chrono::steady_clock;

/// Closes a file descriptor when it goes out of scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

/// A started child; kills and reaps it when it goes out of scope unreaped
/// (a timeout, or an exception while reading its reply).
struct Child {
  pid_t pid = -1;
  bool reaped = false;
  ~Child() {
    if (pid <= 0 || reaped) return;
    ::kill(pid, SIGKILL);
    while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
  }
};

int MillisecondsLeft(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return static_cast<int>(std::clamp<int64_t>(left.count(), 0, 1'000'000'000));
}

enum class Outcome { kDone, kTimedOut, kFailed };

/// Reads `fd` to its end into `out`, giving up at `deadline`. Meshes can be
/// hundreds of MB: read in large pieces, as they come.
Outcome ReadAll(int fd, Clock::time_point deadline, std::string& out) {
  constexpr size_t kPiece = size_t{1} << 20;
  for (;;) {
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, MillisecondsLeft(deadline));
    if (ready < 0 && errno == EINTR) continue;
    if (ready < 0) return Outcome::kFailed;
    if (ready == 0) return Outcome::kTimedOut;
    const size_t had = out.size();
    out.resize(had + kPiece);
    const ssize_t n = ::read(fd, out.data() + had, kPiece);
    out.resize(had + std::max<ssize_t>(n, 0));
    if (n == 0) return Outcome::kDone;
    if (n < 0 && errno != EINTR && errno != EAGAIN) return Outcome::kFailed;
  }
}

/// Waits for the child to exit, until `deadline`: it has closed its output,
/// so it should be gone at once, but it may also hang in its exit.
Outcome WaitUntil(Child& child, Clock::time_point deadline, int& status) {
  auto pause = std::chrono::milliseconds(1);
  for (;;) {
    const pid_t done = ::waitpid(child.pid, &status, WNOHANG);
    if (done == child.pid) {
      child.reaped = true;
      return Outcome::kDone;
    }
    if (done < 0 && errno != EINTR) {
      child.reaped = errno == ECHILD;  // reaped by someone else (SIGCHLD ignored)
      return Outcome::kFailed;
    }
    if (Clock::now() >= deadline) return Outcome::kTimedOut;
    std::this_thread::sleep_for(
        std::min(pause, std::chrono::milliseconds(MillisecondsLeft(deadline))));
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
}

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

/// Starts `argv` with its standard output on `out` and its standard input
/// empty; an errno value on failure.
int Spawn(const std::vector<std::string>& args, int out, Child& child) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawnattr_init(&attr);
  ::posix_spawn_file_actions_adddup2(&actions, out, STDOUT_FILENO);
  ::posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  // the calling thread may block signals, and an embedding interpreter
  // ignores SIGPIPE; the child starts with neither
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  ::posix_spawnattr_setsigmask(&attr, &none);
  ::posix_spawnattr_setsigdefault(&attr, &defaults);
  ::posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  const int rc = ::posix_spawn(&child.pid, args[0].c_str(), &actions, &attr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attr);
  if (rc != 0) child.pid = -1;
  return rc;
}

}  // namespace

MeshOrError LoadMeshInChild(const std::string& reader, const std::string& path,
                            const Limits& limits, const MeshAxes& axes) {
  // mdlc-mesh-reader NAME=VALUE... -- PATH (reader/mdlc_mesh_reader.cc)
  std::vector<std::string> args{reader};
  for (std::string& a : EncodeMeshRequest(path, limits, axes)) args.push_back(std::move(a));

  auto failed = [&](std::string what) { return MeshOrError{nullptr, std::move(what)}; };
  // close-on-exec: children other threads start at the same time must not
  // inherit the write end, or this read would never see its end
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) {
    return failed(fmt::format("cannot start the mesh reader for '{}': {}", path,
                              std::strerror(errno)));
  }
  Fd from_child{ends[0]};
  Child child;
  {
    Fd to_parent{ends[1]};
    if (const int rc = Spawn(args, to_parent.fd, child); rc != 0) {
      return failed(fmt::format("cannot run the mesh reader '{}' for '{}': {}", reader, path,
                                std::strerror(rc)));
    }
  }  // only the child holds the write end now

  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(limits.mesh_seconds);
  std::string reply;
  Outcome outcome = ReadAll(from_child.fd, deadline, reply);
  int status = 0;
  if (outcome == Outcome::kDone) outcome = WaitUntil(child, deadline, status);
  if (outcome == Outcome::kTimedOut) {
    return {nullptr,
            fmt::format("the mesh reader did not finish reading '{}' within {} s (the "
                        "mesh-seconds limit; raise it with --limit mesh-seconds=N)",
                        path, limits.mesh_seconds),
            true};
  }
  if (outcome == Outcome::kFailed) {
    return failed(fmt::format("lost the mesh reader while it read '{}': {}", path,
                              std::strerror(errno)));
  }
  if (WIFSIGNALED(status)) {
    return failed(fmt::format("the mesh reader crashed (signal {}, {}) reading '{}'",
                              WTERMSIG(status), SignalName(WTERMSIG(status)), path));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return failed(fmt::format("the mesh reader failed (exit status {}) reading '{}'",
                              WIFEXITED(status) ? WEXITSTATUS(status) : -1, path));
  }
  std::string problem;
  std::optional<MeshOrError> result = DecodeMeshReply(reply, &problem);
  if (!result) {
    return failed(fmt::format("the mesh reader sent a malformed reply reading '{}': {}", path,
                              problem));
  }
  return std::move(*result);
}

}  // namespace mdlc::mesh
