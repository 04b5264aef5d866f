#include "tests/hsr/scenes.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <utility>

#include "tests/support/random_polygons.h"

namespace shadowgen::test {
namespace {

using glm::dvec3;
using hsr::Loop3;
using hsr::Polygon3;

double uniform(std::mt19937_64& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

dvec3 uniform_point(std::mt19937_64& rng, const dvec3& low, const dvec3& high) {
  return {uniform(rng, low.x, high.x), uniform(rng, low.y, high.y), uniform(rng, low.z, high.z)};
}

dvec3 random_unit(std::mt19937_64& rng) {
  for (;;) {
    const dvec3 p = uniform_point(rng, dvec3(-1.0), dvec3(1.0));
    const double length = glm::length(p);
    if (length > 0.1 && length <= 1.0) return p / length;
  }
}

// Two unit vectors completing `normal` (unit) to a right-handed orthonormal frame.
void complete_frame(const dvec3& normal, dvec3& u, dvec3& v) {
  const dvec3 a = glm::abs(normal);
  const dvec3 axis = a.x <= a.y && a.x <= a.z ? dvec3(1, 0, 0)
                     : a.y <= a.z             ? dvec3(0, 1, 0)
                                              : dvec3(0, 0, 1);
  u = glm::normalize(glm::cross(normal, axis));
  v = glm::cross(normal, u);
}

// c − s − t, c + s − t, c + s + t, c − s + t: counter-clockwise seen from cross(s, t).
Polygon3 rectangle(const dvec3& c, const dvec3& s, const dvec3& t) {
  return {{c - s - t, c + s - t, c + s + t, c - s + t}, {}};
}

Polygon3 reversed(Polygon3 polygon) {
  std::reverse(polygon.outer.begin(), polygon.outer.end());
  for (Loop3& hole : polygon.holes) std::reverse(hole.begin(), hole.end());
  return polygon;
}

// A box standing on z = z0: footprint centre (cx, cy), half sides hx, hy turned by
// `angle` about z, height h. Six faces, counter-clockwise seen from outside; the eight
// corners are computed once, so neighbouring faces share their vertices exactly.
void add_box(std::vector<Polygon3>& polygons, double cx, double cy, double z0, double hx, double hy,
             double h, double angle) {
  const dvec3 ex(std::cos(angle) * hx, std::sin(angle) * hx, 0.0);
  const dvec3 ey(-std::sin(angle) * hy, std::cos(angle) * hy, 0.0);
  dvec3 corner[8];
  for (int b = 0; b < 8; ++b) {
    const double si = (b & 1) != 0 ? 1.0 : -1.0;
    const double sj = (b & 2) != 0 ? 1.0 : -1.0;
    corner[b] =
        dvec3(cx + si * ex.x + sj * ey.x, cy + si * ex.y + sj * ey.y, (b & 4) != 0 ? z0 + h : z0);
  }
  constexpr int kFaces[6][4] = {{4, 5, 7, 6}, {0, 2, 3, 1}, {1, 3, 7, 5},
                                {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}};
  for (const auto& face : kFaces) {
    polygons.push_back({{corner[face[0]], corner[face[1]], corner[face[2]], corner[face[3]]}, {}});
  }
}

void add_random_boxes(std::vector<Polygon3>& polygons, std::mt19937_64& rng, int count, double z0,
                      double extent) {
  for (int i = 0; i < count; ++i) {
    const double cx = uniform(rng, -extent, extent);
    const double cy = uniform(rng, -extent, extent);
    add_box(polygons, cx, cy, z0, uniform(rng, 0.05, 0.25), uniform(rng, 0.05, 0.25),
            uniform(rng, 0.1, 0.6), uniform(rng, 0.0, std::numbers::pi));
  }
}

void add_triangles(std::vector<Polygon3>& polygons, std::mt19937_64& rng, int count,
                   const dvec3& low, const dvec3& high, double radius) {
  for (int i = 0; i < count; ++i) {
    const dvec3 c = uniform_point(rng, low, high);
    Loop3 loop;
    for (int k = 0; k < 3; ++k)
      loop.push_back(c + radius * uniform(rng, 0.3, 1.0) * random_unit(rng));
    polygons.push_back({std::move(loop), {}});
  }
}

Polygon3 ground(double half_side) {
  return {{{-half_side, -half_side, 0.0},
           {half_side, -half_side, 0.0},
           {half_side, half_side, 0.0},
           {-half_side, half_side, 0.0}},
          {}};
}

ViewSpec orthographic(const dvec3& direction, const dvec3& center = dvec3(0.0)) {
  ViewSpec spec;
  spec.perspective = false;
  spec.direction = direction;
  spec.point = center;
  return spec;
}

ViewSpec perspective(const dvec3& eye, const dvec3& forward, double fov_deg, double near) {
  ViewSpec spec;
  spec.perspective = true;
  spec.point = eye;
  spec.direction = forward;
  spec.up = dvec3(0.0, 0.0, 1.0);
  spec.fov_deg = fov_deg;
  spec.near = near;
  return spec;
}

// A direction looking down at the ground from at least ~17 degrees above the horizon.
dvec3 from_above(std::mt19937_64& rng) {
  const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  return {std::cos(angle), std::sin(angle), -uniform(rng, 0.3, 3.0)};
}

}  // namespace

hsr::View make_view(const ViewSpec& spec) {
  if (spec.perspective) {
    return hsr::View::perspective(spec.point, spec.direction, spec.up, spec.fov_deg, spec.near);
  }
  return hsr::View::orthographic(spec.direction, spec.point);
}

Scene placed(const Scene& scene, const Placement& placement) {
  auto move = [&placement](const dvec3& p) { return placement.offset + placement.scale * p; };
  Scene result = scene;
  for (Polygon3& polygon : result.polygons) {
    for (dvec3& p : polygon.outer) p = move(p);
    for (Loop3& hole : polygon.holes) {
      for (dvec3& p : hole) p = move(p);
    }
  }
  for (ViewSpec& view : result.views) {
    view.point = move(view.point);
    view.near *= placement.scale;
  }
  return result;
}

Scene triangle_soup(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  Scene scene{"triangle_soup", {}, {}};
  add_triangles(scene.polygons, rng, count, dvec3(-1.0), dvec3(1.0), 0.35);
  scene.views = {orthographic(random_unit(rng)), orthographic(random_unit(rng))};
  return scene;
}

Scene boxes_on_ground(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  Scene scene{"boxes_on_ground", {ground(1.5)}, {}};
  add_random_boxes(scene.polygons, rng, count, 0.0, 1.1);
  scene.views = {orthographic(from_above(rng)), orthographic(from_above(rng))};
  return scene;
}

Scene polygons_with_holes(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  Scene scene{"polygons_with_holes", {}, {}};
  for (int i = 0; i < count; ++i) {
    const clipper::PolygonWithHoles2 flat = random_polygon_with_holes(rng);
    const dvec3 c = uniform_point(rng, dvec3(-0.8), dvec3(0.8));
    dvec3 u, v;
    complete_frame(random_unit(rng), u, v);
    auto lift = [&](const clipper::Loop2& loop) {
      Loop3 out;
      for (const clipper::Point2& p : loop) out.push_back(c + 0.45 * p.x * u + 0.45 * p.y * v);
      return out;
    };
    Polygon3 polygon{lift(flat.outer), {}};
    for (const clipper::Loop2& hole : flat.holes) polygon.holes.push_back(lift(hole));
    scene.polygons.push_back(std::move(polygon));
  }
  scene.views = {orthographic(random_unit(rng)), orthographic(random_unit(rng))};
  return scene;
}

Scene cyclic_sticks(std::uint64_t seed, int triples) {
  std::mt19937_64 rng(seed);
  Scene scene{"cyclic_sticks", {}, {}};
  constexpr double kRadius = 0.8, kExtension = 0.35, kHalfWidth = 0.08, kRise = 0.5;
  for (int t = 0; t < triples; ++t) {
    const double turn = t == 0 ? 0.0 : uniform(rng, 0.0, 2.0 * std::numbers::pi);
    const dvec3 shift =
        t == 0 ? dvec3(0.0) : dvec3(uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3), 0.8 * t);
    dvec3 corner[3];
    for (int k = 0; k < 3; ++k) {
      const double angle = turn + std::numbers::pi / 2.0 + 2.0 * std::numbers::pi * k / 3.0;
      corner[k] = shift + dvec3(kRadius * std::cos(angle), kRadius * std::sin(angle), 0.0);
    }
    // Stick k runs from (beyond) corner k, high, to (beyond) corner k+1, low; there it
    // passes under stick k+1, which starts high.
    for (int k = 0; k < 3; ++k) {
      const dvec3 a = corner[k], b = corner[(k + 1) % 3];
      const dvec3 along = glm::normalize(b - a);
      const dvec3 across = kHalfWidth * dvec3(-along.y, along.x, 0.0);
      const dvec3 start = a - kExtension * along + dvec3(0.0, 0.0, kRise);
      const dvec3 end = b + kExtension * along;
      scene.polygons.push_back({{start - across, end - across, end + across, start + across}, {}});
    }
  }
  scene.views = {orthographic(dvec3(0.0, 0.0, -1.0)), orthographic(dvec3(0.15, -0.1, -1.0))};
  return scene;
}

Scene interpenetrating_quads(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  Scene scene{"interpenetrating_quads", {}, {}};
  for (int i = 0; i < count; ++i) {
    const dvec3 c = uniform_point(rng, dvec3(-0.4), dvec3(0.4));
    dvec3 u, v;
    complete_frame(random_unit(rng), u, v);
    const double turn = uniform(rng, 0.0, std::numbers::pi);
    const dvec3 s = std::cos(turn) * u + std::sin(turn) * v;
    const dvec3 t = -std::sin(turn) * u + std::cos(turn) * v;
    scene.polygons.push_back(rectangle(c, uniform(rng, 0.3, 0.7) * s, uniform(rng, 0.3, 0.7) * t));
  }
  scene.views = {orthographic(random_unit(rng)), orthographic(random_unit(rng))};
  return scene;
}

Scene near_plane_cut(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene scene{"near_plane_cut", {ground(1.5)}, {}};
  add_random_boxes(scene.polygons, rng, 6, 0.0, 1.1);
  add_triangles(scene.polygons, rng, 30, dvec3(-1.0, -1.0, 0.1), dvec3(1.0, 1.0, 1.0), 0.3);
  const double angle = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  scene.views = {
      perspective({0.1, -0.2, 0.35}, {std::cos(angle), std::sin(angle), -0.25}, 100.0, 0.3),
      perspective({0.0, 0.0, 0.5}, random_unit(rng), 90.0, 0.2),
      perspective({-1.0, -1.0, 0.3}, {1.0, 1.0, -0.2}, 70.0, 0.5),
  };
  return scene;
}

Scene inside_closed_box(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Scene scene{"inside_closed_box", {}, {}};
  add_box(scene.polygons, 0.0, 0.0, -1.0, 1.0, 1.0, 2.0, 0.0);
  for (Polygon3& wall : scene.polygons) wall = reversed(std::move(wall));
  add_random_boxes(scene.polygons, rng, 2, -1.0, 0.6);
  add_triangles(scene.polygons, rng, 8, dvec3(-0.8), dvec3(0.8), 0.3);
  const dvec3 eye(0.15, -0.1, 0.2);
  for (const dvec3& forward :
       {dvec3(1, 0, 0), dvec3(-1, 0, 0), dvec3(0, 1, 0), dvec3(0, -1, 0), dvec3(0, 0, 1),
        dvec3(0, 0, -1), random_unit(rng), random_unit(rng)}) {
    scene.views.push_back(perspective(eye, forward, 100.0, 0.05));
  }
  return scene;
}

Scene near_parallel_stack(std::uint64_t seed, double gap) {
  std::mt19937_64 rng(seed);
  Scene scene{"near_parallel_stack", {}, {}};
  for (int k = 0; k < 8; ++k) {
    const double cx = uniform(rng, -0.3, 0.3), cy = uniform(rng, -0.3, 0.3);
    const bool tilted = k % 2 == 1;
    const double a = tilted ? uniform(rng, -gap, gap) : 0.0;
    const double b = tilted ? uniform(rng, -gap, gap) : 0.0;
    Loop3 loop;
    for (const auto& [dx, dy] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}) {
      loop.emplace_back(cx + dx, cy + dy, k * gap + a * dx + b * dy);
    }
    scene.polygons.push_back({std::move(loop), {}});
  }
  scene.views = {orthographic(dvec3(0.0, 0.0, -1.0)), orthographic(dvec3(0.3, -0.2, -1.0))};
  return scene;
}

