// main.cc - the mdlc command line.
//
//   mdlc compile FILE... [--emit=summary|ir|plant-json|none] [-o FILE]
//                        [--q JOINT=VALUE ...] [--diagnostics-format=text|json]
//                        [-Werror|--strict] [-Wno-GROUP] [-Werror=GROUP]
//                        [--print-after=PASS] [--print-after-all] [--time-passes]
//   mdlc convert FILE... --to urdf -o OUT [--copy-assets DIR] [--keep-package-uris]
//   mdlc tree FILE... [--json]      each model instance's kinematic tree
//   mdlc stats FILE... [--json]     mass properties and counts
//   mdlc graph FILE... [--kind kinematic|frames] [--format dot|json] [-o OUT(.dot|.svg|.png)]
//   mdlc assets FILE... [--json]    every file the model uses, found or not
//   mdlc view FILE... -o model.html   the model in 3D, in one offline HTML page
//   mdlc check PATH... [-j N] [--format text|json|sarif] [--skip-ok REPORT.jsonl]
//   mdlc --list-passes
//
// Exit status: 0 on success, 1 when any error was reported, 2 on bad usage.
#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <thread>

#include "ir/printer.h"
#include "mdlc/mdlc.h"
#include "passes/pass_registry.h"
#include "assets.h"
#include "check.h"
#include "graph.h"
#include "stats.h"
#include "summary.h"
#include "tree.h"
#include "view.h"
#include "verify_diagnostics.h"

