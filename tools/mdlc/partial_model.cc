// partial_model.cc - see partial_model.h.
#include "partial_model.h"

#include "backend/backend.h"
#include "ir/verifier.h"

namespace mdlc::cli {

const backend::CompiledModel* ModelAsFarAsCompiled(const Result& result) {
  if (result.has_model()) return &result.model();
  if (result.module().bodies.size() <= 1) return nullptr;  // nothing but the world
  // What the verifier or the backend says of a half-compiled module is about
  // its missing parts, which the compile's own errors already explain.
  DiagnosticEngine unreported;
  if (!ir::VerifyModule(result.module(), ir::VerifyLevel::Named, unreported)) return nullptr;
  static std::optional<backend::CompiledModel> partial;  // a command prints one model
  partial = backend::Instantiate(result.module(), unreported);
  return partial ? &*partial : nullptr;
}

}  // namespace mdlc::cli
