// worker_process.h - one running mesh reader worker (issue 57): started
// with a socket as its standard input and output, sent requests, its reply
// frames read back within a deadline, killed and reaped when it is done
// with or has failed.
//
// Only the process mechanics live here; what a failure means for the mesh
// in flight is reader_pool.h's business.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace mdlc::mesh {

class WorkerProcess {
 public:
  using Clock = std::chrono::steady_clock;

  /// Starts `argv`; check started() (or error()) before using it.
  explicit WorkerProcess(const std::vector<std::string>& argv);
  /// Kills the worker (it may be blocked on its input or stuck in a file)
  /// and reaps it.
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  bool started() const { return pid_ > 0; }
  /// errno of a failed start.
  int start_error() const { return start_error_; }
  pid_t pid() const { return pid_; }
  /// Requests this worker has answered.
  size_t served() const { return served_; }

  /// Whether the worker looks able to take a request: still running, and
  /// silent (an idle worker has nothing to say; readable means it ended).
  bool LooksAlive();

  /// Sends `frame`; false when the worker is gone (it cannot have read it).
  bool Send(std::string_view frame);

  enum class Outcome { kReply, kEnded, kOverlong, kTimedOut, kFailed };
  /// Reads one reply frame into `reply` (the frame's payload), giving up at
  /// `deadline`; `*bytes_received` counts what came. kEnded: the worker
  /// closed its output before a whole frame; kOverlong: more came than the
  /// frame (one request is in flight at a time, so nothing may follow it);
  /// kFailed: reading failed.
  Outcome Receive(Clock::time_point deadline, std::string* reply, size_t* bytes_received);

  /// After kEnded: waits for the worker's exit until `deadline`, setting
  /// `*status` (a wait status) when it exited; kLost when it cannot be
  /// waited for (someone else reaped it). A worker that did not exit in
  /// time is killed when this object goes.
  enum class Exit { kExited, kTimedOut, kLost };
  Exit WaitForExit(Clock::time_point deadline, int* status);

 private:
  void KillAndReap();

  pid_t pid_ = -1;
  int fd_ = -1;
  int start_error_ = 0;
  bool reaped_ = false;
  size_t served_ = 0;
};

}  // namespace mdlc::mesh