namespace {

struct CliOptions {
  std::vector<std::string> files;
  std::string emit = "summary";
  std::string output;
  std::vector<std::string> q;
  std::string diagnostics_format = "text";
  std::vector<std::string> warning_flags;  // -W<...>
  bool strict = false;
  size_t max_errors = 0;
  std::vector<std::string> print_after;
  bool print_after_all = false;
  bool time_passes = false;
  bool verify_each = false;
  std::vector<std::string> passes;
  std::optional<std::string> model_name;
  bool auto_rename = false;
  bool mass_matrix = false;
  bool verify_diagnostics = false;
  bool no_locations = false;
  std::vector<std::string> package_paths;
  std::vector<std::string> packages;
  std::string color = "auto";
  // convert
  std::string to;
  std::string copy_assets_dir;
  bool keep_package_uris = false;
  bool fuse_fixed = false;
  // tree, stats
  bool json_output = false;
  // check
  int jobs = 1;
  std::string check_format = "text";
  std::string skip_ok_from;
  // graph
  std::string graph_kind = "kinematic";
  std::string graph_format = "dot";
};

// -Werror, -Werror=GROUP, -Wno-GROUP, -WGROUP (enable: the default)
bool ApplyWarningFlags(const CliOptions& cli, mdlc::DiagnosticPolicy& policy, std::string* bad) {
  policy.warnings_as_errors = cli.strict;
  policy.max_errors = cli.max_errors;
  for (const std::string& flag : cli.warning_flags) {
    if (flag == "error") {
      policy.warnings_as_errors = true;
    } else if (flag.starts_with("error=")) {
      policy.error_groups.insert(flag.substr(6));
    } else if (flag.starts_with("no-")) {
      policy.disabled_groups.insert(flag.substr(3));
    } else if (flag.empty()) {
      *bad = "-W needs a value";
      return false;
    }
  }
  return true;
}

// A compile's result is deliberately never freed: the process exits right
// after, and tearing down a large model's DOM and IR would only cost time
// (clang's -disable-free, for the same reason). It stays reachable from here,
// so leak checkers do not count it.
mdlc::Result* volatile g_kept_result = nullptr;  // volatile: the store must stay
mdlc::Result& KeepUntilExit(mdlc::Result result) {
  auto* kept = new mdlc::Result(std::move(result));
  g_kept_result = kept;
  return *kept;
}

int WriteOutput(const CliOptions& cli, const std::string& text) {
  if (cli.output.empty() || cli.output == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
  }
  std::ofstream out(cli.output, std::ios::binary);
  out << text;
  if (!out) {
    fmt::print(stderr, "mdlc: error: cannot write '{}'\n", cli.output);
    return 1;
  }
  return 0;
}

// --q JOINT=VALUE, each into (JOINT, VALUE); false on a malformed one
bool ParseJointPositions(const CliOptions& cli, mdlc::Options& options) {
  for (const std::string& assignment : cli.q) {
    const size_t eq = assignment.rfind('=');
    char* end = nullptr;
    const double value =
        eq == std::string::npos ? 0 : std::strtod(assignment.c_str() + eq + 1, &end);
    if (eq == std::string::npos || end == assignment.c_str() + eq + 1 || *end != '\0') {
      fmt::print(stderr, "mdlc: error: --q expects JOINT=VALUE, got '{}'\n", assignment);
      return false;
    }
    options.joint_positions.emplace_back(assignment.substr(0, eq), value);
  }
  return true;
}

// --package NAME=DIR, --package-path DIR, and ROS_PACKAGE_PATH
bool ParsePackages(const CliOptions& cli, mdlc::Options& options) {
  for (const std::string& definition : cli.packages) {
    const size_t eq = definition.find('=');
    if (eq == std::string::npos || eq == 0) {
      fmt::print(stderr, "mdlc: error: --package expects NAME=DIR, got '{}'\n", definition);
      return false;
    }
    options.packages.emplace_back(definition.substr(0, eq), definition.substr(eq + 1));
  }
  options.package_paths = cli.package_paths;
  options.use_ros_package_path = true;
  return true;
}

/// The options both subcommands share; 0, or the exit status of bad usage.
int PrepareOptions(const CliOptions& cli, mdlc::Options& options) {
  std::string bad;
  if (!ApplyWarningFlags(cli, options.diagnostics, &bad)) {
    fmt::print(stderr, "mdlc: error: {}\n", bad);
    return 2;
  }
  if (!ParseJointPositions(cli, options) || !ParsePackages(cli, options)) return 2;
  options.model_name = cli.model_name;
  options.auto_rename = cli.auto_rename;
  options.passes = cli.passes;
  options.print_after = cli.print_after;
  options.print_after_all = cli.print_after_all;
  options.time_passes = cli.time_passes;
  options.verify_each = cli.verify_each;
  options.skip_backend = cli.emit == "ir";
  return 0;
}

int RunCompile(const CliOptions& cli) {
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;

  // diagnostics stream out as they happen, unless they are being verified
  const bool json = cli.diagnostics_format == "json";
  const bool color = cli.color == "always" || (cli.color == "auto" && isatty(STDERR_FILENO) && !json);
  std::vector<mdlc::Diagnostic> collected;
  options.on_diagnostic = [&](const mdlc::Diagnostic& d, const mdlc::SourceManager& s) {
    if (cli.verify_diagnostics) {
      collected.push_back(d);
    } else if (json) {
      fmt::print(stderr, "{}\n", mdlc::FormatDiagnosticJson(d, s));
    } else {
      fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(d, s, color));
    }
  };

  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  const mdlc::Result& result = KeepUntilExit(mdlc::Compile(inputs, options));

  if (cli.time_passes) fmt::print(stderr, "{}", result.timing_report());
  if (cli.verify_diagnostics) {
    auto problems = mdlc::tools::VerifyDiagnostics(collected, result.sources());
    for (const auto& p : problems) fmt::print(stderr, "{}\n", p);
    return problems.empty() ? 0 : 1;
  }
  if (!result.ok()) {
    if (!json) {
      fmt::print(stderr, "{} error{} generated.\n", result.error_count(),
                 result.error_count() == 1 ? "" : "s");
    }
    return 1;
  }

  if (cli.emit == "ir") {
    mdlc::ir::PrintOptions print;
    print.locations = !cli.no_locations;
    return WriteOutput(cli, mdlc::ir::PrintModule(result.module(), result.sources(), print));
  }
  if (cli.emit == "none") return 0;
  if (cli.emit == "summary") return WriteOutput(cli, mdlc::tools::FormatSummary(result.model()));

