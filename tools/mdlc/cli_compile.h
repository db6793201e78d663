// cli_compile.h - what every compiling subcommand of the command line shares:
// the compile flags, turning them into Options, and CompileForCli, which
// compiles the files, reports diagnostics on standard error and says
// "N errors generated." when it failed.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "mdlc/mdlc.h"

namespace mdlc::cli {

/// The flags of every subcommand that compiles (AddCompileFlags).
struct CompileFlags {
  std::vector<std::string> files;  // '-' is standard input
  /// -x, or --format naming an input format: the files' format, whatever
  /// their names (empty: by name); urdf, sdf, mjcf, dmd or xacro.
  std::string input_format;
  /// What --format may name besides an input format: the subcommand's output
  /// formats, its default first (none: --format names only input formats).
  /// The two sets share no name, so one flag serves both: `--format json`,
  /// `--format urdf`, or both at once.
  std::vector<std::string> output_formats;
  std::string output_format;  // the one asked for (--format, or --json)
  std::string diagnostics_format = "text";
  std::vector<std::string> warning_flags;  // -W<...>
  /// -fno-collapse: show every repeat of a warning (RepeatedWarnings), -fcollapse: the default
  std::vector<std::string> feature_flags;
  bool strict = false;
  size_t max_errors = 0;
  std::vector<std::string> limits;  // --limit NAME=VALUE
  std::string mesh_reader = "process";  // --mesh-reader
  std::string collada_up_axis = "as-written";  // --collada-up-axis
  std::optional<std::string> model_name;
  bool auto_rename = false;
  bool fixed_base = false;  // --fixed-base
  std::vector<std::string> package_paths;
  std::vector<std::string> packages;
  std::string color = "auto";
  std::string cache_dir;  // empty: DefaultMeshCacheDirectory()
  bool no_cache = false;
};

/// Adds the compile flags; set flags.output_formats first.
void AddCompileFlags(CLI::App* command, CompileFlags& flags);

/// Adds `--json`, the older spelling of `--format json`.
void AddJsonAlias(CLI::App* command, CompileFlags& flags);

/// Sets `options` from the flags; 0, or the exit status of bad usage (2,
/// reported).
int ToOptions(const CompileFlags& flags, Options& options);

/// Where a compile's diagnostics go.
enum class DiagnosticOutput {
  Stream,       // to standard error as each is reported (--diagnostics-format)
  Collect,      // into CompileSetup::collected (--verify-diagnostics)
  ErrorsAfter,  // kept in the Result; its errors printed after the compile
};

/// What a subcommand asks of CompileForCli beyond the flags.
struct CompileSetup {
  DiagnosticOutput diagnostics = DiagnosticOutput::Stream;
  std::vector<Diagnostic>* collected = nullptr;
  /// Hand back a failed compile instead of reporting it (the caller does).
  bool keep_failed = false;
  /// Called on the options after the flags set them.
  std::function<void(Options&)> adjust;
};

/// The outcome: `status` 0 with `result` set, 1 when the compile failed
/// (reported, unless keep_failed) or 2 on bad usage.
struct CliCompile {
  int status = 0;
  Result* result = nullptr;
};

/// Compiles flags.files as one model. The Result lives until the process
/// exits.
CliCompile CompileForCli(const CompileFlags& flags, const CompileSetup& setup = {});

/// Reports diagnostics made from the compile's Result after it (Convert's)
/// as the compile's own were reported: shown as CompileForCli shows them
/// (collapsed, collected or errors printed) and counted in the run's closing
/// line (FinishDiagnostics), `warnings` and `errors` being the counts of the
/// engine that made them.
void ReportAfterCompile(const Result& result, const std::vector<Diagnostic>& diagnostics,
                        size_t warnings, size_t errors);

/// The exit status of a failed compile, 1; its count of errors is said at
/// the end of the run (FinishDiagnostics).
int ReportFailure(const CompileFlags& flags, const Result& result);

/// The end of a run of the command line: the notes of the warnings that
/// repeated and were not shown, then "N warnings and M errors generated." on
/// standard error (text diagnostics only; a JSON reader counts them).
/// Returns `status`; main calls it with the subcommand's exit status.
int FinishDiagnostics(int status);

/// Writes `text` to `output` (standard output when empty or '-'); 0, or 1
/// (reported) when the file cannot be written.
int WriteOutput(const std::string& output, const std::string& text);

}  // namespace mdlc::cli
