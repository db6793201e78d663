// bench_meshes.cc - mesh-heavy models (issue 57): what does a compile cost
// when its time goes to mesh files, with the mesh cache cold and warm, with
// meshes read by child processes (the default) and in this process, and
// against MuJoCo 2.2.2's mj_loadXML of the same MJCF file?
//
// Models:
//   synthetic_n100, synthetic_n1000  N free bodies, each with its own binary
//       STL file and no <inertial> (mesh_model_gen.h): both mdlc and MuJoCo
//       read every file. Written once per process into a temporary folder,
//       untimed, when a benchmark first needs them.
//   allegro_hand, robotiq_2f85, shadow_hand, talos, cassie (MuJoCo
//   Menagerie, MJCF) and iiwa14, panda (Drake's models, SDFormat and URDF)
//       from the corpus of real models. Many declare their bodies' inertia,
//       so mdlc reads few or none of their meshes (it reads only what the
//       compile needs), where MuJoCo reads them all.
//
// Benchmarks per model, in wall time (UseRealTime: the child readers work
// in other processes, which this process's CPU time leaves out):
//   mesh_compile/<model>/cold/process     mdlc::Compile, meshes read by child
//                                         processes, the mesh cache an empty
//                                         folder each iteration (emptied
//                                         untimed)
//   mesh_compile/<model>/cold/in_process  the same, meshes read in this process
//   mesh_compile/<model>/warm/process     the cache filled by one untimed
//   mesh_compile/<model>/warm/in_process  compile first
//   mujoco_load/<model>                   MJCF models, when built with MuJoCo
//                                         2.2.2: mj_loadXML + mj_deleteModel
// "Cold" is the mesh cache's state, not the kernel's: the files stay in the
// page cache from run to run, as they do for a user compiling a model again.
// Each benchmark counts the model's mesh files (mesh_files) and the entries
// a cold compile leaves in the cache (cache_entries: the derived mesh data
// it computed, so the meshes it needed).
//
//   mdlc_bench_meshes --corpus=DIR       the corpus folder; else $MDLC_CORPUS,
//                                        else ../shared/corpus (from the
//                                        current folder)
//   mdlc_bench_meshes --write_models=DIR write the synthetic models as
//                                        DIR/synthetic_n{N}/ (to run mdlc on)
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "bench_main.h"
#include "mdlc/ir.h"
#include "mdlc/mdlc.h"
#include "mesh_model_gen.h"
#include "tools/driver/heap_policy.h"

#ifdef MDLC_BENCH_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace mdlc::bench {
namespace {

namespace fs = std::filesystem;

constexpr int kSyntheticSizes[] = {100, 1000};

// from --corpus=DIR, $MDLC_CORPUS or the default, before registration
fs::path g_corpus;

// One benchmark model: generated (bodies > 0) or a file of the corpus.
struct ModelSpec {
  std::string name;
  int bodies = 0;
  std::string corpus_path;  // relative to the corpus folder
  bool mjcf = true;
};

std::vector<ModelSpec> Models() {
  std::vector<ModelSpec> models;
  for (int n : kSyntheticSizes) models.push_back({fmt::format("synthetic_n{}", n), n, {}, true});
  // Menagerie's models compile, and MuJoCo 2.2.2 loads them, except talos,
  // which uses a joint attribute newer than 2.2.2 (the row says so)
  models.push_back({"allegro_hand", 0, "mujoco_menagerie/wonik_allegro/left_hand.xml", true});
  models.push_back({"robotiq_2f85", 0, "mujoco_menagerie/robotiq_2f85/2f85.xml", true});
  models.push_back({"shadow_hand", 0, "mujoco_menagerie/shadow_hand/left_hand.xml", true});
  models.push_back({"talos", 0, "mujoco_menagerie/pal_talos/talos.xml", true});
  models.push_back({"cassie", 0, "mujoco_menagerie/agility_cassie/cassie.xml", true});
  // Drake's manipulation models name their meshes as package://drake_models/...
  models.push_back(
      {"iiwa14", 0, "drake_models/iiwa_description/sdf/iiwa14_polytope_collision.sdf", false});
  models.push_back({"panda", 0, "drake_models/franka_description/urdf/panda_arm_hand.urdf", false});
  return models;
}

// ------------------------------------------------------ scratch folders

// where this process writes its synthetic models and mesh caches; made on
// first use, removed when the benchmarks are done
std::optional<fs::path> g_scratch;

const fs::path& ScratchDir() {
  if (!g_scratch) {
    g_scratch = fs::temp_directory_path() / fmt::format("mdlc_bench_meshes_{}", ::getpid());
    fs::create_directories(*g_scratch);
  }
  return *g_scratch;
}

void RemoveScratchDir() {
  std::error_code ec;
  if (g_scratch) fs::remove_all(*g_scratch, ec);
}

// an empty folder at `dir`, whatever was there
void ResetDir(const fs::path& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
}

size_t CountFiles(const fs::path& dir) {
  size_t n = 0;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::end(it);
       it.increment(ec)) {
    if (it->is_regular_file()) ++n;
  }
  return n;
}

