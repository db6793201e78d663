// inspect_commands.cc - `mdlc tree` and `mdlc stats`: compile, then print
// what a formatter makes of the model (text, or JSON with --json).
#include <memory>

#include "cli_compile.h"
#include "stats.h"
#include "subcommands.h"
#include "tree.h"

namespace mdlc::cli {
namespace {

using Formatter = std::string (*)(const Result&);

struct InspectFlags {
  CompileFlags compile;
  std::string output;
  bool json = false;
};

Subcommand AddInspectCommand(CLI::App& app, const char* name, const char* description,
                             Formatter text, Formatter json) {
  auto flags = std::make_shared<InspectFlags>();
  CLI::App* command = app.add_subcommand(name, description);
  AddCompileFlags(command, flags->compile);
  command->add_flag("--json", flags->json, "Print JSON instead of text");
  command->add_option("-o,--output", flags->output, "Write the output here instead of stdout");
  return {command, [flags, text, json] {
            const CliCompile compiled = CompileForCli(flags->compile);
            if (compiled.status) return compiled.status;
            const Result& result = *compiled.result;
            return WriteOutput(flags->output, flags->json ? json(result) : text(result));
          }};
}

std::string Tree(const Result& result) { return tools::FormatTree(result.model()); }
std::string TreeJson(const Result& result) { return tools::FormatTreeJson(result.model()); }

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
