#pragma once

// shadowgen's exact result as the benchmarks time it against sampled estimators: one
// thread, so that it is compared core for core.

#include <benchmark/benchmark.h>

#include "shadowgen/shadows/generate.h"

namespace shadowgen::bench {

inline GenerateResult exact_one_thread(const Scene& scene) {
  GenerateOptions options;
  options.threads = 1;
  return generate_shadows(scene, options);
}

// exact_one_thread(scene) timed over the state's iterations; the last result.
inline GenerateResult timed_exact_one_thread(benchmark::State& state, const Scene& scene) {
  GenerateResult result;
  for (auto _ : state) {
    result = exact_one_thread(scene);
    benchmark::DoNotOptimize(result.shadowed.lit());
  }
  return result;
}

}  // namespace shadowgen::bench
