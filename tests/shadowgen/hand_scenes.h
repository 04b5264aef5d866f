#pragma once

// Small scenes written by hand whose shadows are known exactly, shared by the tests of
// what is built on a shadowed scene (light regions, OBJ export, render, sun-hours maps),
// and `generated`, which makes a scene's database from its JSON.

#include <string>
#include <utility>

#include "shadowgen/scene/scene_reader.h"
#include "shadowgen/shadows/generate.h"

namespace shadowgen::test {

// The shadowed scene of `json` (read as "test.json"); threads as in GenerateOptions, 0 one
// per hardware thread.
inline ShadowedScene generated(const std::string& json, unsigned threads = 0) {
  GenerateOptions options;
  options.threads = threads;
  return generate_shadows(parse_scene(json, "test.json").scene, options).shadowed;
}

// Ground 10 × 10 at z = 0, a 4 × 4 square at z = 1 over [2,6] × [3,7]. Light "down" casts
// its shadow straight below, light "slant" travels +x as it falls, so its shadow is the
// square moved by 1 in x: [3,7] × [3,7].
inline constexpr const char* kTwoLights = R"({
  "format": "shadowgen-scene/1",
  "polygons": [
    {"id": "ground", "outer": [[0,0,0],[10,0,0],[10,10,0],[0,10,0]]},
    {"id": "square", "outer": [[2,3,1],[6,3,1],[6,7,1],[2,7,1]]}
  ],
  "lights": [
    {"id": "down", "type": "directional", "direction": [0,0,-1]},
    {"id": "slant", "type": "directional", "direction": [1,0,-1]}
  ]
})";

// A 36 × 36 ground under 144 square slabs of 1.2 × 1.1 at z = 2, a grid of 12 × 12 at
// generic offsets, and a sun that casts each slab's shadow whole onto the ground: the
// ground's lit polygon is one outer loop with 144 holes, over 600 vertices, more than a region
// is triangulated or clipped whole (hsr/chart_triangles.h, the picture's region tiles).
inline std::string ground_under_slabs() {
  std::string polygons = R"({"id": "ground", "outer": [[0,0,0],[36,0,0],[36,36,0],[0,36,0]]})";
  for (int i = 0; i < 12; ++i) {
    for (int j = 0; j < 12; ++j) {
      const double x = 3.0 * i + 0.8 + 0.01 * j, y = 3.0 * j + 0.7 + 0.013 * i;
      const std::string id = "slab" + std::to_string(i) + "_" + std::to_string(j);
      auto corner = [](double cx, double cy) {
        return "[" + std::to_string(cx) + "," + std::to_string(cy) + ",2]";
      };
      polygons += R"(, {"id": ")" + id + R"(", "outer": [)" + corner(x, y) + "," +
                  corner(x + 1.2, y) + "," + corner(x + 1.2, y + 1.1) + "," + corner(x, y + 1.1) +
                  "]}";
    }
  }
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons +
         R"(], "lights": [{"id": "sun", "type": "directional", "direction": [0.3, 0.2, -1]}]})";
}

// A dart (its only diagonal runs from the reflex vertex (1,2) to (4,2)) with the reflex
// vertex raised to z = 1: a non-planar face of two triangles, each of area sqrt(14), one
// over y ∈ [0,2], one over y ∈ [2,4]. The sun straight down past a roof over y ∈ [3,5]
// shades the half-size tip of the second: 1/4 of its area.
inline constexpr const char* kDartUnderRoof = R"({
    "format": "shadowgen-scene/1",
    "polygons": [
      {"id": "dart", "outer": [[0,0,0],[4,2,0],[0,4,0],[1,2,1]]},
      {"id": "roof", "outer": [[-1,3,5],[5,3,5],[5,5,5],[-1,5,5]]}
    ],
    "lights": [{"id": "sun", "type": "directional", "direction": [0,0,-1]}]
  })";

// A scene of `polygons` (JSON objects, comma-separated) at London (51.5° N, 0.1° W, UT)
// under one `sun` light "day" whose span is `path` (its "from", "to" and "step_min").
inline std::string site_scene(const std::string& polygons, const std::string& path) {
  return R"({"format": "shadowgen-scene/1", "polygons": [)" + polygons +
         R"(], "site": {"latitude_deg": 51.5, "longitude_deg": -0.1, "utc_offset_h": 0},
         "lights": [{"id": "day", "type": "sun", )" +
         path + "}]}";
}

// A courtyard: ground 20 × 20, a block 6 × 4 × 5 on it, a free-standing wall.
inline const std::string kCourtyard = R"(
  {"id": "ground", "outer": [[-10,-10,0],[10,-10,0],[10,10,0],[-10,10,0]]},
  {"id": "roof", "outer": [[-3,0,5],[3,0,5],[3,4,5],[-3,4,5]]},
  {"id": "south", "outer": [[-3,0,0],[3,0,0],[3,0,5],[-3,0,5]]},
  {"id": "east", "outer": [[3,0,0],[3,4,0],[3,4,5],[3,0,5]]},
  {"id": "north", "outer": [[3,4,0],[-3,4,0],[-3,4,5],[3,4,5]]},
  {"id": "west", "outer": [[-3,4,0],[-3,0,0],[-3,0,5],[-3,4,5]]},
  {"id": "wall", "outer": [[-8,-6,0],[-8,-2,0],[-8,-2,2],[-8,-6,2]]})";

// The span of 21 March from 06:00 to 18:00 every 30 minutes, for site_scene.
inline const std::string kMarch21 =
    R"("from": "2026-03-21T06:00", "to": "2026-03-21T18:00", "step_min": 30)";

// A sun path's sums made by hand, read from "test.json": face "g", 4 × 1 in z = 0, and path
// "p" of four 30-minute instants (lights p@0 ... p@3, no lit polygons kept): [0,1] × [0,1]
// lit at none, [1,3] at three (1.5 h, in two pieces), [3,4] at four (2 h).
inline hsr::Polygon3 unit_strip(double x0, double x1) {
  return {{{x0, 0, 0}, {x1, 0, 0}, {x1, 1, 0}, {x0, 1, 0}}, {}};
}
inline ShadowedScene sun_path_by_hand() {
  Scene scene;
  scene.file = "test.json";
  scene.faces.push_back({"g", {unit_strip(0, 4)}, "test.json"});
  for (int k = 0; k < 4; ++k) {
    Light light;
    light.id = "p@" + std::to_string(k);
    light.sun = SunInstant{"p", "2026-03-21T1" + std::to_string(k) + ":00", 30, 180.0, 30.0};
    scene.lights.push_back(light);
  }
  // instants: lit areas alone
  ShadowedScene shadowed(std::move(scene), LitTable(1, 4, std::vector<bool>(4, false)));
  SunPathHours path;
  path.id = "p";
  path.step_min = 30;
  path.from = "2026-03-21T10:00";
  path.to = "2026-03-21T13:00";
  path.instants = {0, 1, 2, 3};
  path.lit_area = {{3, 3, 3, 1}};
  path.part_lit_area = {{}};
  path.regions = {{{0.0, {{0, unit_strip(0, 1)}}},
                   {1.5, {{0, unit_strip(1, 2)}, {0, unit_strip(2, 3)}}},
                   {2.0, {{0, unit_strip(3, 4)}}}}};
  shadowed.sun_paths.push_back(path);
  return shadowed;
}

}  // namespace shadowgen::test
