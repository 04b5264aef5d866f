#pragma once

// Exact point-in-region tests on loops whose region lies to their left.

#include <vector>

#include "clipper/polygon.h"

namespace shadowgen::clipper::detail {

enum class Location { kOutside, kBoundary, kInside };

// Against one loop, whatever its orientation: inside means enclosed by it.
Location locate(const Point2& p, const Loop2& loop);

// Against a region given by all its loops (outer loops counter-clockwise, holes
// clockwise): the winding number is 1 inside, 0 outside.
Location locate(const Point2& p, const std::vector<Loop2>& loops);

}  // namespace shadowgen::clipper::detail
