// pass_manager.h - runs a pipeline of passes with instrumentation:
// printing the IR after chosen passes, timing, and verification between
// passes (MLIR's PassManager, in miniature).
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "passes/pass.h"

namespace mdlc::passes {

struct PassInstrumentation {
  std::set<std::string, std::less<>> print_after;  // pass names
  bool print_after_all = false;
  bool time_passes = false;
  bool verify_each = false;
  /// Where IR dumps go (default: stderr).
  std::function<void(std::string_view)> print_sink;
};

class PassManager {
 public:
  explicit PassManager(PassInstrumentation instrumentation = {})
      : instrumentation_(std::move(instrumentation)) {}

  void AddPass(std::unique_ptr<Pass> pass) { passes_.push_back(std::move(pass)); }
  /// Every registered pass in default order.
  void AddDefaultPipeline();

  /// Runs the passes in order; stops after the first pass that reported an
  /// error (or whose result fails verification). Returns true on success.
  bool Run(PassContext& ctx);

  /// "--time-passes" report of the last Run.
  std::string TimingReport() const;

 private:
  PassInstrumentation instrumentation_;
  std::vector<std::unique_ptr<Pass>> passes_;
  std::vector<std::pair<std::string, double>> timings_;  // seconds
};

}  // namespace mdlc::passes
