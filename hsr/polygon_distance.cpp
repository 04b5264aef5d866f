#include "hsr/polygon_distance.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen::hsr {
namespace {

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

// Is q inside the outer loop, all seen in the plane's dominant-axis chart?
bool inside_outer(const glm::dvec3& q, const Loop3& loop, const Plane3& plane) {
  const glm::dvec3 a = glm::abs(plane.normal);
  const int k = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  bool inside = false;
  for (std::size_t m = 0, n = loop.size(); m < n; ++m) {
    const glm::dvec3& u = loop[m];
    const glm::dvec3& v = loop[(m + 1) % n];
    if ((u[j] > q[j]) != (v[j] > q[j])) {
      const double x = u[i] + (q[j] - u[j]) * (v[i] - u[i]) / (v[j] - u[j]);
      if (q[i] < x) inside = !inside;
    }
  }
  return inside;
}

}  // namespace

double distance_to_polygon(const glm::dvec3& p, const Polygon3& polygon, const Plane3& plane) {
  const double d = plane.signed_distance(p);
  const glm::dvec3 foot = p - d * plane.normal;
  if (inside_outer(foot, polygon.outer, plane)) return std::fabs(d);
  double best = std::numeric_limits<double>::infinity();
  const Loop3& loop = polygon.outer;
  for (std::size_t m = 0, n = loop.size(); m < n; ++m) {
    best = std::min(best, distance_to_segment(p, loop[m], loop[(m + 1) % n]));
  }
  return best;
}

DepthSpan depth_span(const glm::dvec3& eye, std::span<const Polygon3> polygons,
                     std::span<const Plane3> planes) {
  DepthSpan span;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (glm::length(planes[i].normal) == 0.0) continue;
    if (planes[i].signed_distance(eye) == 0.0) continue;  // seen edge-on: not drawn
    const double distance = distance_to_polygon(eye, polygons[i], planes[i]);
    if (distance < span.nearest) {
      span.nearest = distance;
      span.nearest_polygon = i;
    }
    for (const glm::dvec3& v : polygons[i].outer) {
      span.farthest = std::max(span.farthest, glm::distance(v, eye));
    }
  }
  return span;
}

}  // namespace shadowgen::hsr