// ------------------------------------------------------------ the models

std::string_view ReaderName(MeshReader reader) {
  return reader == MeshReader::Process ? "process" : "in_process";
}

Options CompileOptions(MeshReader reader, const fs::path& cache_dir) {
  Options options;
  options.packages.definitions.emplace_back("drake_models", (g_corpus / "drake_models").string());
  options.meshes.reader = reader;
  options.meshes.cache_dir = cache_dir.string();
  return options;
}

// The file a model is read from (synthetic models are written now), or why
// there is none.
struct Located {
  std::string path;
  std::string error;
};

const Located& Locate(const ModelSpec& spec) {
  static std::map<std::string, Located> found;
  auto [it, inserted] = found.try_emplace(spec.name);
  if (!inserted) return it->second;
  Located& l = it->second;
  if (spec.bodies > 0) {
    try {
      l.path = WriteMeshBodiesModel(ScratchDir() / spec.name, spec.bodies).string();
    } catch (const std::exception& e) {
      l.error = e.what();
    }
  } else if (const fs::path path = g_corpus / spec.corpus_path; fs::is_regular_file(path)) {
    l.path = path.string();
  } else {
    l.error = fmt::format("'{}' not found: give the corpus folder with --corpus=DIR or "
                          "$MDLC_CORPUS", path.string());
  }
  return l;
}

// What one untimed compile of a model tells about it, found once per process.
struct Survey {
  std::string path;
  std::string error;          // the model cannot be compiled (or found)
  std::string reader_missing; // meshes would be read here though a child was asked for
  size_t mesh_files = 0;
  size_t cache_entries = 0;
};

const Survey& SurveyOf(const ModelSpec& spec) {
  static std::map<std::string, Survey> surveys;
  auto [it, inserted] = surveys.try_emplace(spec.name);
  Survey& s = it->second;
  if (!inserted) return s;
  const Located& located = Locate(spec);
  s.path = located.path;
  s.error = located.error;
  if (!s.error.empty()) return s;

  const fs::path cache = ScratchDir() / "cache" / fmt::format("{}_survey", spec.name);
  ResetDir(cache);
  const Result r = Compile(Input::File(s.path), CompileOptions(MeshReader::Process, cache));
  s.cache_entries = CountFiles(cache);
  fs::remove_all(cache);
  std::set<std::string> files;
  for (const ir::Geometry& g : mdlc::IrModule(r).geometries) {
    if (const auto* mesh = std::get_if<ir::Mesh>(&g.shape); mesh && !mesh->resolved.empty()) {
      files.insert(mesh->resolved);
    }
    if (g.fit_to_mesh && !g.fit_to_mesh->mesh.resolved.empty()) {
      files.insert(g.fit_to_mesh->mesh.resolved);
    }
  }
  s.mesh_files = files.size();
  for (const Diagnostic& d : r.diagnostics()) {
    if (s.error.empty() && d.severity == Severity::Error) s.error = r.FormatText(d);
    // without the reader program the "process" rows would time in-process reads
    if (d.kind == DiagKind::MeshReaderMissing) s.reader_missing = d.message;
  }
  if (s.error.empty() && !r.ok()) s.error = "the compile failed";
  return s;
}

// ---------------------------------------------------------- benchmarks

// The survey of `spec`, or nullptr after skipping the benchmark.
const Survey* Usable(benchmark::State& state, const ModelSpec& spec, MeshReader reader) {
  const Survey& s = SurveyOf(spec);
  if (!s.error.empty()) {
    state.SkipWithError(s.error.c_str());
    return nullptr;
  }
  if (reader == MeshReader::Process && !s.reader_missing.empty()) {
    state.SkipWithError(s.reader_missing.c_str());
    return nullptr;
  }
  state.counters["mesh_files"] = static_cast<double>(s.mesh_files);
  state.counters["cache_entries"] = static_cast<double>(s.cache_entries);
  return &s;
}

