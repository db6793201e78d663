// bench_directives.cc - Model Directives scenes of N models.
//
// A scene adds N copies of a three-link arm (one small URDF file) and welds
// each to the one before through a frame on its last link (add_model +
// add_frame + add_weld per arm), so the kinematic chain is 3N deep and every
// directive looks frames up among all the instances before it. Stages:
//   yaml_parse/dmd_chain/N  yaml-cpp's parse of the scene file alone (the floor)
//   frontend/dmd_chain/N    the directives frontend, loading the N models
//   compile/dmd_chain/N     the whole compile (frontends, passes, backend)
//   frontend/auto_renamed/N N copies of the arm's URDF given as N inputs
//                           under one name, auto-renamed arm, arm_1, ...
//                           (COMMON-022): each rename starts past the last
// Each reports a BigO fit over N. Files go to a temporary folder, made once.
// The floor leaves out the arm's URDF, which every add_model loads: a
// compile parses its text twice (frontend/xml/document_cache.h) and lowers
// it once per instance, and the compile's time includes both.
#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <map>

#include "bench_main.h"
#include "tools/driver/compiler.h"
#include "tools/driver/heap_policy.h"

namespace mdlc::bench {
namespace {

namespace fs = std::filesystem;

constexpr int kSizes[] = {10, 100, 1000};

constexpr const char* kArm = R"(<?xml version="1.0"?>
<robot name="arm">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>
  </link>
  <link name="upper">
    <inertial><origin xyz="0 0 0.1"/><mass value="0.5"/><inertia ixx="0.002" iyy="0.002" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.1"/><geometry><cylinder radius="0.02" length="0.2"/></geometry></collision>
  </link>
  <link name="fore">
    <inertial><origin xyz="0 0 0.1"/><mass value="0.3"/><inertia ixx="0.001" iyy="0.001" izz="0.0005" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.1"/><geometry><cylinder radius="0.015" length="0.2"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base"/><child link="upper"/><origin xyz="0 0 0.05"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="upper"/><child link="fore"/><origin xyz="0 0 0.2"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="5" velocity="2"/>
  </joint>
</robot>
)";

std::string Scene(int n) {
  std::string out = "directives:\n";
  for (int i = 0; i < n; ++i) {
    out += fmt::format(
        "- add_model:\n    name: arm_{0}\n    file: package://mdlc_bench_dmd/arm.urdf\n", i);
    if (i == 0) {
      out += "- add_weld:\n    parent: world\n    child: arm_0::base\n";
      continue;
    }
    out += fmt::format(
        "- add_frame:\n    name: arm_{0}::mount\n    X_PF:\n      base_frame: arm_{0}::fore\n"
        "      translation: [0, 0, 0.2]\n      rotation: !Rpy {{deg: [0, 0, 30]}}\n"
        "- add_weld:\n    parent: arm_{0}::mount\n    child: arm_{1}::base\n",
        i - 1, i);
  }
  return out;
}

// The package folder with the arm and one scene per size, written once.
const fs::path& Folder() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / fmt::format("mdlc_bench_dmd_{}", ::getpid());
    fs::create_directories(d);
    std::ofstream(d / "package.xml") << "<package format=\"2\"><name>mdlc_bench_dmd</name></package>\n";
    std::ofstream(d / "arm.urdf") << kArm;
    for (int n : kSizes) std::ofstream(d / fmt::format("chain_n{}.dmd.yaml", n)) << Scene(n);
    return d;
  }();
  return dir;
}

fs::path ScenePath(int n) { return Folder() / fmt::format("chain_n{}.dmd.yaml", n); }

std::unique_ptr<Compilation> Prepare(benchmark::State& state) {
  state.PauseTiming();
  auto c = std::make_unique<Compilation>();
  c->options.inputs = {Input::File(ScenePath(static_cast<int>(state.range(0))).string())};
  c->packages.PopulateFromFolder(Folder().string(), c->sources, c->diags);
  state.ResumeTiming();
  return c;
}

void Finish(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  state.SetComplexityN(n);
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations()) *
                          static_cast<int64_t>(fs::file_size(ScenePath(n))));
}

void BM_YamlParse(benchmark::State& state) {
  std::ifstream in(ScenePath(static_cast<int>(state.range(0))));
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (auto _ : state) benchmark::DoNotOptimize(YAML::Load(text));
  Finish(state);
}

void BM_Frontend(benchmark::State& state) {
  for (auto _ : state) {
    auto c = Prepare(state);
    if (!c->RunFrontends()) state.SkipWithError("the scene did not load");
  }
  Finish(state);
}

void BM_Compile(benchmark::State& state) {
  for (auto _ : state) {
    auto c = Prepare(state);
    if (!c->Run()) state.SkipWithError("the scene did not compile");
  }
  Finish(state);
}

void BM_AutoRenamed(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  for (auto _ : state) {
    state.PauseTiming();
    auto c = std::make_unique<Compilation>();
    c->options.inputs.assign(n, Input::Text(kArm, "arm.urdf"));
    c->options.frontend.auto_rename = true;
    state.ResumeTiming();
    if (!c->RunFrontends()) state.SkipWithError("the copies did not load");
  }
  state.SetComplexityN(n);
}

void RegisterAll() {
  const std::pair<const char*, void (*)(benchmark::State&)> stages[] = {
      {"yaml_parse/dmd_chain", BM_YamlParse},
      {"frontend/dmd_chain", BM_Frontend},
      {"compile/dmd_chain", BM_Compile}};
  for (const auto& [name, fn] : stages) {
    auto* b = benchmark::RegisterBenchmark(name, fn);
    for (int n : kSizes) b->Arg(n);
    b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
  }
  auto* renamed = benchmark::RegisterBenchmark("frontend/auto_renamed", BM_AutoRenamed);
  for (int n : kSizes) renamed->Arg(n);
  renamed->Arg(10000)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
}

}  // namespace
}  // namespace mdlc::bench

int main(int argc, char** argv) {
  mdlc::KeepFreedMemoryForReuse();
  const int status = mdlc::bench::RunBenchmarks(argc, argv, mdlc::bench::RegisterAll);
  std::error_code ec;
  std::filesystem::remove_all(mdlc::bench::Folder(), ec);
  return status;
}
