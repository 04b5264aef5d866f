#pragma once

// Small scenes written by hand whose shadows are known exactly, shared by the tests of
// what is built on a shadowed scene (light regions, OBJ export, render), and `generated`,
// which makes a scene's database from its JSON.

#include <string>

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

}  // namespace shadowgen::test
