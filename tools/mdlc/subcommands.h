// subcommands.h - the subcommands of the mdlc command line, one file each:
// each adds its parser and flags to the application, and hands back what
// runs when it was given.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace mdlc::cli {

struct Subcommand {
  CLI::App* parser = nullptr;
  std::function<int()> run;  // the exit status
};

Subcommand AddCompileCommand(CLI::App& app);  // compile_command.cc
Subcommand AddConvertCommand(CLI::App& app);  // convert_command.cc
Subcommand AddTreeCommand(CLI::App& app);     // inspect_commands.cc
Subcommand AddStatsCommand(CLI::App& app);    // inspect_commands.cc
Subcommand AddGraphCommand(CLI::App& app);    // graph_command.cc
Subcommand AddAssetsCommand(CLI::App& app);   // assets_command.cc
Subcommand AddViewCommand(CLI::App& app);     // view_command.cc
Subcommand AddCheckCommand(CLI::App& app);    // check_command.cc
Subcommand AddXacroCommand(CLI::App& app);    // xacro_command.cc
Subcommand AddDynamicsCommand(CLI::App& app); // dynamics_command.cc

}  // namespace mdlc::cli
