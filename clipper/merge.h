#pragma once

// Merging polygons that share edges, without clipping: the cheap half of a union.

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// Merges disjoint polygons (interiors not overlapping) along the edges they share: an edge
// p -> q of one and q -> p of another cancel. Edges that overlap only in part (a
// T-junction) are first split where a vertex of one lies on the other or within a
// rounding of it (edge_noding.h: twice the crossing error bound of clip.h), and cancel
// there too. So pieces clipped apart join along seams their rounding left a hair apart;
// the joined boundary moves by at most that bound. Where pieces meet otherwise, the
// result may still hold several polygons where an exact union would hold one.
PolygonSet2 merge_adjacent(std::span<const PolygonWithHoles2> polygons);

}  // namespace shadowgen::clipper
