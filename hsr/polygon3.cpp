#include "hsr/polygon3.h"

#include <glm/geometric.hpp>

#include "hsr/vector_length.h"

namespace shadowgen::hsr {

double Plane3::signed_distance(const glm::dvec3& p) const { return glm::dot(normal, p) - offset; }

glm::dvec3 newell_vector(const Loop3& loop) {
  const std::size_t n = loop.size();
  glm::dvec3 normal(0.0);
  if (n < 3) return normal;
  const glm::dvec3 o = loop[0];
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 a = loop[i] - o;
    const glm::dvec3 b = loop[(i + 1) % n] - o;
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
  }
  return normal;
}

Plane3 plane_of(const Polygon3& polygon) {
  const Loop3& loop = polygon.outer;
  Plane3 plane;
  const glm::dvec3 normal = newell_vector(loop);
  const double length = stable_length(normal);
  if (!(length > 0.0)) {
    plane.normal = glm::dvec3(0.0);
    return plane;
  }
  // The centroid relative to the first vertex too.
  const glm::dvec3 o = loop[0];
  glm::dvec3 centroid(0.0);
  for (const glm::dvec3& p : loop) centroid += p - o;
  plane.normal = normal / length;
  centroid = o + centroid / static_cast<double>(loop.size());
  plane.offset = glm::dot(plane.normal, centroid);
  return plane;
}

}  // namespace shadowgen::hsr
