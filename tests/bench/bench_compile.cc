// bench_compile.cc - load-time benchmarks: how much does compiling a URDF or
// an MJCF file cost on top of merely parsing its XML, and does it stay linear
// in size?
//
// For chain and tree models of N = 10, 100, 1000, 10000 links (mechanism.h,
// written as URDF by model_gen.h and as MJCF by model_gen_mjcf.h; the MJCF
// families are named mjcf_chain and mjcf_tree), each stage is timed on an
// in-memory buffer; from xml_document down, each stage includes the ones
// above it:
//
//   libxml2_parse     xmlReadMemory + xmlFreeDoc: libxml2's DOM, the floor
//   libxml2_sax       libxml2's SAX parse with handlers that do nothing
//                     (sax_floor.h): what libxml2 alone costs mdlc's reader
//   xml_document      mdlc's XmlDocument::Parse (libxml2's SAX parse building
//                     mdlc's own located tree)
//   frontend          URDF -> IR (frontend::ReadModel)
//   frontend_passes   ... + the default pass pipeline
//   compile           ... + backend::Instantiate (plant and scene graph)
//   plant_json        EmitPlantJson alone, on a model compiled beforehand, as
//                     the CLI does it (mass matrix included up to 1000 dofs)
//   plant_json_no_mm  the same without the mass matrix (the linear part)
//   mujoco_load       MJCF only, when built with MuJoCo 2.2.2 (libmujoco-dev):
//                     mj_loadXML + mj_deleteModel on the same text (from a
//                     file written once, untimed), for comparison
//
// One more MJCF family, mjcf_nested_defaults (libxml2_parse and compile
// only): N default classes nested in each other, each with a geom default,
// and N geoms of the deepest class, for N = 100, 1000, 4000. An element
// inherits from every class around its own (MJCF-012), and the fit shows
// that costs no walk of the N classes per geom.
//
// Copying the text into a SourceManager is setup and not timed; tearing the
// results down is timed in every stage, libxml2's included. Every joint's
// friction draws an "unsupported" warning (as with gen_models.py's models);
// the engine stores them, nothing prints them. Each family reports BigO over
// N (SetComplexityN = links) and bytes/s.
//
//   mdlc_bench                          run everything
//   mdlc_bench --benchmark_filter=compile/chain
//   mdlc_bench --write_models=DIR       write the models as DIR/{chain,tree}_n{N}.{urdf,mjcf.xml}
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <libxml/parser.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "bench_main.h"
#include "tools/driver/compiler.h"
#include "frontend/xml/xml_document.h"
#include "model_gen.h"
#include "model_gen_mjcf.h"
#include "sax_floor.h"
#include "tools/driver/heap_policy.h"

#ifdef MDLC_BENCH_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace mdlc::bench {
namespace {

constexpr int kSizes[] = {10, 100, 1000, 10000};

// the floor's options: mdlc's reader's, plus the two that make libxml2's DOM
// cheapest (no blank text nodes, short strings kept inside nodes), which
// mdlc's own tree does not need
constexpr int kFloorXmlOptions = XML_PARSE_NONET | XML_PARSE_HUGE | XML_PARSE_BIG_LINES |
                                XML_PARSE_NOWARNING | XML_PARSE_NOERROR | XML_PARSE_NOBLANKS |
                                XML_PARSE_COMPACT;

// a generated model: the mechanism's shape, written in one format
struct Family {
  Format format;
  Shape shape;
  auto operator<=>(const Family&) const = default;
};
constexpr Family kFamilies[] = {{Format::Urdf, Shape::Chain},
                                {Format::Urdf, Shape::Tree},
                                {Format::Mjcf, Shape::Chain},
                                {Format::Mjcf, Shape::Tree}};

// "chain" for URDF (the names the benchmark always had), "mjcf_chain" for MJCF
std::string FamilyName(Family family) {
  return family.format == Format::Urdf ? std::string(ShapeName(family.shape))
                                                 : fmt::format("mjcf_{}", ShapeName(family.shape));
}

const std::string& Model(Family family, int n) {
  static std::map<std::pair<Family, int>, std::string> cache;
  auto [it, inserted] = cache.try_emplace({family, n});
  if (inserted) {
    it->second = family.format == Format::Urdf ? GenerateUrdf(family.shape, n)
                                                         : GenerateMjcf(family.shape, n);
  }
  return it->second;
}

std::string FileName(Family family, int n) {
  return fmt::format("{}_n{}.{}", ShapeName(family.shape), n,
                     family.format == Format::Urdf ? "urdf" : "mjcf.xml");
}

// A Compilation holding `text` as `name`; the copy is setup, not timed.
std::unique_ptr<Compilation> PrepareText(benchmark::State& state, const std::string& name,
                                         const std::string& text, FileId* file) {
  state.PauseTiming();
  auto c = std::make_unique<Compilation>();
  *file = c->sources.AddBuffer(name, text);
  state.ResumeTiming();
  return c;
}

std::unique_ptr<Compilation> Prepare(benchmark::State& state, Family family, FileId* file) {
  const int n = static_cast<int>(state.range(0));
  return PrepareText(state, FileName(family, n), Model(family, n), file);
}

bool RunFrontend(Compilation& c, FileId file, Format format) {
  frontend::FrontendContext ctx{c.sources, c.diags, c.module, c.options.frontend};
  return frontend::ReadModel(file, format, ctx).has_value() && !c.diags.has_errors();
}

bool RunFrontend(Compilation& c, FileId file, Family family) {
  return RunFrontend(c, file, family.format);
}

// O(N) over the state's N, and the input's bytes per second
void FinishText(benchmark::State& state, const std::string& text) {
  state.SetComplexityN(state.range(0));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(text.size()));
}

