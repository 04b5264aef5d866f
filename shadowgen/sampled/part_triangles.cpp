#include "shadowgen/sampled/part_triangles.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>

#include "hsr/area.h"
#include "hsr/chart_triangles.h"

namespace shadowgen::sampled {

PartTriangles part_triangles(const hsr::Polygon3& part) {
  PartTriangles out;
  std::vector<glm::dvec3> vertices(part.outer);
  for (const hsr::Loop3& hole : part.holes)
    vertices.insert(vertices.end(), hole.begin(), hole.end());
  for (const glm::dvec3& v : vertices) {
    out.magnitude = std::max({out.magnitude, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  }
  const hsr::Plane3 plane = hsr::plane_of(part);
  if (plane.normal == glm::dvec3(0.0)) return out;  // no plane, no area: nothing to sample
  out.normal = plane.normal;
  out.area = hsr::area(part);

  const std::optional<hsr::ChartTriangles> split = hsr::chart_triangles(part, plane.normal);
  if (!split) throw std::runtime_error("a face part could not be split into triangles");
  for (std::size_t k = 0; k < split->triangles.size(); ++k) {
    if (split->flat_triangle(k)) continue;  // no area in the chart, none in the plane
    const clipper::Triangle& t = split->triangles[k];
    const Triangle3 tri{split->corners[t[0]], split->corners[t[1]], split->corners[t[2]]};
    const double a = 0.5 * glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a));
    if (!(a > 0.0)) continue;
    out.triangles.push_back(tri);
    out.upto.push_back(out.upto.back() + a);
  }
  return out;
}

}  // namespace shadowgen::sampled