  mdlc::backend::PlantJsonOptions json_options;
  json_options.force_mass_matrix = cli.mass_matrix;
  return WriteOutput(cli, result.PlantJson(result.DefaultPositions(), json_options));
}

int RunConvert(CliOptions cli) {
  // the target: --to, or the output file's extension
  std::optional<mdlc::Format> to;
  if (!cli.to.empty()) {
    to = cli.to == "urdf" ? std::optional(mdlc::Format::Urdf)
         : cli.to == "sdf" ? std::optional(mdlc::Format::Sdf)
         : cli.to == "mjcf" ? std::optional(mdlc::Format::Mjcf)
                           : std::nullopt;
  } else if (!cli.output.empty() && cli.output != "-") {
    to = mdlc::FormatFromPath(cli.output);
  }
  if (!to || *to == mdlc::Format::Directives) {
    fmt::print(stderr, "mdlc: error: convert needs --to urdf|sdf|mjcf, or an output file "
                       "ending in .urdf, .sdf or .xml\n");
    return 2;
  }
  cli.emit = "none";
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;
  const bool json = cli.diagnostics_format == "json";
  const bool color = cli.color == "always" || (cli.color == "auto" && isatty(STDERR_FILENO) && !json);
  options.on_diagnostic = [&](const mdlc::Diagnostic& d, const mdlc::SourceManager& s) {
    if (json) {
      fmt::print(stderr, "{}\n", mdlc::FormatDiagnosticJson(d, s));
    } else {
      fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(d, s, color));
    }
  };
  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  mdlc::Result& result = KeepUntilExit(mdlc::Compile(inputs, options));
  std::optional<std::string> text;
  if (result.ok()) {
    mdlc::ConvertOptions convert;
    convert.to = *to;
    convert.output = cli.output == "-" ? "" : cli.output;
    if (!cli.copy_assets_dir.empty()) convert.copy_assets_dir = cli.copy_assets_dir;
    convert.keep_package_uris = cli.keep_package_uris;
    convert.fuse_fixed = cli.fuse_fixed;
    text = result.Convert(convert);
  }
  if (!result.ok() || !text) {
    if (!json) {
      fmt::print(stderr, "{} error{} generated.\n", result.error_count(),
                 result.error_count() == 1 ? "" : "s");
    }
    return 1;
  }
  return WriteOutput(cli, *text);
}

/// `mdlc tree` and `mdlc stats`: compile, then print what `format` makes of
/// the model (text, or JSON with --json).
int RunInspect(CliOptions cli, std::string (*text)(const mdlc::backend::CompiledModel&),
               std::string (*json)(const mdlc::backend::CompiledModel&)) {
  cli.emit = "none";
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;
  const bool color = cli.color == "always" || (cli.color == "auto" && isatty(STDERR_FILENO));
  options.on_diagnostic = [&](const mdlc::Diagnostic& d, const mdlc::SourceManager& s) {
    fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(d, s, color));
  };
  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  const mdlc::Result& result = KeepUntilExit(mdlc::Compile(inputs, options));
  if (!result.ok()) {
    fmt::print(stderr, "{} error{} generated.\n", result.error_count(),
               result.error_count() == 1 ? "" : "s");
    return 1;
  }
  return WriteOutput(cli, cli.json_output ? json(result.model()) : text(result.model()));
}

/// `dot -T<format> -o OUT`, fed `text`; false (reported) when it fails.
bool RenderWithGraphviz(const std::string& text, const std::string& output) {
  const std::string format = output.substr(output.rfind('.') + 1);
  std::string quoted = "'";
  for (char c : output) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  quoted += "'";
  FILE* dot = popen(fmt::format("dot -T{} -o {} 2>/dev/null", format, quoted).c_str(), "w");
  if (dot) std::fwrite(text.data(), 1, text.size(), dot);
  const int status = dot ? pclose(dot) : -1;
  if (status != 0) {
    fmt::print(stderr, "mdlc: error: rendering '{}' needs Graphviz's dot, which failed or is "
                       "not on the PATH; write a .dot file instead (-o graph.dot)\n",
               output);
    return false;
  }
  return true;
}

