// bench_compile.cc - load-time benchmarks: how much does compiling a URDF
// cost on top of merely parsing its XML, and does it stay linear in size?
//
// For chain and tree models of N = 10, 100, 1000, 10000 links (model_gen.h),
// each stage is timed on an in-memory buffer; from xml_document down, each
// stage includes the ones above it:
//
//   libxml2_parse     xmlReadMemory + xmlFreeDoc with mdlc's options: the floor
//   xml_document      mdlc's XmlDocument::Parse (the above + source offsets)
//   frontend          URDF -> IR (frontend::ReadModel)
//   frontend_passes   ... + the default pass pipeline
//   compile           ... + backend::Instantiate (plant and scene graph)
//   plant_json        EmitPlantJson alone, on a model compiled beforehand, as
//                     the CLI does it (mass matrix included up to 1000 dofs)
//   plant_json_no_mm  the same without the mass matrix (the linear part)
//
// Copying the text into a SourceManager is setup and not timed; tearing the
// results down is timed in every stage, libxml2's included. Every joint's
// friction draws an "unsupported" warning (as with gen_models.py's models);
// the engine stores them, nothing prints them. Each family reports BigO over
// N (SetComplexityN = links) and bytes/s.
//
//   mdlc_bench                          run everything
//   mdlc_bench --benchmark_filter=compile/chain
//   mdlc_bench --write_models=DIR       write the models as DIR/{chain,tree}_n{N}.urdf
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <libxml/parser.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "backend/compiler.h"
#include "frontend/xml/xml_document.h"
#include "model_gen.h"

namespace mdlc::bench {
namespace {

constexpr int kSizes[] = {10, 100, 1000, 10000};

// what frontend/xml/xml_document.cc passes to xmlReadMemory
// keep in step with frontend/xml/xml_document.cc
constexpr int kMdlcXmlOptions = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                                XML_PARSE_NOWARNING | XML_PARSE_NOERROR | XML_PARSE_NOBLANKS |
                                XML_PARSE_COMPACT;

const std::string& Model(Shape shape, int n) {
  static std::map<std::pair<Shape, int>, std::string> cache;
  auto [it, inserted] = cache.try_emplace({shape, n});
  if (inserted) it->second = GenerateUrdf(shape, n);
  return it->second;
}

std::string FileName(Shape shape, int n) { return fmt::format("{}_n{}.urdf", ShapeName(shape), n); }

// A Compilation holding the model's text; the copy is setup, not timed.
std::unique_ptr<Compilation> Prepare(benchmark::State& state, Shape shape, FileId* file) {
  state.PauseTiming();
  auto c = std::make_unique<Compilation>();
  const int n = static_cast<int>(state.range(0));
  *file = c->sources.AddBuffer(FileName(shape, n), Model(shape, n));
  state.ResumeTiming();
  return c;
}

bool RunFrontend(Compilation& c, FileId file) {
  frontend::FrontendContext ctx{c.sources, c.diags, c.module, c.options.frontend};
  return frontend::ReadModel(file, frontend::Format::Urdf, ctx).has_value() &&
         !c.diags.has_errors();
}

void Finish(benchmark::State& state, Shape shape) {
  const int n = static_cast<int>(state.range(0));
  state.SetComplexityN(n);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(Model(shape, n).size()));
}

// ---------------------------------------------------------------- stages

void Libxml2Parse(benchmark::State& state, Shape shape, int options) {
  const std::string& text = Model(shape, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    xmlDocPtr doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), "bench.urdf",
                                  nullptr, options);
    if (!doc) state.SkipWithError("libxml2 rejected the model");
    benchmark::DoNotOptimize(doc);
    xmlFreeDoc(doc);
  }
  Finish(state, shape);
}

void BM_Libxml2Parse(benchmark::State& state, Shape shape) {
  Libxml2Parse(state, shape, kMdlcXmlOptions);
}

void BM_XmlDocument(benchmark::State& state, Shape shape) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, shape, &file);
    auto doc = xml::XmlDocument::Parse(file, c->sources, c->diags);
    if (!doc) state.SkipWithError("XmlDocument::Parse failed");
    benchmark::DoNotOptimize(doc.get());
  }
  Finish(state, shape);
}

void BM_Frontend(benchmark::State& state, Shape shape) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, shape, &file);
    if (!RunFrontend(*c, file)) state.SkipWithError("frontend reported errors");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, shape);
}

void BM_FrontendPasses(benchmark::State& state, Shape shape) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, shape, &file);
    if (!RunFrontend(*c, file) || !c->RunPasses()) state.SkipWithError("passes reported errors");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, shape);
}

void BM_Compile(benchmark::State& state, Shape shape) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, shape, &file);
    if (!RunFrontend(*c, file) || !c->RunPasses() || !c->RunBackend()) {
      state.SkipWithError("compile reported errors");
    }
    benchmark::DoNotOptimize(c->model);
  }
  Finish(state, shape);
}

void BM_PlantJson(benchmark::State& state, Shape shape, bool mass_matrix) {
  // compile once, untimed
  Compilation c;
  const int n = static_cast<int>(state.range(0));
  const FileId file = c.sources.AddBuffer(FileName(shape, n), Model(shape, n));
  if (!RunFrontend(c, file) || !c.RunPasses() || !c.RunBackend()) {
    state.SkipWithError("compile reported errors");
    return;
  }
  const Eigen::VectorXd q = backend::DefaultPositions(c.model->plant);
  backend::PlantJsonOptions options;
  if (!mass_matrix) options.mass_matrix_max_dofs = 0;
  size_t bytes = 0;
  for (auto _ : state) {
    std::string json = backend::EmitPlantJson(*c.model, q, options);
    bytes = json.size();
    benchmark::DoNotOptimize(json);
  }
  state.counters["json_MB"] = static_cast<double>(bytes) / 1e6;
  Finish(state, shape);
}

void RegisterAll() {
  struct Stage {
    const char* name;
    void (*fn)(benchmark::State&, Shape);
  };
  static constexpr Stage kStages[] = {
      {"libxml2_parse", BM_Libxml2Parse},
      {"xml_document", BM_XmlDocument},
      {"frontend", BM_Frontend},
      {"frontend_passes", BM_FrontendPasses},
      {"compile", BM_Compile},
      {"plant_json", [](benchmark::State& s, Shape shape) { BM_PlantJson(s, shape, true); }},
      {"plant_json_no_mm", [](benchmark::State& s, Shape shape) { BM_PlantJson(s, shape, false); }},
  };
  for (Shape shape : {Shape::Chain, Shape::Tree}) {
    for (const Stage& stage : kStages) {
      auto* b = benchmark::RegisterBenchmark(
          fmt::format("{}/{}", stage.name, ShapeName(shape)).c_str(), stage.fn, shape);
      for (int n : kSizes) b->Arg(n);
      b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
    }
  }
}

int WriteModels(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (Shape shape : {Shape::Chain, Shape::Tree}) {
    for (int n : kSizes) {
      const std::filesystem::path path = dir / FileName(shape, n);
      std::ofstream out(path, std::ios::binary);
      out << Model(shape, n);
      if (!out) {
        fmt::print(stderr, "mdlc_bench: cannot write '{}'\n", path.string());
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
  // our own flag first; Google Benchmark rejects flags it does not know
  constexpr std::string_view kWriteModels = "--write_models=";
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]).starts_with(kWriteModels)) {
      return mdlc::bench::WriteModels(argv[i] + kWriteModels.size());
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  mdlc::bench::RegisterAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
