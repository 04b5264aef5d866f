#include "shadowgen/sampled/part_triangles.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <stdexcept>

#include "clipper/predicates.h"
#include "clipper/triangulate.h"
#include "hsr/area.h"
#include "hsr/plane_chart.h"

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

  // The chart drops a coordinate, exactly, so the ear clipper's exact predicates decide on
  // the part's own vertices, and the triangles are taken back on them unchanged.
  const hsr::PlaneChart chart = hsr::chart_facing(plane.normal);
  std::vector<clipper::Loop2> loops{chart.flatten(part.outer)};
  for (const hsr::Loop3& hole : part.holes) loops.push_back(chart.flatten(hole));
  std::vector<clipper::Point2> flat;
  for (const clipper::Loop2& loop : loops) flat.insert(flat.end(), loop.begin(), loop.end());
  const std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
  if (!triangles) throw std::runtime_error("a face part could not be split into triangles");
  for (const clipper::Triangle& t : *triangles) {
    if (clipper::orient2d(flat[t[0]], flat[t[1]], flat[t[2]]) == clipper::Orientation::kCollinear) {
      continue;  // no area in the chart, none in the plane
    }
    const Triangle3 tri{vertices[t[0]], vertices[t[1]], vertices[t[2]]};
    const double a = 0.5 * glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a));
    if (!(a > 0.0)) continue;
    out.triangles.push_back(tri);
    out.upto.push_back(out.upto.back() + a);
  }
  return out;
}

}  // namespace shadowgen::sampled
