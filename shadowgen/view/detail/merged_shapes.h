#pragma once

// Pieces of a picture that touch, joined into as few polygons as their shared edges allow
// (clipper::merge_adjacent), for one path per colour and for outlines.

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::view::detail {

// The union of `pieces`, which do not overlap, by clipper::merge_adjacent; where its snap
// rounding does not settle (clipper::SnapRoundingError), the pieces as they are: the same
// points covered, only not joined. The joined boundary moves by at most the snapping's
// hot pixel (clipper/detail/snap.h: six ulps of the coordinates' magnitude). Vertices
// where a joined boundary runs straight on are dropped (exactly: the area is unchanged).
clipper::PolygonSet2 merged_shapes(std::span<const clipper::PolygonWithHoles2> pieces);

}  // namespace shadowgen::view::detail
