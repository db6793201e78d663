// bench_sdf_frames.cc - load-time benchmarks for SDFormat: does reading
// frame graphs (relative_to / attached_to chains, deeply nested models,
// scoped names) stay linear in their size, what does it cost on top of the
// XML parse, and how does it compare with libsdformat?
//
// For the models of model_gen_sdf.h (frame_chain, nested_models, sdf_chain)
// of N = 10, 100, 1000, 10000, and worlds of N = 1000, 10000, 100000
// one-link models, each stage is timed on an in-memory buffer;
// from xml_document down each stage includes the ones above it:
//
//   libxml2_parse     xmlReadMemory + xmlFreeDoc: libxml2's DOM, the floor
//   libxml2_sax       libxml2's SAX parse with handlers that do nothing
//                     (sax_floor.h): what libxml2 alone costs mdlc's reader
//   xml_document      mdlc's XmlDocument::Parse (libxml2's SAX parse building
//                     mdlc's own located tree)
//   frontend          SDFormat -> IR (frontend::ReadModel), as the CLI calls it
//   frontend_passes   ... + the default pass pipeline (resolve-frames included)
//   compile           ... + backend::Instantiate (plant and scene graph)
//   write_urdf, write_sdf, write_mjcf
//                     what `mdlc convert` writes of the compiled model in
//                     each format (writers::Write; the compile is setup, not
//                     timed). N up to 10000 for the world.
//   libsdformat_load  sdf::Root::LoadSdfString + ~Root (libsdformat 12; only
//                     when the benchmark was built with it; N up to
//                     --sdformat_max_n, default 1000, as it is slow;
//                     nested_models only for N = 10, see RegisterAll)
//
// Copying the text into a SourceManager is setup and not timed; tearing the
// results down is timed in every stage. Each family reports BigO over N and
// bytes/s. sdf_chain's joints have friction, which draws a warning per joint
// (as the URDF chain's do); the engine stores them, nothing prints them.
//
//   mdlc_bench_sdf                        run everything
//   mdlc_bench_sdf --benchmark_filter='(libxml2_parse|compile)/frame_chain'
//   mdlc_bench_sdf --sdformat_max_n=10000 also time libsdformat on N = 10000
//   mdlc_bench_sdf --write_models=DIR     write DIR/{family}_n{N}.sdf
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <libxml/parser.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <span>
#include <string>

#include "bench_main.h"
#include "backend/writers/writer.h"
#include "tools/driver/compiler.h"
#include "frontend/xml/xml_document.h"
#include "model_gen_sdf.h"
#include "sax_floor.h"
#include "tools/driver/heap_policy.h"

#ifdef MDLC_BENCH_HAVE_SDFORMAT
#include <sdf/Root.hh>
#endif