Scene almost_edge_on(std::uint64_t seed, const glm::dvec3& direction) {
  std::mt19937_64 rng(seed);
  Scene scene{"almost_edge_on", {ground(1.5)}, {}};
  const dvec3 d = glm::normalize(direction);
  const dvec3 horizontal = glm::cross(d, dvec3(0.0, 0.0, 1.0));
  const dvec3 a = glm::length(horizontal) > 0.0 ? glm::normalize(horizontal) : dvec3(0, 1, 0);
  const dvec3 c = glm::cross(a, d);
  constexpr double kTilts[] = {1e-3, 1e-6, 1e-9, 1e-12, 0.0};
  for (int row = 0; row < 2; ++row) {
    for (int k = 0; k < 5; ++k) {
      const dvec3 base(-1.0 + 0.5 * k + uniform(rng, -0.1, 0.1), 0.6 * row - 0.3, 0.3);
      const dvec3 width = 0.2 * a;
      const dvec3 height = -0.5 * (d + kTilts[k] * c);
      scene.polygons.push_back(
          {{base - width, base + width, base + width + height, base - width + height}, {}});
    }
  }
  scene.views = {orthographic(d, dvec3(0.0, 0.0, 0.3))};
  return scene;
}

std::vector<clipper::Box2> random_image_boxes(std::uint64_t seed, std::size_t count,
                                              std::size_t wide_every) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<clipper::Box2> boxes;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = 100.0 * unit(random) * unit(random), y = 50.0 * unit(random);
    const bool wide = wide_every != 0 && k % wide_every == 0;
    const double w = wide ? 80.0 : 0.1 + unit(random), h = wide ? 40.0 : 0.1 + unit(random);
    boxes.push_back({x, y, x + w, y + h});
  }
  return boxes;
}

}  // namespace shadowgen::test
