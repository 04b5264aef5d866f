// The outputs of a shadowed database at scale, one thread: the OBJ export
// (shadowgen/output/obj_export.h) and a picture (shadowgen/view/render.h), each made from
// a database generated once beforehand (not timed). Workloads:
//
//   BM_CityExport/faces, BM_CityRender/faces   the procedural city (bench/scenes/city.h)
//                                        of about 1e3, 1e4 and 4e4 faces, its sun and lamp;
//   BM_SunsExport/suns, BM_SunsRender/suns     the city of about 2,000 faces under 10, 30
//                                        and 100 suns spread over a day's arc (elevations
//                                        20 to 60 degrees, azimuths over 180 degrees): how
//                                        the outputs grow with the number of lights;
//   BM_SunsExportByLight/suns,           the same export and picture in layers by light.
//   BM_SunsRenderByLight/suns
//   BM_CityExportGltf/faces,             the glTF export of the same regions
//   BM_SunsExportGltf/suns               (shadowgen/output/gltf_export.h), binary.
//
// The picture: 800 × 600, perspective, from above a corner of the city looking at its
// middle. Counters: faces, lights, obj_mb (the OBJ's size), glb_mb (the glTF's), pieces
// (the picture's).
//
// Run with --benchmark_repetitions=3 --benchmark_report_aggregates_only=true and read the
// medians.
//
// For timing the command line on the same databases:
//   output_bench --write-database=city:FACES:PATH   (or suns:COUNT:PATH, cubes:COUNT:PATH)
// writes the workload's database to PATH (shadowgen-shadowed/1) and exits;
// --write-database=cityscene:FACES:PATH writes the city as a scene under its sun, not
// generated (shadowgen-scene/1), for timing the command from end to end.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <glm/common.hpp>
#include <map>
#include <string>
#include <utility>

#include "bench/bench_main.h"
#include "bench/scenes/box.h"
#include "bench/scenes/city.h"
#include "bench/scenes/cube_grid.h"
#include "shadowgen/json/document.h"
#include "shadowgen/json/json_writer.h"
#include "shadowgen/output/atomic_file.h"
#include "shadowgen/output/database.h"
#include "shadowgen/output/gltf_export.h"
#include "shadowgen/output/obj_export.h"
#include "shadowgen/shadows/generate.h"
#include "shadowgen/view/camera.h"
#include "shadowgen/view/render.h"

