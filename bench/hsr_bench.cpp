// Hidden-surface removal (hsr::remove_hidden_surfaces) against the number of polygons,
// single thread. Workloads:
//
//   BM_HsrCubesOrtho/k        the cube grid of Thakur, Cheng and Miura (k³ cubes, 6k³
//                             polygons, bench/scenes/cube_grid.h), seen by an oblique
//                             orthographic view along (1, 2, -3);
//   BM_HsrCubesPerspective/k  the same grid seen from a perspective eye outside one
//                             corner, looking at the grid's centre (fov 50°: the whole
//                             grid in view);
//   BM_HsrSoup/n              n random triangles in the unit cube
//                             (bench/scenes/triangle_soup.h), oblique orthographic view.
//
// What is timed: one call of remove_hidden_surfaces (projection, the area sort, the merge
// of fragments), polygons already in memory. Counters: polygons (input), fragments
// (visible pieces after the merge), clips, depth_errors and depth_splits (hsr's own
// statistics), visible_area (image area of the fragments), zero_area_fragments
// (fragments whose loops enclose no area: collinear slivers hsr should not emit). The
// run is refused (skipped with an error) when a fragment has negative area, when no
// fragment has area, or when the fragments' total area exceeds the sum of the polygons'
// image areas.
//
// Run with --benchmark_repetitions=5 --benchmark_report_aggregates_only=true and read
// the medians (bench/run_hsr_bench.sh does).

#include <benchmark/benchmark.h>

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "bench/guarded.h"
#include "bench/scenes/cube_grid.h"
#include "bench/scenes/triangle_soup.h"
#include "hsr/hidden_surface.h"

namespace shadowgen::bench {
namespace {

const std::vector<hsr::Polygon3>& cubes(int k) {
  static std::map<int, std::vector<hsr::Polygon3>> cache;
  auto it = cache.find(k);
  if (it == cache.end()) it = cache.emplace(k, cube_grid({k, k, k, 0.0})).first;
  return it->second;
}

const std::vector<hsr::Polygon3>& soup(std::size_t n) {
  static std::map<std::size_t, std::vector<hsr::Polygon3>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, triangle_soup(n)).first;
  return it->second;
}

hsr::View oblique() { return hsr::View::orthographic({1.0, 2.0, -3.0}, {0.5, 0.5, 0.5}); }

hsr::View corner_eye() {
  const glm::dvec3 eye(2.2, 1.9, 1.6), centre(0.5, 0.5, 0.5);
  return hsr::View::perspective(eye, centre - eye, {0.0, 0.0, 1.0}, 50.0, 0.01);
}

// Checks the result and reports its counters; throws on a result no figure may come from.
void report(benchmark::State& state, std::span<const hsr::Polygon3> polygons, const hsr::View& view,
            const hsr::VisibleSurfaces& visible) {
  double visible_area = 0.0;
  std::size_t zero_area = 0;
  for (const hsr::Fragment& f : visible.fragments) {
    const double a = clipper::area(f.shape);
    if (!(a >= 0.0)) throw std::runtime_error("a fragment with negative area");
    if (a == 0.0) ++zero_area;
    visible_area += a;
  }
  if (visible.fragments.size() == zero_area) throw std::runtime_error("no visible area");
  double image_area = 0.0;
  for (const hsr::Polygon3& p : polygons)
    image_area += clipper::area(hsr::project_polygon(p, view));
  if (!(visible_area <= image_area * (1.0 + 1e-9))) {
    throw std::runtime_error("fragments cover more than the polygons' images");
  }
  const hsr::HsrStats& s = visible.stats;
  state.counters["polygons"] = static_cast<double>(polygons.size());
  state.counters["fragments"] = static_cast<double>(visible.fragments.size());
  state.counters["zero_area_fragments"] = static_cast<double>(zero_area);
  state.counters["clips"] = static_cast<double>(s.clips);
  state.counters["depth_errors"] = static_cast<double>(s.depth_errors);
  state.counters["depth_splits"] = static_cast<double>(s.depth_splits);
  state.counters["visible_area"] = visible_area;
}

void run(benchmark::State& state, std::span<const hsr::Polygon3> polygons, const hsr::View& view) {
  guarded(state, [&] {
    hsr::VisibleSurfaces visible;
    for (auto _ : state) {
      visible = hsr::remove_hidden_surfaces(polygons, view);
      benchmark::DoNotOptimize(visible.fragments.data());
    }
    report(state, polygons, view, visible);
  });
}

void BM_HsrCubesOrtho(benchmark::State& state) {
  run(state, cubes(static_cast<int>(state.range(0))), oblique());
}

void BM_HsrCubesPerspective(benchmark::State& state) {
  run(state, cubes(static_cast<int>(state.range(0))), corner_eye());
}

void BM_HsrSoup(benchmark::State& state) {
  run(state, soup(static_cast<std::size_t>(state.range(0))), oblique());
}

BENCHMARK(BM_HsrCubesOrtho)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HsrCubesPerspective)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HsrSoup)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace shadowgen::bench

BENCHMARK_MAIN();
