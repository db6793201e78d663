// pass.h - a named transformation or check over the IR Module.
//
// Passes read and write the Module and report problems to the diagnostic
// engine; they keep going after an error where they can, and return false
// when they reported one. Each pass states the verifier level that holds
// once it has run (see ir/verifier.h).
#pragma once

#include <memory>
#include <string_view>

#include "ir/assets/package_map.h"
#include "ir/diagnostics.h"
#include "ir/module.h"
#include "ir/source_manager.h"
#include "ir/verifier.h"
#include "passes/mesh/mesh_cache.h"

namespace mdlc::passes {

struct PassContext {
  ir::Module& module;
  DiagnosticEngine& diags;
  const SourceManager& sources;
  /// Packages for resolving package:// URIs.
  const assets::PackageMap& packages = assets::NoPackages();
  /// Mesh files read during this compile, each once (load-meshes fills it;
  /// fit-to-mesh, mass-from-geometry and inertia-from-collisions read it),
  /// with the derived data kept on disk between compiles when it has a
  /// DerivedMeshCache. An embedder may share one cache between compiles of
  /// the same files.
  std::shared_ptr<mesh::MeshCache> meshes = std::make_shared<mesh::MeshCache>();
};

class Pass {
 public:
  virtual ~Pass() = default;
  virtual std::string_view name() const = 0;
  virtual std::string_view description() const = 0;
  /// The invariants that hold after this pass succeeded.
  virtual ir::VerifyLevel level_after() const { return ir::VerifyLevel::Raw; }
  /// Returns false to stop the pipeline. A pass need not count its own
  /// errors: the pass manager stops after any pass that reported one.
  virtual bool Run(PassContext& ctx) = 0;
};

}  // namespace mdlc::passes
