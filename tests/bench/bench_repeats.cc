// bench_repeats.cc - models that repeat one element N times: does each
// element still cost the same at N = 16,000 as at N = 1,000?
//
// Each family is a way a file can repeat something that once made mdlc
// look through every element before it, so that N of them cost N^2 (each
// was found by a probe and fixed; these keep it fixed):
//
//   compile/sdf_drake_joints/N    an SDFormat model with N <drake:joint>s,
//                                 each checked for a name its model's joints
//                                 already hold
//   compile/sdf_renamed_joints/N  an SDFormat 1.6 model whose N joints are
//                                 named as their child links, so each joint
//                                 is renamed NAME_joint, with its actuator
//   compile/mjcf_contact_pairs/N  an MJCF model with N <contact><pair>s, each
//                                 between the geoms of two jointed bodies
//   compile/mjcf_models/N         N MJCF models, each with its compiler's
//                                 mass corrections (settotalmass) and a free
//                                 body, given as N inputs (auto-renamed)
//   write_mjcf/same_named_geoms/N an SDFormat chain of N links whose
//                                 collisions are all named "collision",
//                                 written as MJCF, where geom names are one
//                                 namespace (the compile is setup)
//
// Each reports a BigO fit over N (Google Benchmark's "_BigO" and "_RMS"
// rows: an RMS of a few percent says the time is linear). The models are
// made in memory; `--write_models=DIR` writes them as files
// (DIR/{family}_n{N}.{sdf,xml}; the MJCF models' one file for N = 1).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <string_view>

#include "bench_main.h"
#include "backend/writers/writer.h"
#include "tools/driver/compiler.h"
#include "tools/driver/heap_policy.h"

namespace mdlc::bench {
namespace {

constexpr int kSizes[] = {1000, 4000, 16000};

std::string SdfDrakeJoints(int n) {
  std::string out =
      "<sdf version='1.9' xmlns:drake='http://drake.mit.edu'>\n<model name='m'>\n"
      "<link name='l0'/>\n";
  for (int i = 1; i <= n; ++i) {
    out += fmt::format(
        "<link name='l{0}'/>\n<drake:joint name='j{0}' type='planar'>"
        "<drake:parent>l{1}</drake:parent><drake:child>l{0}</drake:child>"
        "<drake:damping>0 0 0</drake:damping></drake:joint>\n",
        i, i - 1);
  }
  return out + "</model>\n</sdf>\n";
}

std::string SdfRenamedJoints(int n) {
  std::string out = "<sdf version='1.6'>\n<model name='m'>\n<link name='l0'/>\n";
  for (int i = 1; i <= n; ++i) {
    out += fmt::format(
        "<link name='l{0}'/>\n<joint name='l{0}' type='revolute'><parent>l{1}</parent>"
        "<child>l{0}</child><axis><xyz>0 0 1</xyz><limit><effort>5</effort></limit></axis>"
        "</joint>\n",
        i, i - 1);
  }
  return out + "</model>\n</sdf>\n";
}

std::string MjcfContactPairs(int n) {
  std::string out = "<mujoco model='pairs'>\n<worldbody>\n";
  for (int i = 0; i <= n; ++i) {
    out += fmt::format(
        "<body name='b{0}' pos='{0} 0 0'><joint type='hinge'/>"
        "<geom name='g{0}' type='sphere' size='0.1'/></body>\n",
        i);
  }
  out += "</worldbody>\n<contact>\n";
  for (int i = 0; i < n; ++i) out += fmt::format("<pair geom1='g{}' geom2='g{}'/>\n", i, i + 1);
  return out + "</contact>\n</mujoco>\n";
}

constexpr std::string_view kMjcfBall =
    "<mujoco model='ball'>\n<compiler settotalmass='2'/>\n<worldbody>\n"
    "<body name='b'><freejoint/><geom type='sphere' size='0.1'/></body>\n"
    "</worldbody>\n</mujoco>\n";

std::string SdfSameNamedGeoms(int n) {
  std::string out = "<sdf version='1.9'>\n<model name='m'>\n";
  for (int i = 0; i <= n; ++i) {
    out += fmt::format(
        "<link name='l{0}'><inertial><mass>1</mass></inertial><collision name='collision'>"
        "<geometry><sphere><radius>0.1</radius></sphere></geometry></collision></link>\n",
        i);
    if (i > 0) {
      out += fmt::format(
          "<joint name='j{0}' type='revolute'><parent>l{1}</parent><child>l{0}</child>"
          "<axis><xyz>0 0 1</xyz></axis></joint>\n",
          i, i - 1);
    }
  }
  return out + "</model>\n</sdf>\n";
}

struct Family {
  const char* name;
  std::string (*make)(int n);
  const char* extension;
};
constexpr Family kSdfDrakeJoints{"sdf_drake_joints", SdfDrakeJoints, "sdf"};
constexpr Family kSdfRenamedJoints{"sdf_renamed_joints", SdfRenamedJoints, "sdf"};
constexpr Family kMjcfContactPairs{"mjcf_contact_pairs", MjcfContactPairs, "xml"};
constexpr Family kSdfSameNamedGeoms{"same_named_geoms", SdfSameNamedGeoms, "sdf"};

const std::string& Model(const Family& family, int n) {
  static std::map<std::pair<std::string, int>, std::string> cache;
  auto [it, inserted] = cache.try_emplace({family.name, n});
  if (inserted) it->second = family.make(n);
  return it->second;
}

std::string FileName(const Family& family, int n) {
  return fmt::format("{}_n{}.{}", family.name, n, family.extension);
}

/// A compile of `inputs`, made outside the timed region.
std::unique_ptr<Compilation> Prepare(std::vector<Input> inputs) {
  auto c = std::make_unique<Compilation>();
  c->options.inputs = std::move(inputs);
  c->options.frontend.auto_rename = true;
  return c;
}

/// The first error of a compile that failed, as the benchmark's error.
void Fail(benchmark::State& state, const Compilation& c) {
  for (const auto& d : c.diags.diagnostics()) {
    if (d.severity == Severity::Error) {
      state.SkipWithError(("the model did not compile: " + d.message).c_str());
      return;
    }
  }
  state.SkipWithError("the model did not compile");
}

void BM_Compile(benchmark::State& state, const Family* family) {
  const int n = static_cast<int>(state.range(0));
  const std::string& text = Model(*family, n);
  for (auto _ : state) {
    state.PauseTiming();
    auto c = Prepare({Input::Text(text, FileName(*family, n))});
    state.ResumeTiming();
    if (!c->Run()) return Fail(state, *c);
  }
  state.SetComplexityN(n);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(text.size()));
}

void BM_CompileMjcfModels(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    auto c = Prepare(std::vector<Input>(n, Input::Text(std::string(kMjcfBall), "ball.xml")));
    state.ResumeTiming();
    if (!c->Run()) return Fail(state, *c);
  }
  state.SetComplexityN(n);
}

