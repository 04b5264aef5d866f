// The accuracy ladder (docs/architecture.md): time against lit-area error,
// shadowgen's exact result next to its two sampled estimators (shadowgen/sampled/estimate.h)
// with a resolution knob, on the same scenes and lights, in one run.
//
//   BM_Exact/scene/light            generate_shadows, one thread, the one light;
//   BM_ShadowMap/scene/light/N/k    the shadow-map estimator (Method shadow-map k² @ N): maps
//                                   of N × N texels (a cube of six for the lamp), k × k
//                                   = k² stratified samples per face;
//   BM_ShadowRays/scene/light/k     the rays estimator (Method rays k²): an Embree shadow ray
//                                   per sample, k² samples per face, in packets.
//
// scene 0: the procedural city of about 1e3 faces (bench/scenes/city.h, 1014 faces);
// scene 1: Thakur, Cheng and Miura's 2000 cubes on a tiled ground (bench/scenes/cube_grid.h,
// 13271 faces). light 0: the scene's sun; light 1: its point light with a range.
//
// Timed: the whole estimate from the scene on one thread (bench/estimate_one_thread.h:
// estimator made, parts triangulated, maps or hierarchy built, samples placed and tested). Counter
// lit_area_err = Σ_faces |estimated lit area − exact lit area| / Σ face areas, the exact lit areas
// from generate_shadows (checked to lie in [0, face area]), computed once per scene and light
// outside the timing; samples = sample points tested.
//
// Run with --benchmark_repetitions=3 --benchmark_report_aggregates_only=true and read
// the medians (bench/run_sampled_bench.sh does).

#include <benchmark/benchmark.h>

#include <cmath>
#include <stdexcept>

#include "bench/estimate_one_thread.h"
#include "bench/exact_one_thread.h"
#include "bench/guarded.h"
#include "bench/once_per_case.h"
#include "bench/scenes/city.h"
#include "bench/scenes/cube_grid.h"
#include "bench/scenes/scene_lit_areas.h"

namespace shadowgen::bench {
namespace {

const Scene& scene_with_light(int scene, int light) {
  return once_per_case(scene, light, [&] {
    Scene s = scene == 0 ? city_scene({city_lots_for_faces(1000), 20.0, 1})
                         : cubes_on_ground({20, 10, 10, 0.0});
    s.lights = {s.lights.at(static_cast<std::size_t>(light))};
    return s;
  });
}

const LitAreas& reference(int scene, int light) {
  return once_per_case(scene, light, [&] {
    LitAreas areas = checked_lit_areas(exact_one_thread(scene_with_light(scene, light)).shadowed);
    double lit = 0.0;
    for (double a : areas.lit[0]) lit += a;
    if (!(lit > 0.0)) throw std::runtime_error("exact result: nothing lit");
    return areas;
  });
}

void report_error(benchmark::State& state, const LitAreas& ref, const std::vector<double>& lit) {
  if (lit.size() != ref.face_area.size()) throw std::runtime_error("estimate per face missing");
  double err = 0.0, lit_sum = 0.0;
  for (std::size_t f = 0; f < lit.size(); ++f) {
    if (!(lit[f] >= 0.0 && lit[f] <= ref.face_area[f] * (1.0 + 1e-9))) {
      throw std::runtime_error("estimated lit area outside [0, face area]");
    }
    err += std::fabs(lit[f] - ref.lit[0][f]);
    lit_sum += lit[f];
  }
  state.counters["lit_area_err"] = err / ref.total_area;
  state.counters["lit_fraction"] = lit_sum / ref.total_area;
}

int arg(const benchmark::State& state, int i) { return static_cast<int>(state.range(i)); }

void BM_Exact(benchmark::State& state) {
  guarded(state, [&] {
    const Scene& scene = scene_with_light(arg(state, 0), arg(state, 1));
    const LitAreas& ref = reference(arg(state, 0), arg(state, 1));
    const GenerateResult result = timed_exact_one_thread(state, scene);
    report_error(state, ref, checked_lit_areas(result.shadowed).lit[0]);
  });
}

void BM_ShadowMap(benchmark::State& state) {
  guarded(state, [&] {
    const Scene& scene = scene_with_light(arg(state, 0), arg(state, 1));
    const LitAreas& ref = reference(arg(state, 0), arg(state, 1));
    std::vector<double> lit;
    for (auto _ : state) {
      const int k = arg(state, 3);
      lit = estimate_one_thread(scene, {MethodKind::kShadowMap, k * k, arg(state, 2)});
      benchmark::DoNotOptimize(lit.data());
    }
    report_error(state, ref, lit);
  });
}

void BM_ShadowRays(benchmark::State& state) {
  guarded(state, [&] {
    const Scene& scene = scene_with_light(arg(state, 0), arg(state, 1));
    const LitAreas& ref = reference(arg(state, 0), arg(state, 1));
    std::vector<double> lit;
    for (auto _ : state) {
      const int k = arg(state, 2);
      lit = estimate_one_thread(scene, {MethodKind::kRays, k * k, 0});
      benchmark::DoNotOptimize(lit.data());
    }
    report_error(state, ref, lit);
  });
}

void exact_args(benchmark::internal::Benchmark* b) {
  for (int scene : {0, 1}) {
    for (int light : {0, 1}) b->Args({scene, light});
  }
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

void map_args(benchmark::internal::Benchmark* b) {
  for (int scene : {0, 1}) {
    for (int light : {0, 1}) {
      for (int n : {256, 1024, 4096}) {
        for (int k : {4, 16}) b->Args({scene, light, n, k});
      }
    }
  }
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

void ray_args(benchmark::internal::Benchmark* b) {
  for (int scene : {0, 1}) {
    for (int light : {0, 1}) {
      for (int k : {2, 4, 8, 16}) b->Args({scene, light, k});
    }
  }
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Exact)->Apply(exact_args);
BENCHMARK(BM_ShadowMap)->Apply(map_args);
BENCHMARK(BM_ShadowRays)->Apply(ray_args);

}  // namespace
}  // namespace shadowgen::bench

BENCHMARK_MAIN();
