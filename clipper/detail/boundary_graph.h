#pragma once

// Turning a set of directed boundary edges (region on the left) into polygons with
// holes: the traversal half of the clipper, shared by the inside and outside pieces.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

// An edge with its ends' ids in a numbering of the points that the edges come with
// (the overlay's): equal points, equal ids, all below the count given with the edges.
struct DirectedEdge {
  Point2 from;
  Point2 to;
  std::uint32_t from_id;
  std::uint32_t to_id;
};

// Traces closed loops through the edges (a walk that ends where no edge leaves, which
// edges whose every point has as many edges in as out never do, makes no loop). Where
// several edges leave one point, the walk
// takes the first one clockwise from the way it came in (the tightest turn around the
// region on its left), so regions that only touch at a point become separate loops;
// loops are then split at repeated vertices, rid of spikes (normalize.h's remove_spikes), and
// sorted into counter-clockwise outer loops and clockwise holes, each hole attached to
// the smallest outer loop containing it.
// `point_count`: the number of ids the edges' points are numbered with.
PolygonSet2 assemble_polygons(const std::vector<DirectedEdge>& edges, std::size_t point_count);

}  // namespace shadowgen::clipper::detail
