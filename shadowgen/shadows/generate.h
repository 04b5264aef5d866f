#pragma once

// Shadow generation (Atherton, Weiler and Greenberg 1978, section IV): hidden-surface
// removal from every light; what a light sees becomes lit detail polygons on their parent
// faces, in 3D, in the scene's own coordinates.
//
// Per light:
//   - directional: one orthographic light view along the light's direction, centred on
//     the scene (the paper's "fitting the environment into the viewbox");
//   - point: up to six 90-degree perspective frusta around the light (cube-map style),
//     only those that see part of the scene, so a light may stand anywhere, inside the
//     scene included;
//   - faces wholly beyond range.end are left out entirely; faces turned away from the
//     light (or seeing it edge-on) get no lit area but still occlude.
// The visible fragments are mapped back onto their parent face's plane and merged per
// (face, light). Lights are independent and run in parallel.
//
// Coplanar faces do not shadow each other (the spec's meaning of "lit"): where hidden-
// surface removal gives an overlap of exactly coplanar faces to one of them, the lit
// region of each is its own area within the visible region of the plane they share.

#include <cstddef>
#include <functional>
#include <vector>

#include "shadowgen/model/scene.h"
#include "shadowgen/model/shadowed_scene.h"

namespace shadowgen {

struct LightStats {
  std::size_t faces_considered = 0;  // within range
  std::size_t faces_culled_range = 0;
  std::size_t faces_facing_away = 0;
  std::size_t faces_grazed = 0;  // lit regions worked out in their plane (grazing_light.h)
  std::size_t frusta = 0;        // light views used (1 for directional lights)
  std::size_t fragments = 0;
  std::size_t lit_polygons = 0;
  double seconds = 0.0;
};

struct GenerateOptions {
  unsigned threads = 0;  // 0: one per hardware thread
  // Called after each light is done (from the worker that finished it); for progress.
  std::function<void(std::size_t light, const LightStats&)> on_light_done;
};

struct GenerateResult {
  ShadowedScene shadowed;
  std::vector<LightStats> stats;  // per light
};

GenerateResult generate_shadows(const Scene& scene, const GenerateOptions& options = {});

}  // namespace shadowgen
