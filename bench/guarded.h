#pragma once

// A benchmark body whose exception becomes a skipped benchmark carrying its message, so
// that one failing case is reported in its row and the others still run.

#include <benchmark/benchmark.h>

#include <exception>

namespace shadowgen::bench {

template <class Body>
void guarded(benchmark::State& state, Body body) {
  try {
    body();
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

}  // namespace shadowgen::bench
