// cli_compile.cc - see cli_compile.h.
#include "cli_compile.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string_view>

#include "cli_input.h"
#include "diagnostic_stream.h"
#include "ir/count_text.h"
#include "ir/location_text.h"
#include "ir/source_manager.h"
#include "mdlc/option_names.h"
#include "repeated_warnings.h"

namespace mdlc::cli {
namespace {

// --strict, --max-errors, and each -W flag: -Werror, -Werror=GROUP,
// -Wno-GROUP, -WGROUP (enabled: the default); a group no diagnostic has is
// an error (option_names.h), not a flag that quietly does nothing
std::optional<std::string> ApplyWarningFlags(const CompileFlags& flags, DiagnosticPolicy& policy) {
  policy.warnings_as_errors = flags.strict;
  policy.max_errors = flags.max_errors;
  for (const std::string& flag : flags.warning_flags) {
    if (auto problem = ApplyWarningFlag(policy, flag, "-W" + flag)) return problem;
  }
  return std::nullopt;
}

// -fno-collapse shows every repeat of a warning; -fcollapse, the default,
// shows the first of each and counts the rest
bool CollapsesRepeats(const CompileFlags& flags) {
  bool collapse = true;
  for (const std::string& flag : flags.feature_flags) collapse = flag == "collapse";
  return collapse;
}

// What the run's text diagnostics say at its end (FinishDiagnostics): the
// compile whose counts end it, and the warnings shown once.
struct RunDiagnostics {
  const Result* result = nullptr;
  RepeatedWarnings repeated;
  /// How the compile's diagnostics were shown, for those reported after it
  /// (ReportAfterCompile), and how many of those there were.
  std::function<void(const Diagnostic&, const SourceManager&)> show;
  size_t warnings_after = 0;
  size_t errors_after = 0;
};
RunDiagnostics& TheRun() {
  static RunDiagnostics run;
  return run;
}

// --package NAME=DIR, --package-path DIR, and the ROS environment
// (ROS_PACKAGE_PATH, AMENT_PREFIX_PATH)
bool ParsePackages(const CompileFlags& flags, PackageOptions& packages) {
  for (const std::string& definition : flags.packages) {
    const size_t eq = definition.find('=');
    if (eq == std::string::npos || eq == 0) {
      fmt::print(stderr, "mdlc: error: --package expects NAME=DIR, got '{}'\n", definition);
      return false;
    }
    packages.definitions.emplace_back(definition.substr(0, eq), definition.substr(eq + 1));
  }
  packages.paths = flags.package_paths;
  packages.use_ros_package_path = true;
  return true;
}

// A compile's result is deliberately never freed: the process exits right
// after, and tearing down a large model's DOM and IR would only cost time
// (clang's -disable-free, for the same reason). It stays reachable from here,
// so leak checkers do not count it.
Result* volatile g_kept_result = nullptr;  // volatile: the store must stay
Result& KeepUntilExit(Result result) {
  auto* kept = new Result(std::move(result));
  g_kept_result = kept;
  return *kept;
}

bool IsOutputFormat(const CompileFlags& flags, const std::string& name) {
  return std::find(flags.output_formats.begin(), flags.output_formats.end(), name) !=
         flags.output_formats.end();
}

}  // namespace

void AddCompileFlags(CLI::App* command, CompileFlags& flags) {
  command
      ->add_option("files", flags.files,
                   "Model files (.urdf, .sdf, .world, .xml, .dmd.yaml, .xacro), Gazebo model "
                   "folders, '-' for standard input, and NAME:=VALUE arguments for a .xacro")
      ->required();
  command
      ->add_option("-x,--input-format", flags.input_format,
                   fmt::format("Read the files as this format whatever their names: {}",
                               kInputFormatNames))
      ->check([](const std::string& name) {
        return IsInputFormatName(name) ? std::string()
                                       : fmt::format("unknown format '{}'; expected {}", name,
                                                     kInputFormatNames);
      });
  if (flags.output_format.empty() && !flags.output_formats.empty()) {
    flags.output_format = flags.output_formats.front();
  }
  std::string outputs;
  for (const std::string& name : flags.output_formats) {
    outputs += (outputs.empty() ? "" : ", ") + name;
  }
  command
      ->add_option_function<std::vector<std::string>>(
          "--format",
          [&flags](const std::vector<std::string>& names) {
            for (const std::string& name : names) {
              (IsOutputFormat(flags, name) ? flags.output_format : flags.input_format) = name;
            }
          },
          outputs.empty()
              ? fmt::format("The files' format, whatever their names: {}", kInputFormatNames)
              : fmt::format("The output ({}; default {}) or the files' format, whatever their "
                            "names ({}); may be given twice",
                            outputs, flags.output_formats.front(), kInputFormatNames))
      ->allow_extra_args(false)
      ->check([&flags, outputs](const std::string& name) {
        return IsOutputFormat(flags, name) || IsInputFormatName(name)
                   ? std::string()
                   : fmt::format("unknown format '{}'; expected {}{}", name,
                                 outputs.empty() ? "" : outputs + " or ", kInputFormatNames);
      });
  command->add_option("--diagnostics-format", flags.diagnostics_format, "text or json")
      ->check(CLI::IsMember({"text", "json"}));
  command
      ->add_option("-W", flags.warning_flags,
                   "-Werror: warnings are errors; -Werror=GROUP; -Wno-GROUP silences a group "
                   "(mdlc --list-warnings names the groups)")
      ->allow_extra_args(false);
  command
      ->add_option("-f", flags.feature_flags,
                   "-fno-collapse: show every repeat of a warning (by default the first is "
                   "shown and a note at the end counts the rest)")
      ->check(CLI::IsMember({"collapse", "no-collapse"}))
      ->allow_extra_args(false);
  command->add_flag("--strict", flags.strict, "Warnings are errors (Drake's strict parsing)");
  command->add_option("--max-errors", flags.max_errors,
                      "Stop reporting after N errors (0: no limit)");
  command->add_option("--limit", flags.limits,
                      "Set an input limit NAME=VALUE: file-size, total-size, elements, depth, "
                      "include-depth, model-depth, mesh-vertices, mesh-seconds, macro-depth, "
                      "expansion-nodes (see the README)")
      ->allow_extra_args(false);
  // the values of these two are checked by ToOptions, which suggests a near one
  command
      ->add_option("--mesh-reader", flags.mesh_reader,
                   "Read mesh files in a child process (process, the default: a crash of the "
                   "mesh importer is an error about the file) or in-process");
  command
      ->add_option("--collada-up-axis", flags.collada_up_axis,
                   "COLLADA meshes: as-written (the default, as RViz and Gazebo show them) or "
                   "apply (turn a file's declared X_UP or Y_UP to Z-up)");
  command->add_option("--model-name", flags.model_name, "Name the model instance this");
  command->add_flag("--auto-rename", flags.auto_rename,
                    "Rename a model whose name is taken to NAME_1, NAME_2, ...");
  command->add_flag("--fixed-base", flags.fixed_base,
                    "Weld each free root body to the world at its default pose instead of "
                    "floating it");
  command->add_option("--package-path", flags.package_paths, "Search DIR for package.xml files")
      ->allow_extra_args(false);
  command->add_option("--package", flags.packages, "Define package NAME=DIR")
      ->allow_extra_args(false);
  command->add_option("--color", flags.color, "Color diagnostics: auto, always or never")
      ->check(CLI::IsMember({"auto", "always", "never"}));
  command->add_option("--cache-dir", flags.cache_dir,
                      "Keep derived mesh data here (default: $MDLC_CACHE_DIR, "
                      "$XDG_CACHE_HOME/mdlc or ~/.cache/mdlc)");
  command->add_flag("--no-cache", flags.no_cache, "Compute derived mesh data every time");
}

void AddJsonAlias(CLI::App* command, CompileFlags& flags) {
  command->add_flag_callback(
      "--json", [&flags] { flags.output_format = "json"; }, "The same as --format json");
}

int ToOptions(const CompileFlags& flags, Options& options) {
  std::optional<std::string> problem = ApplyWarningFlags(flags, options.diagnostics.policy);
  for (const std::string& setting : flags.limits) {
    if (!problem) problem = ApplyLimitSetting(options.limits, setting, "--limit");
  }
  if (!problem) {
    problem = ParseMeshReader(flags.mesh_reader, "--mesh-reader", options.meshes.reader);
  }
  if (!problem) {
    problem = ParseColladaUpAxis(flags.collada_up_axis, "--collada-up-axis",
                                 options.meshes.collada_up_axis);
  }
  if (problem) {
    fmt::print(stderr, "mdlc: error: {}\n", *problem);
    return 2;
  }
  if (!ParsePackages(flags, options.packages)) return 2;
  options.naming.model_name = flags.model_name;
  options.naming.auto_rename = flags.auto_rename;
  options.model.fixed_base = flags.fixed_base;
  for (const std::string& word : flags.files) {
    // xacro's NAME:=VALUE arguments sit among the files, as on xacro's command line
    if (const size_t at = word.find(":="); at != std::string::npos && at > 0) {
      options.model.xacro_args.emplace_back(word.substr(0, at), word.substr(at + 2));
    }
  }
  if (!flags.no_cache) {
    options.meshes.cache_dir =
        flags.cache_dir.empty() ? DefaultMeshCacheDirectory() : flags.cache_dir;
  }
  return 0;
}

CliCompile CompileForCli(const CompileFlags& flags, const CompileSetup& setup) {
  Options options;
  if (int status = ToOptions(flags, options)) return {status, nullptr};
  if (setup.adjust) setup.adjust(options);

  const bool json = flags.diagnostics_format == "json";
  const bool color =
      flags.color == "always" || (flags.color == "auto" && isatty(STDERR_FILENO) && !json);
  std::shared_ptr<DiagnosticStream> stream;
  switch (setup.diagnostics) {
    case DiagnosticOutput::Stream:
    {
      stream = std::make_shared<DiagnosticStream>([](std::string_view text) {
        std::fwrite(text.data(), 1, text.size(), stderr);
      });
      // JSON is never collapsed: its reader wants every diagnostic
      const bool collapse = !json && CollapsesRepeats(flags);
      options.diagnostics.on_diagnostic = [json, color, collapse, stream](
                                              const Diagnostic& d, const SourceManager& s) {
        if (collapse && d.severity == Severity::Warning &&
            !TheRun().repeated.FirstOfItsKind(InfoFor(d.kind).group, d.message,
                                              LocationText(d.loc, s))) {
          return;
        }
        stream->Write(json ? FormatDiagnosticJson(d, s) + "\n" : FormatDiagnosticText(d, s, color));
      };
      break;
    }
    case DiagnosticOutput::Collect:
      // the list, not `setup`: the consumer outlives this call (ReportAfterCompile)
      options.diagnostics.on_diagnostic = [collected = setup.collected](
                                              const Diagnostic& d, const SourceManager&) {
        collected->push_back(d);
      };
      break;
    case DiagnosticOutput::ErrorsAfter:
      break;  // the Result keeps them
  }

  std::vector<Input> inputs;
  for (const std::string& file : flags.files) {
    if (file.find(":=") == std::string::npos || file.find(":=") == 0) {
      std::string problem;
      std::optional<Input> input = InputFor(file, flags.input_format, &problem);
      if (!input) {
        fmt::print(stderr, "mdlc: error: {}\n", problem);
        return {1, nullptr};
      }
      inputs.push_back(std::move(*input));
    }
  }
  if (setup.diagnostics == DiagnosticOutput::ErrorsAfter) {
    TheRun().show = [](const Diagnostic& d, const SourceManager& s) {
      if (d.severity == Severity::Error) fmt::print(stderr, "{}", FormatDiagnosticText(d, s));
    };
  } else {
    TheRun().show = options.diagnostics.on_diagnostic;
  }
  Result& result = KeepUntilExit(Compile(inputs, options));
  if (stream) stream->Finish();
  if (stream && !json) TheRun().result = &result;  // its counts end the run
  if (setup.diagnostics == DiagnosticOutput::ErrorsAfter) {
    for (const Diagnostic& d : result.diagnostics()) {
      if (d.severity == Severity::Error) fmt::print(stderr, "{}", result.FormatText(d));
    }
  }
  if (!result.ok() && !setup.keep_failed) return {ReportFailure(flags, result), &result};
  return {0, &result};
}

void ReportAfterCompile(const Result& result, const std::vector<Diagnostic>& diagnostics,
                        size_t warnings, size_t errors) {
  RunDiagnostics& run = TheRun();
  if (run.show) {
    for (const Diagnostic& d : diagnostics) run.show(d, result.sources());
  }
  run.warnings_after += warnings;
  run.errors_after += errors;
}

int ReportFailure(const CompileFlags&, const Result&) { return 1; }

int FinishDiagnostics(int status) {
  const RunDiagnostics& run = TheRun();
  if (!run.result) return status;
  std::string text = run.repeated.Notes();
  // clang's closing line: the warnings and errors reported, shown or not
  const size_t warnings = run.result->warning_count() + run.warnings_after;
  const size_t errors = run.result->error_count() + run.errors_after;
  if (warnings && errors) {
    text += fmt::format("{} and {} generated.\n", ir::CountOf(warnings, "warning"),
                        ir::CountOf(errors, "error"));
  } else if (warnings || errors) {
    text += fmt::format("{} generated.\n", warnings ? ir::CountOf(warnings, "warning")
                                                    : ir::CountOf(errors, "error"));
  }
  std::fwrite(text.data(), 1, text.size(), stderr);
  return status;
}

int WriteOutput(const std::string& output, const std::string& text) {
  if (output.empty() || output == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
  }
  errno = 0;
  std::ofstream out(output, std::ios::binary);
  if (!out) {
    // the system's reason: no such directory, permission denied, ...
    fmt::print(stderr, "mdlc: error: cannot write '{}': {}\n", output,
               errno ? std::strerror(errno) : "the file cannot be opened");
    return 1;
  }
  out << text;
  out.flush();
  if (!out) {
    fmt::print(stderr, "mdlc: error: cannot write '{}': {}\n", output,
               errno ? std::strerror(errno) : "writing it failed");
    return 1;
  }
  return 0;
}

}  // namespace mdlc::cli
