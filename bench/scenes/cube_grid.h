#pragma once

// Benchmark scene: the cube grid of Thakur, Cheng and Miura's scalability simulation
// ("Discretized shadow volume with angular lookup", section 9): nx·ny·nz equal cubes on
// a regular grid in a box of fixed size, so that the cubes shrink as their number grows
// and never intersect. Here each cube's side is half its cell's (spacing s = 1 / the
// largest count, side s/2, cube centred in its cell); the box is [0, nx·s] × [0, ny·s]
// × [0, nz·s] plus `lift` in z. Every cube has 6 faces, normals outward.

#include <vector>

#include "hsr/polygon3.h"
#include "shadowgen/model/scene.h"

namespace shadowgen::bench {

struct CubeGridSpec {
  int nx = 5, ny = 5, nz = 5;
  double lift = 0.0;  // added to every z
};

// The cubes' faces, 6 per cube, cube by cube in x-major order.
std::vector<hsr::Polygon3> cube_grid(const CubeGridSpec& spec);

// The grid lifted half a cell above a ground (a grid of square tiles on z = 0 reaching
// one grid height beyond the grid on every side, tiles of about one cell), with two
// lights: "sun" (directional, elevation 45°, azimuth 30°) and "lamp" (a point light in
// the gap between cubes near the grid's centre, range end half the grid's width). The
// scene of "a scene containing 2000 cubes" is cubes_on_ground({20, 10, 10}).
Scene cubes_on_ground(const CubeGridSpec& spec);

}  // namespace shadowgen::bench
