// diagnostic_stream.h - the command line's diagnostics on their way to
// standard error, gathered into few writes when they come in a flood.
//
// Every write to standard error is a system call. A model that draws one
// warning per joint makes thousands of them: writing the 10,000 warnings of
// a 10,000-joint URDF chain one at a time took longer than compiling the
// chain. So a diagnostic that comes alone is written at once, as before, but
// one that follows the last write within kGatherWindow waits in a buffer,
// written when it holds kGatherBytes, when a later diagnostic comes after a
// quiet spell, or when the compile ends (Finish). Until then a gathered
// diagnostic may wait for the rest of the compile; the order of the text
// never changes.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace mdlc::cli {

class DiagnosticStream {
 public:
  using Clock = std::chrono::steady_clock;
  /// Receives the text, written in as few pieces as the stream can.
  using Sink = std::function<void(std::string_view)>;

  static constexpr Clock::duration kGatherWindow = std::chrono::milliseconds(50);
  static constexpr size_t kGatherBytes = 64 * 1024;

  explicit DiagnosticStream(Sink sink, std::function<Clock::time_point()> now = Clock::now)
      : sink_(std::move(sink)), now_(std::move(now)) {}
  DiagnosticStream(const DiagnosticStream&) = delete;
  DiagnosticStream& operator=(const DiagnosticStream&) = delete;
  ~DiagnosticStream() { Flush(); }

  /// One diagnostic's whole text.
  void Write(std::string_view text);
  /// Writes what is gathered; what comes after is written at once, as the
  /// diagnostics of writing the output come one by one after the compile.
  void Finish();

 private:
  void Flush();

  Sink sink_;
  std::function<Clock::time_point()> now_;
  std::string pending_;
  std::optional<Clock::time_point> last_write_;
  bool finished_ = false;
};

}  // namespace mdlc::cli
