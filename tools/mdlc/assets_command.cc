// assets_command.cc - `mdlc assets`: every file the model uses, found or
// not. It lists what was read and named even when the compile failed (a
// missing mesh is the usual reason to run it); exit 1 when any file is
// missing or the model has errors.
#include <memory>

#include "assets.h"
#include "cli_compile.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct AssetsFlags {
  CompileFlags compile;
  std::string output;
};

int Run(const AssetsFlags& flags) {
  CompileSetup setup;
  setup.diagnostics = DiagnosticOutput::ErrorsAfter;  // the listing reads the rest
  setup.keep_failed = true;
  setup.adjust = [](Options& options) { options.skip_backend = true; };  // files known by then
  const CliCompile compiled = CompileForCli(flags.compile, setup);
  if (!compiled.result) return compiled.status;
  const tools::AssetReport report = tools::ListAssets(*compiled.result, flags.compile.output_format == "json");
  if (int status = WriteOutput(flags.output, report.text)) return status;
  return report.all_found && compiled.result->ok() ? 0 : 1;
}

}  // namespace

Subcommand AddAssetsCommand(CLI::App& app) {
  auto flags = std::make_shared<AssetsFlags>();
  CLI::App* assets = app.add_subcommand("assets", "List every file a model uses, found or not");
  flags->compile.output_formats = {"text", "json"};
  AddCompileFlags(assets, flags->compile);
  AddJsonAlias(assets, flags->compile);
  assets->add_option("-o,--output", flags->output, "Write the output here instead of stdout");
  return {assets, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
