#include "shadowgen/shadows/light_views.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen {
namespace {

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::distance(p, a + t * ab);
}

// Is q inside the outer loop, all seen in the plane's dominant-axis chart?
bool inside_outer(const glm::dvec3& q, const hsr::Loop3& loop, const hsr::Plane3& plane) {
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

double distance_to_polygon(const glm::dvec3& p, const hsr::Polygon3& polygon,
                           const hsr::Plane3& plane) {
  const double d = plane.signed_distance(p);
  const glm::dvec3 foot = p - d * plane.normal;
  if (inside_outer(foot, polygon.outer, plane)) return std::fabs(d);
  double best = std::numeric_limits<double>::infinity();
  const hsr::Loop3& loop = polygon.outer;
  for (std::size_t m = 0, n = loop.size(); m < n; ++m) {
    best = std::min(best, distance_to_segment(p, loop[m], loop[(m + 1) % n]));
  }
  return best;
}

std::vector<hsr::View> light_views(const Light& light, std::span<const hsr::Polygon3> polygons,
                                   std::span<const hsr::Plane3> planes, const glm::dvec3& centre) {
  if (light.type == LightType::kDirectional) {
    return {hsr::View::orthographic(light.direction, centre)};
  }
  const glm::dvec3& eye = light.position;
  double nearest = std::numeric_limits<double>::infinity();
  double farthest = 0.0;
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    if (glm::length(planes[i].normal) == 0.0) continue;
    if (planes[i].signed_distance(eye) == 0.0) continue;  // seen edge-on: not drawn
    nearest = std::min(nearest, distance_to_polygon(eye, polygons[i], planes[i]));
    for (const glm::dvec3& v : polygons[i].outer) {
      farthest = std::max(farthest, glm::distance(v, eye));
    }
  }
  if (!std::isfinite(nearest)) return {};
  // Half the smallest depth any polygon point can have in a frustum, so nothing is cut
  // off: a polygon 1e-12 from the lamp still occludes (a light exactly on a polygon's
  // plane is handled by that polygon being edge-on). Never below 2^-450 of the farthest
  // distance, only so that image coordinates (up to farthest / near) keep finite squares.
  const double near = std::max(0.5 * nearest / std::sqrt(3.0), 0x1p-450 * farthest);

  static const std::array<glm::dvec3, 6> kAxes = {glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
                                                  glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0),
                                                  glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)};
  std::vector<hsr::View> views;
  for (const glm::dvec3& axis : kAxes) {
    const glm::dvec3 up = std::fabs(axis.z) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
    hsr::View view = hsr::View::perspective(eye, axis, up, 90.0, near);
    // Keep the frustum when some polygon is not wholly outside one of its five planes.
    const bool sees_something = std::any_of(polygons.begin(), polygons.end(), [&](const auto& p) {
      std::array<bool, 5> all_out{true, true, true, true, true};
      for (const glm::dvec3& v : p.outer) {
        const glm::dvec3 e = view.to_eye_frame(v);
        const double side[5] = {e.z - near, e.z - e.x, e.z + e.x, e.z - e.y, e.z + e.y};
        for (int s = 0; s < 5; ++s) all_out[s] = all_out[s] && side[s] < 0.0;
      }
      return std::none_of(all_out.begin(), all_out.end(), [](bool b) { return b; });
    });
    if (sees_something) views.push_back(view);
  }
  return views;
}

}  // namespace shadowgen
