#include "clipper/merge.h"

#include "clipper/normalize.h"
#include "detail/boundary_graph.h"
#include "detail/overlay.h"
#include "detail/snap_rounding.h"

namespace shadowgen::clipper {

PolygonSet2 merge_adjacent(std::span<const PolygonWithHoles2> polygons) {
  if (polygons.size() <= 1) return normalized(PolygonSet2(polygons.begin(), polygons.end()));
  // Snapped together (detail/snap_rounding.h), the pieces' boundaries meet only at
  // common vertices: T-junctions, and seams whose vertices were rounded on either side of
  // the common line, become runs of segments shared exactly. Their multiplicities cancel
  // in the overlay (detail/overlay.h), whose boundary of "subject minus nothing" is the
  // boundary of the points some piece covers.
  std::vector<Loop2> loops[2];
  for (const PolygonWithHoles2& p : normalized(PolygonSet2(polygons.begin(), polygons.end()))) {
    loops[0].push_back(p.outer);
    for (const Loop2& h : p.holes) loops[0].push_back(h);
  }
  detail::snap_round(loops);
  const detail::OverlayEdges edges = detail::overlay(loops);
  return detail::assemble_polygons(edges.outside, edges.point_count);
}

}  // namespace shadowgen::clipper
