#pragma once

// Areas of planar 3D polygons with holes, measured in their own plane.

#include <span>

#include "hsr/polygon3.h"

namespace shadowgen::hsr {

// Area of the region (outer minus holes) of a planar polygon: for each loop half the
// length of its Newell vector (the true area in its plane, whatever the plane's
// orientation), summed relative to the loop's first vertex; a loop whose vertices are all
// collinear counts exactly 0. The holes' areas are subtracted from the outer loop's.
double area(const Polygon3& polygon);
double area(std::span<const Polygon3> polygons);

}  // namespace shadowgen::hsr
