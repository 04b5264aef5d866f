#pragma once

// Merging polygons that share edges, without clipping: the cheap half of a union.

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// Merges disjoint polygons (interiors not overlapping) along the edges they share exactly:
// an edge p -> q of one and q -> p of another cancel, and the rest is traced into polygons
// with holes. Edges that overlap only in part (a T-junction) are left as they are, so the
// result may still hold several polygons where an exact union would hold one; its region
// is always the union of the inputs.
PolygonSet2 merge_adjacent(std::span<const PolygonWithHoles2> polygons);

}  // namespace shadowgen::clipper
