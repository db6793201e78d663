#include "tools/driver/compiler.h"

#include <fmt/format.h>

#include "frontend/model_naming.h"
#include "ir/count_text.h"
#include "frontend/xacro/xacro.h"
#include "passes/mesh/in_process_reader.h"
#include "passes/build_kinematic_tree.h"
#include "passes/pass_registry.h"

namespace mdlc {

namespace {

void ReadInput(const Input& input, frontend::FrontendContext& ctx) {
  if (!input.text) {
    frontend::ReadModelFile(input.path, ctx, input.format);
    return;
  }
  std::optional<Format> format = input.format ? input.format : FormatFromPath(input.path);
  if (!format && xacro::IsXacroPath(input.path)) {
    const FileId file = ctx.sources.AddBuffer(input.path, *input.text);
    if (auto xacro_format = frontend::XacroFormat(file, ctx.sources)) {
      frontend::ReadModel(file, *xacro_format, ctx);
      return;
    }
  }
  if (!format) {
    ctx.diags.Report(DiagKind::UnknownFormat, {},
                     fmt::format("model text '{}': no format given and none known by its "
                                 "extension; expected .urdf, .sdf, .xml (MJCF) or .dmd.yaml, or "
                                 "a format named ({})",
                                 input.path, kFormatNames));
    return;
  }
  frontend::ReadModel(ctx.sources.AddBuffer(input.path, *input.text), *format, ctx);
}

}  // namespace

bool Compilation::RunFrontends() {
  // a file the inputs load many times is parsed at most twice (see
  // document_cache.h); the trees go when the frontends are done, as the IR
  // holds copies of what it needs
  xml::DocumentCache documents;
  frontend::RenameSuffixes renames;
  frontend::FrontendContext ctx{sources, diags, module, options.frontend, packages, &documents,
                                &renames};
  for (const Input& input : options.inputs) {
    // keep going: report the problems of every input in one run
    ReadInput(input, ctx);
  }
  return !diags.has_errors();
}

bool Compilation::RunPasses() {
  passes::PassManager pm(options.instrumentation);
  // --fixed-base: the tree is built with free bodies welded, not floating
  auto create = [&](std::string_view name) {
    if (options.fixed_base && name == "build-kinematic-tree") {
      return passes::CreateFixedBaseKinematicTreePass();
    }
    return passes::CreatePass(name);
  };
  if (options.pipeline.empty()) {
    for (const auto& info : passes::RegisteredPasses()) pm.AddPass(create(info.name));
  } else {
    for (const std::string& name : options.pipeline) {
      auto pass = create(name);
      if (!pass) {
        diags.Report(DiagKind::UnknownReference, {},
                     fmt::format("unknown pass '{}' (see --list-passes)", name));
        return false;
      }
      pm.AddPass(std::move(pass));
    }
  }
  // read within the limits, where the options say
  meshes = std::make_shared<mesh::MeshCache>(sources.limits(), options.mesh_reading,
                                             options.mesh_axes, derived_meshes);
  passes::PassContext ctx{module, diags, sources, packages, meshes};
  const bool ok = pm.Run(ctx);
  if (options.instrumentation.time_passes) {
    timing_report_ = pm.TimingReport();
    timing_report_ += fmt::format(
        "  meshes: {} parsed, {} hashed, {} known from the cache; {} reader workers started\n",
        meshes->files_read(), meshes->files_hashed(), meshes->facts_from_cache(),
        meshes->workers_started());
    if (derived_meshes) {
      timing_report_ += fmt::format("  mesh cache: {}, {} ({})\n",
                                    ir::CountOf(derived_meshes->hits(), "hit"),
                                    ir::CountOf(derived_meshes->misses(), "miss", "misses"),
                                    derived_meshes->directory());
    } else {
      timing_report_ += "  mesh cache: off\n";
    }
    if (!meshes->reader().empty()) {
      timing_report_ += fmt::format("  mesh reader: {}\n", meshes->reader());
    } else {
      const mesh::MeshReaderLocation module = mesh::ImportModuleLocation();
      timing_report_ += fmt::format(
          "  mesh reader: {}, with {}\n",
          meshes->reader_missing().empty() ? "in this process (asked for)"
                                           : "none, meshes read in this process",
          module.path.empty() ? module.why_none : module.path);
    }
  }
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