namespace shadowgen::bench {
namespace {

ShadowedScene generated(Scene scene) {
  GenerateOptions options;
  options.threads = 1;
  return generate_shadows(scene, options).shadowed;
}

// The city of about `faces` faces with its own sun and lamp.
const ShadowedScene& city(std::size_t faces) {
  static std::map<std::size_t, ShadowedScene> cache;
  auto it = cache.find(faces);
  if (it == cache.end()) {
    it = cache.emplace(faces, generated(city_scene({city_lots_for_faces(faces), 20.0, 1}))).first;
  }
  return it->second;
}

// The city of about 2,000 faces under `suns` suns and nothing else.
const ShadowedScene& suns(int count) {
  static std::map<int, ShadowedScene> cache;
  auto it = cache.find(count);
  if (it == cache.end()) {
    Scene scene = city_scene({city_lots_for_faces(2000), 20.0, 1});
    scene.lights.clear();
    for (int k = 0; k < count; ++k) {
      const double t = count == 1 ? 0.5 : static_cast<double>(k) / (count - 1);
      Light sun = sun_at(20.0 + 40.0 * (1.0 - (2.0 * t - 1.0) * (2.0 * t - 1.0)), 180.0 * t);
      sun.id = "sun" + std::to_string(k);
      scene.lights.push_back(sun);
    }
    it = cache.emplace(count, generated(std::move(scene))).first;
  }
  return it->second;
}

Camera corner_camera(const Scene& scene) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Face& face : scene.faces) {
    for (const hsr::Polygon3& part : face.parts) {
      for (const glm::dvec3& p : part.outer) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
  }
  const glm::dvec3 middle = 0.5 * (lo + hi);
  const double size = hi.x - lo.x;
  Camera camera;
  camera.eye = {lo.x - 0.2 * size, lo.y - 0.3 * size, 0.6 * size};
  camera.target = {middle.x, middle.y, 0.0};
  camera.fov_deg = 50.0;
  return camera;
}

void counters(benchmark::State& state, const ShadowedScene& shadowed) {
  state.counters["faces"] = static_cast<double>(shadowed.scene().faces.size());
  state.counters["lights"] = static_cast<double>(shadowed.scene().lights.size());
}

void time_export(benchmark::State& state, const ShadowedScene& shadowed,
                 ObjFiles (*exporter)(const ShadowedScene&, std::string_view) = obj_export) {
  try {
    ObjFiles files;
    for (auto _ : state) {
      files = exporter(shadowed, "out.mtl");
      benchmark::DoNotOptimize(files.obj.data());
    }
    counters(state, shadowed);
    state.counters["obj_mb"] = static_cast<double>(files.obj.size()) / 1e6;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void time_gltf_export(benchmark::State& state, const ShadowedScene& shadowed) {
  try {
    std::string glb;
    for (auto _ : state) {
      glb = gltf_export(shadowed, GltfForm::kBinary);
      benchmark::DoNotOptimize(glb.data());
    }
    counters(state, shadowed);
    state.counters["glb_mb"] = static_cast<double>(glb.size()) / 1e6;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

void time_render(benchmark::State& state, const ShadowedScene& shadowed,
                 Picture (*renderer)(const ShadowedScene&, const Camera&,
                                     const RenderOptions&) = render) {
  try {
    const Camera camera = corner_camera(shadowed.scene());
    Picture picture;
    for (auto _ : state) {
      picture = renderer(shadowed, camera, RenderOptions{});
      benchmark::DoNotOptimize(picture.pieces.data());
    }
    counters(state, shadowed);
    state.counters["pieces"] = static_cast<double>(picture.pieces.size());
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

std::size_t arg(const benchmark::State& state) { return static_cast<std::size_t>(state.range(0)); }

void BM_CityExport(benchmark::State& state) { time_export(state, city(arg(state))); }
void BM_CityExportGltf(benchmark::State& state) { time_gltf_export(state, city(arg(state))); }
void BM_CityRender(benchmark::State& state) { time_render(state, city(arg(state))); }
void BM_SunsExport(benchmark::State& state) {
  time_export(state, suns(static_cast<int>(arg(state))));
}
void BM_SunsExportGltf(benchmark::State& state) {
  time_gltf_export(state, suns(static_cast<int>(arg(state))));
}
void BM_SunsExportByLight(benchmark::State& state) {
  time_export(state, suns(static_cast<int>(arg(state))), obj_export_by_light);
}
void BM_SunsRender(benchmark::State& state) {
  time_render(state, suns(static_cast<int>(arg(state))));
}
void BM_SunsRenderByLight(benchmark::State& state) {
  time_render(state, suns(static_cast<int>(arg(state))), render_by_light);
}

BENCHMARK(BM_CityExport)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(40000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_CityExportGltf)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(40000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_CityRender)
    ->Arg(1000)
    ->Arg(10000)
    ->Arg(40000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_SunsExport)->Arg(10)->Arg(30)->Arg(100)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_SunsExportGltf)->Arg(10)->Arg(30)->Arg(100)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_SunsExportByLight)
    ->Arg(10)
    ->Arg(30)
    ->Arg(100)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);
BENCHMARK(BM_SunsRender)->Arg(10)->Arg(30)->Arg(100)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_SunsRenderByLight)
    ->Arg(10)
    ->Arg(30)
    ->Arg(100)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The city of about `faces` faces as a scene under its sun alone, ungenerated: each face a
// polygon, its id's '/' turned to '.' (a polygon id has none), what `shadowgen report`
// and `generate` read end to end.
void write_city_scene(std::size_t faces, const std::string& path) {
  const Scene scene = city_scene({.lots_per_side = city_lots_for_faces(faces)});
  JsonWriter out;
  out.begin_object(JsonWriter::Layout::kLines).key("format").value(kSceneFormat);
  out.key("polygons").begin_array(JsonWriter::Layout::kLines);
  for (const Face& face : scene.faces) {
    for (std::size_t k = 0; k < face.parts.size(); ++k) {
      std::string id = face.id;
      if (face.parts.size() > 1) {  // appended piece by piece: g++ 12 warns falsely on "/" + ...
        id += '/';
        id += std::to_string(k);
      }
      std::replace(id.begin(), id.end(), '/', '.');
      out.begin_object().key("id").value(id).key("outer").begin_array();
      for (const glm::dvec3& p : face.parts[k].outer) out.value(p);
      out.end_array().key("holes").begin_array();
      for (const hsr::Loop3& hole : face.parts[k].holes) {
        out.begin_array();
        for (const glm::dvec3& p : hole) out.value(p);
        out.end_array();
      }
      out.end_array().end_object();
    }
  }
  out.end_array().key("lights").begin_array(JsonWriter::Layout::kLines);
  for (const Light& light : scene.lights) {
    if (light.id != "sun") continue;
    out.begin_object().key("id").value(light.id).key("type").value("directional");
    out.key("direction").value(light.direction).end_object();
  }
  out.end_array().end_object();
  write_file_atomically(path, out.take());
}

// --write-database=WORKLOAD:SIZE:PATH, WORKLOAD city (SIZE faces), suns (SIZE suns) or
// cubes (Thakur, Cheng and Miura's grid of SIZE cubes, 2n × n × n, on a ground, with its
// sun and lamp: bench/scenes/cube_grid.h); or cityscene, the city of SIZE faces as a scene
// under its sun alone (write_city_scene), not generated.
int write_workload(const std::string& spec) {
  char workload[16] = {};
  std::size_t size = 0;
  int path_at = 0;
  if (std::sscanf(spec.c_str(), "%15[a-z]:%zu:%n", workload, &size, &path_at) != 2 ||
      path_at == 0 ||
      (std::strcmp(workload, "city") != 0 && std::strcmp(workload, "suns") != 0 &&
       std::strcmp(workload, "cubes") != 0 && std::strcmp(workload, "cityscene") != 0)) {
    std::fprintf(stderr, "bad --write-database=%s\n", spec.c_str());
    return 2;
  }
  const std::string path = spec.substr(path_at);
  if (std::strcmp(workload, "cityscene") == 0) {
    write_city_scene(size, path);
    return 0;
  }
  if (std::strcmp(workload, "cubes") == 0) {
    const int n =
        std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(size) / 2.0))));
    write_database(generate_shadows(cubes_on_ground({2 * n, n, n})).shadowed, path);
    return 0;
  }
  const bool is_city = std::strcmp(workload, "city") == 0;
  write_database(is_city ? city(size) : suns(static_cast<int>(size)), path);
  return 0;
}

}  // namespace
}  // namespace shadowgen::bench

int main(int argc, char** argv) {
  return shadowgen::bench::main_with_mode(argc, argv, "write-database",
                                          shadowgen::bench::write_workload);
}
