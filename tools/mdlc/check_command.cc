// check_command.cc - `mdlc check`: compile many models, each on its own, and
// report a verdict per file (check.h does the work).
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <thread>

#include "check.h"
#include "cli_compile.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct CheckFlags {
  CompileFlags compile;
  std::string output;
  int jobs = 1;
  std::string skip_ok_from;
  bool summary_only = false;
};

int Run(const CheckFlags& flags) {
  tools::CheckOptions check;
  if (int status = ToOptions(flags.compile, check.compile)) return status;
  check.paths = flags.compile.files;
  if (flags.compile.input_format == "xacro") {
    // a .xacro is told by its name, and a walk finds none
    fmt::print(stderr, "mdlc: error: check reads xacro files by their names (.xacro); "
                       "--format xacro names the format of one file for the other commands\n");
    return 2;
  }
  if (!flags.compile.input_format.empty()) {
    check.input_format = FormatFromName(flags.compile.input_format);
  }
  check.jobs = flags.jobs > 0 ? flags.jobs : static_cast<int>(std::thread::hardware_concurrency());
  const std::string& format = flags.compile.output_format;
  check.format = format == "json"    ? tools::CheckFormat::JsonLines
                 : format == "sarif" ? tools::CheckFormat::Sarif
                                     : tools::CheckFormat::Text;
  check.skip_ok_from = flags.skip_ok_from;
  check.summary_only = flags.summary_only;
  check.progress = isatty(STDERR_FILENO) && !isatty(STDOUT_FILENO);
  check.color = flags.compile.color == "always" ||
                (flags.compile.color == "auto" && isatty(STDOUT_FILENO) && flags.output.empty());
  std::FILE* out = stdout;
  if (!flags.output.empty() && flags.output != "-") {
    out = std::fopen(flags.output.c_str(), "wb");
    if (!out) {
      fmt::print(stderr, "mdlc: error: cannot write '{}': {}\n", flags.output,
                 std::strerror(errno));
      return 1;
    }
  }
  const int status = tools::RunCheck(check, [&](std::string_view text) {
    std::fwrite(text.data(), 1, text.size(), out);
    std::fflush(out);
  });
  if (out != stdout) std::fclose(out);
  return status;
}

}  // namespace

Subcommand AddCheckCommand(CLI::App& app) {
  auto flags = std::make_shared<CheckFlags>();
  CLI::App* check =
      app.add_subcommand("check", "Compile many models, each on its own, and report");
  // json: JSON Lines; sarif: SARIF 2.1.0
  flags->compile.output_formats = {"text", "json", "sarif"};
  AddCompileFlags(check, flags->compile);
  AddJsonAlias(check, flags->compile);
  check->add_option("-j,--jobs", flags->jobs, "Compile this many files at once (0: one per core)");
  check->add_option("--skip-ok", flags->skip_ok_from,
                    "Skip the files an earlier --format=json report lists as ok");
  check->add_flag("--summary", flags->summary_only,
                  "Print only the totals, not the report of each file");
  check->add_option("-o,--output", flags->output, "Write the report here instead of stdout");
  return {check, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
