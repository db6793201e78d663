// urdf_test_util.h - lowers URDF text into a Module for frontend and pass
// tests, and finds entities by name. Strict about diagnostics: see
// diagnostic_claims.h.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "frontend/frontend.h"
#include "ir/module.h"
#include "passes/pass_manager.h"
#include "tests/unit/diagnostic_claims.h"
#include "tests/unit/test_values.h"

namespace mdlc::testing {

struct Lowered : ClaimsDiagnostics {
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  std::optional<ModelId> model;

  Lowered() : ClaimsDiagnostics(diags) {}
  ~Lowered() { CheckClaimsAtEnd(); }
  Lowered(const Lowered&) = delete;
  Lowered& operator=(const Lowered&) = delete;

  /// Runs the URDF frontend on `text`.
  bool Read(std::string text, frontend::FrontendOptions options = {}) {
    FileId file = sources.AddBuffer("test.urdf", std::move(text));
    frontend::FrontendContext ctx{sources, diags, module, std::move(options)};
    model = frontend::ReadUrdf(file, ctx);
    return model.has_value() && !diags.has_errors();
  }
  /// Runs the default pass pipeline, verifying after each pass.
  bool RunPasses() {
    passes::PassInstrumentation inst;
    inst.verify_each = true;
    passes::PassManager pm(inst);
    pm.AddDefaultPipeline();
    passes::PassContext ctx{module, diags, sources};
    return pm.Run(ctx);
  }

  const ir::Body* Body(std::string_view name) const {
    return FindNamed(module, module.bodies, name);
  }
  const ir::Joint* Joint(std::string_view name) const {
    return FindNamed(module, module.joints, name);
  }
  /// Messages of all diagnostics, one per line, for failure output.
  std::string Messages() const {
    std::string out;
    for (const auto& d : diags.diagnostics()) out += d.message + "\n";
    return out;
  }

};

}  // namespace mdlc::testing