namespace mdlc::bench {
namespace {

constexpr int kSizes[] = {10, 100, 1000, 10000};
// worlds of many one-link models: does the cost per model stay flat up to 100k?
constexpr int kWorldSizes[] = {1000, 10000, 100000};
constexpr SdfFamily kFamilies[] = {SdfFamily::FrameChain, SdfFamily::NestedModels,
                                   SdfFamily::SdfChain, SdfFamily::World};

std::span<const int> SizesFor(SdfFamily family) {
  if (family == SdfFamily::World) return kWorldSizes;
  return kSizes;
}
int sdformat_max_n = 1000;

// the floor's options, as bench_compile.cc's
constexpr int kFloorXmlOptions = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                                XML_PARSE_NOWARNING | XML_PARSE_NOERROR | XML_PARSE_NOBLANKS |
                                XML_PARSE_COMPACT;

const std::string& Model(SdfFamily family, int n) {
  static std::map<std::pair<SdfFamily, int>, std::string> cache;
  auto [it, inserted] = cache.try_emplace({family, n});
  if (inserted) it->second = GenerateSdf(family, n);
  return it->second;
}

std::string FileName(SdfFamily family, int n) {
  return fmt::format("{}_n{}.sdf", SdfFamilyName(family), n);
}

// A compilation whose limits admit the deepest family: nested_models at
// 10,000 levels, past the model-depth limit's default (ir/limits.h).
std::unique_ptr<Compilation> NewCompilation() {
  auto c = std::make_unique<Compilation>();
  Limits limits;
  limits.model_depth = 100'000;
  c->sources.set_limits(limits);
  return c;
}

std::unique_ptr<Compilation> Prepare(benchmark::State& state, SdfFamily family, FileId* file) {
  state.PauseTiming();
  auto c = NewCompilation();
  const int n = static_cast<int>(state.range(0));
  *file = c->sources.AddBuffer(FileName(family, n), Model(family, n));
  state.ResumeTiming();
  return c;
}

// as Compilation::RunFrontends does it: packages known
bool RunFrontend(Compilation& c, FileId file) {
  frontend::FrontendContext ctx{c.sources, c.diags, c.module, c.options.frontend,
                                c.packages};
  return frontend::ReadModel(file, Format::Sdf, ctx).has_value() &&
         !c.diags.has_errors();
}

void ReportFirstError(benchmark::State& state, const Compilation& c, std::string_view stage) {
  for (const auto& d : c.diags.diagnostics()) {
    if (d.severity == Severity::Error) {
      state.SkipWithError(fmt::format("{}: {}", stage, d.message).c_str());
      return;
    }
  }
  state.SkipWithError(fmt::format("{} failed", stage).c_str());
}

void Finish(benchmark::State& state, SdfFamily family) {
  const int n = static_cast<int>(state.range(0));
  state.SetComplexityN(n);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(Model(family, n).size()));
}

// ---------------------------------------------------------------- stages

void BM_Libxml2Parse(benchmark::State& state, SdfFamily family) {
  const std::string& text = Model(family, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    xmlDocPtr doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), "bench.sdf",
                                  nullptr, kFloorXmlOptions);
    if (!doc) state.SkipWithError("libxml2 rejected the model");
    benchmark::DoNotOptimize(doc);
    xmlFreeDoc(doc);
  }
  Finish(state, family);
}

void BM_Libxml2Sax(benchmark::State& state, SdfFamily family) {
  TimeEmptySaxParse(state, Model(family, static_cast<int>(state.range(0))));
  Finish(state, family);
}

void BM_XmlDocument(benchmark::State& state, SdfFamily family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    auto doc = xml::XmlDocument::Parse(file, c->sources, c->diags);
    if (!doc) ReportFirstError(state, *c, "XmlDocument::Parse");
    benchmark::DoNotOptimize(doc.get());
  }
  Finish(state, family);
}

void BM_Frontend(benchmark::State& state, SdfFamily family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file)) ReportFirstError(state, *c, "frontend");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, family);
}

void BM_FrontendPasses(benchmark::State& state, SdfFamily family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file) || !c->RunPasses()) ReportFirstError(state, *c, "passes");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, family);
}

void BM_Compile(benchmark::State& state, SdfFamily family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file) || !c->RunPasses() || !c->RunBackend()) {
      ReportFirstError(state, *c, "compile");
    }
    benchmark::DoNotOptimize(c->model);
  }
  Finish(state, family);
}

void BM_Write(benchmark::State& state, SdfFamily family, Format to) {
  auto c = NewCompilation();
  const int n = static_cast<int>(state.range(0));
  const FileId file = c->sources.AddBuffer(FileName(family, n), Model(family, n));
  if (!RunFrontend(*c, file) || !c->RunPasses() || !c->RunBackend()) {
    ReportFirstError(state, *c, "compile");
    return;
  }
  writers::WriteOptions options;
  options.to = to;
  for (auto _ : state) {
    DiagnosticEngine diags;  // the lossy warnings a conversion draws
    std::optional<std::string> text = writers::Write(*c->model, c->module, options, diags);
    if (!text) state.SkipWithError("the writer failed");
    benchmark::DoNotOptimize(text);
  }
  Finish(state, family);
}
void BM_WriteUrdf(benchmark::State& state, SdfFamily family) {
  BM_Write(state, family, Format::Urdf);
}
void BM_WriteSdf(benchmark::State& state, SdfFamily family) {
  BM_Write(state, family, Format::Sdf);
}
void BM_WriteMjcf(benchmark::State& state, SdfFamily family) {
  BM_Write(state, family, Format::Mjcf);
}