int RunGraph(CliOptions cli) {
  cli.emit = "none";
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;
  const bool color = cli.color == "always" || (cli.color == "auto" && isatty(STDERR_FILENO));
  options.on_diagnostic = [&](const mdlc::Diagnostic& d, const mdlc::SourceManager& s) {
    fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(d, s, color));
  };
  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  const mdlc::Result& result = KeepUntilExit(mdlc::Compile(inputs, options));
  if (!result.ok()) {
    fmt::print(stderr, "{} error{} generated.\n", result.error_count(),
               result.error_count() == 1 ? "" : "s");
    return 1;
  }
  const auto kind = cli.graph_kind == "frames" ? mdlc::tools::GraphKind::Frames
                                               : mdlc::tools::GraphKind::Kinematic;
  if (cli.graph_format == "json") {
    return WriteOutput(cli, mdlc::tools::FormatGraphJson(result.model(), kind));
  }
  const std::string dot = mdlc::tools::FormatGraphDot(result.model(), kind);
  for (const char* rendered : {".svg", ".png", ".pdf"}) {
    if (cli.output.ends_with(rendered)) return RenderWithGraphviz(dot, cli.output) ? 0 : 1;
  }
  return WriteOutput(cli, dot);
}

/// `mdlc assets`: lists what was read and named even when the compile
/// failed (a missing mesh is the usual reason to run it); exit 1 when any
/// file is missing or the model has errors.
int RunAssets(CliOptions cli) {
  cli.emit = "none";
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;
  options.skip_backend = true;  // the files are known once the passes ran
  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  const mdlc::Result& result = KeepUntilExit(mdlc::Compile(inputs, options));
  for (const mdlc::Diagnostic& d : result.diagnostics()) {
    if (d.severity == mdlc::Severity::Error) fmt::print(stderr, "{}", result.FormatText(d));
  }
  const mdlc::tools::AssetReport report = mdlc::tools::ListAssets(result, cli.json_output);
  if (int status = WriteOutput(cli, report.text)) return status;
  return report.all_found && result.ok() ? 0 : 1;
}

/// `mdlc view`: the page needs a file to go to (it is too big for a
/// terminal), and a build with the viewer.
int RunView(CliOptions cli) {
  if (!mdlc::tools::ViewerAvailable()) {
    fmt::print(stderr, "mdlc: error: this mdlc was built without the viewer (three.js is "
                       "embedded at build time and needs npm then); rebuild with npm installed\n");
    return 1;
  }
  cli.emit = "none";
  mdlc::Options options;
  if (int status = PrepareOptions(cli, options)) return status;
  const bool color = cli.color == "always" || (cli.color == "auto" && isatty(STDERR_FILENO));
  options.on_diagnostic = [&](const mdlc::Diagnostic& d, const mdlc::SourceManager& s) {
    fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(d, s, color));
  };
  std::vector<mdlc::Input> inputs;
  for (const std::string& file : cli.files) inputs.push_back(mdlc::Input::File(file));
  const mdlc::Result& result = *new mdlc::Result(mdlc::Compile(inputs, options));  // see RunCompile
  if (!result.ok()) {
    fmt::print(stderr, "{} error{} generated.\n", result.error_count(),
               result.error_count() == 1 ? "" : "s");
    return 1;
  }
  std::string title;
  for (const std::string& file : cli.files) {
    if (!title.empty()) title += ", ";
    title += file.substr(file.find_last_of('/') + 1);
  }
  return WriteOutput(cli, mdlc::tools::ViewPage(result, title));
}

