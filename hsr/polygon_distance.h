#pragma once

// Distances from a point to planar polygons, as light ranges and point lights' near
// planes need them.

#include <cstddef>
#include <glm/vec3.hpp>
#include <limits>
#include <span>

#include "hsr/polygon3.h"

namespace shadowgen::hsr {

// Distance from p to the polygon's region (outer minus holes treated as the outer's
// region: a lower bound, which is what range culling and near planes need). `plane` is
// plane_of(polygon).
double distance_to_polygon(const glm::dvec3& p, const Polygon3& polygon, const Plane3& plane);

// How deep a point light at `eye` sees into the polygons (planes[i] == plane_of
// (polygons[i])): the distance to the nearest polygon and to the farthest outer vertex,
// over the polygons with a plane that does not pass through the eye (those seen edge-on
// show nothing). nearest is infinite, and nearest_polygon npos, where no polygon counts.
struct DepthSpan {
  double nearest = std::numeric_limits<double>::infinity();
  double farthest = 0.0;
  std::size_t nearest_polygon = static_cast<std::size_t>(-1);
};
DepthSpan depth_span(const glm::dvec3& eye, std::span<const Polygon3> polygons,
                     std::span<const Plane3> planes);

}  // namespace shadowgen::hsr
