// compile_command.cc - `mdlc compile`: compile model files into a plant and
// print a summary, the IR or plant-json; also the pass instrumentation
// (--print-after, --time-passes, --verify-each) and --verify-diagnostics.
#include <fmt/format.h>

#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "ir/printer.h"
#include "mdlc/ir.h"
#include "mdlc/kinematics.h"
#include "mdlc/option_names.h"
#include "mdlc/pass_list.h"
#include "cli_compile.h"
#include "q_flag.h"
#include "subcommands.h"
#include "summary.h"
#include "verify_diagnostics.h"

namespace mdlc::cli {
namespace {

struct CompileCommandFlags {
  CompileFlags compile;
  std::string emit = "summary";
  std::string output;
  std::vector<std::string> q;
  std::vector<std::string> print_after;
  bool print_after_all = false;
  bool time_passes = false;
  bool verify_each = false;
  std::vector<std::string> passes;
  bool mass_matrix = false;
  bool verify_diagnostics = false;
  bool no_locations = false;
};

// --passes and --print-after name passes; a misspelt one would run a
// pipeline that fails on it, or print nothing, so it is bad usage instead
bool CheckPassNames(const CompileCommandFlags& flags) {
  std::optional<std::string> problem;
  for (const std::string& name : flags.passes) {
    if (!problem) problem = CheckPassName(name, "--passes");
  }
  for (const std::string& name : flags.print_after) {
    if (!problem) problem = CheckPassName(name, "--print-after");
  }
  if (problem) fmt::print(stderr, "mdlc: error: {}\n", *problem);
  return !problem;
}

int Run(const CompileCommandFlags& flags) {
  Options joint_positions;
  if (!ParseJointPositions(flags.q, joint_positions)) return 2;
  if (!CheckPassNames(flags)) return 2;

  std::vector<Diagnostic> collected;
  CompileSetup setup;
  if (flags.verify_diagnostics) {
    setup.diagnostics = DiagnosticOutput::Collect;
    setup.collected = &collected;
  }
  setup.keep_failed = true;  // the timing report comes first
  setup.adjust = [&](Options& options) {
    options.model.joint_positions = joint_positions.model.joint_positions;
    options.instrumentation.passes = flags.passes;
    options.instrumentation.print_after = flags.print_after;
    options.instrumentation.print_after_all = flags.print_after_all;
    options.instrumentation.time_passes = flags.time_passes;
    options.instrumentation.verify_each = flags.verify_each;
    options.skip_backend = flags.emit == "ir";
  };
  const CliCompile compiled = CompileForCli(flags.compile, setup);
  if (!compiled.result) return compiled.status;
  const Result& result = *compiled.result;

  if (flags.time_passes) fmt::print(stderr, "{}", TimingReport(result));
  if (flags.verify_diagnostics) {
    auto problems = tools::VerifyDiagnostics(collected, result.sources());
    for (const auto& p : problems) fmt::print(stderr, "{}\n", p);
    return problems.empty() ? 0 : 1;
  }
  if (!result.ok()) return ReportFailure(flags.compile, result);

  if (flags.emit == "ir") {
    ir::PrintOptions print;
    print.locations = !flags.no_locations;
    return WriteOutput(flags.output, ir::PrintModule(IrModule(result), result.sources(), print));
  }
  if (flags.emit == "none") return 0;
  // --format json asks for the machine-readable output: plant-json
  if (flags.emit == "summary" && flags.compile.output_format != "json") {
    return WriteOutput(flags.output, tools::FormatSummary(result.model()));
  }

  backend::PlantJsonOptions json_options;
  json_options.force_mass_matrix = flags.mass_matrix;
  return WriteOutput(flags.output, PlantJson(result, DefaultPositions(result), json_options));
}

}  // namespace

Subcommand AddCompileCommand(CLI::App& app) {
  auto flags = std::make_shared<CompileCommandFlags>();
  CLI::App* compile = app.add_subcommand("compile", "Compile robot model files into a plant");
  flags->compile.output_formats = {"text", "json"};  // json: --emit=plant-json
  AddCompileFlags(compile, flags->compile);
  compile->add_option("--emit", flags->emit, "What to print: summary, ir, plant-json or none")
      ->check(CLI::IsMember({"summary", "ir", "plant-json", "none"}));
  compile->add_option("-o,--output", flags->output, "Write the output here instead of stdout");
  AddJointPositionsFlag(compile, flags->q);
  compile
      ->add_option("--print-after", flags->print_after, "Print the IR after this pass (repeatable)")
      ->allow_extra_args(false);
  compile->add_flag("--print-after-all", flags->print_after_all, "Print the IR after every pass");
  compile->add_flag("--time-passes", flags->time_passes, "Report the time each pass takes");
  compile->add_flag("--verify-each", flags->verify_each, "Run the IR verifier after every pass");
  compile
      ->add_option("--passes", flags->passes, "Run these passes instead of the default pipeline")
      ->delimiter(',');
  compile->add_flag("--mass-matrix", flags->mass_matrix,
                    "Include the mass matrix in plant-json even above 1000 dofs");
  compile->add_flag("--verify-diagnostics", flags->verify_diagnostics,
                    "Check diagnostics against expected-error comments in the input");
  compile->add_flag("--no-locations", flags->no_locations,
                    "Leave source locations out of --emit=ir");
  return {compile, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
