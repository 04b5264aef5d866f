#pragma once

// A polygon of many vertices cut into tiles, for the algorithms whose cost grows with the
// square of one polygon's vertices. Ear clipping (triangulate.h) scans the whole boundary
// for each hole's bridge and each ear, so a ground's lit region with a hole per building
// (10^4 holes, 10^5 vertices) takes minutes whole and milliseconds as tiles of a few
// hundred vertices.
//
// Method. Cut lines parallel to the axes at quantiles of the vertices' coordinates (each
// halfway between two consecutive distinct values, so that no vertex lies on one) make a
// grid of about 2n / max_vertices cells, as many across as the polygon's box is wide
// against its height. The polygon is clipped by the grid's black cells as a chessboard
// colours them, in one clip (clip.h): the inside pieces lie in black cells and the
// outside pieces in white ones, and all come from the same snapped graph, so tiles that
// share a seam share every vertex along it. Cost O((n + k) log n + n·g) for n vertices,
// k crossings of the cuts with the edges and g cells across, instead of ear clipping's
// O(n²) on the whole.

#include <cstddef>

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// `polygon` (a valid polygon with holes, either orientation) as tiles: itself, unchanged,
// when it has at most `max_vertices` vertices (outer loop and holes together); else its
// pieces in the cells of the grid above. The tiles cover the polygon without overlapping,
// up to the clipper's snapping of the crossings (clip.h: each new point within its hot
// pixel), so their areas sum to its area within rounding_area_bound of the cut lines'
// pieces. Every vertex of the polygon is a vertex of a tile, where a loop runs straight on
// included (it may be where another polygon touches this one, as between a face's light
// regions); the tiles' other vertices are the crossings on the cut lines. The tiles' loops
// run the way the polygon's run: outer loops as its outer loop, holes the other way.
// Where the snapping does not settle (SnapRoundingError, clip.h), the polygon is returned
// whole: it is then as slow to triangulate as before, never wrong. A tile may have more
// than `max_vertices` vertices where the vertices crowd into one cell.
PolygonSet2 split_into_tiles(const PolygonWithHoles2& polygon, std::size_t max_vertices);

}  // namespace shadowgen::clipper