void BM_WriteMjcf(benchmark::State& state, const Family* family) {
  const int n = static_cast<int>(state.range(0));
  auto c = Prepare({Input::Text(Model(*family, n), FileName(*family, n))});
  if (!c->Run()) return Fail(state, *c);
  writers::WriteOptions options;
  options.to = Format::Mjcf;
  for (auto _ : state) {
    DiagnosticEngine diags;
    std::optional<std::string> text = writers::Write(*c->model, c->module, options, diags);
    if (!text) state.SkipWithError("the writer failed");
    benchmark::DoNotOptimize(text);
  }
  state.SetComplexityN(n);
}

void Sized(benchmark::internal::Benchmark* b) {
  for (int n : kSizes) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
}

void RegisterAll() {
  for (const Family* family : {&kSdfDrakeJoints, &kSdfRenamedJoints, &kMjcfContactPairs}) {
    Sized(benchmark::RegisterBenchmark(fmt::format("compile/{}", family->name).c_str(),
                                       BM_Compile, family));
  }
  Sized(benchmark::RegisterBenchmark("compile/mjcf_models", BM_CompileMjcfModels));
  Sized(benchmark::RegisterBenchmark("write_mjcf/same_named_geoms", BM_WriteMjcf,
                                     &kSdfSameNamedGeoms));
}

/// --write_models=DIR: the models as files, to run the command line on.
int WriteModels(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  for (const Family* family :
       {&kSdfDrakeJoints, &kSdfRenamedJoints, &kMjcfContactPairs, &kSdfSameNamedGeoms}) {
    for (int n : kSizes) std::ofstream(dir / FileName(*family, n)) << Model(*family, n);
  }
  std::ofstream(dir / "mjcf_models_n1.xml") << kMjcfBall;
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
