// diagnostic_stream.cc - gathering a flood of diagnostics into few writes.
#include "diagnostic_stream.h"

namespace mdlc::cli {

void DiagnosticStream::Write(std::string_view text) {
  if (finished_) {
    sink_(text);
    return;
  }
  const Clock::time_point now = now_();
  const bool alone = !last_write_ || now - *last_write_ >= kGatherWindow;
  pending_.append(text);
  if (alone || pending_.size() >= kGatherBytes) {
    Flush();
    last_write_ = now;
  }
}

void DiagnosticStream::Finish() {
  Flush();
  finished_ = true;
}

void DiagnosticStream::Flush() {
  if (pending_.empty()) return;
  sink_(pending_);
  pending_.clear();
}

}  // namespace mdlc::cli
