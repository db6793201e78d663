// graph_command.cc - `mdlc graph`: the kinematic or frame graph as Graphviz
// DOT or JSON; rendered to .svg/.png/.pdf when Graphviz's dot is installed
// (and never needing it otherwise). A model that failed to compile is drawn
// as far as it compiled, after its errors; the exit status is then 1.
#include <fmt/format.h>

#include <cstdio>
#include <memory>

#include "cli_compile.h"
#include "graph.h"
#include "partial_model.h"
#include "subcommands.h"

namespace mdlc::cli {
namespace {

struct GraphFlags {
  CompileFlags compile;
  std::string output;
  std::string kind = "kinematic";
};

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

int WriteGraph(const GraphFlags& flags, const backend::CompiledModel& model) {
  const auto kind =
      flags.kind == "frames" ? tools::GraphKind::Frames : tools::GraphKind::Kinematic;
  if (flags.compile.output_format == "json") {
    return WriteOutput(flags.output, tools::FormatGraphJson(model, kind));
  }
  const std::string dot = tools::FormatGraphDot(model, kind);
  for (const char* rendered : {".svg", ".png", ".pdf"}) {
    if (flags.output.ends_with(rendered)) return RenderWithGraphviz(dot, flags.output) ? 0 : 1;
  }
  return WriteOutput(flags.output, dot);
}

int Run(const GraphFlags& flags) {
  return PrintAsFarAsCompiled(flags.compile, "graph",
                              [&](const backend::CompiledModel& model, const Result&) {
                                return WriteGraph(flags, model);
                              });
}

}  // namespace

Subcommand AddGraphCommand(CLI::App& app) {
  auto flags = std::make_shared<GraphFlags>();
  CLI::App* graph =
      app.add_subcommand("graph", "Print the kinematic or frame graph (DOT, JSON)");
  flags->compile.output_formats = {"dot", "json"};
  AddCompileFlags(graph, flags->compile);
  graph->add_option("--kind", flags->kind, "kinematic (default) or frames")
      ->check(CLI::IsMember({"kinematic", "frames"}));
  graph->add_option("-o,--output", flags->output,
                    "Write here instead of stdout; .svg, .png or .pdf render with Graphviz");
  return {graph, [flags] { return Run(*flags); }};
}

}  // namespace mdlc::cli
