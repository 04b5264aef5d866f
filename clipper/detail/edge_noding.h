#pragma once

// Noding of the clipper's traced edges, the last step before assembly.
//
// The inside and outside pieces are traced through rounded crossing points. A rounded
// point can land on the far side of a vertex or an edge that passes within a rounding of
// it, and then two stretches that met only at their ends in exact arithmetic cross or
// touch (a loop crossing itself, two pieces overlapping along a sliver). This step finds
// every such contact exactly, splits the edges there (proper crossings at a rounded
// point again, so it repeats until no new contact appears) and cancels edges that run
// both ways along the same segment. Afterwards the edges meet only at their endpoints,
// which is what the assembly needs to trace simple loops.
//
// Only edges with an endpoint at a constructed point can have moved, so only pairs with
// such an edge are tested; the others are exact pieces of input edges, already noded.

#include <unordered_set>
#include <vector>

#include "clipper/detail/boundary_graph.h"
#include "clipper/point.h"

namespace shadowgen::clipper::detail {

struct NodingStats {
  int rounds = 0;          // rounds that split something
  std::size_t splits = 0;  // edges split
  std::size_t cancelled = 0;
};

// `constructed`: the points that are not input vertices (rounded crossings); edges
// touching none of them are not tested against each other. `made`, when given,
// receives the crossing points the noding constructed.
std::vector<DirectedEdge> node_edges(std::vector<DirectedEdge> edges,
                                     const std::unordered_set<Point2, Point2Hash>& constructed,
                                     NodingStats* stats = nullptr,
                                     std::unordered_set<Point2, Point2Hash>* made = nullptr);

// For edges of pieces computed apart (merge.h), which meet at T-junctions and along
// seams whose vertices were rounded on either side of the common line: every edge is
// split at each vertex lying on it or within snap distance of it (snap.h), then opposite
// edges cancel. No point is
// constructed, so nothing new can come into contact; an edge moves by at most that
// distance. (Noding such a seam at its rounded crossings instead would cut it into a
// chain of slivers.)
// `snapped`, when given, receives the vertices that split an edge they were not exactly
// on: the edges at them moved, and may need noding again.
std::vector<DirectedEdge> snap_vertices_onto_edges(
    std::vector<DirectedEdge> edges, NodingStats* stats = nullptr,
    std::unordered_set<Point2, Point2Hash>* snapped = nullptr);

}  // namespace shadowgen::clipper::detail
