#pragma once

// Seeded 3D scenes for the hidden-surface suites, and the views to look at them from.
//
// Every scene is built in local coordinates of size about 1 to 6 around the origin; its
// views are described in the same coordinates (ViewSpec), so `placed` can move the scene
// far from the origin or scale it together with its views, and each case also runs at
// the extremes. Generators draw only from a std::mt19937_64 seeded by the caller: a seed
// names the same scene on every run of one build.

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "clipper/box.h"
#include "hsr/polygon3.h"
#include "hsr/view.h"

namespace shadowgen::test {

struct ViewSpec {
  bool perspective = false;
  glm::dvec3 point{0.0};  // orthographic: the image centre; perspective: the eye
  glm::dvec3 direction{0.0, 0.0, -1.0};
  glm::dvec3 up{0.0, 0.0, 1.0};
  double fov_deg = 90.0;  // perspective only
  double near = 0.1;      // perspective only
};

hsr::View make_view(const ViewSpec& spec);

struct Scene {
  std::string name;
  std::vector<hsr::Polygon3> polygons;
  std::vector<ViewSpec> views;
};

// p -> offset + scale·p, for the polygons and the views' points (near distances scale
// too). Each coordinate is rounded once: far from the origin, polygons with more than
// three vertices stop being exactly planar, by about one ulp of the offset.
struct Placement {
  glm::dvec3 offset{0.0};
  double scale = 1.0;
};
Scene placed(const Scene& scene, const Placement& placement);

// `count` triangles with vertices within 0.35 of random centres in [-1, 1]³: they
// overlap and pierce each other. Two random orthographic views.
Scene triangle_soup(std::uint64_t seed, int count);

// A ground square [-1.5, 1.5]² at z = 0 and `count` boxes standing on it (six outward
// faces each, the bottom face on the ground plane), rotated about z, some of them
// interpenetrating. Two orthographic views from above.
Scene boxes_on_ground(std::uint64_t seed, int count);

// `count` concave polygons with 1 to 3 holes (test::random_polygon_with_holes, scaled to
// radius about 0.5) in random planes through points of [-0.8, 0.8]³. Two orthographic
// views.
Scene polygons_with_holes(std::uint64_t seed, int count);

// `triples` stacked triples of sticks, each triple cyclic: stick k lies above stick k+1
// at one crossing and below stick k-1 at the other (A over B over C over A), so no
// depth order of whole polygons exists. Views from straight above and slightly tilted.
Scene cyclic_sticks(std::uint64_t seed, int triples);

// `count` rectangles of side 0.6 to 1.4 through points of [-0.4, 0.4]³ in random
// orientations: nearly every pair interpenetrates. Two orthographic views.
Scene interpenetrating_quads(std::uint64_t seed, int count);

// Boxes on a ground and a triangle soup seen in perspective from eyes standing among
// them: the near plane cuts the ground, boxes and triangles.
Scene near_plane_cut(std::uint64_t seed);

// The six faces of the cube [-1, 1]³ turned inward, two boxes on its floor and a few
// triangles, seen in perspective from an eye inside, along the six axes and two random
// directions. Every view's near plane cuts the side walls.
Scene inside_closed_box(std::uint64_t seed);

// Eight overlapping squares stacked `gap` apart in depth, half of them tilted by slopes
// up to `gap`, so neighbours either lie `gap` apart or cross at an angle of about `gap`.
// Views from straight above and oblique.
Scene near_parallel_stack(std::uint64_t seed, double gap);

// A ground square and fins standing above it, each tilted from the view direction by
// 1e-3, 1e-6, 1e-9, 1e-12 or 0 radians (the last seen exactly edge-on when `direction`
// is an axis). One orthographic view along `direction`, which must point downward.
Scene almost_edge_on(std::uint64_t seed, const glm::dvec3& direction);

// Image-space boxes of pieces: x in [0, 100], denser to the left (quantile cuts, not equal
// widths, balance image regions over them), y in [0, 50], sides 0.1 to 1.1; every
// `wide_every`-th box (0: none) is 80 × 40 instead, as wide as a ground plane.
std::vector<clipper::Box2> random_image_boxes(std::uint64_t seed, std::size_t count,
                                              std::size_t wide_every = 0);

}  // namespace shadowgen::test
