#pragma once

// Cleaning and orientation of input polygons: what clip() does to its inputs first.

#include "clipper/polygon.h"

namespace shadowgen::clipper {

// Removes repeated consecutive vertices, zero-area spikes (a vertex where the boundary
// turns straight back) and collinear vertices, all decided exactly, repeating until
// none is left. Returns false when fewer than three vertices remain (no area).
bool clean_loop(Loop2& loop);

// Cleans every loop, drops loops without area, orients outer loops counter-clockwise and
// holes clockwise. A polygon whose outer loop has no area is dropped with its holes.
PolygonSet2 normalized(const PolygonSet2& polygons);

// Exact orientation of a clean loop (at least three vertices, no spike): the turn at its
// lexicographically smallest vertex.
bool is_counter_clockwise(const Loop2& loop);

}  // namespace shadowgen::clipper