// One timed compile; the Result is torn down inside the timing, as a
// caller's would be.
void TimedCompile(benchmark::State& state, const std::string& path, const Options& options) {
  const Result r = Compile(Input::File(path), options);
  if (!r.ok()) state.SkipWithError("the compile reported errors");
  benchmark::DoNotOptimize(&r);
}

void BM_Cold(benchmark::State& state, const ModelSpec* spec, MeshReader reader) {
  const Survey* s = Usable(state, *spec, reader);
  if (!s) return;
  const fs::path cache =
      ScratchDir() / "cache" / fmt::format("{}_cold_{}", spec->name, ReaderName(reader));
  const Options options = CompileOptions(reader, cache);
  for (auto _ : state) {
    state.PauseTiming();
    ResetDir(cache);
    state.ResumeTiming();
    TimedCompile(state, s->path, options);
  }
  fs::remove_all(cache);
}

void BM_Warm(benchmark::State& state, const ModelSpec* spec, MeshReader reader) {
  const Survey* s = Usable(state, *spec, reader);
  if (!s) return;
  const fs::path cache =
      ScratchDir() / "cache" / fmt::format("{}_warm_{}", spec->name, ReaderName(reader));
  ResetDir(cache);
  const Options options = CompileOptions(reader, cache);
  if (!Compile(Input::File(s->path), options).ok()) {  // fills the cache, untimed
    state.SkipWithError("the compile that fills the cache reported errors");
    return;
  }
  for (auto _ : state) TimedCompile(state, s->path, options);
  fs::remove_all(cache);
}

#ifdef MDLC_BENCH_HAVE_MUJOCO
void BM_MujocoLoad(benchmark::State& state, const ModelSpec* spec) {
  // MuJoCo needs only the file: its row does not depend on mdlc compiling it
  const Located& located = Locate(*spec);
  if (!located.error.empty()) {
    state.SkipWithError(located.error.c_str());
    return;
  }
  char error[1024] = "";
  for (auto _ : state) {
    mjModel* m = mj_loadXML(located.path.c_str(), nullptr, error, sizeof error);
    if (!m) {
      state.SkipWithError(fmt::format("MuJoCo 2.2.2: {}", error).c_str());
      break;
    }
    benchmark::DoNotOptimize(m);
    mj_deleteModel(m);
  }
}
#endif

void RegisterAll() {
  // the specs outlive the benchmarks, which hold pointers to them
  static const std::vector<ModelSpec> models = Models();
  for (const ModelSpec& spec : models) {
    for (MeshReader reader : {MeshReader::Process, MeshReader::InProcess}) {
      benchmark::RegisterBenchmark(
          fmt::format("mesh_compile/{}/cold/{}", spec.name, ReaderName(reader)).c_str(), BM_Cold,
          &spec, reader)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(
          fmt::format("mesh_compile/{}/warm/{}", spec.name, ReaderName(reader)).c_str(), BM_Warm,
          &spec, reader)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
#ifdef MDLC_BENCH_HAVE_MUJOCO
    if (spec.mjcf) {
      benchmark::RegisterBenchmark(fmt::format("mujoco_load/{}", spec.name).c_str(),
                                   BM_MujocoLoad, &spec)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
#endif
  }
}

int WriteModels(const fs::path& dir) {
  try {
    for (int n : kSyntheticSizes) {
      fmt::print("{}\n", WriteMeshBodiesModel(dir / fmt::format("synthetic_n{}", n), n).string());
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "mdlc_bench_meshes: {}\n", e.what());
    return 1;
  }
  return 0;
}

fs::path CorpusFolder(std::string_view flag) {
  if (!flag.empty()) return fs::path(flag);
  if (const char* env = std::getenv("MDLC_CORPUS"); env && *env) return fs::path(env);
  return fs::path("..") / "shared" / "corpus";
}

}  // namespace
}  // namespace mdlc::bench

int main(int argc, char** argv) {
  mdlc::KeepFreedMemoryForReuse();
  // our own flags first; Google Benchmark rejects flags it does not know
  constexpr std::string_view kWriteModels = "--write_models=";
  constexpr std::string_view kCorpus = "--corpus=";
  std::string_view corpus;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg.starts_with(kWriteModels)) {
      return mdlc::bench::WriteModels(std::string(arg.substr(kWriteModels.size())));
    }
    if (arg.starts_with(kCorpus)) {
      corpus = arg.substr(kCorpus.size());
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  mdlc::bench::g_corpus = mdlc::bench::CorpusFolder(corpus);
  const int status = mdlc::bench::RunBenchmarks(argc, argv, mdlc::bench::RegisterAll);
  mdlc::bench::RemoveScratchDir();
  return status;
}