void Finish(benchmark::State& state, Family family) {
  FinishText(state, Model(family, static_cast<int>(state.range(0))));
}

// ---------------------------------------------------------------- stages

void ParseWithLibxml2(benchmark::State& state, const std::string& text, int options) {
  for (auto _ : state) {
    xmlDocPtr doc = xmlReadMemory(text.data(), static_cast<int>(text.size()), "bench.xml",
                                  nullptr, options);
    if (!doc) state.SkipWithError("libxml2 rejected the model");
    benchmark::DoNotOptimize(doc);
    xmlFreeDoc(doc);
  }
}

void Libxml2Parse(benchmark::State& state, Family family, int options) {
  ParseWithLibxml2(state, Model(family, static_cast<int>(state.range(0))), options);
  Finish(state, family);
}

void BM_Libxml2Parse(benchmark::State& state, Family family) {
  Libxml2Parse(state, family, kFloorXmlOptions);
}

void BM_Libxml2Sax(benchmark::State& state, Family family) {
  TimeEmptySaxParse(state, Model(family, static_cast<int>(state.range(0))));
  Finish(state, family);
}

void BM_XmlDocument(benchmark::State& state, Family family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    auto doc = xml::XmlDocument::Parse(file, c->sources, c->diags);
    if (!doc) state.SkipWithError("XmlDocument::Parse failed");
    benchmark::DoNotOptimize(doc.get());
  }
  Finish(state, family);
}

void BM_Frontend(benchmark::State& state, Family family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file, family)) state.SkipWithError("frontend reported errors");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, family);
}

void BM_FrontendPasses(benchmark::State& state, Family family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file, family) || !c->RunPasses()) state.SkipWithError("passes reported errors");
    benchmark::DoNotOptimize(c->module);
  }
  Finish(state, family);
}

void BM_Compile(benchmark::State& state, Family family) {
  for (auto _ : state) {
    FileId file;
    auto c = Prepare(state, family, &file);
    if (!RunFrontend(*c, file, family) || !c->RunPasses() || !c->RunBackend()) {
      state.SkipWithError("compile reported errors");
    }
    benchmark::DoNotOptimize(c->model);
  }
  Finish(state, family);
}

void BM_PlantJson(benchmark::State& state, Family family, bool mass_matrix) {
  // compile once, untimed
  Compilation c;
  const int n = static_cast<int>(state.range(0));
  const FileId file = c.sources.AddBuffer(FileName(family, n), Model(family, n));
  if (!RunFrontend(c, file, family) || !c.RunPasses() || !c.RunBackend()) {
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
  Finish(state, family);
}

#ifdef MDLC_BENCH_HAVE_MUJOCO
void BM_MujocoLoad(benchmark::State& state, Family family) {
  const int n = static_cast<int>(state.range(0));
  // mj_loadXML reads a file: write it once, untimed
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / fmt::format("mdlc_bench_{}", FileName(family, n));
  std::ofstream(path, std::ios::binary) << Model(family, n);
  char error[512] = "";
  for (auto _ : state) {
    mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof error);
    if (!m) state.SkipWithError(fmt::format("MuJoCo: {}", error).c_str());
    benchmark::DoNotOptimize(m);
    mj_deleteModel(m);
  }
  std::filesystem::remove(path);
  Finish(state, family);
}
#endif

// ------------------------------------------------ nested default classes

