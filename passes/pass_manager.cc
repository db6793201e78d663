#include "passes/pass_manager.h"

#include <fmt/format.h>

#include <cstdio>

#include "ir/printer.h"
#include "passes/pass_registry.h"

namespace mdlc::passes {

void PassManager::AddDefaultPipeline() {
  for (const auto& info : RegisteredPasses()) AddPass(info.create());
}

bool PassManager::Run(PassContext& ctx) {
  timings_.clear();
  auto sink = instrumentation_.print_sink
                  ? instrumentation_.print_sink
                  : [](std::string_view s) { std::fwrite(s.data(), 1, s.size(), stderr); };
  for (auto& pass : passes_) {
    const size_t errors_before = ctx.diags.error_count();
    const auto start = std::chrono::steady_clock::now();
    bool ok = pass->Run(ctx);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    timings_.emplace_back(std::string(pass->name()), elapsed.count());
    ok = ok && ctx.diags.error_count() == errors_before;
    if (instrumentation_.print_after_all || instrumentation_.print_after.count(pass->name())) {
      sink(fmt::format("// ----- IR dump after {} -----\n", pass->name()));
      sink(ir::PrintModule(ctx.module, ctx.sources));
    }
    if (!ok) return false;
    if (instrumentation_.verify_each &&
        !ir::VerifyModule(ctx.module, pass->level_after(), ctx.diags)) {
      return false;
    }
  }
  return true;
}

std::string PassManager::TimingReport() const {
  double total = 0;
  for (const auto& [name, seconds] : timings_) total += seconds;
  std::string out = "===-------------------------------------------------------------===\n";
  out += "                      mdlc pass execution timing\n";
  out += "===-------------------------------------------------------------===\n";
  out += fmt::format("  Total: {:.6f} s\n", total);
  out += "   Wall time (s)   (%)    Pass\n";
  for (const auto& [name, seconds] : timings_) {
    out += fmt::format("  {:12.6f}  {:6.1f}%  {}\n", seconds,
                       total > 0 ? 100.0 * seconds / total : 0.0, name);
  }
  return out;
}

}  // namespace mdlc::passes
