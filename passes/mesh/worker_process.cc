// worker_process.cc - see worker_process.h.
#include "passes/mesh/worker_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <optional>
#include <thread>

#include "passes/mesh/io/worker_frames.h"

extern char** environ;

namespace mdlc::mesh {
namespace {

int MillisecondsLeft(WorkerProcess::Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - WorkerProcess::Clock::now());
  return static_cast<int>(std::clamp<int64_t>(left.count(), 0, 1'000'000'000));
}

}  // namespace

WorkerProcess::WorkerProcess(const std::vector<std::string>& args) {
  // one socket for both directions: the worker's standard input and output
  // are its end. Close-on-exec: workers other threads start at the same
  // time must not inherit this end, or a worker's exit would go unseen.
  int ends[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    start_error_ = errno;
    return;
  }
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attr;
  ::posix_spawn_file_actions_init(&actions);
  ::posix_spawnattr_init(&attr);
  ::posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
  ::posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
  // the calling thread may block signals, and an embedding interpreter
  // ignores SIGPIPE; the worker starts with neither
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  ::posix_spawnattr_setsigmask(&attr, &none);
  ::posix_spawnattr_setsigdefault(&attr, &defaults);
  ::posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  const int rc = ::posix_spawn(&pid_, args[0].c_str(), &actions, &attr, argv.data(), environ);
  ::posix_spawn_file_actions_destroy(&actions);
  ::posix_spawnattr_destroy(&attr);
  ::close(ends[1]);  // only the worker holds its end now
  if (rc != 0) {
    pid_ = -1;
    start_error_ = rc;
    ::close(ends[0]);
    return;
  }
  fd_ = ends[0];
}

WorkerProcess::~WorkerProcess() {
  KillAndReap();
  if (fd_ >= 0) ::close(fd_);
}

void WorkerProcess::KillAndReap() {
  if (pid_ <= 0 || reaped_) return;
  ::kill(pid_, SIGKILL);
  while (::waitpid(pid_, nullptr, 0) < 0 && errno == EINTR) {
  }
  reaped_ = true;
}

bool WorkerProcess::LooksAlive() {
  if (!started() || reaped_) return false;
  pollfd p{fd_, POLLIN, 0};
  if (::poll(&p, 1, 0) != 0) return false;  // it spoke, or its end closed
  int status = 0;
  return ::waitpid(pid_, &status, WNOHANG) == 0;
}

bool WorkerProcess::Send(std::string_view frame) {
  size_t done = 0;
  while (done < frame.size()) {
    // MSG_NOSIGNAL: a worker that has died is an answer, not a SIGPIPE
    const ssize_t n = ::send(fd_, frame.data() + done, frame.size() - done, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

namespace {

/// What ReadSome got when it got no bytes.
enum : ssize_t { kEnd = 0, kError = -1, kTimeout = -2 };

/// Up to `want` bytes from `fd` into `into`, waiting for them until
/// `deadline`: a read first (a reply is usually there already), a poll only
/// when there is nothing yet. The count, or kEnd, kError or kTimeout.
ssize_t ReadSome(int fd, char* into, size_t want, WorkerProcess::Clock::time_point deadline) {
  for (;;) {
    const ssize_t n = ::recv(fd, into, want, MSG_DONTWAIT);
    if (n > 0) return n;
    if (n == 0 || errno == ECONNRESET) return kEnd;
    if (errno == EINTR) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) return kError;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, MillisecondsLeft(deadline));
    if (ready < 0 && errno != EINTR) return kError;
    if (ready == 0) return kTimeout;
  }
}

}  // namespace

WorkerProcess::Outcome WorkerProcess::Receive(Clock::time_point deadline, std::string* reply,
                                              size_t* bytes_received) {
  // Read the header, then the payload into a buffer that grows as bytes
  // come (never by what the header claims: the worker is not trusted),
  // in pieces of at most a MB. Nothing is read past the frame.
  constexpr size_t kPiece = size_t{1} << 20;
  char header[kReplyFrameHeader];
  size_t header_got = 0;
  std::optional<uint64_t> length;
  std::string& payload = *reply;
  payload.clear();
  size_t got = 0;
  *bytes_received = 0;
  for (;;) {
    if (length && got == *length) {
      payload.resize(got);
      // one request is in flight at a time, so nothing may follow the frame
      char extra;
      if (::recv(fd_, &extra, 1, MSG_PEEK | MSG_DONTWAIT) == 1) return Outcome::kOverlong;
      ++served_;
      return Outcome::kReply;
    }
    char* into;
    size_t want;
    if (!length) {
      into = header + header_got;
      want = kReplyFrameHeader - header_got;
    } else {
      want = static_cast<size_t>(std::min<uint64_t>(*length - got, kPiece));
      if (payload.size() < got + want) payload.resize(got + want);
      into = payload.data() + got;
    }
    const ssize_t n = ReadSome(fd_, into, want, deadline);
    if (n == kEnd) return Outcome::kEnded;
    if (n == kTimeout) return Outcome::kTimedOut;
    if (n < 0) return Outcome::kFailed;
    *bytes_received += static_cast<size_t>(n);
    if (!length) {
      header_got += static_cast<size_t>(n);
      if (header_got == kReplyFrameHeader) {
        length = ReplyFrameLength(std::string_view(header, kReplyFrameHeader));
      }
    } else {
      got += static_cast<size_t>(n);
    }
  }
}

WorkerProcess::Exit WorkerProcess::WaitForExit(Clock::time_point deadline, int* status) {
  auto pause = std::chrono::milliseconds(1);
  for (;;) {
    const pid_t done = ::waitpid(pid_, status, WNOHANG);
    if (done == pid_) {
      reaped_ = true;
      return Exit::kExited;
    }
    if (done < 0 && errno != EINTR) {
      reaped_ = errno == ECHILD;  // reaped by someone else (SIGCHLD ignored)
      return Exit::kLost;
    }
    if (Clock::now() >= deadline) return Exit::kTimedOut;
    std::this_thread::sleep_for(
        std::min(pause, std::chrono::milliseconds(MillisecondsLeft(deadline))));
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
}

}  // namespace mdlc::mesh
