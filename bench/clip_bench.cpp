// Time to produce both the inside pieces (subject ∩ clip) and the outside pieces
// (subject − clip) of one overlapping pair of jittered stars with holes
// (bench/jittered_star.h), per polygon size, single thread:
//
//   BM_Shadowgen      shadowgen::clipper::clip, doubles in, doubles out;
//   BM_Clipper1       ClipperLib 6.4: rounding to integers + intersection + difference,
//                     PolyTree output (outer loops with their holes, like ours);
//   BM_Clipper1Paths  the same with flat Paths output, Clipper's cheapest form;
//   BM_Geos           GEOSIntersection_r + GEOSDifference_r on prebuilt geometries;
//   BM_Cgal           CGAL::intersection + CGAL::difference, Epeck, prebuilt polygons.
//
// and, for shadowgen alone, the shape of a ground under a city's buildings:
//
//   BM_GroundUnderBlocks  one square against N small squares in a grid as one span of
//                     clips (hidden-surface removal's call): N + 1 separate parts in the
//                     overlay, whose windings are found against each other.
//
// The adapters' headers say exactly what each timed iteration contains. Every timed
// iteration also frees the previous iteration's result.
//
// Counters, computed outside the timing from the last iteration's result:
//   rel_area_err  (|A_in − A*_in| + |A_out − A*_out|) / (A*_in + A*_out), where A is the
//                 exact area of the tool's output polygons (as doubles) and A* the
//                 exact area of CGAL's exact result, all in rational arithmetic
//                 (ExactAreaReference): the error of the output coordinates, not of a
//                 floating-point area sum;
//   pieces        number of output polygons, inside plus outside.
//
// Run with --benchmark_repetitions=5 --benchmark_report_aggregates_only=true and read
// the medians (bench/run_clip_bench.sh does).

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "bench/cgal_bool_ops.h"
#include "bench/clipper1_bool_ops.h"
#include "bench/geos_bool_ops.h"
#include "bench/guarded.h"
#include "bench/jittered_star.h"
#include "clipper/clip.h"

namespace shadowgen::bench {
namespace {

const StarPair& workload(std::size_t vertex_count) {
  static std::map<std::size_t, StarPair> cache;
  auto it = cache.find(vertex_count);
  if (it == cache.end()) {
    StarPair pair = overlapping_star_pair(vertex_count);
    if (!GeosBoolOps(pair.subject, pair.clip).inputs_valid()) {
      throw std::logic_error("jittered_star_with_holes made an invalid polygon");
    }
    it = cache.emplace(vertex_count, std::move(pair)).first;
  }
  return it->second;
}

const ExactAreaReference& reference(std::size_t vertex_count) {
  static std::map<std::size_t, ExactAreaReference> cache;
  auto it = cache.find(vertex_count);
  if (it == cache.end()) {
    const StarPair& pair = workload(vertex_count);
    it = cache.emplace(vertex_count, ExactAreaReference(pair.subject, pair.clip)).first;
  }
  return it->second;
}

void report(benchmark::State& state, std::size_t vertex_count, const clipper::ClipResult& r) {
  state.counters["rel_area_err"] = reference(vertex_count).relative_area_error(r);
  state.counters["pieces"] = static_cast<double>(r.inside.size() + r.outside.size());
}

std::size_t vertex_count(const benchmark::State& state) {
  return static_cast<std::size_t>(state.range(0));
}

void BM_Shadowgen(benchmark::State& state) {
  guarded(state, [&] {
    const StarPair& pair = workload(vertex_count(state));
    clipper::ClipResult r;
    for (auto _ : state) {
      r = clipper::clip(pair.subject, pair.clip);
      benchmark::DoNotOptimize(r.inside.data());
      benchmark::DoNotOptimize(r.outside.data());
    }
    report(state, vertex_count(state), r);
  });
}

void BM_Clipper1(benchmark::State& state) {
  guarded(state, [&] {
    const StarPair& pair = workload(vertex_count(state));
    Clipper1BoolOps ops(pair.subject, pair.clip, Clipper1BoolOps::Output::kPolyTree);
    for (auto _ : state) {
      ops.run();
      benchmark::ClobberMemory();
    }
    report(state, vertex_count(state), ops.result());
  });
}

void BM_Clipper1Paths(benchmark::State& state) {
  guarded(state, [&] {
    const StarPair& pair = workload(vertex_count(state));
    Clipper1BoolOps ops(pair.subject, pair.clip, Clipper1BoolOps::Output::kPaths);
    for (auto _ : state) {
      ops.run();
      benchmark::ClobberMemory();
    }
  });
}

void BM_Geos(benchmark::State& state) {
  guarded(state, [&] {
    const StarPair& pair = workload(vertex_count(state));
    GeosBoolOps ops(pair.subject, pair.clip);
    for (auto _ : state) {
      ops.run();
      benchmark::ClobberMemory();
    }
    report(state, vertex_count(state), ops.result());
  });
}

void BM_Cgal(benchmark::State& state) {
  guarded(state, [&] {
    const StarPair& pair = workload(vertex_count(state));
    CgalBoolOps ops(pair.subject, pair.clip);
    for (auto _ : state) {
      ops.run();
      benchmark::ClobberMemory();
    }
    report(state, vertex_count(state), ops.result());
  });
}

void BM_GroundUnderBlocks(benchmark::State& state) {
  const auto side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(state.range(0)))));
  const double size = 10.0 * side;
  const clipper::PolygonWithHoles2 ground{{{0, 0}, {size, 0}, {size, size}, {0, size}}, {}};
  std::vector<clipper::PolygonWithHoles2> blocks;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const double x = 10.0 * i + 2.0, y = 10.0 * j + 3.0;
      blocks.push_back({{{x, y}, {x + 5, y}, {x + 5, y + 6}, {x, y + 6}}, {}});
    }
  }
  clipper::ClipResult r;
  for (auto _ : state) {
    r = clipper::clip(ground, blocks);
    benchmark::DoNotOptimize(r.outside.data());
  }
  state.counters["blocks"] = static_cast<double>(blocks.size());
  state.counters["holes"] =
      r.outside.empty() ? 0.0 : static_cast<double>(r.outside[0].holes.size());
}

void sizes(benchmark::internal::Benchmark* b) {
  b->Arg(64)->Arg(1024)->Arg(4096)->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_Shadowgen)->Apply(sizes);
BENCHMARK(BM_Clipper1)->Apply(sizes);
BENCHMARK(BM_Clipper1Paths)->Apply(sizes);
BENCHMARK(BM_Geos)->Apply(sizes);
BENCHMARK(BM_Cgal)->Apply(sizes);
BENCHMARK(BM_GroundUnderBlocks)
    ->Arg(1024)
    ->Arg(4096)
    ->Arg(16384)
    ->Arg(65536)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadowgen::bench

BENCHMARK_MAIN();
