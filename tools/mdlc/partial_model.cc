// partial_model.cc - see partial_model.h.
#include "partial_model.h"

#include <fmt/format.h>

#include <cstdio>

#include "backend/backend.h"
#include "ir/verifier.h"
#include "mdlc/ir.h"

namespace mdlc::cli {

const backend::CompiledModel* ModelAsFarAsCompiled(const Result& result) {
  if (result.has_model()) return &result.model();
  if (IrModule(result).bodies.size() <= 1) return nullptr;  // nothing but the world
  // What the verifier or the backend says of a half-compiled module is about
  // its missing parts, which the compile's own errors already explain.
  DiagnosticEngine unreported;
  if (!ir::VerifyModule(IrModule(result), ir::VerifyLevel::Named, unreported)) return nullptr;
  static std::optional<backend::CompiledModel> partial;  // a command prints one model
  partial = backend::Instantiate(IrModule(result), unreported);
  return partial ? &*partial : nullptr;
}

int PrintAsFarAsCompiled(
    const CompileFlags& flags, const char* what,
    const std::function<int(const backend::CompiledModel&, const Result&)>& print) {
  CompileSetup setup;
  setup.keep_failed = true;  // printed as far as it compiled
  const CliCompile compiled = CompileForCli(flags, setup);
  if (!compiled.result) return compiled.status;
  const Result& result = *compiled.result;
  const backend::CompiledModel* model = ModelAsFarAsCompiled(result);
  int status = 0;
  if (model) {
    if (!result.ok()) {
      fmt::print(stderr,
                 "mdlc: note: {} of the model as far as it compiled; what the errors "
                 "above name is left out\n",
                 what);
    }
    status = print(*model, result);
  }
  return result.ok() ? status : ReportFailure(flags, result);
}

}  // namespace mdlc::cli