int RunCheck(CliOptions cli) {
  cli.emit = "none";
  mdlc::tools::CheckOptions check;
  if (int status = PrepareOptions(cli, check.compile)) return status;
  check.paths = cli.files;
  check.jobs = cli.jobs > 0 ? cli.jobs : static_cast<int>(std::thread::hardware_concurrency());
  check.format = cli.check_format == "json"    ? mdlc::tools::CheckFormat::JsonLines
                 : cli.check_format == "sarif" ? mdlc::tools::CheckFormat::Sarif
                                               : mdlc::tools::CheckFormat::Text;
  check.skip_ok_from = cli.skip_ok_from;
  check.progress = isatty(STDERR_FILENO) && !isatty(STDOUT_FILENO);
  check.color = cli.color == "always" ||
                (cli.color == "auto" && isatty(STDOUT_FILENO) && cli.output.empty());
  std::FILE* out = stdout;
  if (!cli.output.empty() && cli.output != "-") {
    out = std::fopen(cli.output.c_str(), "wb");
    if (!out) {
      fmt::print(stderr, "mdlc: error: cannot write '{}'\n", cli.output);
      return 1;
    }
  }
  const int status = mdlc::tools::RunCheck(check, [&](std::string_view text) {
    std::fwrite(text.data(), 1, text.size(), out);
    std::fflush(out);
  });
  if (out != stdout) std::fclose(out);
  return status;
}

