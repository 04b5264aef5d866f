// Shadow generation (shadowgen::generate_shadows) at scale, one light at a time, on one
// thread (GenerateOptions::threads = 1) unless a workload names its threads. Workloads:
//
//   BM_CitySun/faces/threads,             the procedural city (bench/scenes/city.h) of
//   BM_CityLamp/faces/threads             about 1e3, 1e4 and 1e5 faces with only its sun
//                                         or only its street lamp (range 4 lots), on 1
//                                         thread and (1e4, 1e5) on 2: one light's image
//                                         regions in parallel (hsr/image_regions.h);
//   BM_CubesSun, BM_CubesLamp             Thakur, Cheng and Miura's 2000 cubes (a 20 × 10
//                                         × 10 grid) half a cell above a tiled ground
//                                         (bench/scenes/cube_grid.h).
//
// What is timed: one generate_shadows call (copy of the scene into the result, flattening,
// coplanar groups, the light's views, hidden-surface removal, back-projection and merge
// of the lit details). Counters: light_s (LightStats::seconds: the light's own work, not
// the copy or the flattening), faces, considered (faces within range), frusta,
// fragments, detail_polygons (lit detail polygons), lit_fraction (lit area / total
// area). Every lit area is checked to lie in [0, face area] and some must be lit, or the
// benchmark is skipped with an error.
//
// Peak memory is measured per workload in a process of its own:
//   shadow_bench --peak-rss=city:100000:sun   (or city:N:lamp, cubes:2000:sun, ...)
// builds the scene, runs generate_shadows once and prints ru_maxrss (kB) before and after.
//
// Run with --benchmark_repetitions=5 --benchmark_report_aggregates_only=true and read
// the medians (bench/run_shadow_bench.sh does).

#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "bench/bench_main.h"
#include "bench/scenes/city.h"
#include "bench/scenes/cube_grid.h"
#include "bench/scenes/scene_lit_areas.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::bench {
namespace {

enum LightIndex { kSun = 0, kLamp = 1 };  // the order city_scene and cubes_on_ground use

Scene with_one_light(Scene scene, int light) {
  scene.lights = {scene.lights.at(static_cast<std::size_t>(light))};
  return scene;
}

const Scene& city(std::size_t faces, int light) {
  static std::map<std::pair<std::size_t, int>, Scene> cache;
  auto it = cache.find({faces, light});
  if (it == cache.end()) {
    Scene s = city_scene({city_lots_for_faces(faces), 20.0, 1});
    it = cache.emplace(std::pair{faces, light}, with_one_light(std::move(s), light)).first;
  }
  return it->second;
}

const Scene& cubes(int light) {
  static std::map<int, Scene> cache;
  auto it = cache.find(light);
  if (it == cache.end()) {
    it = cache.emplace(light, with_one_light(cubes_on_ground({20, 10, 10, 0.0}), light)).first;
  }
  return it->second;
}

GenerateResult generate(const Scene& scene, unsigned threads) {
  GenerateOptions options;
  options.threads = threads;
  return generate_shadows(scene, options);
}

void run(benchmark::State& state, const Scene& scene, unsigned threads = 1) {
  try {
    GenerateResult result;
    for (auto _ : state) {
      result = generate(scene, threads);
      benchmark::DoNotOptimize(result.shadowed.lit());
    }
    const LitAreas areas = checked_lit_areas(result.shadowed);
    double lit = 0.0;
    for (double a : areas.lit[0]) lit += a;
    if (!(lit > 0.0)) throw std::runtime_error("nothing lit");
    const LightStats& s = result.stats.at(0);
    state.counters["light_s"] = s.seconds;
    state.counters["faces"] = static_cast<double>(scene.faces.size());
    state.counters["considered"] = static_cast<double>(s.faces_considered);
    state.counters["frusta"] = static_cast<double>(s.frusta);
    state.counters["fragments"] = static_cast<double>(s.fragments);
    state.counters["detail_polygons"] = static_cast<double>(s.lit_polygons);
    state.counters["lit_fraction"] = lit / areas.total_area;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

std::size_t faces(const benchmark::State& state) {
  return static_cast<std::size_t>(state.range(0));
}

unsigned threads(const benchmark::State& state) { return static_cast<unsigned>(state.range(1)); }

void BM_CitySun(benchmark::State& state) { run(state, city(faces(state), kSun), threads(state)); }
void BM_CityLamp(benchmark::State& state) { run(state, city(faces(state), kLamp), threads(state)); }
void BM_CubesSun(benchmark::State& state) { run(state, cubes(kSun)); }
void BM_CubesLamp(benchmark::State& state) { run(state, cubes(kLamp)); }

// Each iteration takes from milliseconds to a minute: one iteration per repetition.
BENCHMARK(BM_CitySun)
    ->ArgsProduct({{1000}, {1}})
    ->ArgsProduct({{10000, 100000}, {1, 2}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_CityLamp)
    ->ArgsProduct({{1000}, {1}})
    ->ArgsProduct({{10000, 100000}, {1, 2}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_CubesSun)->Arg(2000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_CubesLamp)->Arg(2000)->Iterations(1)->Unit(benchmark::kSecond);

long max_rss_kb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

// --peak-rss=WORKLOAD:SIZE:LIGHT, WORKLOAD city or cubes, LIGHT sun or lamp.
int peak_rss(const std::string& spec) {
  char workload[16] = {}, light_name[16] = {};
  std::size_t size = 0;
  if (std::sscanf(spec.c_str(), "%15[a-z]:%zu:%15[a-z]", workload, &size, light_name) != 3) {
    std::fprintf(stderr, "bad --peak-rss=%s\n", spec.c_str());
    return 2;
  }
  const int light = std::strcmp(light_name, "lamp") == 0 ? kLamp : kSun;
  const Scene& scene = std::strcmp(workload, "cubes") == 0 ? cubes(light) : city(size, light);
  const long before = max_rss_kb();
  const GenerateResult result = generate(scene, 1);
  checked_lit_areas(result.shadowed);
  std::printf("%s faces %zu light %s: scene built %ld kB, peak %ld kB, light_s %.3f\n", workload,
              scene.faces.size(), light_name, before, max_rss_kb(), result.stats.at(0).seconds);
  return 0;
}

}  // namespace
}  // namespace shadowgen::bench

int main(int argc, char** argv) {
  return shadowgen::bench::main_with_mode(argc, argv, "peak-rss", shadowgen::bench::peak_rss);
}
