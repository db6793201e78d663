// compiler.h - the whole pipeline, frontends -> passes -> backend, stage by
// stage. mdlc::Compile (mdlc/mdlc.h) is the public face of this class; the
// test suite and the benchmarks drive the stages one at a time.
//
//   mdlc::Compilation c;
//   c.options.inputs = {mdlc::Input::File("robot.urdf")};
//   if (!c.Run()) { for (auto& d : c.diags.diagnostics()) ...; }
//   const mdlc::backend::Plant& plant = c.model->plant;
//
// A Compilation owns everything a compile reads and makes: the source
// buffers (diagnostics point into them), the IR and the instantiated model.
// It is neither copyable nor movable, because those parts refer to each other.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backend/backend.h"
#include "frontend/frontend.h"
#include "ir/assets/package_map.h"
#include "ir/diagnostics.h"
#include "ir/module.h"
#include "ir/source_manager.h"
#include "mdlc/mdlc.h"
#include "passes/pass_manager.h"

namespace mdlc {

struct CompileOptions {
  std::vector<Input> inputs;
  frontend::FrontendOptions frontend;
  passes::PassInstrumentation instrumentation;
  /// Pass names to run instead of the default pipeline (empty: default).
  std::vector<std::string> pipeline;
  /// Stop after the passes (no plant, no scene graph).
  bool skip_backend = false;
  /// Where mesh files are read (Options::meshes.reader).
  mesh::MeshReading mesh_reading = mesh::MeshReading::kChildProcess;
  /// How they are turned Z-up (Options::meshes.collada_up_axis).
  mesh::MeshAxes mesh_axes;
  /// Weld free bodies to the world instead of floating them
  /// (Options::model.fixed_base).
  bool fixed_base = false;
  /// Options::diagnostics.policy, kept for what reports after the compile (Convert).
  DiagnosticPolicy diagnostics;
};

class Compilation {
 public:
  Compilation() = default;
  explicit Compilation(DiagnosticPolicy policy) : diags(std::move(policy)) {}
  Compilation(const Compilation&) = delete;
  Compilation& operator=(const Compilation&) = delete;

  CompileOptions options;
  SourceManager sources;
  DiagnosticEngine diags;
  ir::Module module;
  /// Packages for package:// and model:// URIs; fill before Run().
  assets::PackageMap packages;
  std::optional<backend::CompiledModel> model;
  /// Mesh files read during the compile, each once (the passes fill it;
  /// tools read it afterwards, e.g. MeshSizes in mdlc/meshes.h).
  std::shared_ptr<mesh::MeshCache> meshes = std::make_shared<mesh::MeshCache>();
  /// Derived mesh data on disk (CompileOptions::mesh_cache_dir); null: none.
  std::shared_ptr<mesh::DerivedMeshCache> derived_meshes;

  /// Each stage returns false once an error has been reported.
  bool RunFrontends();
  bool RunPasses();
  bool RunBackend();
  /// All three; false when any error was reported.
  bool Run();

  /// The pass manager's --time-passes report, after RunPasses.
  const std::string& timing_report() const { return timing_report_; }

 private:
  std::string timing_report_;
};

}  // namespace mdlc
