// bench_main.h - what every benchmark binary's main does once it has taken
// its own flags (--write_models=DIR and the like) out of argv: Google
// Benchmark rejects flags it does not know.
#pragma once

#include <benchmark/benchmark.h>

namespace mdlc::bench {

/// Runs the benchmarks `register_all` registers, as the command line asks.
inline int RunBenchmarks(int argc, char** argv, void (*register_all)()) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace mdlc::bench
