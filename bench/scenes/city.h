#pragma once

// Benchmark scene: a procedural city. A square grid of lots, each a ground tile (a
// square of side `lot` on the plane z = 0, normal up) carrying one box building (four
// walls and a flat roof, normals outward; no floor, which would lie on the ground tile
// and face away from every light above it). Footprints are random rectangles of 40 to
// 80 % of the lot's side, placed at random within the lot, so streets of varying width
// run between them; heights are log-uniform between 6 and 60 (metres, say). Every
// lot has a building: lots² · 6 faces in all.
//
// Lights, in this order:
//   "sun":  directional, elevation 40°, azimuth 30° off the grid's axes, so every wall
//           and roof edge casts an oblique shadow;
//   "lamp": a point light 6 above the street corner nearest the city's centre (a
//           street lamp inside the city), range end 4 lots, so its cost is bounded
//           whatever the size of the city.

#include <cstddef>
#include <cstdint>

#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

struct CitySpec {
  int lots_per_side = 13;
  double lot = 20.0;
  std::uint64_t seed = 1;
};

Scene city_scene(const CitySpec& spec);

// Lots per side giving about `faces` faces (6 per lot): 13 -> 1014, 41 -> 10086,
// 129 -> 99846.
int city_lots_for_faces(std::size_t faces);

}  // namespace shadowgen::bench
