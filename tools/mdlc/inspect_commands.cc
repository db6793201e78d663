// inspect_commands.cc - `mdlc tree` and `mdlc stats`: compile, then print
// what a formatter makes of the model (text, or JSON with --format json).
// A model that failed to compile is printed as far as it compiled (a mesh
// in an unknown package leaves the tree whole), after its errors; the exit
// status is then 1.
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
  return PrintAsFarAsCompiled(flags.compile, name,
                              [&](const backend::CompiledModel& model, const Result& result) {
                                return WriteOutput(flags.output, format(model, result));
                              });
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
