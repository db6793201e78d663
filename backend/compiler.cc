#include "backend/compiler.h"

#include <fmt/format.h>

#include "passes/pass_registry.h"

namespace mdlc {

bool Compilation::RunFrontends() {
  frontend::FrontendContext ctx{sources, diags, module, options.frontend, &documents};
  ctx.packages = &packages;
  for (const std::string& file : options.files) {
    // keep going: report the problems of every file in one run
    frontend::ReadModelFile(file, ctx);
  }
  return !diags.has_errors();
}

bool Compilation::RunPasses() {
  passes::PassManager pm(options.instrumentation);
  if (options.pipeline.empty()) {
    pm.AddDefaultPipeline();
  } else {
    for (const std::string& name : options.pipeline) {
      auto pass = passes::CreatePass(name);
      if (!pass) {
        diags.Report(DiagKind::UnknownReference, {},
                     fmt::format("unknown pass '{}' (see --list-passes)", name));
        return false;
      }
      pm.AddPass(std::move(pass));
    }
  }
  passes::PassContext ctx{module, diags, sources, &packages};
  const bool ok = pm.Run(ctx);
  if (options.instrumentation.time_passes) timing_report_ = pm.TimingReport();
  return ok && !diags.has_errors();
}

bool Compilation::RunBackend() {
  model = backend::Instantiate(module, diags);
  return model.has_value() && !diags.has_errors();
}

bool Compilation::Run() {
  if (!RunFrontends()) return false;
  if (!RunPasses()) return false;
  if (options.skip_backend) return true;
  return RunBackend();
}

}  // namespace mdlc
