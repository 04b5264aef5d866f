#pragma once

// Whether a closed surface touches or crosses itself (closed_solids.h): the exact check
// of every pair of its triangles whose boxes meet, found in a grid of cubes, within a
// budget of candidate pairs linear in the triangles.

#include <vector>

#include "hsr/triangles_meet.h"

namespace shadowgen::shadows::detail {

// Whether some two of the triangles meet anywhere but where neighbours on a surface must
// (hsr::triangles_overlap_beyond_shared), told where two lie in one plane (`planes`: the
// coplanar group of each, -1 for none). Candidates are the pairs whose boxes meet, found
// in a grid of cubes about the size of the triangles: each pair is looked at in the one
// cube that holds the higher of the two boxes' low corners. Degenerate triangles are left
// out. Past the budget of candidate pairs, true: the surface is taken as touching itself.
bool touches_itself(const std::vector<hsr::Triangle3>& triangles, const std::vector<int>& planes);

}  // namespace shadowgen::shadows::detail
