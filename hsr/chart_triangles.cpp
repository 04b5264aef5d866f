#include "hsr/chart_triangles.h"

#include "clipper/predicates.h"
#include "hsr/plane_chart.h"

namespace shadowgen::hsr {

bool ChartTriangles::flat_triangle(std::size_t k) const {
  const clipper::Triangle& t = triangles[k];
  return clipper::orient2d(flat[t[0]], flat[t[1]], flat[t[2]]) == clipper::Orientation::kCollinear;
}

std::optional<ChartTriangles> chart_triangles(const Polygon3& polygon, const glm::dvec3& normal) {
  const PlaneChart chart = chart_facing(normal);
  ChartTriangles out;
  out.corners = polygon.outer;
  std::vector<clipper::Loop2> loops{chart.flatten(polygon.outer)};
  for (const Loop3& hole : polygon.holes) {
    loops.push_back(chart.flatten(hole));
    out.corners.insert(out.corners.end(), hole.begin(), hole.end());
  }
  for (const clipper::Loop2& loop : loops)
    out.flat.insert(out.flat.end(), loop.begin(), loop.end());
  std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
  if (!triangles) return std::nullopt;
  out.triangles = std::move(*triangles);
  return out;
}

}  // namespace shadowgen::hsr