std::string NestedDefaultsMjcf(int n) {
  std::string xml = fmt::format(
      "<mujoco model=\"nested_defaults_n{}\">\n<default>\n"
      "<geom type=\"box\" size=\"0.1 0.2 0.3\" euler=\"0 0 10\" density=\"500\"/>\n",
      n);
  // every class overwrites the first size and its color, so each geom's
  // size is layered through all of them
  for (int k = 0; k < n; ++k) {
    xml += fmt::format("<default class=\"c{}\"><geom size=\"{}\" rgba=\"0.5 0.5 {} 1\"/>\n", k,
                       0.1 + 1e-6 * k, (k % 10) / 10.0);
  }
  for (int k = 0; k < n; ++k) xml += "</default>\n";
  xml += "</default>\n<worldbody>\n<body name=\"b\" pos=\"0 0 1\">\n<freejoint/>\n";
  for (int k = 0; k < n; ++k) {
    xml += fmt::format("<geom class=\"c{}\" pos=\"{} 0 0\"/>\n", n - 1, 0.01 * k);
  }
  return xml + "</body>\n</worldbody>\n</mujoco>\n";
}

const std::string& NestedDefaultsModel(int n) {
  static std::map<int, std::string> cache;
  auto [it, inserted] = cache.try_emplace(n);
  if (inserted) it->second = NestedDefaultsMjcf(n);
  return it->second;
}

void BM_Libxml2ParseNestedDefaults(benchmark::State& state) {
  const std::string& text = NestedDefaultsModel(static_cast<int>(state.range(0)));
  ParseWithLibxml2(state, text, kFloorXmlOptions);
  FinishText(state, text);
}

void BM_CompileNestedDefaults(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const std::string& text = NestedDefaultsModel(n);
  for (auto _ : state) {
    FileId file;
    auto c = PrepareText(state, fmt::format("nested_defaults_n{}.xml", n), text, &file);
    if (!RunFrontend(*c, file, Format::Mjcf) || !c->RunPasses() || !c->RunBackend()) {
      state.SkipWithError("compile reported errors");
    }
    benchmark::DoNotOptimize(c->model);
  }
  FinishText(state, text);
}

void RegisterAll() {
  struct Stage {
    const char* name;
    void (*fn)(benchmark::State&, Family);
  };
  static constexpr Stage kStages[] = {
      {"libxml2_parse", BM_Libxml2Parse},
      {"libxml2_sax", BM_Libxml2Sax},
      {"xml_document", BM_XmlDocument},
      {"frontend", BM_Frontend},
      {"frontend_passes", BM_FrontendPasses},
      {"compile", BM_Compile},
      {"plant_json", [](benchmark::State& s, Family family) { BM_PlantJson(s, family, true); }},
      {"plant_json_no_mm", [](benchmark::State& s, Family family) { BM_PlantJson(s, family, false); }},
#ifdef MDLC_BENCH_HAVE_MUJOCO
      {"mujoco_load", BM_MujocoLoad},
#endif
  };
  for (Family family : kFamilies) {
    for (const Stage& stage : kStages) {
#ifdef MDLC_BENCH_HAVE_MUJOCO
      if (stage.fn == BM_MujocoLoad && family.format != Format::Mjcf) continue;
#endif
      auto* b = benchmark::RegisterBenchmark(
          fmt::format("{}/{}", stage.name, FamilyName(family)).c_str(), stage.fn, family);
      for (int n : kSizes) b->Arg(n);
      b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
    }
  }
  struct NestedStage {
    const char* name;
    void (*fn)(benchmark::State&);
  };
  for (const NestedStage& stage : {NestedStage{"libxml2_parse", BM_Libxml2ParseNestedDefaults},
                                   NestedStage{"compile", BM_CompileNestedDefaults}}) {
    auto* b = benchmark::RegisterBenchmark(
        fmt::format("{}/mjcf_nested_defaults", stage.name).c_str(), stage.fn);
    for (int n : {100, 1000, 4000}) b->Arg(n);
    b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
  }
}

int WriteModels(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (Family family : kFamilies) {
    for (int n : kSizes) {
      const std::filesystem::path path = dir / FileName(family, n);
      std::ofstream out(path, std::ios::binary);
      out << Model(family, n);
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
  mdlc::KeepFreedMemoryForReuse();
  // our own flag first; Google Benchmark rejects flags it does not know
  constexpr std::string_view kWriteModels = "--write_models=";
  for (int i = 1; i < argc; ++i) {
    if (std::string_view(argv[i]).starts_with(kWriteModels)) {
      return mdlc::bench::WriteModels(argv[i] + kWriteModels.size());
    }
  }
  return mdlc::bench::RunBenchmarks(argc, argv, mdlc::bench::RegisterAll);
}
