#pragma once

// The region of a face whose holes share segments of their edges with its outer loop or
// with each other (loops that check_loops accepts with LoopCheck::shares_edges, in the
// face's chart): the outer loop less the holes, as the clipper's pieces (clipper/clip.h:
// the outer loop the subject, the holes the clips, their union taken), in the clipper's
// conventions (clipper/polygon.h): each piece's outer loop counter-clockwise in the chart,
// its holes clockwise, loops meeting only at points. A window across the whole width of
// a wall leaves two pieces; holes that cover the outer loop whole leave none.
//
// Vertices. The loops being valid, nothing crosses: every point where two loops meet is a
// vertex of one of them, so the clipper constructs no point, and every vertex of a piece
// is an input vertex at the same chart coordinates, bit for bit. The one exception is the
// clipper's snapping (docs/clipper.md, "Exactness and tolerance"): where it has to snap on a grid,
// a vertex moves by less than 12u of the largest coordinate (u = 2^-53), and a piece's
// vertex may then be no input vertex; the caller puts such a point on the face's plane.
// A vertex where loops meet stays where a piece's boundary runs straight on through it (the
// corners where two windows side by side meet); a vertex of one loop alone where it runs
// straight on may be left out (clip.h normalises its input).
//
// Throws clipper::SnapRoundingError where the clipper's snapping does not settle
// (docs/clipper.md, Limit; no input is known to cause it).

#include <span>

#include "clipper/polygon.h"

namespace shadowgen::scene::detail {

// loops[0] is the outer loop, the others holes, either orientation.
clipper::PolygonSet2 region_less_holes(std::span<const clipper::Loop2> loops);

}  // namespace shadowgen::scene::detail
