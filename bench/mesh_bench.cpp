// Exact against Embree on real meshes: shadowgen's generate_shadows next to its own rays
// estimator (shadowgen/sampled/estimate.h: Intel Embree 3 casting 1024 stratified shadow
// rays per face), one core each, on the same scenes in the same run.
//
//   BM_Exact/mesh/light    generate_shadows, GenerateOptions::threads = 1, the one light;
//   BM_Embree/mesh/light   the rays estimator (Method rays 1024: 32 rows of 32 strata per
//                          face), one rtcOccluded1 per ray, on one thread, estimator and
//                          hierarchy made inside the timing (bench/estimate_one_thread.h);
//   BM_Embree16/mesh/light the same rays in packets of 16 (rtcOccluded16, the width Embree
//                          traverses natively on an AVX-512 CPU; 8 or 4 elsewhere,
//                          shadowgen/sampled/ray_caster.h): the same answers, the faster way
//                          to ask, and what the product casts.
//
// Meshes (kMeshes below): files of Debian's assimp-testmodels and of the CGAL data shipped
// by libcgal-demo (extracted by bench/CMakeLists.txt), each of 1k to 4k faces, standing
// above a ground (bench/scenes/mesh_on_ground.h). light 0: the sun; light 1: the lamp.
//
// Counters. BM_Exact: faces = the mesh's faces (the ground is one more); partly = the
// share of the faces facing the light that the exact result lights partly (lit fraction
// strictly between 1e-9 and 1 − 1e-9). BM_Embree and BM_Embree16, against the exact lit
// areas (computed once per scene and light outside the timing, checked to lie in
// [0, face area]): frac_err_mean and frac_err_max = mean and largest |estimated − exact
// lit fraction| over the faces of non-zero area facing the light (the others are unlit
// by both); area_err = Σ_faces |estimated − exact lit area| / Σ face areas.
//
// --worst=MESH:LIGHT: where Embree is furthest from the exact result (print_worst below).
//
// Run with --benchmark_repetitions=3 --benchmark_report_aggregates_only=true and read
// the medians (bench/run_mesh_bench.sh does).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_main.h"
#include "bench/estimate_one_thread.h"
#include "bench/exact_one_thread.h"
#include "bench/guarded.h"
#include "bench/once_per_case.h"
#include "bench/sampled/shadow_rays.h"
#include "bench/scenes/mesh_on_ground.h"
#include "bench/scenes/scene_lit_areas.h"
#include "hsr/polygon3.h"
#include "shadowgen/shadows/light_scope.h"

