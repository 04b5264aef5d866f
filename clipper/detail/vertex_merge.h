#pragma once

// Vertex–vertex snapping of the clipper's traced edges.
//
// A crossing that exact arithmetic puts on a vertex (an edge passing within a rounding
// of the other operand's vertex crosses the edges there) is rounded to a point an ulp or
// two beside it. Traced through both points, the boundary runs out to the far end of an
// edge and comes back along a nearly identical one: a needle loop whose two tips are an
// ulp apart, which the assembly cannot tell from a real hole or island. Merging the
// constructed point into the vertex makes those two edges one segment run both ways,
// which the noding cancels.
//
// Two vertices are close when they lie within snap_distance (snap.h) of each other: for
// points that near, 2u·|P|, the part of a crossing's error bound that does not depend on
// edge length. Two crossings are also close within the sum of their own error bounds
// (`radii` below). Farther points are genuine features, and input vertices never move.

#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "clipper/detail/boundary_graph.h"
#include "clipper/point.h"

namespace shadowgen::clipper::detail {

// Replaces each constructed vertex of `edges` (one for which `is_input` is false) that
// is close to another vertex: by the nearest close input vertex (ties to the least
// point), or, with none, by the least close vertex if that is less than itself, so the
// choice does not depend on the edges' order. Edges shrunk to a point are dropped.
// `candidates`: every point of `edges` that may be constructed (a superset will do;
// `is_input` has the last word); only pairs with one of them are looked at.
// `moved` receives the vertices that gained edges: those edges moved, by at most the
// snap distance, and may need noding again. `is_input` is asked only about vertices
// that have a close neighbour, which is rare.
// `radii`, when given, holds for crossings the error bound of their construction
// (clip.h: 4u·min(|a|, |b|) + u·|P|). Two crossings less than the sum of their bounds
// apart are close too: rounded nearer than their errors, nothing tells where either
// exact point lies relative to the other, and kept apart they can leave the traced
// boundary without a consistent order (three edges folded onto one line within 1e-17 of
// each other, each crossed by one edge of the other operand, rounded 2 ulps apart).
using ErrorRadii = std::unordered_map<Point2, double, Point2Hash>;
std::vector<DirectedEdge> merge_close_vertices(
    std::vector<DirectedEdge> edges, const std::unordered_set<Point2, Point2Hash>& candidates,
    const std::function<bool(const Point2&)>& is_input,
    std::unordered_set<Point2, Point2Hash>& moved, const ErrorRadii* radii = nullptr);

}  // namespace shadowgen::clipper::detail
