#pragma once

// Merging polygons that share edges, without clipping: the cheap half of a union.

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// Merges disjoint polygons (interiors not overlapping) along the edges they share: an edge
// p -> q of one and q -> p of another cancel. The pieces are first snap rounded together
// (detail/snap_rounding.h), so edges that overlap only in part (a T-junction) or along
// seams whose vertices were rounded on either side of the common line, within a hot
// pixel of each other, become runs of the same segments and cancel too; the joined
// boundary moves by at most a pixel. The result bounds the points some piece covers
// (pieces that do overlap, by rounding or otherwise, are joined as a union would), as
// few polygons as the snapped boundaries allow. Throws SnapRoundingError (clip.h) where
// the snapping does not settle.
PolygonSet2 merge_adjacent(std::span<const PolygonWithHoles2> polygons);

}  // namespace shadowgen::clipper