namespace shadowgen::bench {
namespace {

constexpr int kSamples = 1024;  // rays per face: 32 rows of 32 strata

struct MeshFile {
  const char* folder;  // SHADOWGEN_ASSIMP_MODELS or SHADOWGEN_CGAL_MESHES
  const char* file;
  UpAxis up;
};

const MeshFile kMeshes[] = {
    {SHADOWGEN_ASSIMP_MODELS, "OBJ/spider.obj", UpAxis::kY},
    {SHADOWGEN_ASSIMP_MODELS, "STL/Wuson.stl", UpAxis::kY},
    {SHADOWGEN_CGAL_MESHES, "anchor.off", UpAxis::kZ},
    {SHADOWGEN_CGAL_MESHES, "hand.off", UpAxis::kZ},
    {SHADOWGEN_CGAL_MESHES, "elk.off", UpAxis::kZ},
    {SHADOWGEN_CGAL_MESHES, "couplingdown.off", UpAxis::kZ},
};
constexpr int kMeshCount = static_cast<int>(std::size(kMeshes));

const Scene& scene_with_light(int mesh, int light) {
  return once_per_case(mesh, light, [&] {
    const MeshFile& m = kMeshes[mesh];
    Scene s = mesh_on_ground(std::filesystem::path(m.folder) / m.file, m.up);
    s.lights = {s.lights.at(static_cast<std::size_t>(light))};
    return s;
  });
}

struct Reference {
  LitAreas areas;
  std::vector<bool> facing;  // non-zero area, front side towards the light
};

const Reference& reference(int mesh, int light) {
  return once_per_case(mesh, light, [&] {
    const Scene& scene = scene_with_light(mesh, light);
    Reference ref{checked_lit_areas(exact_one_thread(scene).shadowed), {}};
    // The light's roles of every part (shadowgen/shadows/light_scope.h): a face faces the
    // light where one of its parts does.
    const ScenePartPlanes all(scene);
    const std::vector<PartRole> roles = part_roles(all.polygons, all.planes, scene.lights[0]);
    std::size_t part = 0;
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      bool facing = false;
      for (std::size_t k = 0; k < scene.faces[f].parts.size(); ++k, ++part) {
        facing = facing || roles[part] == PartRole::kFacing;
      }
      ref.facing.push_back(facing && ref.areas.face_area[f] > 0.0);
    }
    return ref;
  });
}

double lit_fraction(const Reference& ref, std::size_t f, double lit) {
  return lit / ref.areas.face_area[f];
}

void report_exact(benchmark::State& state, const Reference& ref) {
  const std::vector<double>& lit = ref.areas.lit[0];
  std::size_t facing = 0, partly = 0;
  for (std::size_t f = 0; f < lit.size(); ++f) {
    if (!ref.facing[f]) continue;
    ++facing;
    const double q = lit_fraction(ref, f, lit[f]);
    if (q > 1e-9 && q < 1.0 - 1e-9) ++partly;
  }
  state.counters["faces"] = static_cast<double>(lit.size() - 1);
  state.counters["partly"] =
      facing ? static_cast<double>(partly) / static_cast<double>(facing) : 0.0;
}

void report_error(benchmark::State& state, const Reference& ref, const std::vector<double>& lit) {
  const std::vector<double>& exact_lit = ref.areas.lit[0];
  if (lit.size() != exact_lit.size()) throw std::runtime_error("estimate per face missing");
  double area_err = 0.0, frac_sum = 0.0, frac_max = 0.0;
  std::size_t facing = 0;
  for (std::size_t f = 0; f < lit.size(); ++f) {
    if (!(lit[f] >= 0.0 && lit[f] <= ref.areas.face_area[f] * (1.0 + 1e-9))) {
      throw std::runtime_error("estimated lit area outside [0, face area]");
    }
    area_err += std::fabs(lit[f] - exact_lit[f]);
    if (!ref.facing[f]) continue;
    ++facing;
    const double e = std::fabs(lit_fraction(ref, f, lit[f]) - lit_fraction(ref, f, exact_lit[f]));
    frac_sum += e;
    frac_max = std::max(frac_max, e);
  }
  state.counters["frac_err_mean"] = facing ? frac_sum / static_cast<double>(facing) : 0.0;
  state.counters["frac_err_max"] = frac_max;
  state.counters["area_err"] = area_err / ref.areas.total_area;
}

int arg(const benchmark::State& state, int i) { return static_cast<int>(state.range(i)); }

void BM_Exact(benchmark::State& state) {
  guarded(state, [&] {
    const Scene& scene = scene_with_light(arg(state, 0), arg(state, 1));
    const Reference& ref = reference(arg(state, 0), arg(state, 1));
    timed_exact_one_thread(state, scene);
    report_exact(state, ref);
    state.SetLabel(kMeshes[arg(state, 0)].file);
  });
}

void time_embree(benchmark::State& state, sampled::Casting casting) {
  guarded(state, [&] {
    const Scene& scene = scene_with_light(arg(state, 0), arg(state, 1));
    const Reference& ref = reference(arg(state, 0), arg(state, 1));
    std::vector<double> lit;
    for (auto _ : state) {
      lit = estimate_one_thread(scene, {MethodKind::kRays, kSamples, 0}, casting);
      benchmark::DoNotOptimize(lit.data());
    }
    report_error(state, ref, lit);
  });
}

void BM_Embree(benchmark::State& state) { time_embree(state, sampled::Casting::kOneByOne); }
void BM_Embree16(benchmark::State& state) { time_embree(state, sampled::Casting::kPackets); }

// --worst=MESH:LIGHT prints the ten faces facing the light whose lit fraction Embree
// gets furthest from the exact one, with a third opinion: double-precision shadow rays from
// the same sample points (bench/sampled/shadow_rays.h), which share neither Embree's
// single precision and origin offset nor the exact generator's clipping.
int print_worst(const std::string& spec) {
  const int mesh = std::stoi(spec), light = std::stoi(spec.substr(spec.find(':') + 1));
  const Scene& scene = scene_with_light(mesh, light);
  const Reference& ref = reference(mesh, light);
  const std::vector<double> embree = estimate_one_thread(scene, {MethodKind::kRays, kSamples, 0});
  auto fraction = [&](const std::vector<double>& lit, std::size_t f) {
    return lit_fraction(ref, f, lit[f]);
  };
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < embree.size(); ++f) {
    if (ref.facing[f]) faces.push_back(f);
  }
  auto error = [&](std::size_t f) {
    return std::fabs(fraction(embree, f) - fraction(ref.areas.lit[0], f));
  };
  std::sort(faces.begin(), faces.end(),
            [&](std::size_t a, std::size_t b) { return error(a) > error(b); });
  faces.resize(std::min<std::size_t>(faces.size(), 10));
  const std::vector<double> rays = double_ray_lit_areas(scene, scene.lights[0], faces, kSamples);
  std::printf("face, area, lit fraction: exact, Embree, double-precision rays\n");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const std::size_t f = faces[i];
    std::printf("%s %.3e %.4f %.4f %.4f\n", scene.faces[f].id.c_str(), ref.areas.face_area[f],
                fraction(ref.areas.lit[0], f), fraction(embree, f), lit_fraction(ref, f, rays[i]));
  }
  return 0;
}

void mesh_light_args(benchmark::internal::Benchmark* b) {
  for (int mesh = 0; mesh < kMeshCount; ++mesh) {
    for (int light : {0, 1}) b->Args({mesh, light});
  }
  b->Iterations(1)->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_Exact)->Apply(mesh_light_args);
BENCHMARK(BM_Embree)->Apply(mesh_light_args);
BENCHMARK(BM_Embree16)->Apply(mesh_light_args);

}  // namespace
}  // namespace shadowgen::bench

int main(int argc, char** argv) {
  return shadowgen::bench::main_with_mode(argc, argv, "worst", shadowgen::bench::print_worst);
}
