#pragma once

// Which side of the other operand each edge of the snapped boundaries lies on: the
// classification half of the clipper, exact on the plane graph that snap rounding left
// (snap_rounding.h).
//
// An operand's edges that run both ways along one segment cancel (a needle or crack of
// its region that the snapping closed, bounding nothing). Each stretch of a boundary
// between two vertices both operands share lies on one side; it is decided at such a
// vertex from the other operand's live edges there alone: turning counter-clockwise from
// the stretch, the first of them met has the region on its left, so the stretch is
// inside when that one arrives, outside when it leaves, and shared when it runs along the
// stretch. Where the other operand's edges at the vertex do not alternate between
// arriving and leaving (snapping folded its boundary onto itself there), the stretch is
// located exactly against the whole other boundary instead. A loop that shares no vertex
// with the other operand is located at one of its vertices.

#include <array>
#include <vector>

#include "clipper/detail/boundary_graph.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

struct ClassifiedEdges {
  std::vector<DirectedEdge> inside, outside, shared_same, shared_opposite;
};

// loops[0], loops[1]: the snapped loops of the two operands, each with its region on the
// left. Returns each operand's live edges by side of the other.
std::array<ClassifiedEdges, 2> classify_edges(const std::vector<Loop2> (&loops)[2]);

}  // namespace shadowgen::clipper::detail
