#pragma once

// The Boolean combination of the snapped boundaries: the classification half of the
// clipper, exact on the plane graph that snap rounding left (snap_rounding.h).
//
// Both operands' loops become one graph: a vertex for every distinct point, an edge for
// every distinct segment, carrying each operand's net multiplicity along it (how many
// times its loops run one way along the segment minus the other way). Snapping can make
// a loop run along a segment twice, or both ways (a needle of its region closed up), or
// fold back on itself; net multiplicities count all of that as it is.
//
// Every face of the graph then has a winding number for each operand, and crossing an
// edge from its right to its left adds the edge's multiplicities. Around a vertex the
// windings of the sectors between its edges follow from one another that way, so they
// spread from vertex to vertex along the edges, exactly (no geometry beyond the order of
// edges around a vertex, by orient2d). Each connected part of the graph starts from the
// sector left of its lowest-leftmost vertex, which lies outside all of the part's own
// loops: its winding numbers are those of that vertex against the other parts' loops,
// found by exact point location.
//
// A point lies in an operand's region where that operand's winding number is positive.
// An edge bounds the intersection (or the difference) where that holds of the faces on
// one side and not the other, and runs with the region on its left.

#include <cstddef>
#include <vector>

#include "boundary_graph.h"
#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

struct OverlayEdges {
  std::vector<DirectedEdge> inside;   // bounding subject ∩ clip
  std::vector<DirectedEdge> outside;  // bounding subject − clip
  std::size_t point_count = 0;        // the ids of the edges' points are below it
};

// loops[0], loops[1]: the snapped loops of the subject and the clip, each with its
// region on the left. The clip's loops may be those of several overlapping polygons:
// their winding numbers add up, and the clip is their union. Edges where snapping left the graph
// unnoded (two edges crossing, or running along one another without sharing their ends) are not
// detected here; the faces around them get the windings of whichever side the spreading reached
// first.
OverlayEdges overlay(const std::vector<Loop2> (&loops)[2]);

}  // namespace shadowgen::clipper::detail