#ifdef MDLC_BENCH_HAVE_SDFORMAT
void BM_LibsdformatLoad(benchmark::State& state, SdfFamily family) {
  const std::string& text = Model(family, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sdf::Root root;
    sdf::Errors errors = root.LoadSdfString(text);
    if (!errors.empty()) {
      // the message may quote the whole model: its first line is enough
      std::string first = errors.front().Message();
      first = first.substr(0, std::min<size_t>(first.find('\n'), 160));
      state.SkipWithError(
          fmt::format("libsdformat: {} errors, the first: {}", errors.size(), first).c_str());
    }
    benchmark::DoNotOptimize(root.Model());
  }
  Finish(state, family);
}
#endif

void RegisterAll() {
  struct Stage {
    const char* name;
    void (*fn)(benchmark::State&, SdfFamily);
    int max_n;
  };
  const Stage stages[] = {
      {"libxml2_parse", BM_Libxml2Parse, kWorldSizes[2]},
      {"libxml2_sax", BM_Libxml2Sax, kWorldSizes[2]},
      {"xml_document", BM_XmlDocument, kWorldSizes[2]},
      {"frontend", BM_Frontend, kWorldSizes[2]},
      {"frontend_passes", BM_FrontendPasses, kWorldSizes[2]},
      {"compile", BM_Compile, kWorldSizes[2]},
      {"write_urdf", BM_WriteUrdf, kWorldSizes[1]},
      {"write_sdf", BM_WriteSdf, kWorldSizes[1]},
      {"write_mjcf", BM_WriteMjcf, kWorldSizes[1]},
#ifdef MDLC_BENCH_HAVE_SDFORMAT
      {"libsdformat_load", BM_LibsdformatLoad, sdformat_max_n},
#endif
  };
  for (SdfFamily family : kFamilies) {
    for (const Stage& stage : stages) {
      auto* b = benchmark::RegisterBenchmark(
          fmt::format("{}/{}", stage.name, SdfFamilyName(family)).c_str(), stage.fn, family);
      int max_n = stage.max_n;
      // libsdformat's tinyxml2 rejects XML nested deeper than 100 elements,
      // and Debian's Google Benchmark 1.7 crashes fitting BigO over a family
      // whose every run failed: only N = 10 of nested_models loads there
      if (std::string_view(stage.name) == "libsdformat_load" &&
          family == SdfFamily::NestedModels) {
        max_n = std::min(max_n, kSizes[0]);
      }
      for (int n : SizesFor(family)) {
        if (n <= max_n) b->Arg(n);
      }
      b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
    }
  }
}

int WriteModels(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (SdfFamily family : kFamilies) {
    for (int n : SizesFor(family)) {
      const std::filesystem::path path = dir / FileName(family, n);
      std::ofstream out(path, std::ios::binary);
      out << Model(family, n);
      if (!out) {
        fmt::print(stderr, "mdlc_bench_sdf: cannot write '{}'\n", path.string());
        return 1;
      }
      fmt::print("{}\n", path.string());
    }
  }
  return 0;
}

}  // namespace
}  // namespace mdlc::bench

int main(int argc, char** argv) {
  mdlc::KeepFreedMemoryForReuse();
  // our own flags first (removed from argv); Google Benchmark rejects flags it does not know
  constexpr std::string_view kWriteModels = "--write_models=";
  constexpr std::string_view kSdformatMaxN = "--sdformat_max_n=";
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg(argv[i]);
    if (arg.starts_with(kWriteModels)) {
      return mdlc::bench::WriteModels(argv[i] + kWriteModels.size());
    }
    if (arg.starts_with(kSdformatMaxN)) {
      arg.remove_prefix(kSdformatMaxN.size());
      auto [end, error] = std::from_chars(arg.data(), arg.data() + arg.size(),
                                          mdlc::bench::sdformat_max_n);
      if (error != std::errc() || end != arg.data() + arg.size()) {
        fmt::print(stderr, "mdlc_bench_sdf: --sdformat_max_n wants a number\n");
        return 1;
      }
      continue;
    }
    argv[kept++] = argv[i];
  }
  argc = kept;
  return mdlc::bench::RunBenchmarks(argc, argv, mdlc::bench::RegisterAll);
}
