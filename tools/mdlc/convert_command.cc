// convert_command.cc - `mdlc convert`: compile models and write them in
// another format (URDF, SDFormat or MJCF).
#include <fmt/format.h>

#include <memory>

#include "cli_compile.h"
#include "mdlc/convert.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct ConvertFlags {
  CompileFlags compile;
  std::string output;
  std::string to;
  std::string copy_assets_dir;
  bool keep_package_uris = false;
  bool fuse_fixed = false;
  bool plain = false;
};

/// The target: --to, or the output file's extension.
std::optional<Format> Target(const ConvertFlags& flags) {
  if (!flags.to.empty()) {
    return FormatFromName(flags.to);  // --to takes urdf, sdf or mjcf only
  }
  if (!flags.output.empty() && flags.output != "-") return FormatFromPath(flags.output);
  return std::nullopt;
}

int Run(const ConvertFlags& flags) {
  const std::optional<Format> to = Target(flags);
  if (!to || *to == Format::Directives) {
    fmt::print(stderr, "mdlc: error: convert needs --to urdf|sdf|mjcf, or an output file "
                       "ending in .urdf, .sdf or .xml\n");
    return 2;
  }
  const CliCompile compiled = CompileForCli(flags.compile);
  if (compiled.status) return compiled.status;
  const Result& result = *compiled.result;

  ConvertOptions convert;
  convert.to = *to;
  convert.output = flags.output == "-" ? "" : flags.output;
  if (!flags.copy_assets_dir.empty()) convert.copy_assets_dir = flags.copy_assets_dir;
  convert.keep_package_uris = flags.keep_package_uris;
  convert.fuse_fixed = flags.fuse_fixed;
  convert.plain = flags.plain;
  // what the target cannot hold, and why the model could not be written,
  // are diagnostics of the run like the compile's
  const ConvertOutput out = Convert(result, convert);
  ReportAfterCompile(result, out.diagnostics, out.warning_count, out.error_count);
  if (!out.ok()) return ReportFailure(flags.compile, result);
  return WriteOutput(flags.output, *out.text);
}

}  // namespace

Subcommand AddConvertCommand(CLI::App& app) {
  auto flags = std::make_shared<ConvertFlags>();
  CLI::App* convert =
      app.add_subcommand("convert", "Compile models and write them in another format");
  AddCompileFlags(convert, flags->compile);
  convert
      ->add_option("--to", flags->to, "The format to write: urdf, sdf or mjcf (default: from -o)")
      ->check(CLI::IsMember({"urdf", "sdf", "mjcf"}));
  convert
      ->add_option("-o,--output", flags->output, "Write the converted model here ('-': stdout)")
      ->required();
  convert->add_option("--copy-assets", flags->copy_assets_dir,
                      "Copy the meshes into DIR (one copy per distinct content) and name them; "
                      "a mesh the target cannot read is written as OBJ");
  convert->add_flag("--keep-package-uris", flags->keep_package_uris,
                    "Keep package:// URIs as written instead of naming the files");
  convert->add_flag("--fuse-fixed", flags->fuse_fixed,
                    "MJCF: fuse each body welded to its parent into it");
  convert->add_flag("--plain", flags->plain,
                    "URDF: plain URDF that urdfdom and ROS read (one root link; Drake's shapes "
                    "and joints approximated)");
  return {convert, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
