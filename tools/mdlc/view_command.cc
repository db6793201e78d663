// view_command.cc - `mdlc view`: the model in 3D, in one offline HTML page.
// The page needs a file to go to (it is too big for a terminal), and a build
// with the viewer.
#include <fmt/format.h>

#include <memory>

#include "cli_compile.h"
#include "q_flag.h"
#include "subcommands.h"
#include "view.h"

namespace mdlc::cli {
namespace {

struct ViewFlags {
  CompileFlags compile;
  std::string output;
  std::vector<std::string> q;  // --q JOINT=VALUE: the configuration the page opens in
};

int Run(const ViewFlags& flags) {
  if (!tools::ViewerAvailable()) {
    fmt::print(stderr, "mdlc: error: this mdlc was built without the viewer (three.js is "
                       "embedded at build time and needs npm then); rebuild with npm installed\n");
    return 1;
  }
  Options joint_positions;
  if (!ParseJointPositions(flags.q, joint_positions)) return 2;
  CompileSetup setup;
  setup.adjust = [&](Options& options) {
    options.model.joint_positions = joint_positions.model.joint_positions;
  };
  const CliCompile compiled = CompileForCli(flags.compile, setup);
  if (compiled.status) return compiled.status;
  std::string title;
  for (const std::string& file : flags.compile.files) {
    if (!title.empty()) title += ", ";
    title += file.substr(file.find_last_of('/') + 1);
  }
  return WriteOutput(flags.output, tools::ViewPage(*compiled.result, title,
                                                     flags.compile.files.empty()
                                                         ? std::string()
                                                         : flags.compile.files.front()));
}

}  // namespace

Subcommand AddViewCommand(CLI::App& app) {
  auto flags = std::make_shared<ViewFlags>();
  CLI::App* view =
      app.add_subcommand("view", "Write the model as one offline HTML page to view in 3D");
  AddCompileFlags(view, flags->compile);
  view->add_option("-o,--output", flags->output, "The page to write (model.html)")->required();
  AddJointPositionsFlag(view, flags->q);
  return {view, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
