// main.cc - the mdlc command line.
//
//   mdlc compile FILE... [--emit=summary|ir|plant-json|none] [-o FILE]
//                        [--q JOINT=VALUE ...] [--diagnostics-format=text|json]
//                        [-Werror|--strict] [-Wno-GROUP] [-Werror=GROUP]
//                        [--print-after=PASS] [--print-after-all] [--time-passes]
//   mdlc convert FILE... --to urdf -o OUT [--copy-assets DIR] [--keep-package-uris]
//                        [--fuse-fixed]
//   mdlc tree FILE... [--format json] each model instance's kinematic tree
//   mdlc stats FILE... [--format json] mass properties and counts
//   mdlc graph FILE... [--kind kinematic|frames] [--format dot|json] [-o OUT(.dot|.svg|.png)]
//   mdlc assets FILE... [--format json] every file the model uses, found or not
//   mdlc view FILE... -o model.html   the model in 3D, in one offline HTML page
//   mdlc check PATH... [-j N] [--format text|json|sarif] [--skip-ok REPORT.jsonl]
//   mdlc dynamics FILE... [--q J=X] [--v J=X] [--vdot J=X] [--tau J=X] [--format json]
//   mdlc --list-passes
//   mdlc --list-warnings            the diagnostic groups -W selects
//
// FILE is a model file, a Gazebo model folder (its model.config names the
// file) or '-' (standard input). --format names the output (text, json, ...)
// or the input's format (urdf, sdf, mjcf, dmd, xacro; also -x); --json is
// the older spelling of --format json.
//
// Each subcommand lives in its own file (subcommands.h); what the compiling
// ones share is in cli_compile.h.
//
// Exit status: 0 on success, 1 when any error was reported, 2 on bad usage.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <filesystem>

#include "mdlc/mdlc.h"
#include "mdlc/pass_list.h"
#include "cli_compile.h"
#include "subcommands.h"
#include "tools/driver/heap_policy.h"
#include "warning_groups.h"

int main(int argc, char** argv) {
  mdlc::KeepFreedMemoryForReuse();  // one batch that exits when done
  CLI::App app{"mdlc - a model compiler for robotics (URDF, SDFormat, MJCF, Model Directives)"};
  app.set_version_flag("--version", fmt::format("mdlc {}", mdlc::kVersion));
  // the usage line names the program as it was called, without its folder
  if (argc > 0) app.name(std::filesystem::path(argv[0]).filename().string());
  app.require_subcommand(0, 1);
  bool list_passes = false;
  app.add_flag("--list-passes", list_passes, "List the registered passes and exit");
  bool list_warnings = false;
  app.add_flag("--list-warnings", list_warnings,
               "List the diagnostic groups that -W, -Wno- and -Werror= select, and exit");

  namespace cli = mdlc::cli;
  const cli::Subcommand subcommands[] = {
      cli::AddCompileCommand(app), cli::AddConvertCommand(app), cli::AddTreeCommand(app),
      cli::AddStatsCommand(app),   cli::AddGraphCommand(app),   cli::AddAssetsCommand(app),
      cli::AddViewCommand(app),    cli::AddCheckCommand(app),   cli::AddXacroCommand(app),
      cli::AddDynamicsCommand(app),
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (list_passes) {
    for (const mdlc::PassListing& info : mdlc::PassList()) {
      fmt::print("  {:<24} {}\n", info.name, info.description);
    }
    return 0;
  }
  if (list_warnings) {
    fmt::print("{}", cli::ListWarningGroups());
    return 0;
  }
  for (const cli::Subcommand& subcommand : subcommands) {
    // the end of the run counts the warnings and errors it reported
    if (subcommand.parser->parsed()) return cli::FinishDiagnostics(subcommand.run());
  }
  fmt::print("{}", app.help());
  return 2;
}
