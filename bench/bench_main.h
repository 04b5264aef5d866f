#pragma once

// The main of a benchmark executable with one mode of its own besides Google Benchmark's:
// `--FLAG=SPEC` runs `mode(SPEC)` and exits with its code (1 with the message when it
// throws); otherwise the benchmarks run as usual.

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

namespace shadowgen::bench {

template <class Mode>
int main_with_mode(int argc, char** argv, const char* flag, Mode mode) {
  const std::string prefix = std::string("--") + flag + "=";
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], prefix.c_str(), prefix.size()) == 0) {
      try {
        return mode(std::string(argv[i] + prefix.size()));
      } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
      }
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace shadowgen::bench
