// xacro_command.cc - `mdlc xacro`: a drop-in for ROS's `xacro` command.
//
//   mdlc xacro robot.urdf.xacro ur_type:=ur5e -o robot.urdf
//   mdlc xacro robot.urdf.xacro --deps     # the files it reads, for build systems
//
// The expansion is written as xacro writes it; errors are mdlc's located
// diagnostics, with the macro calls and includes that led to them.
#include <fmt/format.h>

#include <memory>

#include "cli_compile.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct XacroFlags {
  CompileFlags compile;  // the file, NAME:=VALUE arguments, packages, limits, diagnostics
  std::string output;
  bool deps = false;
};

int Run(const XacroFlags& flags) {
  Options options;
  if (int status = ToOptions(flags.compile, options)) return status;
  std::vector<std::string> files;
  for (const std::string& file : flags.compile.files) {
    if (file.find(":=") == std::string::npos) files.push_back(file);
  }
  if (files.size() != 1) {
    fmt::print(stderr, "mdlc: error: xacro expands one file; {} given\n", files.size());
    return 2;
  }
  const bool json = flags.compile.diagnostics_format == "json";
  options.diagnostics.on_diagnostic = [json](const Diagnostic& d, const SourceManager& s) {
    const std::string text = json ? FormatDiagnosticJson(d, s) + "\n" : FormatDiagnosticText(d, s);
    std::fwrite(text.data(), 1, text.size(), stderr);
  };
  const XacroExpansion expansion = ExpandXacro(files[0], options);
  if (!expansion.ok()) return 1;
  if (flags.deps) {
    std::string listed;
    for (const std::string& path : expansion.dependencies) {
      listed += (listed.empty() ? "" : " ") + path;
    }
    return WriteOutput(flags.output, listed);
  }
  return WriteOutput(flags.output, *expansion.xml);
}

}  // namespace

Subcommand AddXacroCommand(CLI::App& app) {
  auto flags = std::make_shared<XacroFlags>();
  CLI::App* xacro = app.add_subcommand(
      "xacro", "Expand a xacro file to XML, as ROS's xacro command does (NAME:=VALUE arguments)");
  AddCompileFlags(xacro, flags->compile);
  xacro->add_option("-o,--output", flags->output, "Write the XML here instead of stdout");
  xacro->add_flag("--deps", flags->deps, "Print the files the expansion reads instead");
  return {xacro, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
