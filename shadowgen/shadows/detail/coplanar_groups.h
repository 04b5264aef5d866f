#pragma once

// Which faces lie in exactly the same plane: such faces never shadow each other.

#include <span>
#include <vector>

#include "hsr/polygon3.h"

namespace shadowgen::shadows::detail {

// Group index per polygon, or -1 for a polygon that shares its plane with no other.
// Candidates are found by sorting on the fitted planes; membership is then decided
// exactly (clipper::orient3d of every vertex against three of the group's first member),
// so "coplanar" means exactly coplanar in the given coordinates, as the spec says.
std::vector<int> coplanar_groups(std::span<const hsr::Polygon3> polygons,
                                 std::span<const hsr::Plane3> planes);

}  // namespace shadowgen::shadows::detail
