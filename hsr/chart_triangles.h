#pragma once

// A planar polygon with holes as triangles on its own corners: ear clipping
// (clipper/triangulate.h) in the chart facing its normal (plane_chart.h), which drops a
// coordinate exactly, so the clipper's exact predicates decide on the corners themselves
// and the triangles are taken back on them unchanged. Triangles run as the outer loop
// does: counter-clockwise seen from the polygon's front side. Shared by the OBJ export,
// the sampled estimators' faces and the closed solids' surfaces.

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

}  // namespace shadowgen::hsr
