// The main of a Google Benchmark program that runs with the command line's memory settings (runtime/memory.h), so
// that it times what a user's run does.
#pragma once

#include <benchmark/benchmark.h>

#include "runtime/memory.h"

namespace contactcert::bench {

/// Keeps the heap, pools GMP's blocks, then runs the benchmarks named on the command line; 1 for an unknown argument.
inline int run_with_user_memory(int argc, char** argv) {
  runtime::keep_heap_until_exit();
  runtime::use_pooled_gmp_memory();
  benchmark::Initialize(&argc, argv);
  const bool unknown = benchmark::ReportUnrecognizedArguments(argc, argv);
  if (!unknown) benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return unknown ? 1 : 0;
}

}  // namespace contactcert::bench
