#include "hsr/chart_triangles.h"

#include "clipper/predicates.h"
#include "clipper/tiles.h"
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

std::optional<ChartTriangles> tiled_chart_triangles(const Polygon3& polygon,
                                                    const glm::dvec3& normal) {
  std::size_t n = polygon.outer.size();
  for (const Loop3& hole : polygon.holes) n += hole.size();
  if (n <= kTileVertices || polygon.outer.empty()) return chart_triangles(polygon, normal);
  ChartedPlane plane(normal, polygon.outer.front(), ChartFrom::kWorld);
  const clipper::PolygonWithHoles2 flat = plane.flatten_known(polygon);
  ChartTriangles out;
  for (const clipper::PolygonWithHoles2& tile : clipper::split_into_tiles(flat, kTileVertices)) {
    std::vector<clipper::Loop2> loops{tile.outer};
    loops.insert(loops.end(), tile.holes.begin(), tile.holes.end());
    std::optional<std::vector<clipper::Triangle>> triangles = clipper::triangulate(loops);
    if (!triangles) return std::nullopt;
    const std::size_t first = out.flat.size();
    for (const clipper::Loop2& loop : loops) {
      for (const clipper::Point2& q : loop) {
        out.flat.push_back(q);
        out.corners.push_back(plane.lift(q));
      }
    }
    for (const clipper::Triangle& t : *triangles) {
      out.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    }
  }
  return out;
}

}  // namespace shadowgen::hsr
