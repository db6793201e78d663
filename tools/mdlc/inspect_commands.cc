// inspect_commands.cc - `mdlc tree` and `mdlc stats`: compile, then print
// what a formatter makes of the model (text, or JSON with --format json).
// A model that failed to compile is printed as far as it compiled (a mesh
// in an unknown package leaves the tree whole), after its errors; the exit
// status is then 1.
#include <fmt/format.h>

#include <memory>

#include "cli_compile.h"
#include "partial_model.h"
#include "stats.h"
#include "subcommands.h"
#include "tree.h"

namespace mdlc::cli {
namespace {

using Formatter = std::string (*)(const backend::CompiledModel&, const Result&);

struct InspectFlags {
  CompileFlags compile;
  std::string output;
};

int Inspect(const InspectFlags& flags, const char* name, Formatter format) {
  CompileSetup setup;
  setup.keep_failed = true;  // printed as far as it compiled
  const CliCompile compiled = CompileForCli(flags.compile, setup);
  if (!compiled.result) return compiled.status;
  const Result& result = *compiled.result;
  const backend::CompiledModel* model = ModelAsFarAsCompiled(result);
  int status = 0;
  if (model) {
    if (!result.ok()) {
      fmt::print(stderr,
                 "mdlc: note: {} of the model as far as it compiled; what the errors "
                 "above name is left out\n",
                 name);
    }
    status = WriteOutput(flags.output, format(*model, result));
  }
  return result.ok() ? status : ReportFailure(flags.compile, result);
}

Subcommand AddInspectCommand(CLI::App& app, const char* name, const char* description,
                             Formatter text, Formatter json) {
  auto flags = std::make_shared<InspectFlags>();
  CLI::App* command = app.add_subcommand(name, description);
  flags->compile.output_formats = {"text", "json"};
  AddCompileFlags(command, flags->compile);
  AddJsonAlias(command, flags->compile);
  command->add_option("-o,--output", flags->output, "Write the output here instead of stdout");
  return {command, [flags, name, text, json] {
            return Inspect(*flags, name, flags->compile.output_format == "json" ? json : text);
          }};
}

std::string Tree(const backend::CompiledModel& model, const Result&) {
  return tools::FormatTree(model);
}
std::string TreeJson(const backend::CompiledModel& model, const Result&) {
  return tools::FormatTreeJson(model);
}

}  // namespace

Subcommand AddTreeCommand(CLI::App& app) {
  return AddInspectCommand(app, "tree", "Print each model instance's kinematic tree", Tree,
                           TreeJson);
}

Subcommand AddStatsCommand(CLI::App& app) {
  return AddInspectCommand(app, "stats", "Print mass properties and counts", tools::FormatStats,
                           tools::FormatStatsJson);
}

}  // namespace mdlc::cli
