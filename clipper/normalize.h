#pragma once

// Cleaning and orientation of input polygons: what clip() does to its inputs first.

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// Removes repeated consecutive vertices, zero-area spikes (a vertex where the boundary
// turns straight back) and collinear vertices, all decided exactly, repeating until
// none is left. Returns false when fewer than three vertices remain (no area).
bool clean_loop(Loop2& loop);

// The same but keeps vertices where the boundary runs straight on: such a vertex may be
// where another loop touches this one, which must stay a vertex of both.
bool remove_spikes(Loop2& loop);

// Cleans every loop, drops loops without area, orients outer loops counter-clockwise and
// holes clockwise. A polygon whose outer loop has no area is dropped with its holes.
PolygonSet2 normalized(const PolygonSet2& polygons);
// The same for one polygon: none or one.
PolygonSet2 normalized_polygon(const PolygonWithHoles2& polygon);

// Exact orientation of a loop without spikes (at least three vertices, not all on one
// line): the turn at its lexicographically smallest vertex, which is never straight.
bool is_counter_clockwise(const Loop2& loop);

// The orientation of an input loop's body: the sign of its signed area where floating
// point decides it (the sum's rounding error bound is below its magnitude), else
// is_counter_clockwise. The two agree on every simple loop. They differ on a loop that
// crosses itself by rounding, as a polygon lifted to 3D and charted in another plane
// can: a lobe of 1e-31 at its lowest vertex turns the other way from the body around
// it, and orienting by the lobe would make the body a hole.
bool encloses_counter_clockwise(const Loop2& loop);

}  // namespace shadowgen::clipper
