#pragma once

// A planar polygon with holes as triangles on its own corners: ear clipping
// (clipper/triangulate.h) in the chart facing its normal (plane_chart.h), which drops a
// coordinate exactly, so the clipper's exact predicates decide on the corners themselves
// and the triangles are taken back on them unchanged. Triangles run as the outer loop
// does: counter-clockwise seen from the polygon's front side. Shared by the OBJ export,
// the sampled estimators' faces and the closed solids' surfaces.

#include <cstddef>
#include <optional>
#include <vector>

#include "clipper/polygon.h"
#include "clipper/triangulate.h"
#include "hsr/polygon3.h"

namespace shadowgen::hsr {

struct ChartTriangles {
  std::vector<glm::dvec3> corners;           // the outer loop's, then each hole's
  std::vector<clipper::Point2> flat;         // the same in the chart
  std::vector<clipper::Triangle> triangles;  // into both

  // Whether triangle k's corners are exactly collinear in the chart: no area.
  bool flat_triangle(std::size_t k) const;
};

// nullopt only where a hole could not be bridged, which valid polygons do not give.
std::optional<ChartTriangles> chart_triangles(const Polygon3& polygon, const glm::dvec3& normal);

// Tiles of at most this many vertices bound ear clipping's O(v²) to a few hundred steps
// per vertex, while a polygon of up to this many is triangulated whole, as before.
inline constexpr std::size_t kTileVertices = 256;

// chart_triangles for regions however large (a ground's lit region with a hole per
// building), as the exports want them: a polygon of more than kTileVertices vertices is
// first cut into tiles in its chart (clipper/tiles.h) and each tile triangulated, so the
// cost is near linear in its vertices instead of quadratic. Its corners are then the
// polygon's own, exactly, and the tiles' crossings with the cut lines, on the plane
// through its first vertex with `normal` (plane_chart.h, ChartedPlane::on_plane); the
// triangles' areas sum to the polygon's up to the clipper's rounding of those crossings.
// A polygon of at most kTileVertices vertices gets chart_triangles' triangles.
std::optional<ChartTriangles> tiled_chart_triangles(const Polygon3& polygon,
                                                    const glm::dvec3& normal);

}  // namespace shadowgen::hsr
