#include "bench/scenes/cube_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bench/scenes/box.h"

namespace shadowgen::bench {
namespace {

double spacing(const CubeGridSpec& spec) { return 1.0 / std::max({spec.nx, spec.ny, spec.nz}); }

}  // namespace

std::vector<hsr::Polygon3> cube_grid(const CubeGridSpec& spec) {
  const double s = spacing(spec);
  std::vector<hsr::Polygon3> faces;
  faces.reserve(static_cast<std::size_t>(spec.nx * spec.ny * spec.nz) * 6);
  for (int i = 0; i < spec.nx; ++i) {
    for (int j = 0; j < spec.ny; ++j) {
      for (int k = 0; k < spec.nz; ++k) {
        const glm::dvec3 lo((i + 0.25) * s, (j + 0.25) * s, (k + 0.25) * s + spec.lift);
        for (hsr::Polygon3& p : box_faces(lo, lo + glm::dvec3(0.5 * s), true)) {
          faces.push_back(std::move(p));
        }
      }
    }
  }
  return faces;
}

Scene cubes_on_ground(const CubeGridSpec& spec) {
  const double s = spacing(spec);
  CubeGridSpec lifted = spec;
  lifted.lift = 0.5 * s;
  Scene scene;
  std::size_t k = 0;
  for (hsr::Polygon3& p : cube_grid(lifted)) {
    scene.faces.push_back(
        {"cube" + std::to_string(k / 6) + "/" + std::to_string(k % 6), {std::move(p)}, ""});
    ++k;
  }
  // Ground tiles of about one cell, reaching one grid height beyond the grid.
  const double height = spec.nz * s + lifted.lift;
  const double x0 = -height, x1 = spec.nx * s + height;
  const double y0 = -height, y1 = spec.ny * s + height;
  const int tx = static_cast<int>(std::ceil((x1 - x0) / s));
  const int ty = static_cast<int>(std::ceil((y1 - y0) / s));
  for (int i = 0; i < tx; ++i) {
    for (int j = 0; j < ty; ++j) {
      const double a = x0 + (x1 - x0) * i / tx, b = x0 + (x1 - x0) * (i + 1) / tx;
      const double c = y0 + (y1 - y0) * j / ty, d = y0 + (y1 - y0) * (j + 1) / ty;
      scene.faces.push_back(
          {"ground" + std::to_string(i) + "_" + std::to_string(j),
           {hsr::Polygon3{{{a, c, 0.0}, {b, c, 0.0}, {b, d, 0.0}, {a, d, 0.0}}, {}}},
           ""});
    }
  }

  scene.lights.push_back(sun_at(45, 30));

  // In the gap between the cubes of the cells just below and left of the grid's centre:
  // cell boundaries are gaps (cubes fill only the middle half of each cell).
  Light lamp;
  lamp.id = "lamp";
  lamp.type = LightType::kPoint;
  lamp.position = {std::floor(0.5 * spec.nx) * s, std::floor(0.5 * spec.ny) * s + 0.1 * s,
                   std::floor(0.5 * spec.nz) * s + lifted.lift + 0.2 * s};
  lamp.range = LightRange{0.0, 0.5 * std::max(spec.nx, spec.ny) * s, 2.0};
  scene.lights.push_back(lamp);
  return scene;
}

}  // namespace shadowgen::bench
