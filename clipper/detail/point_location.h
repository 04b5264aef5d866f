#pragma once

// Exact point-in-region tests on loops whose region lies to their left.

#include <vector>

#include "clipper/polygon.h"
#include "clipper/predicates.h"

namespace shadowgen::clipper::detail {

enum class Location { kOutside, kBoundary, kInside };

// Against one loop, whatever its orientation: inside means enclosed by it.
Location locate(const Point2& p, const Loop2& loop);

// Against a region given by all its loops (outer loops counter-clockwise, holes
// clockwise): the winding number is 1 inside, 0 outside.
Location locate(const Point2& p, const std::vector<Loop2>& loops);

// The same for the midpoint (a + b) / 2, decided exactly without rounding it: the rounded
// midpoint of a segment can lie an ulp off it, across a boundary running within an ulp
// of the segment, and so be located on the wrong side of that boundary.
Location locate_midpoint(const Point2& a, const Point2& b, const Loop2& loop);
Location locate_midpoint(const Point2& a, const Point2& b, const std::vector<Loop2>& loops);

// Adds the loop's winding number around p (counter-clockwise turns positive) to
// `winding`; returns false, leaving it partly added, when p lies on the loop.
bool add_winding_number(const Point2& p, const Loop2& loop, int& winding);
bool add_winding_number(const Midpoint2& p, const Loop2& loop, int& winding);

}  // namespace shadowgen::clipper::detail