/// The options of every subcommand that compiles.
void AddCompileOptions(CLI::App* command, CliOptions& cli) {
  command->add_option("files", cli.files, "Model files (.urdf, .sdf, .xml, .dmd.yaml)")
      ->required();
  command->add_option("--diagnostics-format", cli.diagnostics_format, "text or json")
      ->check(CLI::IsMember({"text", "json"}));
  command
      ->add_option("-W", cli.warning_flags,
                   "-Werror: warnings are errors; -Werror=GROUP; -Wno-GROUP silences a group")
      ->allow_extra_args(false);
  command->add_flag("--strict", cli.strict, "Warnings are errors (Drake's strict parsing)");
  command->add_option("--max-errors", cli.max_errors,
                      "Stop reporting after N errors (0: no limit)");
  command->add_option("--model-name", cli.model_name, "Name the model instance this");
  command->add_flag("--auto-rename", cli.auto_rename,
                    "Rename a model whose name is taken to NAME_1, NAME_2, ...");
  command->add_option("--package-path", cli.package_paths, "Search DIR for package.xml files")
      ->allow_extra_args(false);
  command->add_option("--package", cli.packages, "Define package NAME=DIR")
      ->allow_extra_args(false);
  command->add_option("--color", cli.color, "Color diagnostics: auto, always or never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mdlc - a model compiler for robotics (URDF, SDFormat, MJCF, Model Directives)"};
  app.set_version_flag("--version", fmt::format("mdlc {}", mdlc::kVersion));
  app.require_subcommand(0, 1);
  bool list_passes = false;
  app.add_flag("--list-passes", list_passes, "List the registered passes and exit");

  CliOptions cli;
  CLI::App* compile = app.add_subcommand("compile", "Compile robot model files into a plant");
  AddCompileOptions(compile, cli);
  compile->add_option("--emit", cli.emit, "What to print: summary, ir, plant-json or none")
      ->check(CLI::IsMember({"summary", "ir", "plant-json", "none"}));
  compile->add_option("-o,--output", cli.output, "Write the output here instead of stdout");
  compile->add_option("--q", cli.q, "Set a 1-dof joint's position: JOINT=VALUE (repeatable)")
      ->allow_extra_args(false);
  compile->add_option("--print-after", cli.print_after, "Print the IR after this pass (repeatable)")
      ->allow_extra_args(false);
  compile->add_flag("--print-after-all", cli.print_after_all, "Print the IR after every pass");
  compile->add_flag("--time-passes", cli.time_passes, "Report the time each pass takes");
  compile->add_flag("--verify-each", cli.verify_each, "Run the IR verifier after every pass");
  compile->add_option("--passes", cli.passes, "Run these passes instead of the default pipeline")
      ->delimiter(',');
  compile->add_flag("--mass-matrix", cli.mass_matrix,
                    "Include the mass matrix in plant-json even above 1000 dofs");
  compile->add_flag("--verify-diagnostics", cli.verify_diagnostics,
                    "Check diagnostics against expected-error comments in the input");
  compile->add_flag("--no-locations", cli.no_locations, "Leave source locations out of --emit=ir");

  CLI::App* convert =
      app.add_subcommand("convert", "Compile models and write them in another format");
  AddCompileOptions(convert, cli);
  convert->add_option("--to", cli.to, "The format to write: urdf, sdf or mjcf (default: from -o)")
      ->check(CLI::IsMember({"urdf", "sdf", "mjcf"}));
  convert->add_option("-o,--output", cli.output, "Write the converted model here ('-': stdout)")
      ->required();
  convert->add_option("--copy-assets", cli.copy_assets_dir,
                      "Copy the meshes into DIR (one copy per distinct content) and name them");
  convert->add_flag("--keep-package-uris", cli.keep_package_uris,
                    "Keep package:// URIs as written instead of naming the files");
  convert->add_flag("--fuse-fixed", cli.fuse_fixed,
                    "MJCF: fuse each body welded to its parent into it");

  CLI::App* tree = app.add_subcommand("tree", "Print each model instance's kinematic tree");
  AddCompileOptions(tree, cli);
  tree->add_flag("--json", cli.json_output, "Print JSON instead of text");
  tree->add_option("-o,--output", cli.output, "Write the output here instead of stdout");
  CLI::App* stats = app.add_subcommand("stats", "Print mass properties and counts");
  AddCompileOptions(stats, cli);
  stats->add_flag("--json", cli.json_output, "Print JSON instead of text");
  stats->add_option("-o,--output", cli.output, "Write the output here instead of stdout");

  CLI::App* graph = app.add_subcommand("graph", "Print the kinematic or frame graph (DOT, JSON)");
  AddCompileOptions(graph, cli);
  graph->add_option("--kind", cli.graph_kind, "kinematic (default) or frames")
      ->check(CLI::IsMember({"kinematic", "frames"}));
  graph->add_option("--format", cli.graph_format, "dot (default) or json")
      ->check(CLI::IsMember({"dot", "json"}));
  graph->add_option("-o,--output", cli.output,
                    "Write here instead of stdout; .svg, .png or .pdf render with Graphviz");

  CLI::App* assets = app.add_subcommand("assets", "List every file a model uses, found or not");
  AddCompileOptions(assets, cli);
  assets->add_flag("--json", cli.json_output, "Print JSON instead of text");
  assets->add_option("-o,--output", cli.output, "Write the output here instead of stdout");

  CLI::App* view = app.add_subcommand("view", "Write the model as one offline HTML page to view in 3D");
  AddCompileOptions(view, cli);
  view->add_option("-o,--output", cli.output, "The page to write (model.html)")->required();

  CLI::App* check = app.add_subcommand("check", "Compile many models, each on its own, and report");
  AddCompileOptions(check, cli);
  check->add_option("-j,--jobs", cli.jobs, "Compile this many files at once (0: one per core)");
  check->add_option("--format", cli.check_format, "text, json (JSON Lines) or sarif (2.1.0)")
      ->check(CLI::IsMember({"text", "json", "sarif"}));
  check->add_option("--skip-ok", cli.skip_ok_from,
                    "Skip the files an earlier --format=json report lists as ok");
  check->add_option("-o,--output", cli.output, "Write the report here instead of stdout");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (list_passes) {
    for (const auto& info : mdlc::passes::RegisteredPasses()) {
      fmt::print("  {:<24} {}\n", info.name, info.description);
    }
    return 0;
  }
  if (compile->parsed()) return RunCompile(cli);
  if (convert->parsed()) return RunConvert(cli);
  if (graph->parsed()) return RunGraph(cli);
  if (assets->parsed()) return RunAssets(cli);
  if (check->parsed()) return RunCheck(cli);
  if (view->parsed()) return RunView(cli);
  if (tree->parsed()) {
    return RunInspect(cli, mdlc::tools::FormatTree, mdlc::tools::FormatTreeJson);
  }
  if (stats->parsed()) {
    return RunInspect(cli, mdlc::tools::FormatStats, mdlc::tools::FormatStatsJson);
  }
  fmt::print("{}", app.help());
  return 2;
}
